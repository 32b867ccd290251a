// The lens as set up: a prescription with its aperture stop set (its semi-diameter and the
// shape of its opening) and its film placed (the back focus: last vertex to film), with the
// first-order data of that arrangement computed once, when the stop changes. Everything that
// traces or analyses a lens takes one: the exact and batch tracers, the pupil bounds,
// focusing, the f-number and the real-ray analyses; each surface's reflectance (bare, or
// through its coating) for the transmission and the ghosts. optics/lens_setup.h builds one as a camera or `objektiv lens` asks for it.
//
// Lens space: millimetres, z along the axis toward the film, the first vertex at z = 0.
#pragma once
#include <optional>
#include <vector>

#include "optics/coating.h"
#include "optics/lens_hood.h"
#include "optics/lens_prescription.h"
#include "optics/paraxial.h"
#include "optics/stop_shape.h"

namespace objektiv {

class LensSystem {
 public:
  // The stop fully open and round, the film where the prescription puts it (its last
  // thickness behind the last vertex).
  explicit LensSystem(LensPrescription prescription);

  const LensPrescription& prescription() const { return prescription_; }
  const LensSurface& surface(int i) const { return prescription_.surfaces[i]; }
  int SurfaceCount() const { return int(prescription_.surfaces.size()); }
  int StopIndex() const { return stop_index_; }  // -1 if none

  // The stop's semi-diameter (mm): narrowed, never widened beyond the prescription's.
  void SetStopSemiDiameter(double mm);
  double StopSemiDiameter() const { return stop_semi_; }
  double FullStopSemiDiameter() const;  // the prescription's
  // The opening's shape (round, an iris of blades, cut by a mask's support).
  void SetStopShape(const StopShape& shape) { stop_shape_ = shape; }
  const StopShape& stop_shape() const { return stop_shape_; }
  // A lens hood in front of the first element (optics/lens_hood.h): every tracer lets light in
  // from the scene, and out toward it, only through its mouth; none by default.
  void SetHood(const std::optional<LensHood>& hood) { hood_ = hood; }
  const std::optional<LensHood>& hood() const { return hood_; }
  // Whether a ray entering the lens from the scene (or leaving toward it) passes the hood.
  bool PassesHood(const Vec3d& o, const Vec3d& d) const { return !hood_ || hood_->Passes(o, d, vertex_z_.front()); }
  // Whether (x, y) in the stop's plane (mm from the axis) lies inside the opening.
  bool InsideStop(double x, double y) const;

  // The film `mm` behind the last vertex (the last thickness).
  void SetBackFocus(double mm) { film_z_ = vertex_z_.back() + mm; }
  double BackFocus() const { return film_z_ - vertex_z_.back(); }
  double VertexZ(int i) const { return vertex_z_[i]; }
  // A lens-space point in surface i's own frame, relative to its vertex (its placement undone:
  // optics/surface_placement.h); for a centred surface, p - (0, 0, VertexZ(i)).
  Vec3d InSurfaceFrame(int i, const Vec3d& p) const {
    const Vec3d rel = p - Vec3d(0, 0, vertex_z_[i]);
    const std::optional<SurfacePlacement>& placed = prescription_.surfaces[i].placement;
    return placed ? placed->ToLocal(rel - placed->offset) : rel;
  }
  // The inverse: a point of surface i's frame (relative to its vertex) in lens space.
  Vec3d FromSurfaceFrame(int i, const Vec3d& p) const {
    const std::optional<SurfacePlacement>& placed = prescription_.surfaces[i].placement;
    return Vec3d(0, 0, vertex_z_[i]) + (placed ? placed->PointFromLocal(p) : p);
  }
  double FilmZ() const { return film_z_; }

  // Unpolarised reflectance of surface i for light crossing it toward the film (or toward the
  // object) at cos_i (in the medium it comes from): Fresnel's where the surface is bare, the
  // thin-film stack's where coated; 0 where the media on both sides are the same, 1 beyond
  // the critical angle.
  double SurfaceReflectance(int i, double lambda_nm, double cos_i, bool toward_film) const;
  // The same where the caller has the indices on the object and film sides at lambda_nm
  // already (the exact tracer: each glass's formula evaluated once per surface, not twice).
  double SurfaceReflectance(int i, double lambda_nm, double cos_i, bool toward_film, double n_object,
                            double n_film) const;
  // The same lens as set up without its central obstructions (obscuration= on any surface):
  // where light could get through but for them.
  LensSystem WithoutObstructions() const;
  // What mirror i reflects for light arriving at cos_i (in the medium it travels in).
  double MirrorReflectance(int i, double lambda_nm, double cos_i) const;
  // The coating as it lies on surface i, or null (bare, or no change of medium there).
  const CoatedInterface* Coated(int i) const { return coated_[i] ? &*coated_[i] : nullptr; }
  // Whether surface i's coating has its outer side toward the object (its glass on the film
  // side): light toward the film meets it from outside.
  bool CoatingFacesObject(int i) const { return outer_faces_object_[size_t(i)]; }

  // First-order data at the d line, object at infinity, for the stop as set.
  const ParaxialData& paraxial() const { return paraxial_; }
  // The same at another wavelength (computed on each call; the d line's is kept).
  ParaxialData Paraxial(double lambda_nm) const;
  // Lens-space z of the entrance and exit pupils (paraxial, d line).
  double EntrancePupilZ() const { return vertex_z_.front() + paraxial_.entrance_pupil_position; }
  double ExitPupilZ() const { return vertex_z_.back() + paraxial_.exit_pupil_position; }

 private:
  LensPrescription prescription_;
  std::vector<double> vertex_z_;
  // Per surface: its coating as laid on it, and whether the coating's outer side faces the
  // object (its glass on the film side).
  std::vector<std::optional<CoatedInterface>> coated_;
  std::vector<bool> outer_faces_object_;
  int stop_index_ = -1;
  double film_z_ = 0, stop_semi_ = 0;
  StopShape stop_shape_;
  std::optional<LensHood> hood_;
  ParaxialData paraxial_;
};

}  // namespace objektiv
