#include "optics/element_tolerances.h"

#include <cmath>

#include "base/rng.h"

namespace objektiv {

std::vector<std::pair<size_t, size_t>> LensElements(const LensPrescription& lens) {
  std::vector<std::pair<size_t, size_t>> elements;
  const size_t n = lens.surfaces.size();
  for (size_t i = 0; i < n; ++i) {
    const LensSurface& s = lens.surfaces[i];
    if (lens.MediumBefore(i) || !s.medium) continue;  // an element starts where glass begins after air
    size_t j = i;
    while (j + 1 < n && lens.surfaces[j].medium) ++j;  // to the surface that leaves it into air
    elements.push_back({i, j});
    i = j;
  }
  return elements;
}

LensPrescription WithToleranceSample(const LensPrescription& lens, const ElementTolerances& tolerances) {
  LensPrescription out = lens;
  PCG32 rng(0x746f6c6572616e63ull, tolerances.seed);  // "toleranc"
  auto uniform = [&] { return rng.Uniform32() * 0x1p-32; };
  const std::vector<double> vertex_z = lens.VertexZs();
  for (const auto& [first, last] : LensElements(lens)) {
    // Four draws per element whatever the tolerances, so that one seed moves each element the
    // same way when only one tolerance changes.
    const double r = tolerances.decenter_mm * std::sqrt(uniform()), phi = 2 * M_PI * uniform();
    const double angle = tolerances.tilt_deg * M_PI / 180 * uniform(), axis = 2 * M_PI * uniform();
    // The motion: a turn by `angle` about the axis (cos axis, sin axis, 0), then the decentre.
    SurfacePlacement motion;
    const Vec3d a(std::cos(axis), std::sin(axis), 0);
    auto turn = [&](const Vec3d& v) {  // Rodrigues' formula
      return v * std::cos(angle) + Cross(a, v) * std::sin(angle) + a * (Dot(a, v) * (1 - std::cos(angle)));
    };
    motion.ex = turn(Vec3d(1, 0, 0)), motion.ey = turn(Vec3d(0, 1, 0)), motion.ez = turn(Vec3d(0, 0, 1));
    motion.offset = Vec3d(r * std::cos(phi), r * std::sin(phi), 0);
    const Vec3d pivot(0, 0, vertex_z[first]);
    for (size_t k = first; k <= last; ++k) {
      LensSurface& surface = out.surfaces[k];
      surface.placement = surface.placement.value_or(SurfacePlacement{}).MovedBy(motion, pivot, Vec3d(0, 0, vertex_z[k]));
    }
  }
  return out;
}

}  // namespace objektiv
