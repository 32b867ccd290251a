#!/usr/bin/env bash
# The viewer's window driven by the mouse and the keys as a user drives it, under Xvfb with
# xdotool: a drag orbits the camera, a click focuses on what lies under it, ctrl + S saves the
# image and the camera, Escape closes the window (exit status 0). The saved camera must carry
# the orbit (a to_world matrix) and the clicked point (focus_point), and render the saved image
# bit for bit.
# Usage: view_interactive.sh OBJEKTIV SOURCE_DIR WORK_DIR
set -uo pipefail
if [[ ${1:-} == --inside ]]; then  # (within Xvfb)
  obj=$2 work=$3
  fail() { echo "FAIL: $*"; kill "$pid" 2> /dev/null; exit 1; }
  "$obj" view "$work/cornell-box-lens.xml" -D res=96 -D spp=2 > "$work/view.log" 2>&1 &
  pid=$!
  wid=$(timeout 60 xdotool search --sync --onlyvisible --name "objektiv view" | head -1)
  [[ -n $wid ]] || fail "no window: $(cat "$work/view.log")"
  xdotool windowfocus --sync "$wid"
  sleep 1
  # Orbit: a drag across the picture (which fills the window's top left, 96 x 96).
  xdotool mousemove --window "$wid" 30 50 mousedown 1
  for _ in $(seq 12); do xdotool mousemove_relative 3 1; sleep 0.05; done
  xdotool mouseup 1
  sleep 1
  # Focus: a click on the picture.
  xdotool mousemove --window "$wid" 40 60 click 1
  sleep 3
  # ctrl + S, again every 2 s until both are saved and the image has its 2 samples per pixel
  # (a loaded machine may take a while to render them).
  for _ in $(seq 30); do
    xdotool key --window "$wid" ctrl+s
    sleep 2
    [[ -s $work/cornell-box-lens-view.xml && -s $work/cornell-box-lens-view.exr ]] &&
      oiiotool --info -v "$work/cornell-box-lens-view.exr" | grep -q 'objektiv:spp: 2$' && break
  done
  [[ -s $work/cornell-box-lens-view.xml ]] || fail "ctrl + S saved no camera: $(cat "$work/view.log")"
  [[ -s $work/cornell-box-lens-view.exr ]] || fail "ctrl + S saved no image: $(cat "$work/view.log")"
  sleep 1
  xdotool key --window "$wid" Escape
  for _ in $(seq 100); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
  kill -0 "$pid" 2> /dev/null && fail "Escape did not close the window"
  wait "$pid" || fail "the viewer exited with status $?: $(cat "$work/view.log")"
  exit 0
fi
obj=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
cp "$src/scenes/cornell-box/cornell-box-lens.xml" "$src/scenes/cornell-box/cornell-box.obj" "$work/" || exit 1
xvfb-run -a -s "-screen 0 1280x1024x24" bash "$0" --inside "$obj" "$work" || exit 1
camera=$work/cornell-box-lens-view.xml
grep -q '<point name="focus_point"' "$camera" || fail "the click set no focus point: $(cat "$camera")"
grep -q '<matrix value=' "$camera" || fail "the drag moved no camera"
grep -q 'name="focus_distance"' "$camera" && fail "the scene's focus distance is still there beside the point"
echo "ok: the drag orbited, the click focused, ctrl + S saved"
"$obj" render "$camera" -o "$work/offline.exr" -q || fail "the saved camera does not render"
"$obj" imgtool diff "$work/offline.exr" "$work/cornell-box-lens-view.exr" --exact || fail "the saved camera renders another image"
echo "ok: the saved camera renders the saved image bit for bit"
