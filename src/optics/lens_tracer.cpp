#include "optics/lens_tracer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/fresnel_dielectric.h"
#include "optics/gradient_propagation.h"

namespace objektiv {

std::optional<Vec3d> StopCrossingFromFilm(const LensSystem& lens, const LensRay& ray, double lambda_nm) {
  const int stop = lens.StopIndex();
  if (stop < 0) return std::nullopt;
  // The path holds the point on every surface the ray reached, the blocking one included.
  std::vector<Vec3d> path;
  TraceFromFilm(lens, ray, lambda_nm, &path);
  const size_t k = size_t(lens.SurfaceCount()) - 1 - size_t(stop);
  if (path.size() <= k) return std::nullopt;
  return lens.InSurfaceFrame(stop, path[k]) + Vec3d(0, 0, lens.VertexZ(stop));
}

double FresnelReflectance(double n1, double n2, double cos_i) {
  return FresnelDielectric(std::clamp(cos_i, 0.0, 1.0), n2 / n1);
}

Vec3d SurfaceNormal(const LensSurface& s, const Vec3d& p) {
  double z, gx = 0, gy = 0;
  if (!s.SagAt(p.x, p.y, z, &gx, &gy)) gx = gy = 0;
  Vec3d n(-gx, -gy, 1);
  return n / Length(n);
}

namespace {

// Where the ray (o relative to the vertex) meets a surface without rotational symmetry (a
// toroid, a form error): Newton on f(t) = z(t) - sag(x(t), y(t)) from t (the vertex plane's
// crossing, or the nominal surface's); a step that leaves the surface's domain is halved.
std::optional<double> RefineOnSurface(const LensSurface& s, const Vec3d& o, const Vec3d& d, double t) {
  for (int it = 0; it < 60; ++it) {
    const Vec3d p = o + d * t;
    double z, gx, gy;
    if (!s.SagAt(p.x, p.y, z, &gx, &gy)) return std::nullopt;
    const double df = d.z - gx * d.x - gy * d.y;
    if (df == 0) return std::nullopt;
    double step = (p.z - z) / df;
    for (int halve = 0; halve < 30 && !s.SagAt(o.x + d.x * (t - step), o.y + d.y * (t - step), z); ++halve) step *= 0.5;
    t -= step;
    if (std::abs(step) < 1e-13 * (1 + std::abs(t))) return t;
  }
  return std::nullopt;
}

// Where a ray (o relative to the surface's vertex, in its frame) meets surface s as prescribed
// (a toroid with its form error): the parameter t, or nothing; `blocked` is set where it meets
// a Fresnel surface's riser.
std::optional<double> IntersectNominal(const LensSurface& s, const Vec3d& o, const Vec3d& d, bool& blocked) {
  blocked = false;
  if (s.fresnel) {
    const std::optional<FresnelZones::Hit> hit = s.fresnel->Intersect(s, o, d);
    if (!hit) return std::nullopt;
    blocked = hit->riser;
    return hit->t;
  }
  if (s.toroidal) return d.z == 0 ? std::nullopt : RefineOnSurface(s, o, d, -o.z / d.z);
  double c = s.Curvature();
  bool aspheric = s.HasAsphericTerms();
  double t;
  if (c == 0) {
    if (d.z == 0) return std::nullopt;
    t = -o.z / d.z;
  } else {
    const std::optional<double> conic = IntersectConic(c, 1 + s.conic, o, d);
    if (!conic) return std::nullopt;
    t = *conic;
  }
  if (aspheric) {
    // Newton on f(t) = z(t) - sag(r(t)), from the conic's (or plane's) intersection.
    for (int it = 0; it < 60; ++it) {
      Vec3d p = o + d * t;
      double r = std::sqrt(p.x * p.x + p.y * p.y);
      if (c != 0 && (1 + s.conic) * c * c * r * r > 1) return std::nullopt;
      double sag, slope;  // one pass for both
      s.SagWithSlope(r, sag, slope);
      double f = p.z - sag;
      double drdt = r > 0 ? (p.x * d.x + p.y * d.y) / r : 0;
      double df = d.z - slope * drdt;
      if (df == 0) return std::nullopt;
      double step = f / df;
      t -= step;
      if (std::abs(step) < 1e-13 * (1 + std::abs(t))) break;
      if (it == 59) return std::nullopt;
    }
  }
  return t;
}

// Gap `gap`'s medium (index n) as a wave sees it: isotropic, or the crystal's ordinary or
// extraordinary wave, its optic axis turned into lens space by the surface's placement.
WaveMedium CrystalWaveMedium(const LensSystem& lens, int gap, const UniaxialCrystal* crystal, double n, double lambda_nm,
                             bool extraordinary) {
  WaveMedium m;
  m.n = n;
  if (!crystal) return m;
  m.crystal = true;
  m.extraordinary = extraordinary;
  m.ne = crystal->extraordinary->Index(lambda_nm);
  const LensSurface& s = lens.surface(gap);
  m.axis = s.placement ? s.placement->FromLocal(crystal->axis) : crystal->axis;
  return m;
}

}  // namespace

std::optional<double> IntersectSurface(const LensSurface& s, const Vec3d& o, const Vec3d& d, bool& blocked) {
  const std::optional<double> t = IntersectNominal(s, o, d, blocked);
  // A form error: Newton from the prescribed surface's crossing (a toroid's already has it).
  if (t && !blocked && s.form_error && !s.toroidal) return RefineOnSurface(s, o, d, *t);
  return t;
}

SurfaceCrossing CrossSurface(const LensSystem& lens, int i, const LensRay& ray, double lambda_nm, bool toward_film,
                             double gradient_tolerance, std::vector<Vec3d>* curve, bool with_reflectance) {
  SurfaceCrossing c;
  const LensSurface& s = lens.surface(i);
  // The ray in the surface's frame (its vertex at the origin): a rigid motion, so the ray's
  // parameter t is the same in both.
  const Vec3d vertex(0, 0, lens.VertexZ(i));
  const SurfacePlacement* placed = s.placement ? &*s.placement : nullptr;
  // The medium the ray travels in: a gradient bends it on the way.
  const int gap = toward_film ? i - 1 : i;
  Vec3d p;  // the point in the surface's frame
  if (gap >= 0 && lens.surface(gap).gradient) {
    const GradientArrival a = PropagateThroughGradient(lens, gap, toward_film, ray, lambda_nm, gradient_tolerance, curve);
    c.failure = a.failure;
    c.p = a.p, c.d = a.d, c.t = a.length;
    if (a.failure != TraceFailure::kNone) return c;
    p = lens.InSurfaceFrame(i, c.p);
  } else {
    const Vec3d o = placed ? placed->ToLocal(ray.o - vertex - placed->offset) : ray.o - vertex;
    const Vec3d d = placed ? placed->ToLocal(ray.d) : ray.d;
    bool blocked;
    std::optional<double> t = IntersectSurface(s, o, d, blocked);
    if (!t || *t < -1e-9) {
      c.failure = TraceFailure::kMissedSurface;
      return c;
    }
    c.t = *t;
    c.p = ray.o + ray.d * *t;
    c.d = ray.d;
    if (curve) curve->push_back(c.p);
    if (blocked) {  // a Fresnel surface's riser
      c.failure = TraceFailure::kClipped;
      return c;
    }
    p = o + d * *t;
  }
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  if ((s.is_stop ? !lens.InsideStop(p.x, p.y) : r > s.semi_diameter) || r < s.obscuration) {
    c.failure = TraceFailure::kClipped;
    return c;
  }
  if (s.dirt) c.clean = s.dirt->Transmittance(p.x, p.y);
  // Indices on the incoming and outgoing sides (a stop inside glass has the same on both;
  // between different media it refracts as the flat interface it is).
  // Where a gradient-index medium lies on either side, its index at the point.
  const double n_object_side = i > 0 && lens.surface(i - 1).gradient ? IndexInGap(lens, i - 1, c.p, lambda_nm)
                                                                     : lens.prescription().IndexBefore(size_t(i), lambda_nm);
  const double n_film_side = s.gradient ? IndexInGap(lens, i, c.p, lambda_nm) : s.IndexAfter(lambda_nm);
  const double n1 = toward_film ? n_object_side : n_film_side, n2 = toward_film ? n_film_side : n_object_side;
  // Birefringent crystals on either side (optics/uniaxial_crystal.h).
  const UniaxialCrystal* crystal_object_side = i > 0 ? lens.surface(i - 1).crystal.get() : nullptr;
  const UniaxialCrystal* crystal_in = toward_film ? crystal_object_side : s.crystal.get();
  const UniaxialCrystal* crystal_out = toward_film ? s.crystal.get() : crystal_object_side;
  c.extraordinary = ray.extraordinary && crystal_in;
  c.wave_choices = ray.wave_choices;
  c.anisotropic = crystal_in || crystal_out;
  c.mirror = s.mirror;
  c.interface = (n1 != n2 || crystal_in != crystal_out) && !s.mirror;
  if (!c.interface && !c.mirror) return c;
  // The normal facing the incoming ray.
  c.normal = InterfaceNormal(s, p);
  if (placed) c.normal = placed->FromLocal(c.normal);
  if (Dot(c.normal, c.d) > 0) c.normal = -c.normal;
  c.cos_i = -Dot(c.normal, c.d);
  if (c.mirror) {
    c.reflectance = lens.MirrorReflectance(i, lambda_nm, c.cos_i);
    return c;
  }
  c.eta = n1 / n2;
  if (!c.anisotropic) {
    if (with_reflectance) c.reflectance = lens.SurfaceReflectance(i, lambda_nm, c.cos_i, toward_film, n_object_side, n_film_side);
    return c;
  }
  // Into or out of a crystal: the waves on either side as they are; the reflected and the
  // refracted wave in a crystal is the one the ray's next choice names.
  const bool next_extraordinary = c.wave_choices & 1u;
  const int gap_in = toward_film ? i - 1 : i, gap_out = toward_film ? i : i - 1;
  const WaveMedium m_in = CrystalWaveMedium(lens, gap_in, crystal_in, n1, lambda_nm, c.extraordinary);
  c.reflected_medium = CrystalWaveMedium(lens, gap_in, crystal_in, n1, lambda_nm, next_extraordinary);
  c.refracted_medium = CrystalWaveMedium(lens, gap_out, crystal_out, n2, lambda_nm, next_extraordinary);
  c.k_in = WaveVectorOf(c.d, m_in);
  const double k_in = Length(c.k_in);
  c.cos_i = -Dot(c.normal, c.k_in) / k_in;
  const std::optional<Vec3d> k_out = WaveVectorInto(c.k_in + c.normal * (c.cos_i * k_in), -c.normal, c.refracted_medium);
  if (!k_out) {  // beyond the critical angle: all reflected
    c.eta = INFINITY;
    c.reflectance = 1;
    return c;
  }
  // Fresnel's unpolarised reflectance with each wave's own index (an approximation).
  const double k_after = Length(*k_out);
  c.eta = k_in / k_after;
  if (with_reflectance)
    c.reflectance = lens.SurfaceReflectance(i, lambda_nm, c.cos_i, toward_film, toward_film ? k_in : k_after,
                                          toward_film ? k_after : k_in);
  return c;
}

LensRay Reflected(const SurfaceCrossing& c, const Vec3d& d) {
  if (c.anisotropic) {
    // The wave vector's part along the surface is kept; the reflected wave goes back into the
    // incoming side (where the normal points). Where the wave the choice names cannot exist
    // there (a quartz extraordinary wave reflected as an ordinary one beyond its critical
    // angle), the ray's own wave is reflected, which always exists.
    const Vec3d t = c.k_in + c.normal * (c.cos_i * Length(c.k_in));
    WaveMedium m = c.reflected_medium;
    std::optional<Vec3d> k = WaveVectorInto(t, c.normal, m);
    if (!k) m.extraordinary = c.extraordinary, k = WaveVectorInto(t, c.normal, m);
    const bool in_crystal = c.reflected_medium.crystal;
    const Vec3d dir = k ? RayDirectionOf(*k, m) : d + c.normal * (2 * c.cos_i);
    return {c.p, dir / Length(dir), m.extraordinary, in_crystal ? c.wave_choices >> 1 : c.wave_choices};
  }
  return {c.p, ReflectedDirection(d, c.normal, c.cos_i), false, c.wave_choices};
}

std::optional<LensRay> Refracted(const SurfaceCrossing& c, const Vec3d& d) {
  if (c.anisotropic) {
    const Vec3d t = c.k_in + c.normal * (c.cos_i * Length(c.k_in));
    const std::optional<Vec3d> k = WaveVectorInto(t, -c.normal, c.refracted_medium);
    if (!k) return std::nullopt;
    const bool into_crystal = c.refracted_medium.crystal;
    return LensRay{c.p, RayDirectionOf(*k, c.refracted_medium), c.refracted_medium.extraordinary,
                   into_crystal ? c.wave_choices >> 1 : c.wave_choices};
  }
  const std::optional<Vec3d> r = RefractedDirection(d, c.normal, c.eta, c.cos_i);
  if (!r) return std::nullopt;
  return LensRay{c.p, *r, false, c.wave_choices};
}

Vec3d InterfaceNormal(const LensSurface& s, const Vec3d& p) {
  if (s.HasAsphericTerms() || s.toroidal || s.fresnel || s.form_error) return SurfaceNormal(s, p);
  return ConicNormal(s.Curvature(), 1 + s.conic, p);
}

Vec3d ReflectedDirection(const Vec3d& d, const Vec3d& n, double cos_i) {
  const Vec3d r = d + n * (2 * cos_i);
  return r / Length(r);
}

std::optional<Vec3d> RefractedDirection(const Vec3d& d, const Vec3d& n, double eta, double cos_i) {
  const double k2 = 1 - eta * eta * (1 - cos_i * cos_i);
  if (k2 < 0) return std::nullopt;
  const Vec3d r = d * eta + n * (eta * cos_i - std::sqrt(k2));
  return r / Length(r);
}

double SegmentTransmittance(const LensSystem& lens, int from, int to, double lambda_nm, double length) {
  const Glass* g = lens.surface(std::min(from, to)).medium.get();
  return g ? g->InternalTransmittance(lambda_nm, length) : 1.0;
}

namespace {

// The ray through `count` visits, visit(k) giving the k-th (surface, reflect, toward_film):
// consecutive visits are neighbouring surfaces (or the same surface's neighbours after a
// reflection), so the segment between them lies in one medium.
template <typename Visit>
TraceResult TraceVisits(const LensSystem& lens, const LensRay& in, double lambda_nm, int count, Visit visit,
                        std::vector<Vec3d>* path, std::vector<SurfaceEvent>* events, std::vector<Vec3d>* curve = nullptr) {
  LensRay ray = in;
  TraceResult result;
  int previous = -1;
  // From the scene into the front element: through the hood's mouth first.
  if (count > 0 && visit(0).surface == 0 && visit(0).toward_film && !lens.PassesHood(ray.o, ray.d)) {
    result.failure = TraceFailure::kClipped;
    result.surface = -1;
    return result;
  }
  for (int k = 0; k < count; ++k) {
    const SurfaceVisit v = visit(k);
    const int i = v.surface;
    const SurfaceCrossing c = CrossSurface(lens, i, ray, lambda_nm, v.toward_film, kGradientTolerance, curve);
    if (c.failure == TraceFailure::kMissedSurface) {
      result.failure = c.failure;
      result.surface = i;
      return result;
    }
    if (path) path->push_back(c.p);
    if (c.failure != TraceFailure::kNone) {
      result.failure = c.failure;
      result.surface = i;
      return result;
    }
    // Absorption along the segment just travelled, inside the medium between the surfaces.
    if (previous >= 0) result.internal_transmittance *= SegmentTransmittance(lens, previous, i, lambda_nm, c.t);
    previous = i;
    result.dirt *= c.clean;
    if (c.mirror) {  // always reflects; the path goes on to the next surface in order
      if (v.reflect) {  // a ghost cannot pass through a mirror
        result.failure = TraceFailure::kMissedSurface;
        result.surface = i;
        return result;
      }
      result.surface_transmittance *= c.reflectance;
      ray = Reflected(c, c.d);
      continue;
    }
    if (!c.interface) {
      if (v.reflect) {  // nothing to reflect from
        result.failure = TraceFailure::kMissedSurface;
        result.surface = i;
        return result;
      }
      ray = Onward(c);
      continue;
    }
    if (events) events->push_back({i, c.reflectance, c.cos_i});
    if (v.reflect) {
      result.surface_transmittance *= c.reflectance;
      ray = Reflected(c, c.d);
      continue;
    }
    result.surface_transmittance *= 1 - c.reflectance;
    std::optional<LensRay> out = Refracted(c, c.d);
    if (!out) {
      result.failure = TraceFailure::kTotalInternalReflection;
      result.surface = i;
      return result;
    }
    ray = *out;
  }
  // Out of the front element toward the scene: through the hood's mouth last.
  if (count > 0 && visit(count - 1).surface == 0 && !visit(count - 1).toward_film && !visit(count - 1).reflect &&
      !lens.PassesHood(ray.o, ray.d)) {
    result.failure = TraceFailure::kClipped;
    result.surface = -1;
    return result;
  }
  result.ray = ray;
  return result;
}

TraceResult Trace(const LensSystem& lens, const LensRay& in, double lambda_nm, bool from_film,
                  std::vector<Vec3d>* path, std::vector<SurfaceEvent>* events, std::vector<Vec3d>* curve = nullptr) {
  const int n = lens.SurfaceCount();
  return TraceVisits(
      lens, in, lambda_nm, n, [&](int k) { return SurfaceVisit{from_film ? n - 1 - k : k, false, !from_film}; }, path,
      events, curve);
}

}  // namespace

TraceResult TraceFromObject(const LensSystem& lens, const LensRay& ray, double lambda_nm, std::vector<Vec3d>* path,
                            std::vector<SurfaceEvent>* events, std::vector<Vec3d>* curve) {
  return Trace(lens, ray, lambda_nm, false, path, events, curve);
}
TraceResult TraceFromFilm(const LensSystem& lens, const LensRay& ray, double lambda_nm, std::vector<Vec3d>* path,
                          std::vector<SurfaceEvent>* events) {
  return Trace(lens, ray, lambda_nm, true, path, events);
}

TraceResult TraceSequence(const LensSystem& lens, const LensRay& ray, double lambda_nm,
                          std::span<const SurfaceVisit> visits, std::vector<Vec3d>* path,
                          std::vector<SurfaceEvent>* events) {
  return TraceVisits(
      lens, ray, lambda_nm, int(visits.size()), [&](int k) { return visits[k]; }, path, events);
}

}  // namespace objektiv
