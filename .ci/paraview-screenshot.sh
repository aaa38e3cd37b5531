#!/usr/bin/env bash
# Makes the README's ParaView screenshot (Testing/Benchmarks/images/
# paraview_gui.png): ParaView's GUI on a virtual X display with the plugin
# loaded and the state of WriteSurfaceMapsState (three meshes -> Surface Map
# -> average, interpolator, evaluation) opened, captured with xwd. Not part of
# .ci/run (it waits for the GUI); run after .ci/build-paraview.sh. Needs
# xvfb, x11-apps (xwd) and imagemagick (convert), which it installs.
# No Python: pvpython's package conflicts with python3-vtk9.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=${1:-Testing/Benchmarks/images/paraview_gui.png}
wait_seconds=${SURFACEMAPS_SCREENSHOT_WAIT:-90}

missing=()
for p in xvfb x11-apps imagemagick; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

plugin_dir=$root/build-paraview/lib/paraview-5.11/plugins/SurfaceMaps
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One X server for the state writer (it renders once) and the GUI.
xvfb-run -a -s "-screen 0 1600x1000x24" bash -c '
  set -euo pipefail
  "$0"/build-paraview/bin/WriteSurfaceMapsState "$1"/SurfaceMaps.so "$2"/surfacemaps.pvsm
  # --dr: no user settings (no welcome dialog, default layout).
  PV_PLUGIN_PATH="$1" paraview --dr --state="$2"/surfacemaps.pvsm \
    -qwindowgeometry 1600x1000+0+0 > "$2"/paraview.log 2>&1 &
  gui=$!
  sleep "$3"
  xwd -root -silent > "$2"/screen.xwd
  kill "$gui"
' "$root" "$plugin_dir" "$work" "$wait_seconds"
convert "$work/screen.xwd" "$out"
echo "paraview-screenshot: wrote $out"
