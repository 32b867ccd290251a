// Film triangles and their splatting: the pieces a ray bundle (optics/ghosts.h) lands on the
// film as, each with the flux it carries, and their rasterisation into an image with each
// pixel's exact share of every triangle (or, for a preview, a varying irradiance taken at pixel
// centres).
#pragma once
#include <cmath>
#include <span>

#include "base/vec.h"

namespace objektiv {

// A triangle on the film (lens-space x, y, mm) and the flux it carries: per unit intensity
// (W/sr) of a point at a finite distance, per unit irradiance (W/mm^2, across the beam) of one
// at infinity.
// The irradiance over the triangle varies linearly between the relative values ea, eb, ec at
// its corners (equal: uniform), scaled so that it carries `flux`: a bundle estimates them at
// its grid's corners from the cells around, so that its picture is smooth where the light is
// rather than faceted cell by cell.
struct FilmTriangle {
  Vec2d a, b, c;
  double flux;
  double ea = 1, eb = 1, ec = 1;
  // A bundle traced with a spectrum (BundleOptions::spectrum): its colour per unit flux.
  Vec3d tint{1, 1, 1};
  double Area() const { return 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)); }
};

// The flux the triangles carry into the rectangle [lo, hi] of the film (each triangle's flux
// times the share of its area inside; the irradiance taken uniform over each).
double FluxWithin(std::span<const FilmTriangle> triangles, Vec2d lo, Vec2d hi);

// Rasterises triangles into an image of irradiance: pixel (x, y) covers film x in [x0 + x w,
// x0 + (x + 1) w), y likewise with h; each pixel gets the flux that lands on it over its area:
// the triangle's irradiance integrated exactly over the part of it inside the pixel (the
// triangle clipped to the pixel: its area, and for a varying irradiance its centroid, where a
// linear function takes its mean), so every triangle's flux lands exactly once, without the
// aliasing of sampling pixel centres. `weight` scales every value.
struct FilmRaster {
  int width = 0, height = 0;
  double x0 = 0, y0 = 0, w = 1, h = 1;  // mm
};
void Splat(std::span<const FilmTriangle> triangles, const FilmRaster& raster, double weight, float* image, int stride = 1);

// A preview's coarse splat, for ghosts large on the film, whose light changes little from one
// pixel to the next but at their edges: the raster at half the resolution of `r`, each pixel
// 2 x 2 of r's (where r's width or height is odd, the last column or row reaching half a pixel
// past r's edge).
FilmRaster HalfResolution(const FilmRaster& r);
// How far a bundle's irradiance rises above its mean: the largest of its triangles' (their
// flux over their area) over the mean irradiance its flux has (the flux-weighted mean), 1 for a
// uniform one. A focused core or a caustic gives a large value; triangles whose area is below
// a thousandth of the mean's (an edge's slivers) are not counted.
double IrradianceContrast(std::span<const FilmTriangle> triangles);
// Adds an image of 3 interleaved channels on HalfResolution of a width x height raster into
// rows [y0, y1) of one on the raster itself: each pixel's value interpolated bilinearly at its
// centre (the half image's edges extended), so an irradiance stays one and a flux is kept
// (but for what the extension moves at the image's edges); a sharp edge becomes a ramp about
// two pixels wide.
void AddUpsampled(const float* half, int width, int height, int y0, int y1, float* full);
// The same into three interleaved channels at once, each with its own weight. With
// `pixel_centres` (a preview's) a varying irradiance is taken at the centre of every pixel,
// also of those the triangle covers only in part (no clipping for the part's centroid: up to
// half a pixel's change of the irradiance off there).
void SplatColour(std::span<const FilmTriangle> triangles, const FilmRaster& raster, const Vec3d& weight, float* image,
                 bool pixel_centres = false);
// The same for a bundle traced with a spectrum: each triangle's weight is its tint.
void SplatTinted(std::span<const FilmTriangle> triangles, const FilmRaster& raster, float* image,
                 bool pixel_centres = false);

}  // namespace objektiv
