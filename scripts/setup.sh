#!/usr/bin/env bash
# Installs the Debian packages Objektiv needs to build, test and benchmark (the viewer's window:
# GLFW, Dear ImGui, Mesa's OpenGL, and Xvfb for its tests); with
# --sanitizers also clang, its sanitizer and libFuzzer runtimes and llvm-symbolizer (for the
# sanitizer build, the fuzz harnesses and readable reports); with --cluster Slurm and munge
# (for the test that renders on a one-node Slurm cluster: scripts/slurm-check.sh).
# Idempotent: when every package is present it prints nothing and does nothing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config make
  libembree-dev libtbb-dev libopenimageio-dev openimageio-tools libopenexr-dev
  libpugixml-dev libtinyobjloader-dev libassimp-dev
  libcli11-dev libfmt-dev libspdlog-dev nlohmann-json3-dev libfftw3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libglfw3-dev libimgui-dev libgl1-mesa-dri libglx-mesa0 xvfb xauth xdotool
)
[[ ${1:-} == --sanitizers ]] && packages+=(clang libclang-rt-14-dev llvm)
[[ ${1:-} == --cluster ]] && packages+=(slurm-wlm munge)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ $status == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

as_root=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
