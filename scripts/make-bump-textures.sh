#!/usr/bin/env bash
# Makes the floor tile's height map of scenes/bump/ (committed; rerun only to change it):
# one 128 x 128 tile, 1 inside and 0 in a groove 6 texels wide along its edges (12 between
# two tiles), the groove's walls bevelled by a blur, and a faint smooth unevenness on the
# tile (blurred Gaussian noise, zero in the groove, so that the texture repeats seamlessly).
# 16 bits, so that the bump map's slopes do not step. Needs oiiotool (openimageio-tools).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oiiotool --pattern constant:color=1 128x128 1 --fill:color=0 128x6+0+0 --fill:color=0 128x6+0+122 \
  --fill:color=0 6x128+0+0 --fill:color=0 6x128+122+0 -o "$tmp/mask.exr"
oiiotool "$tmp/mask.exr" --blur 7x7 -o "$tmp/bevel.exr"
oiiotool --pattern noise:type=gaussian:mean=0:stddev=1:seed=7 128x128 1 --blur 13x13 "$tmp/mask.exr" --blur 9x9 \
  --mul --mulc 0.6 -o "$tmp/uneven.exr"
oiiotool "$tmp/bevel.exr" "$tmp/uneven.exr" --add --mulc 0.7 --addc 0.1 --clamp:min=0:max=1 -d uint16 \
  -o scenes/bump/textures/tile-height.png
echo "wrote scenes/bump/textures/tile-height.png"
