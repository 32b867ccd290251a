#!/usr/bin/env bash
# The viewer's window under Xvfb with Mesa's software OpenGL, driven by a script as a user
# would drive it: the lens stopped down, focused on what a pixel shows, the camera orbited, 4
# samples per pixel, a screenshot of the window, the image and the camera saved. Checks:
#  - the picture in the screenshot (the window's top left) is the saved PNG, pixel for pixel
#    (the same 8-bit values);
#  - `objektiv render` of the saved camera gives the saved image, bit for bit;
#  - a scripted run without a window (--headless) gives the same image.
# Usage: view_window.sh OBJEKTIV SOURCE_DIR WORK_DIR
set -uo pipefail
obj=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
cp "$src/scenes/cornell-box/cornell-box-lens.xml" "$src/scenes/cornell-box/cornell-box.obj" "$work/" || exit 1
scene=$work/cornell-box-lens.xml
script() {  # script NAME: the run's commands, its outputs named NAME.*
  cat > "$work/$1.txt" << END
set fnumber 4
set blades 6
focus 20 60
orbit 8 3
samples 4
screenshot $work/$1-window.png
save $work/$1.exr
save-camera $work/$1-camera.xml
quit
END
}
script window
xvfb-run -a -s "-screen 0 1280x1024x24" "$obj" view "$scene" -D res=96 -D spp=4 --script "$work/window.txt" -q \
  > "$work/window.log" 2>&1 || fail "the windowed run failed: $(cat "$work/window.log")"
[ -s "$work/window-window.png" ] || fail "no screenshot"
oiiotool "$work/window-window.png" --cut 96x96+0+0 -o "$work/window-picture.png" || fail "cannot crop the screenshot"
"$obj" imgtool diff "$work/window-picture.png" "$work/window.png" --metric mae --threshold 0 ||
  fail "the window does not show the saved image"
echo "ok: the window shows the saved image"
"$obj" render "$work/window-camera.xml" -o "$work/offline.exr" -q || fail "the saved camera does not render"
"$obj" imgtool diff "$work/offline.exr" "$work/window.exr" --exact || fail "the saved camera renders another image"
echo "ok: the saved camera renders the viewer's image bit for bit"
script headless
"$obj" view "$scene" -D res=96 -D spp=4 --script "$work/headless.txt" --headless -q > "$work/headless.log" 2>&1 ||
  fail "the headless run failed: $(cat "$work/headless.log")"
"$obj" imgtool diff "$work/headless.exr" "$work/window.exr" --exact || fail "the headless run made another image"
"$obj" imgtool diff "$work/headless-window.png" "$work/window.png" --metric mae --threshold 0 ||
  fail "the headless screenshot is not the image"
echo "ok: the headless run makes the same image"
