// An aperture mask: a greyscale image laid over the stop (or, for the ideal lens cameras, the
// exit pupil), its transmittance multiplying the light through each point. The image spans
// the stop's full diameter as a square, seen from behind the lens (image right is the
// photographer's right, image up is up); outside the image nothing passes. Values are taken
// as they are in the file (no sRGB decoding): white passes everything, black nothing.
#pragma once
#include "base/convex_polygon.h"
#include "base/image.h"

namespace objektiv {

class ApertureMask {
 public:
  explicit ApertureMask(const Image& image);  // its first channel (or the mean of R, G, B)
  // Transmittance at (x, y) in stop radii (lens space: +x is the photographer's left).
  float Transmittance(float x, float y) const;
  // The convex hull of where the transmittance is not zero (in stop radii): the realistic
  // camera cuts the stop's opening to it, so that no ray is aimed where the mask is shut.
  ConvexPolygon OpenHull() const;

 private:
  int width_, height_;
  std::vector<float> values_;  // rows top to bottom
};

}  // namespace objektiv
