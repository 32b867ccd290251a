#include "camera/paraxial_lens_camera.h"

#include <cmath>

#include "base/sampling.h"
#include "optics/dispersion.h"
#include "optics/real_focus.h"
#include "optics/paraxial.h"

namespace objektiv {

ParaxialLensModel MakeParaxialModel(const LensSystem& lens, double distance_from_film, bool thin) {
  const LensPrescription& rx = lens.prescription();
  const int last = int(rx.surfaces.size()) - 1;
  ParaxialData p = ComputeParaxial(rx, kLambdad, lens.StopSemiDiameter());
  const bool infinite = !(distance_from_film < 1e12);
  ParaxialLensModel m;
  m.efl = p.efl;
  if (thin) {
    // Lens-to-film distance v with 1/v + 1/(D - v) = 1/f (the root near f); the lens sits
    // where the real lens's rear principal plane is at infinity focus, the film behind it.
    double v = p.efl;
    if (!infinite) {
      double disc = distance_from_film * distance_from_film - 4 * p.efl * distance_from_film;
      v = disc >= 0 ? 0.5 * (distance_from_film - std::sqrt(disc)) : 2 * p.efl;  // too close: closest focus
    }
    double z = lens.VertexZ(last) + p.back_principal_plane;
    m.front_principal_z = m.back_principal_z = m.entrance_pupil_z = m.exit_pupil_z = z;
    m.entrance_pupil_radius = m.exit_pupil_radius = p.efl / (2 * p.fnumber);
    m.film_z = z + v;
    return m;
  }
  LensSystem t = lens;
  t.SetBackFocus(ParaxialFocus(rx, distance_from_film).back_focus);
  m.front_principal_z = t.VertexZ(0) + p.front_principal_plane;
  m.back_principal_z = t.VertexZ(last) + p.back_principal_plane;
  m.entrance_pupil_z = t.VertexZ(0) + p.entrance_pupil_position;
  m.entrance_pupil_radius = p.entrance_pupil_diameter / 2;
  m.exit_pupil_z = t.VertexZ(last) + p.exit_pupil_position;
  m.exit_pupil_radius = p.exit_pupil_diameter / 2;
  m.film_z = t.FilmZ();
  return m;
}

ParaxialLensCamera::ParaxialLensCamera(const Transform& to_world, int width, int height, const ParaxialLensModel& model,
                                       const StopShape& stop, const LensCameraSettings& settings)
    : LensCamera(to_world, width, height, settings), m_(model), stop_(stop) {
  SetOriginZ(m_.entrance_pupil_z);
}

std::optional<CameraRay> ParaxialLensCamera::GenerateRay(const CameraSample& s, SampledWavelengths&) const {
  Vec2d film = FilmPoint(s.p_film);
  // A point of the exit pupil (the iris inscribed in it).
  Vec2d u = stop_.SampleIris(Vec2d(s.p_lens.x, s.p_lens.y));
  double area = stop_.IrisArea() * m_.exit_pupil_radius * m_.exit_pupil_radius;
  Vec3d f(film.x, film.y, m_.film_z), xp(u.x * m_.exit_pupil_radius, u.y * m_.exit_pupil_radius, m_.exit_pupil_z);
  double dz = m_.film_z - m_.exit_pupil_z;
  Vec3d to_pupil = Normalize(xp - f);
  // The pupils are conjugate: the matching entrance-pupil point, scaled by their sizes.
  double pupil_scale = m_.entrance_pupil_radius / m_.exit_pupil_radius;
  Vec3d ep(xp.x * pupil_scale, xp.y * pupil_scale, m_.entrance_pupil_z);
  // The film point's conjugate: Gaussian imaging about the principal planes.
  double image = m_.film_z - m_.back_principal_z;  // from H', toward the film
  double inv_object = 1 / m_.efl - 1 / image;
  Vec3d d;
  if (std::abs(inv_object) * m_.efl < 1e-9) {
    // Object at infinity: every ray parallel to the one through the nodal points.
    d = Normalize(Vec3d(-f.x, -f.y, -image));
  } else {
    double object = 1 / inv_object;  // in front of H; negative: a virtual object behind it
    Vec3d o(-f.x * object / image, -f.y * object / image, m_.front_principal_z - object);
    d = object > 0 ? Normalize(o - ep) : Normalize(ep - o);
  }
  float w = Weight(film, -to_pupil.z, dz, 1 / area);
  if (settings_.aperture_mask) w *= settings_.aperture_mask->Transmittance(float(u.x), float(u.y));
  CameraRay cr;
  cr.ray = WorldRay(ep, d);
  cr.weight = SampledSpectrum(w);
  return cr;
}

}  // namespace objektiv
