#include "optics/lens_prescription.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"

namespace objektiv {

void LensSurface::SetCurvature(double c) {
  flat = !std::isfinite(1 / c);
  radius = flat ? 0 : 1 / c;
}

int LensPrescription::StopIndex() const {
  for (size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].is_stop) return int(i);
  return -1;
}

int LensPrescription::MirrorCount() const {
  return int(std::count_if(surfaces.begin(), surfaces.end(), [](const LensSurface& s) { return s.mirror; }));
}

int LensPrescription::DirectionAfter(size_t i) const {
  int direction = 1;
  for (size_t k = 0; k <= i && k < surfaces.size(); ++k)
    if (surfaces[k].mirror) direction = -direction;
  return direction;
}

std::optional<std::pair<size_t, std::string>> FirstDirectionMismatch(const LensPrescription& lens) {
  int mirrors = 0;
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    mirrors += s.mirror;
    const bool toward_film = mirrors % 2 == 0;
    if (toward_film ? s.thickness < 0 : s.thickness > 0)
      return {{i, fmt::format("thickness {} goes against the light: after {} mirror(s) it travels toward the {}, so the "
                              "thickness to the next surface must be {} (a z step, as lens designers write it)",
                              s.thickness, mirrors, toward_film ? "film" : "object",
                              toward_film ? "positive" : "negative")}};
  }
  if (mirrors % 2)
    return {{lens.surfaces.size() - 1,
             fmt::format("the lens has {} mirror{}, an odd number: its image would lie on the object's side; a "
                         "camera needs an even number (a fold mirror needs a coordinate break, which is not supported)",
                         mirrors, mirrors == 1 ? "" : "s")}};
  return std::nullopt;
}

double LensPrescription::TotalTrack() const {
  double t = 0;
  for (size_t i = 0; i + 1 < surfaces.size(); ++i) t += surfaces[i].thickness;
  return t;
}

double LensSurface::Sag(double r) const {
  const LensSurface& s = *this;
  double c = s.Curvature(), r2 = r * r;
  double z = 0;
  if (c != 0) {
    double arg = 1 - (1 + s.conic) * c * c * r2;
    z = c * r2 / (1 + std::sqrt(std::max(arg, 0.0)));
  }
  z += s.a2 * r2;
  double rp = r2 * r2;  // r^4
  for (double a : s.aspheric) {
    z += a * rp;
    rp *= r2;
  }
  return z;
}

double LensSurface::SagSlope(double r) const {
  const LensSurface& s = *this;
  double c = s.Curvature(), r2 = r * r;
  double dz = 0;
  if (c != 0) {
    double arg = 1 - (1 + s.conic) * c * c * r2;
    dz = c * r / std::sqrt(std::max(arg, 1e-300));
  }
  dz += 2 * s.a2 * r;
  double rp = r2 * r;  // r^3
  int order = 4;
  for (double a : s.aspheric) {
    dz += order * a * rp;
    rp *= r2;
    order += 2;
  }
  return dz;
}

void CheckReachable(const LensSurface& s, const std::string& path, int line) {
  double c = s.Curvature();
  if (c == 0 || s.conic <= -1) return;
  double limit = 1 / (std::abs(c) * std::sqrt(1 + s.conic));
  if (s.semi_diameter > limit)
    throw MakeInputError(path, line, "semi-diameter {} is larger than the surface can reach ({:.4g})", s.semi_diameter, limit);
}

std::optional<std::pair<size_t, std::string>> FirstCoatingMismatch(const LensPrescription& lens) {
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    const Glass* before = lens.MediumBefore(i).get();
    if (!s.coating || before == s.medium.get()) continue;  // coats nothing
    if (std::string why = CoatingMismatch(*s.coating, before, s.medium.get()); !why.empty()) return {{i, why}};
  }
  return std::nullopt;
}

void CheckSize(const LensSurface& s, const std::string& path, int line) {
  if (!(std::abs(s.thickness) <= kMaxLensLength))
    throw MakeInputError(path, line, "thickness {} mm is beyond {} mm: not a lens", s.thickness, kMaxLensLength);
  if (!(s.semi_diameter <= kMaxLensLength))
    throw MakeInputError(path, line, "semi-diameter {} mm is beyond {} mm: not a lens", s.semi_diameter, kMaxLensLength);
}

LensPrescription LensPrescription::Scaled(double factor) const {
  LensPrescription out = *this;
  for (LensSurface& s : out.surfaces) {
    s.radius *= factor;
    s.thickness *= factor;
    s.semi_diameter *= factor;
    s.obscuration *= factor;
    s.a2 /= factor;
    double scale = factor * factor * factor;  // 2k - 1 = 3 for a4
    for (double& a : s.aspheric) {
      a /= scale;
      scale *= factor * factor;
    }
  }
  if (out.design_focal_length > 0) out.design_focal_length *= factor;
  if (out.image_circle > 0) out.image_circle *= factor;
  return out;
}

}  // namespace objektiv

namespace objektiv {

void CoatAirGlassSurfaces(LensPrescription& lens, const std::shared_ptr<const Coating>& coating, bool only_bare) {
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    LensSurface& s = lens.surfaces[i];
    const bool glass_before = bool(lens.MediumBefore(i)), glass_after = bool(s.medium);
    if (glass_before == glass_after) continue;  // air on both sides, or cemented
    if (!only_bare || !s.coating) s.coating = coating;
  }
}

}  // namespace objektiv
