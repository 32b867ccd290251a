#include "optics/lens_system.h"

#include <algorithm>

#include "optics/dispersion.h"

namespace objektiv {

LensSystem::LensSystem(LensPrescription prescription)
    : prescription_(std::move(prescription)), stop_index_(prescription_.StopIndex()) {
  double z = 0;
  for (const LensSurface& s : prescription_.surfaces) {
    vertex_z_.push_back(z);
    z += s.thickness;
  }
  film_z_ = z;
  stop_semi_ = FullStopSemiDiameter();
  paraxial_ = ComputeParaxial(prescription_, kLambdad, stop_semi_);
}

double LensSystem::FullStopSemiDiameter() const {
  return stop_index_ >= 0 ? prescription_.surfaces[stop_index_].semi_diameter : 0;
}

void LensSystem::SetStopSemiDiameter(double mm) {
  if (stop_index_ < 0) return;
  stop_semi_ = std::clamp(mm, 0.0, FullStopSemiDiameter());
  paraxial_ = ComputeParaxial(prescription_, kLambdad, stop_semi_);
}

bool LensSystem::InsideStop(double x, double y) const {
  if (x * x + y * y > stop_semi_ * stop_semi_) return false;
  return stop_shape_.IsRound() || stop_shape_.Contains(x / stop_semi_, y / stop_semi_);
}

}  // namespace objektiv
