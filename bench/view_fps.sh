#!/usr/bin/env bash
# The interactive viewer's speed without a window (objektiv view --benchmark): the Cornell box
# through the double Gauss at f/2.8 (cornell-box-lens.xml) on a 640x480 film, the camera
# orbiting a degree a frame for N frames (default 300) at the preview's 30 frames per second
# target; prints the frames per second and the resolutions the preview chose, then the first
# full-resolution preview and passes of the path tracer once the camera stands still.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-300}
bin=build/objektiv
[[ -x $bin ]] || { echo "build first: make" >&2; exit 1; }
$bin view scenes/cornell-box/cornell-box-lens.xml --size 640x480 --benchmark "$frames" --quiet
