#!/usr/bin/env bash
# The packaging stage of .ci/run: makes the Debian packages of the main build
# (cpack -G DEB in ./build, see CMake/SurfaceMapsPackaging.cmake) into
# build/packages and checks them without installing anything on this machine:
#
#  1. every installed file belongs to a package (none in CMake's
#     "Unspecified" component, which no package holds);
#  2. apt would install them: `apt-get install --simulate` of the .deb files
#     resolves every Depends from Debian's archives, on a fresh machine (an
#     empty dpkg status) and on this one without removing any package;
#  3. the packages alone work: unpacked with `dpkg -x` into a throw-away
#     prefix, the program (found through its RUNPATH, not the build tree)
#     runs the README's quick-start main job (.ci/quickstart --installed) and
#     Debian's python3 imports `surfacemaps` from the prefix and maps with it.
#
# Run after .ci/build.sh. Prints each package's size and Depends.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
if [ ! -f build/CPackConfig.cmake ]; then
  echo "package: run .ci/build.sh first (no build/CPackConfig.cmake)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rm -rf build/packages
(cd build && cpack -G DEB) > "$work/cpack.log" 2>&1 || {
  cat "$work/cpack.log" >&2
  exit 1
}
debs=(build/packages/*.deb)
for deb in "${debs[@]}"; do
  echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) kB, installed $(dpkg-deb -f "$deb" Installed-Size) kB"
  echo "  Depends: $(dpkg-deb -f "$deb" Depends)"
done
if [ ${#debs[@]} -ne 3 ]; then
  echo "package: expected 3 packages, cpack made ${#debs[@]}" >&2
  exit 1
fi

# 1. Nothing outside the packages.
cmake --install build --component Unspecified --prefix "$work/unspecified" > /dev/null
if [ -d "$work/unspecified" ] && [ -n "$(find "$work/unspecified" -type f -print -quit)" ]; then
  echo "package: installed files in no package (give their install() a COMPONENT):" >&2
  find "$work/unspecified" -type f >&2
  exit 1
fi

# 2. apt resolves the Depends from Debian's repositories alone, on a fresh
# machine (simulated with an empty dpkg status: nothing installed) and on
# this one (where it must remove nothing, e.g. python3-vtk9). Every package
# apt would add is one of these .deb files or comes from an archive whose
# origin is Debian (apt prints it: "Inst name (version Debian:12.x/... [arch])").
local_debs=()
for deb in "${debs[@]}"; do local_debs+=("$root/$deb"); done
: > "$work/empty-status"
simulate() {
  apt-get install --simulate -q --no-install-recommends "$@" "${local_debs[@]}" 2>&1
}
simulate -o Dir::State::status="$work/empty-status" > "$work/fresh.log" || {
  cat "$work/fresh.log" >&2
  echo "package: apt cannot resolve the packages' dependencies on a fresh machine" >&2
  exit 1
}
ours=$(for deb in "${debs[@]}"; do dpkg-deb -f "$deb" Package; done)
foreign=$(grep '^Inst ' "$work/fresh.log" | while read -r _ name rest; do
  if ! grep -qx "$name" <<< "$ours" && ! grep -q '(.* Debian[-A-Za-z]*:' <<< "$rest"; then
    echo "$name $rest"
  fi
done)
if [ -n "$foreign" ]; then
  echo "package: dependencies from outside Debian's archives:" >&2
  echo "$foreign" >&2
  exit 1
fi
for package in $ours; do
  grep -q "^Inst $package " "$work/fresh.log" || {
    echo "package: apt would not install $package:" >&2
    cat "$work/fresh.log" >&2
    exit 1
  }
done
simulate > "$work/here.log" || {
  cat "$work/here.log" >&2
  echo "package: apt cannot install the packages on this machine" >&2
  exit 1
}
if grep -q '^Remv ' "$work/here.log"; then
  echo "package: installing would remove packages:" >&2
  grep '^Remv ' "$work/here.log" >&2
  exit 1
fi
echo "apt-get install --simulate: $(grep -c '^Inst ' "$work/fresh.log") packages on a fresh" \
  "Debian 12, all from Debian but these; $(grep -c '^Inst ' "$work/here.log") here, none removed"

# 3. The packages alone, in a throw-away prefix.
prefix=$work/prefix
for deb in "${debs[@]}"; do dpkg -x "$deb" "$prefix"; done
program=$prefix/usr/bin/surfacemap
if ldd "$program" | grep -q "$root/build"; then
  echo "package: the packaged program loads libraries from the build tree:" >&2
  ldd "$program" | grep "$root/build" >&2
  exit 1
fi
ldd "$program" | grep -q "=> $prefix/usr/[^ ]*libSurfaceMapsFilters" || {
  echo "package: the packaged program does not load the packaged module library:" >&2
  ldd "$program" >&2
  exit 1
}
env -u LD_LIBRARY_PATH -u PYTHONPATH PATH="$prefix/usr/bin:/usr/bin:/bin" \
  bash .ci/quickstart --installed > "$work/quickstart.log" 2>&1 || {
  cat "$work/quickstart.log" >&2
  echo "package: the quick-start main job failed with the packaged program" >&2
  exit 1
}
grep -q "certified bijective" "$work/quickstart.log" || {
  cat "$work/quickstart.log" >&2
  echo "package: the packaged program's map is not certified" >&2
  exit 1
}
env -u LD_LIBRARY_PATH PYTHONPATH="$prefix/usr/lib/python3/dist-packages" \
  /usr/bin/python3 - "$prefix" Data <<'PY'
import sys
import surfacemaps

prefix, data = sys.argv[1], sys.argv[2]
assert surfacemaps.__file__.startswith(prefix), surfacemaps.__file__
a = surfacemaps.read_mesh(f"{data}/ellipsoid.obj", landmarks=f"{data}/ellipsoid.pinned")
b = surfacemaps.read_mesh(f"{data}/blob.off", landmarks=f"{data}/blob.vts")
common = surfacemaps.map_surfaces([a, b], CoarseIterations=5, FineIterations=5, RefinementRounds=0)
assert common[0].GetFieldData().GetArray("Bijective").GetValue(0) == 1
print("python3-surfacemaps: imported from", surfacemaps.__file__.replace(prefix, "<prefix>"),
      "and mapped:", common[0].GetNumberOfPoints(), "vertices")
PY
echo "package: build/packages/*.deb checked (apt install ./build/packages/*.deb installs them)"
