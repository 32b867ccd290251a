#!/usr/bin/env bash
# README command 1: install, build, and render the demo scene (the Cornell box) to
# out/demo.png and out/demo.exr.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --target objektiv
mkdir -p out
build/objektiv render scenes/cornell-box/cornell-box.xml -o out/demo.exr "$@"
