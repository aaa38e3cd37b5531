#!/usr/bin/env bash
# Optional step: installs Debian 12's ParaView 5.11 SDK (paraview, paraview-dev),
# which the ParaView plugin (-DSURFACEMAPS_PARAVIEW_PLUGIN=ON) builds against.
# Idempotent like install-deps.sh: apt is only touched when something is
# missing. Run as root (or with sudo available).
#
# ParaView bundles its own VTK; its Python package (python3-paraview) ships
# vtkmodules too and conflicts with python3-vtk9, which the module's Python
# tests need. So: never python3-paraview, never recommends (they would pull
# it), and the script fails loudly if python3-vtk9 is gone afterwards. For
# pvbatch and pvpython, python3-paraview is unpacked into a private folder
# instead, never installed (ParaView/pvsurfacemaps, which then runs them).
set -euo pipefail

# libx11-dev, libglew-dev: ParaView's rendering modules name X11::X11 and
# GLEW::GLEW, which the plugin's configuration must find (libvtk9-dev brings
# them too; listed for a machine without it). libvtk9-dev: the wrapping
# hierarchy files that paraview-dev lacks (ParaView/CMake/ParaViewWrapHierarchy.cmake).
packages=(paraview paraview-dev libx11-dev libglew-dev libvtk9-dev)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-paraview: all ${#packages[@]} packages present"
else
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "install-paraview: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  # A simulated install first: refuse any plan that removes a package (that
  # is how the python3-vtk9 conflict would show up).
  if $SUDO apt-get install -s -q --no-install-recommends "${missing[@]}" | grep -q '^Remv '; then
    echo "install-paraview: the install would remove packages; refusing:" >&2
    $SUDO apt-get install -s -q --no-install-recommends "${missing[@]}" | grep '^Remv ' >&2
    exit 1
  fi
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if ! dpkg-query -W -f='${Status}' python3-vtk9 2>/dev/null | grep -q "install ok installed"; then
  echo "install-paraview: python3-vtk9 is no longer installed" >&2
  exit 1
fi
/usr/bin/python3 -c "import vtkmodules" || {
  echo "install-paraview: /usr/bin/python3 cannot import vtkmodules any more" >&2
  exit 1
}

# ParaView's Python for pvbatch/pvpython, unpacked privately (ParaView.pvbatch).
bash "$(dirname "$0")/../ParaView/pvsurfacemaps" --unpack
