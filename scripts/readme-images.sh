#!/usr/bin/env bash
# Renders the realistic-camera pictures in the README (docs/images/lens-*.png) from the
# scenes in scenes/ (a few minutes on 2 cores). Needs a build (make) and oiiotool
# (openimageio-tools) to put panels side by side.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/objektiv
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
render() { "$bin" render "$@" --quiet; }

render scenes/bokeh/bokeh-lens.xml -D spp=1024 -o "$tmp/bokeh-f2.8.exr"
render scenes/bokeh/bokeh-lens.xml -D spp=1024 -D fnumber=2.03 -o "$tmp/bokeh-open.exr"
cp "$tmp/bokeh-f2.8.png" "$out/lens-bokeh.png"
cp "$tmp/bokeh-open.png" "$out/lens-bokeh-wide-open.png"

render scenes/lens/distortion-chart.xml -D spp=64 -o "$tmp/dist-wide.exr"
render scenes/lens/distortion-chart.xml -D spp=64 -D lens=telephoto.250mm -D distance=11.4 -o "$tmp/dist-tele.exr"
cp "$tmp/dist-wide.png" "$out/lens-distortion-wide.png"
cp "$tmp/dist-tele.png" "$out/lens-distortion-tele.png"

render scenes/lens/fisheye-interior.xml -D spp=256 -D size=500 -o "$tmp/fisheye.exr"
cp "$tmp/fisheye.png" "$out/lens-fisheye.png"

for v in full cos4 aperture none; do
  render scenes/lens/vignetting-card.xml -D spp=256 -D vignetting=$v -o "$tmp/vig-$v.exr"
done
oiiotool "$tmp/vig-full.png" "$tmp/vig-cos4.png" "$tmp/vig-aperture.png" "$tmp/vig-none.png" \
  --mosaic:pad=6 2x2 -o "$out/lens-vignetting.png"

render scenes/lens/chromatic-closeup.xml -D spp=1024 -o "$tmp/ca-corner.exr"
render scenes/lens/chromatic-closeup.xml -D spp=1024 -D crop_x=1680 -D crop_y=1120 -o "$tmp/ca-centre.exr"
oiiotool "$tmp/ca-corner.png" --resize:filter=box 480x320 "$tmp/ca-centre.png" --resize:filter=box 480x320 \
  --mosaic:pad=6 2x1 -o "$out/lens-chromatic.png"

for f in 0.85 2.25 6.05; do
  render scenes/lens/focus-series.xml -D spp=256 -D focus=$f -D width=420 -D height=280 -o "$tmp/focus-$f.exr"
done
oiiotool "$tmp/focus-0.85.png" "$tmp/focus-2.25.png" "$tmp/focus-6.05.png" --mosaic:pad=6 3x1 -o "$out/lens-focus-series.png"
echo "wrote $out/lens-*.png"
