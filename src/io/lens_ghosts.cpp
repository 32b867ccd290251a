#include "io/lens_ghosts.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "io/white_light.h"

namespace objektiv {

namespace {

// At one wavelength: the picture (share per pixel) and each ghost's share.
struct OneWavelength {
  std::vector<double> picture;
  std::vector<double> shares;
  double direct = 0;  // the point's own image's share
};

OneWavelength AtWavelength(const LensSystem& lens, const std::vector<Ghost>& ghosts, const PointSource& source,
                           const FilmRaster& raster, int grid, double lambda_nm) {
  OneWavelength out;
  out.picture.assign(size_t(raster.width) * raster.height, 0);
  out.shares.assign(ghosts.size(), 0);
  // Shares of the light the point sends onto the front element.
  const double incident = FrontElementFlux(lens, source);
  for (const FilmTriangle& t : DirectBundle(lens, source, lambda_nm, grid)) out.direct += t.flux / incident;
  std::vector<std::vector<FilmTriangle>> bundles(ghosts.size());
  tbb::parallel_for(size_t(0), ghosts.size(), [&](size_t g) { bundles[g] = GhostBundle(lens, ghosts[g], source, lambda_nm, grid); });
  std::vector<float> image(out.picture.size(), 0.f);
  // Irradiance times the pixel's area over the incident flux: the share of the light per pixel.
  const double weight = raster.w * raster.h / incident;
  for (size_t g = 0; g < ghosts.size(); ++g) {
    double flux = 0;
    for (const FilmTriangle& t : bundles[g]) flux += t.flux;
    out.shares[g] = flux / incident;
    Splat(bundles[g], raster, weight, image.data());
  }
  std::copy(image.begin(), image.end(), out.picture.begin());
  return out;
}

}  // namespace

GhostPicture PictureGhosts(const LensSystem& lens, const GhostPictureRequest& q) {
  const double theta = q.field_deg * M_PI / 180, phi = q.azimuth_deg * M_PI / 180;
  // Light from a point at field angle theta toward azimuth phi (camera space: +x the image's
  // left) travels the other way: lens-space direction (-sin theta cos phi, -sin theta sin phi, cos theta).
  const PointSource source = PointSource::Distant({-std::sin(theta) * std::cos(phi), -std::sin(theta) * std::sin(phi), std::cos(theta)});
  FilmRaster raster;
  raster.width = q.width;
  raster.height = std::max(1, int(std::lround(q.width * q.sensor_height / q.sensor_width)));
  raster.w = q.sensor_width / raster.width;
  raster.h = q.sensor_height / raster.height;
  raster.x0 = -q.sensor_width / 2;
  raster.y0 = -q.sensor_height / 2;
  const std::vector<Ghost> ghosts = TwoReflectionGhosts(lens);
  GhostPicture out;
  std::vector<double> shares(ghosts.size(), 0);
  if (q.lambda_nm) {
    OneWavelength one = AtWavelength(lens, ghosts, source, raster, q.grid, *q.lambda_nm);
    out.image = Image(raster.width, raster.height, {"R", "G", "B"});
    for (size_t i = 0; i < one.picture.size(); ++i)
      for (int c = 0; c < 3; ++c) out.image.pixels[i * 3 + c] = float(one.picture[i]);
    shares = one.shares;
    out.direct_share = one.direct;
  } else {
    // 25 nm steps: coatings' reflectances change slowly with the wavelength.
    const double step = 25;
    const std::vector<std::pair<double, double>> weights = LuminanceWeights(step);
    size_t k = 0;
    out.image = WhiteLightImage(raster.width, raster.height, step, [&](double l) {
      OneWavelength one = AtWavelength(lens, ghosts, source, raster, q.grid, l);
      for (size_t g = 0; g < ghosts.size(); ++g) shares[g] += weights[k].second * one.shares[g];
      out.direct_share += weights[k].second * one.direct;
      ++k;
      return one.picture;
    });
  }
  for (size_t g = 0; g < ghosts.size(); ++g) {
    out.ghosts.push_back({ghosts[g], shares[g]});
    out.total_share += shares[g];
  }
  std::sort(out.ghosts.begin(), out.ghosts.end(), [](const GhostShare& a, const GhostShare& b) { return a.share > b.share; });
  return out;
}

}  // namespace objektiv
