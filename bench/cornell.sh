#!/usr/bin/env bash
# The reference timing: the Cornell box at 512x512, 64 spp, maximum path length 6, on all
# cores (best of N runs, default 3). Prints seconds, samples/s and Mrays/s. A second argument
# `lens` renders it through the double Gauss at f/2.8 instead (cornell-box-lens.xml).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
scene=scenes/cornell-box/cornell-box.xml
[[ ${2:-} == lens ]] && scene=scenes/cornell-box/cornell-box-lens.xml
bin=build/objektiv
[[ -x $bin ]] || { echo "build first: make" >&2; exit 1; }
best=""
for i in $(seq "$runs"); do
  $bin render "$scene" -D res=512 -D spp=64 -D max_depth=6 \
    -o /tmp/objektiv-bench-cornell.exr --quiet --stats-json /tmp/objektiv-bench-cornell.json
  s=$(grep '"seconds"' /tmp/objektiv-bench-cornell.json | tr -dc '0-9.')
  echo "run $i: $(tr -d '\n ' < /tmp/objektiv-bench-cornell.json)"
  if [[ -z $best ]] || awk "BEGIN{exit !($s < $best)}"; then best=$s; fi
done
echo "best of $runs: ${best} s ($scene, 512x512, 64 spp, max_depth 6, $(nproc) threads)"
