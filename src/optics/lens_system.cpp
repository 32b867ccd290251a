#include "optics/lens_system.h"

#include <algorithm>

#include "optics/dispersion.h"
#include "optics/lens_tracer.h"

namespace objektiv {

LensSystem::LensSystem(LensPrescription prescription)
    : prescription_(std::move(prescription)), stop_index_(prescription_.StopIndex()) {
  double z = 0;
  const std::vector<LensSurface>& surfaces = prescription_.surfaces;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const LensSurface& s = surfaces[i];
    vertex_z_.push_back(z);
    z += s.thickness;
    const std::shared_ptr<const Glass>& before = prescription_.MediumBefore(i);
    const bool outer_faces_object = CoatingOuterFacesObject(before != nullptr, s.medium != nullptr);
    outer_faces_object_.push_back(outer_faces_object);
    if (s.coating && before != s.medium)
      coated_.emplace_back(std::in_place, s.coating, outer_faces_object ? before : s.medium,
                           outer_faces_object ? s.medium : before);
    else
      coated_.emplace_back();
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

ParaxialData LensSystem::Paraxial(double lambda_nm) const {
  return lambda_nm == kLambdad ? paraxial_ : ComputeParaxial(prescription_, lambda_nm, stop_semi_);
}

double LensSystem::SurfaceReflectance(int i, double lambda_nm, double cos_i, bool toward_film) const {
  return SurfaceReflectance(i, lambda_nm, cos_i, toward_film, prescription_.IndexBefore(size_t(i), lambda_nm),
                            surface(i).IndexAfter(lambda_nm));
}

double LensSystem::SurfaceReflectance(int i, double lambda_nm, double cos_i, bool toward_film, double n_object,
                                      double n_film) const {
  if (n_object == n_film) return 0;
  if (coated_[i]) return coated_[i]->Reflectance(lambda_nm, cos_i, toward_film == outer_faces_object_[i]);
  return toward_film ? FresnelReflectance(n_object, n_film, cos_i) : FresnelReflectance(n_film, n_object, cos_i);
}

LensSystem LensSystem::WithoutObstructions() const {
  LensSystem open = *this;
  for (LensSurface& s : open.prescription_.surfaces) s.obscuration = 0;
  return open;
}

double LensSystem::MirrorReflectance(int i, double lambda_nm, double cos_i) const {
  const LensSurface& s = surface(i);
  return s.mirror_metal ? s.mirror_metal->Reflectance(lambda_nm, cos_i, s.IndexAfter(lambda_nm)) : s.mirror_reflectance;
}

bool LensSystem::InsideStop(double x, double y) const {
  if (x * x + y * y > stop_semi_ * stop_semi_) return false;
  return stop_shape_.IsRound() || stop_shape_.Contains(x / stop_semi_, y / stop_semi_);
}

}  // namespace objektiv
