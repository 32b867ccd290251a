#!/usr/bin/env bash
# Colour noise through dispersive glass: the Cornell box through the Brendel Tessar with its
# catalog glasses (tessar.brendel.100mm.lens: each wavelength takes its own path) with spectral
# MIS and with the hero wavelength alone, against the same lens and coatings with constant
# indices (bench/tessar-constant-index.lens, whose rays serve every wavelength) and pbrt's
# uncoated constant-index version (tessar.brendel.100mm.dat). Each is compared with its own reference (REF_SPP samples
# per pixel) by relMSE; noise times time is the inverse of efficiency, and "time to the
# constant-index noise" = seconds x relMSE / relMSE(constant index) is what the catalog lens
# needs to look as clean. 256 x 256, path length 6, all cores. Usage: colour_noise.sh [SPP [REF_SPP]].
set -euo pipefail
cd "$(dirname "$0")/.."
spp=${1:-16}
ref_spp=${2:-1024}
bin=build/objektiv
[[ -x $bin ]] || { echo "build first: make" >&2; exit 1; }
dir=${TMPDIR:-/tmp}/objektiv-colour-noise
mkdir -p "$dir"
scene=scenes/cornell-box/cornell-box-lens.xml
common=(-D sensor=34.4 -D res=256 -D max_depth=6)
render() {  # name lens mis spp -> seconds
  "$bin" render "$scene" "${common[@]}" -D lens="$2" -D spectral_mis="$3" -D spp="$4" -o "$dir/$1.exr" --quiet \
    --stats-json "$dir/$1.json"
  grep '"seconds"' "$dir/$1.json" | tr -dc '0-9.'
}
relmse() { "$bin" imgtool diff "$dir/$1.exr" "$dir/$2.exr" | awk '/^relmse/ {print $2}'; }
constant=$PWD/bench/tessar-constant-index.lens
for l in tessar.brendel.100mm.lens "$constant" tessar.brendel.100mm.dat; do
  [[ -f $dir/ref-$(basename "$l")-$ref_spp.exr ]] || render "ref-$(basename "$l")-$ref_spp" "$l" true "$ref_spp" > /dev/null
done
declare -A sec err
for cfg in "const $constant true" "dat tessar.brendel.100mm.dat true" "mis tessar.brendel.100mm.lens true" \
  "hero tessar.brendel.100mm.lens false"; do
  read -r name lens mis <<< "$cfg"
  best=""
  for run in 1 2 3; do  # best of three
    s=$(render "$name" "$lens" "$mis" "$spp")
    if [[ -z $best ]] || awk "BEGIN{exit !($s < $best)}"; then best=$s; fi
  done
  sec[$name]=$best
  err[$name]=$(relmse "$name" "ref-$(basename "$lens")-$ref_spp")
done
for name in const dat mis hero; do
  awk -v n="$name" -v s="${sec[$name]}" -v e="${err[$name]}" -v e0="${err[const]}" -v s0="${sec[const]}" 'BEGIN {
    t = s * e / e0; printf "%-5s %6.2f s  relMSE %.5g  relMSE x s %.5g  time to the constant-index noise %.2f s (%.2fx)\n",
    n, s, e, e * s, t, t / s0 }'
done
echo "($spp spp, references $ref_spp spp, $(nproc) threads; const: constant indices, coated; dat: pbrt's, uncoated;"
echo " mis: catalog glass with spectral MIS; hero: catalog glass, the hero wavelength alone; times to the const noise)"
