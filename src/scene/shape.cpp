#include "scene/shape.h"

#include <stdexcept>

#include <fmt/format.h>

namespace objektiv {

float AreaToSolidAnglePdf(float pdf_area, const Vec3f& ref, const Vec3f& p, const Vec3f& n) {
  Vec3f d = p - ref;
  float dist2 = LengthSquared(d);
  if (dist2 == 0) return 0;
  float cos = AbsDot(n, d) / std::sqrt(dist2);
  if (cos == 0) return 0;
  return pdf_area * dist2 / cos;
}

ShapeSample Shape::SampleFrom(const Vec3f& ref, Vec2f u) const {
  ShapeSample s = SampleArea(u);
  s.pdf = AreaToSolidAnglePdf(s.pdf, ref, s.p, s.n);
  if (!(s.pdf > 0) || std::isinf(s.pdf)) s.pdf = 0;
  return s;
}

float Shape::PdfFrom(const Vec3f& ref, const SurfaceInteraction& hit) const {
  return AreaToSolidAnglePdf(1 / Area(), ref, hit.p, hit.n);
}

bool WithinSceneLimit(const Vec3f& p) {
  return std::abs(p.x) <= kMaxSceneCoordinate && std::abs(p.y) <= kMaxSceneCoordinate &&
         std::abs(p.z) <= kMaxSceneCoordinate;
}

void CheckSceneLimit(const Bounds3f& b, const char* what) {
  if (b.Empty() || !WithinSceneLimit(b.lo) || !WithinSceneLimit(b.hi))
    throw std::invalid_argument(fmt::format("{} reaches ({:g}, {:g}, {:g}) - ({:g}, {:g}, {:g}), beyond the scene's coordinate limit "
                                            "of {:g}",
                                            what, b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z, kMaxSceneCoordinate));
}

}  // namespace objektiv
