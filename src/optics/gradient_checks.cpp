#include "optics/gradient_checks.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/dispersion.h"

namespace objektiv {

namespace {

// Where the index over the element after surface i leaves 1..5 (on a grid of 65 radii by 65
// depths between the two surfaces' sags, out to the wider face plus either face's decentre, at
// the d line): a message naming the farthest point out, or empty.
std::string IndexOutOfRange(const LensSurface& front, const LensSurface& back) {
  const double n_v = front.IndexAfter(kLambdad);
  auto offset = [](const LensSurface& s) { return s.placement ? std::hypot(s.placement->offset.x, s.placement->offset.y) : 0.0; };
  const double semi = std::max(front.semi_diameter, back.semi_diameter) + offset(front) + offset(back);
  double worst = 0, worst_n = n_v, worst_r = 0, worst_z = 0;  // how far out of 1..5, and where
  for (int a = 0; a <= 64; ++a) {
    const double r = semi * a / 64;
    // The element's depth at this radius: from the front's sag to the back's (each surface's
    // sag where it reaches that far, else its vertex plane's).
    const double z_front = r <= front.semi_diameter ? front.Sag(r) : 0;
    const double z_back = front.thickness + (r <= back.semi_diameter ? back.Sag(r) : 0);
    const double lo = std::min(z_front, z_back), hi = std::max(z_front, z_back);
    for (int b = 0; b <= 64; ++b) {
      const double z = lo + (hi - lo) * b / 64;
      const double n2 = front.gradient->IndexSquared(n_v, Vec3d(r, 0, z));
      const double n = std::sqrt(std::max(n2, 0.0));
      const double out = !std::isfinite(n) ? INFINITY : n < 1 ? 1 - n : n - 5;
      if (out > worst) worst = out, worst_n = n, worst_r = r, worst_z = z;
    }
  }
  if (!(worst > 0)) return "";
  return fmt::format("the gradient's index reaches {:.4g} at r = {:.4g} mm, z = {:.4g} mm from the vertex (d line): a "
                     "glass's lies between 1 and 5 over the whole element", worst_n, worst_r, worst_z);
}

}  // namespace

std::optional<std::pair<size_t, std::string>> FirstGradientMismatch(const LensPrescription& lens) {
  const size_t n = lens.surfaces.size();
  for (size_t i = 0; i < n; ++i) {
    const LensSurface& s = lens.surfaces[i];
    if (!s.gradient) continue;
    if (lens.MirrorCount() > 0)
      return std::pair{i, std::string("a gradient-index medium in a lens with mirrors is not modelled")};
    if (i + 1 >= n) return std::pair{i, std::string("a gradient-index medium must end at a surface")};
    const LensSurface& next = lens.surfaces[i + 1];
    if (next.is_stop && next.medium)
      return std::pair{i + 1, std::string("the stop lies inside glass right after the gradient-index medium the row before "
                                          "begins (the gradient would end at the stop): not modelled")};
    if (s.fresnel || next.fresnel)
      return std::pair{s.fresnel ? i : i + 1, std::string("a Fresnel surface (zones=) next to a gradient-index medium is "
                                                           "not modelled")};
    if (s.gradient->kind() == GradientIndex::Kind::kSpherical) {
      const double centre = s.gradient->coefficients()[0];
      if (centre >= std::min(0.0, s.thickness) && centre <= std::max(0.0, s.thickness))
        return std::pair{i, fmt::format("grin_sphere's centre {} mm lies inside the element on the axis (0 to {} mm), where "
                                        "the shells shrink to a point: not modelled", centre, s.thickness)};
    }
    if (std::string why = IndexOutOfRange(s, next); !why.empty()) return std::pair{i, why};
  }
  return std::nullopt;
}

}  // namespace objektiv
