#!/usr/bin/env bash
# Renders the realistic-camera pictures in the README (docs/images/lens-*.png) from the
# scenes in scenes/ (a few minutes on 2 cores). Needs a build (make) and oiiotool
# (openimageio-tools) to put panels side by side. `readme-images.sh flare` renders only the
# ghost and starburst pictures (docs/images/flare-*.png), `readme-images.sh caustics` the
# light-traced caustics (docs/images/caustics-*.png), `readme-images.sh bump` the bump-mapped
# floor (docs/images/bump-*.png), `readme-images.sh stereo` the stereo rig's anaglyph
# (docs/images/stereo-*.png), `readme-images.sh classic` the classic tracer's picture
# (docs/images/classic-*.png), `readme-images.sh media` the participating media's pictures
# (docs/images/media-*.png), `readme-images.sh sampling` adaptive sampling's picture and
# sample counts (docs/images/sampling-*.png), `readme-images.sh filter` the colour filter's
# pair (docs/images/filter-yellow.png), `readme-images.sh mirror` the mirror lens's bokeh
# (docs/images/lens-mirror-bokeh.png), `readme-images.sh underwater` the flat port's pair
# (docs/images/lens-underwater.png), `readme-images.sh anamorphic` the anamorphic lens's
# bokeh (docs/images/lens-anamorphic-bokeh.png), `readme-images.sh tilt` the tilt lens's pair
# (docs/images/lens-tilt-shift.png), `readme-images.sh asphere` the singlet, its Q-type
# asphere, its axial GRIN version and the Fresnel lens (docs/images/lens-asphere.png), `readme-images.sh
# dust` dust on a cover glass at f/2.8 and f/22 (docs/images/lens-dust.png), `readme-images.sh hood`
# a hood that fits the wide-angle and one too long (docs/images/lens-hood.png), `readme-images.sh
# calcite` the Tessar without and with a calcite plate (docs/images/lens-calcite.png),
# `readme-images.sh spectral` the hero wavelength alone against spectral MIS through the Tessar's
# catalog glasses (docs/images/lens-spectral-mis.png), `readme-images.sh viewer` the interactive
# viewer's window (docs/images/viewer.png; needs xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/objektiv
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
render() { "$bin" render "$@" --quiet; }

flare() {
  render scenes/flare/night-street.xml -D spp=64 -o "$tmp/street.exr"
  cp "$tmp/street.png" "$out/flare-night-street.png"
  # The pictures, then their ghost layers alone 5 stops brighter (sRGB, clipped).
  for c in none MgF2 multi; do
    render scenes/flare/night-street.xml -D coating=$c -D spp=64 -D width=480 -D height=270 -o "$tmp/coat-$c.exr"
    oiiotool "$tmp/coat-$c.exr" --ch ghosts.R,ghosts.G,ghosts.B --chnames R,G,B --mulc 32 --colorconvert linear sRGB \
      -o "$tmp/ghosts-$c.png"
  done
  oiiotool "$tmp/coat-none.png" "$tmp/coat-MgF2.png" "$tmp/coat-multi.png" \
    "$tmp/ghosts-none.png" "$tmp/ghosts-MgF2.png" "$tmp/ghosts-multi.png" --mosaic:pad=4 3x2 -o "$out/flare-coatings.png"
  for l in tessar.brendel.100mm wide.22mm; do
    render scenes/flare/night-street.xml -D lens=$l -D spp=64 -D width=480 -D height=270 -o "$tmp/lens-$l.exr"
  done
  oiiotool "$tmp/coat-none.png" "$tmp/lens-tessar.brendel.100mm.png" "$tmp/lens-wide.22mm.png" --mosaic:pad=4 3x1 \
    -o "$out/flare-lenses.png"
  render scenes/flare/sun-disc.xml -D spp=64 -D glare=1024 -D width=480 -D height=270 -o "$tmp/sun.exr"
  cp "$tmp/sun.png" "$out/flare-sun.png"
  for b in 0 5 6 8 9; do
    render scenes/flare/starburst.xml -D blades=$b -o "$tmp/star-$b.exr"
  done
  oiiotool "$tmp/star-0.png" "$tmp/star-5.png" "$tmp/star-6.png" "$tmp/star-8.png" "$tmp/star-9.png" \
    --mosaic:pad=4 1x5 -o "$out/flare-starbursts.png"
}
caustics() {
  # The glass balls by camera paths alone, and with light-traced caustics; the prism's spectrum.
  render scenes/caustics/glass-sphere.xml -D caustics=false -D spp=256 -D width=480 -D height=300 -o "$tmp/balls-path.exr"
  render scenes/caustics/glass-sphere.xml -D spp=256 -D width=480 -D height=300 -o "$tmp/balls-caustics.exr"
  oiiotool "$tmp/balls-path.png" "$tmp/balls-caustics.png" --mosaic:pad=4 2x1 -o "$out/caustics-glass-balls.png"
  render scenes/prism/spectrum.xml -D spp=256 -D width=480 -D height=300 -o "$tmp/spectrum.exr"
  cp "$tmp/spectrum.png" "$out/caustics-prism-spectrum.png"
}
bump() {
  # The table and chairs on the bump-mapped tiled floor.
  render scenes/bump/table-and-chairs.xml -D spp=64 -D width=640 -D height=400 -o "$tmp/table.exr"
  cp "$tmp/table.png" "$out/bump-table-and-chairs.png"
}
stereo() {
  # The still life through a stereo rig: the red-cyan anaglyph, and its EXR's eyes side by side.
  render scenes/stereo/anaglyph.xml -o "$tmp/anaglyph.exr"
  cp "$tmp/anaglyph.png" "$out/stereo-anaglyph.png"
  for e in left right; do
    oiiotool "$tmp/anaglyph.exr" --ch $e.R,$e.G,$e.B --chnames R,G,B --resize 50% --colorconvert linear sRGB -o "$tmp/$e.png"
  done
  oiiotool "$tmp/left.png" "$tmp/right.png" --mosaic:pad=4 2x1 -o "$out/stereo-eyes.png"
}
classic() {
  # Spheres on a checkerboard by the classic tracer, at one sample per pixel and at 16.
  render scenes/classic/spheres-checkerboard.xml -o "$tmp/classic-1.exr"
  render scenes/classic/spheres-checkerboard.xml -D spp=16 -o "$tmp/classic-16.exr"
  cp "$tmp/classic-1.png" "$out/classic-spheres-1spp.png"
  cp "$tmp/classic-16.png" "$out/classic-spheres.png"
}
media() {
  # Light shafts through fog, and a glass of milk.
  render scenes/media/fog-light-shafts.xml -D spp=48 -D width=480 -D height=300 -o "$tmp/fog.exr"
  cp "$tmp/fog.png" "$out/media-fog-light-shafts.png"
  render scenes/media/milk-glass.xml -D spp=128 -D width=320 -D height=320 -o "$tmp/milk.exr"
  cp "$tmp/milk.png" "$out/media-milk-glass.png"
}
sampling() {
  # The Cornell box by statistical adaptive sampling, beside its sample counts (16 to 512:
  # black to yellow).
  render scenes/cornell-box/cornell-box.xml -D spp=512 -D res=256 --adaptive statistical --adaptive-threshold 0.06 --adaptive-min-samples 64 \
    --sample-count-layer -o "$tmp/adaptive.exr"
  oiiotool "$tmp/adaptive.exr" --ch sample_count --mulc 0.001953125 --clamp:min=0:max=1 --colormap inferno \
    -o "$tmp/counts.png"
  oiiotool "$tmp/adaptive.png" "$tmp/counts.png" --mosaic:pad=4 2x1 -o "$out/sampling-cornell-adaptive.png"
}
filter() {
  # The Tessar without and with the yellow filter plate of scenes/cornell-box/tessar-yellow-filter.*
  render scenes/cornell-box/cornell-box-filter.xml -D res=256 -D spp=256 -D lens=tessar.brendel.100mm -o "$tmp/plain.exr"
  render scenes/cornell-box/cornell-box-filter.xml -D res=256 -D spp=256 -o "$tmp/yellow.exr"
  oiiotool "$tmp/plain.png" "$tmp/yellow.png" --mosaic:pad=6 2x1 -o "$out/filter-yellow.png"
}

# The mirror lens's rings beside a refracting lens's discs at the same focal length.
mirror() {
  render scenes/bokeh/bokeh-mirror-lens.xml -D spp=512 -D width=600 -D height=400 -o "$tmp/mirror.exr"
  render scenes/bokeh/bokeh-mirror-lens.xml -D spp=512 -D width=600 -D height=400 -D lens=telephoto.250mm \
    -o "$tmp/mirror-tele.exr"
  oiiotool "$tmp/mirror.png" "$tmp/mirror-tele.png" --mosaic:pad=6 2x1 -o "$out/lens-mirror-bokeh.png"
}

# The anamorphic's upright ovals, desqueezed to a 3:1 frame.
anamorphic() {
  render scenes/bokeh/bokeh-anamorphic.xml -D spp=256 -o "$tmp/anamorphic.exr"
  cp "$tmp/anamorphic.png" "$out/lens-anamorphic-bokeh.png"
}

# The double Gauss wide open over a floor, straight and tilted by the Scheimpflug angle.
tilt() {
  render scenes/lens/tilt-shift.xml -D spp=256 -D width=480 -D height=320 -D tilt=0 -o "$tmp/tilt-0.exr"
  render scenes/lens/tilt-shift.xml -D spp=256 -D width=480 -D height=320 -o "$tmp/tilt-9.exr"
  oiiotool "$tmp/tilt-0.png" "$tmp/tilt-9.png" --mosaic:pad=6 2x1 -o "$out/lens-tilt-shift.png"
}

# The spherical singlet, the same singlet with a Q-type aspheric front, in an axial GRIN glass,
# and the Fresnel lens.
asphere() {
  render scenes/lens/asphere-singlet.xml -D spp=256 -o "$tmp/singlet.exr"
  render scenes/lens/asphere-singlet.xml -D spp=256 -D lens=asphere.50mm -o "$tmp/asphere.exr"
  render scenes/lens/asphere-singlet.xml -D spp=256 -D lens=grin.50mm -o "$tmp/grin.exr"
  render scenes/lens/asphere-singlet.xml -D spp=256 -D lens=fresnel.50mm -o "$tmp/fresnel.exr"
  oiiotool "$tmp/singlet.png" "$tmp/asphere.png" "$tmp/grin.png" "$tmp/fresnel.png" --mosaic:pad=6 2x2 \
    -o "$out/lens-asphere.png"
}

# Dust on the cover glass before the film: invisible wide open, dark spots at f/22.
dust() {
  render scenes/lens/sensor-dust.xml -D spp=256 -o "$tmp/dust-open.exr"
  render scenes/lens/sensor-dust.xml -D spp=256 -D fnumber=22 -D exposure=411 -o "$tmp/dust-f22.exr"
  oiiotool "$tmp/dust-open.png" "$tmp/dust-f22.png" --mosaic:pad=6 2x1 -o "$out/lens-dust.png"
}

# A hood that clears the wide-angle's frame and one too long.
hood() {
  render scenes/lens/hood-vignetting.xml -D spp=64 -o "$tmp/hood-short.exr"
  render scenes/lens/hood-vignetting.xml -D spp=64 -D hood_length=20 -o "$tmp/hood-long.exr"
  oiiotool "$tmp/hood-short.png" "$tmp/hood-long.png" --mosaic:pad=6 2x1 -o "$out/lens-hood.png"
}

# A checkerboard through the Tessar alone and with a calcite plate before the film (double image).
calcite() {
  render scenes/lens/calcite-double-image.xml -D spp=256 -D lens=tessar.brendel.100mm -o "$tmp/calcite-none.exr"
  render scenes/lens/calcite-double-image.xml -D spp=256 -o "$tmp/calcite-plate.exr"
  oiiotool "$tmp/calcite-none.png" "$tmp/calcite-plate.png" --mosaic:pad=6 2x1 -o "$out/lens-calcite.png"
}

# Colour noise through dispersive glass: the hero wavelength alone, and spectral MIS (16 spp each).
spectral() {
  for mis in false true; do
    render scenes/cornell-box/cornell-box-lens.xml -D lens=tessar.brendel.100mm -D sensor=34.4 -D res=320 -D spp=16 \
      -D spectral_mis=$mis -o "$tmp/mis-$mis.exr"
  done
  oiiotool "$tmp/mis-false.png" "$tmp/mis-true.png" --mosaic:pad=6 2x1 -o "$out/lens-spectral-mis.png"
}

# The Cornell box through the Tessar in air and behind a flat port under water.
viewer() {
  # The window under Xvfb, scripted: the double Gauss stopped to f/2.8 with six blades, focused
  # on the tall box by its pixel, the camera orbited, 64 samples per pixel.
  cat > "$tmp/viewer.txt" << END
set fnumber 2.8
set blades 6
focus 200 300
orbit -14 4
samples 64
screenshot $tmp/viewer.png
END
  xvfb-run -a -s "-screen 0 1280x1024x24" "$bin" view scenes/cornell-box/cornell-box-lens.xml --size 640x480 \
    -D spp=64 --script "$tmp/viewer.txt" --quiet
  oiiotool "$tmp/viewer.png" --cut 1040x700+0+0 -o "$out/viewer.png"
}

underwater() {
  render scenes/cornell-box/cornell-box-underwater.xml -D spp=256 -D res=400 -D lens=tessar.brendel.100mm \
    -D exposure=8.2 -o "$tmp/uw-air.exr"
  render scenes/cornell-box/cornell-box-underwater.xml -D spp=256 -D res=400 -o "$tmp/uw-port.exr"
  oiiotool "$tmp/uw-air.png" "$tmp/uw-port.png" --mosaic:pad=6 2x1 -o "$out/lens-underwater.png"
}

case "${1:-}" in
  flare | caustics | bump | stereo | classic | media | sampling | filter | mirror | underwater | anamorphic | tilt | asphere | dust | hood | calcite | spectral | viewer)
    "$1"
    echo "wrote $out/$1-*.png"
    exit 0
    ;;
esac

render scenes/bokeh/bokeh-lens.xml -D spp=1024 -o "$tmp/bokeh-f2.8.exr"
render scenes/bokeh/bokeh-lens.xml -D spp=1024 -D fnumber=2.03 -o "$tmp/bokeh-open.exr"
cp "$tmp/bokeh-f2.8.png" "$out/lens-bokeh.png"
cp "$tmp/bokeh-open.png" "$out/lens-bokeh-wide-open.png"
mirror
underwater
anamorphic
tilt
asphere
dust
hood
calcite
spectral

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
for part in flare caustics bump stereo classic media filter; do "$part"; done
echo "wrote $out/*.png"
