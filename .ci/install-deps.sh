#!/usr/bin/env bash
# Installs SurfaceMaps' build and test dependencies from Debian 12 packages.
# Idempotent: packages already present are skipped, apt is only touched when
# something is missing. Run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libvtk9-dev python3-vtk9 vtk9
  libeigen3-dev libsuitesparse-dev libopenblas0-openmp libopenmesh-dev libcgal-dev libboost-dev libgmp-dev libmpfr-dev
  libgtest-dev
  python3-numpy python3-matplotlib python3-pytest
  xvfb
  python3-mpi4py openmpi-bin
  # .ci/package.sh: cpack's Debian generator runs dpkg-shlibdeps and file.
  dpkg-dev file
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
