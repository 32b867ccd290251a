#include "optics/batch_tracer.h"

#include <cmath>

namespace objektiv {

void RayBatch::Resize(size_t n) {
  for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz, &lambda}) v->resize(n);
  transmittance.assign(n, 1.f);
  alive.assign(n, 1);
}

void RayBatch::Push(const FloatRay& r) {
  ox.push_back(r.ox), oy.push_back(r.oy), oz.push_back(r.oz);
  dx.push_back(r.dx), dy.push_back(r.dy), dz.push_back(r.dz);
  lambda.push_back(r.lambda);
  transmittance.push_back(r.transmittance);
  alive.push_back(1);
}

FloatRay RayBatch::Get(size_t i) const {
  return {ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], lambda[i], transmittance[i]};
}

namespace {
constexpr float kTableMin = 360.f, kTableMax = 830.f;
constexpr int kTableSize = 471;  // 1 nm steps
}  // namespace

BatchLensTracer::BatchLensTracer(const LensTracer& tracer)
    : film_z_(float(tracer.FilmZ())), shape_(tracer), bladed_(tracer.StopIsBladed()) {
  const LensPrescription& lens = tracer.lens();
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    Surface f;
    f.z = float(tracer.VertexZ(int(i)));
    f.c = float(s.Curvature());
    f.k1 = float(1 + s.conic);
    double semi = s.is_stop ? tracer.StopSemiDiameter() : s.semi_diameter;
    f.semi2 = float(semi * semi);
    f.plane = f.c == 0;
    f.aspheric = s.HasAsphericTerms();
    f.is_stop = s.is_stop;
    f.a2 = float(s.a2);
    for (int k = 0; k < 7; ++k) f.a[k] = float(s.aspheric[k]);
    f.medium_after = -1;
    if (s.medium) {
      std::vector<float> n(kTableSize), alpha(kTableSize);
      for (int l = 0; l < kTableSize; ++l) {
        n[l] = float(s.medium->Index(kTableMin + l));
        // Absorption coefficient per mm from the transmittance over 1 mm.
        alpha[l] = float(-std::log(std::max(s.medium->InternalTransmittance(kTableMin + l, 1.0), 1e-30)));
      }
      f.medium_after = int(index_tables_.size());
      index_tables_.push_back(std::move(n));
      absorption_tables_.push_back(std::move(alpha));
    }
    surfaces_.push_back(f);
  }
}

namespace {
// Linear interpolation in a table at 1 nm from kTableMin.
float Lookup(const std::vector<float>& tab, float lambda) {
  float x = std::min(std::max(lambda - kTableMin, 0.f), kTableMax - kTableMin - 1e-3f);
  int i = int(x);
  float t = x - float(i);
  return tab[i] + t * (tab[i + 1] - tab[i]);
}
}  // namespace

float BatchLensTracer::Index(int medium, float lambda) const {
  return medium < 0 ? 1.f : Lookup(index_tables_[medium], lambda);
}

float BatchLensTracer::Absorption(int medium, float lambda) const {
  return medium < 0 ? 0.f : Lookup(absorption_tables_[medium], lambda);
}

void BatchLensTracer::IgnoreRims() {
  for (Surface& s : surfaces_)
    if (!s.is_stop) s.semi2 = INFINITY;
}

void BatchLensTracer::TraceFromFilm(RayBatch& rays, bool transmission) const { Trace(rays, true, transmission); }
void BatchLensTracer::TraceFromObject(RayBatch& rays, bool transmission) const { Trace(rays, false, transmission); }

// Moves the ray to surface s and refracts it there (media m_in -> m_out in the direction of
// travel); false if it misses, is clipped or is totally reflected. Absorption in m_in is
// counted from the ray's origin unless this is the first surface (the ray starts on the film
// or in front of the lens, in air).
__attribute__((always_inline)) inline bool BatchLensTracer::Refract(const Surface& s, int m_in, int m_out, bool absorb, bool transmission,
                              FloatRay& ray) const {
  float ox = ray.ox, oy = ray.oy, oz = ray.oz - s.z;
  float dx = ray.dx, dy = ray.dy, dz = ray.dz;
  float t;
  if (s.plane) {
    t = -oz / dz;
  } else {
    // The conic through the vertex; C / q is the root on the vertex's sheet.
    float A = s.c * (dx * dx + dy * dy) + s.k1 * s.c * dz * dz;
    float B = 2 * (s.c * (ox * dx + oy * dy) + s.k1 * s.c * oz * dz - dz);
    float C = s.c * (ox * ox + oy * oy) + s.k1 * s.c * oz * oz - 2 * oz;
    float disc = B * B - 4 * A * C;
    if (disc < 0) return false;
    // As the double tracer: the first positive root on the vertex's sheet ((1 + k) c z <= 1).
    float q = -0.5f * (B + std::copysign(std::sqrt(disc), B));
    float t1 = q != 0 ? C / q : INFINITY, t2 = A != 0 ? q / A : INFINITY;
    bool ok1 = t1 > -1e-6f && s.k1 * s.c * (oz + t1 * dz) <= 1;
    bool ok2 = t2 > -1e-6f && s.k1 * s.c * (oz + t2 * dz) <= 1;
    if (!ok1 && !ok2) return false;
    t = ok1 && ok2 ? std::min(t1, t2) : (ok1 ? t1 : t2);
  }
  if (s.aspheric) {
    // Newton on z(t) - sag(r(t)) from the conic's intersection.
    for (int it = 0; it < 8; ++it) {
      float px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
      float r2 = px * px + py * py, r = std::sqrt(r2);
      float arg = std::max(1 - s.k1 * s.c * s.c * r2, 1e-12f);
      float root = std::sqrt(arg);
      float sag = s.c * r2 / (1 + root) + s.a2 * r2, slope = s.c * r / root + 2 * s.a2 * r;
      float rp = r2 * r2, rd = r2 * r;
      for (int a = 0; a < 7; ++a) {
        sag += s.a[a] * rp;
        slope += float(4 + 2 * a) * s.a[a] * rd;
        rp *= r2;
        rd *= r2;
      }
      float drdt = r > 0 ? (px * dx + py * dy) / r : 0.f;
      float step = (pz - sag) / (dz - slope * drdt);
      t -= step;
      if (std::abs(step) < 1e-7f) break;
    }
  }
  if (!(t >= -1e-6f)) return false;
  float px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
  float r2 = px * px + py * py;
  if (r2 > s.semi2 || (s.is_stop && bladed_ && !shape_.InsideStop(px, py))) return false;
  if (transmission && absorb) ray.transmittance *= std::exp(-Absorption(m_in, ray.lambda) * t);
  ray.ox = px;
  ray.oy = py;
  ray.oz = pz + s.z;
  if (s.is_stop || m_in == m_out) return true;
  // Normal from the sag's slope (unit, toward +z), turned to face the incoming ray.
  float r = std::sqrt(r2);
  float slope = 0;
  if (r > 0) {
    slope = s.c * r / std::sqrt(std::max(1 - s.k1 * s.c * s.c * r2, 1e-12f)) + 2 * s.a2 * r;
    if (s.aspheric) {
      float rd = r2 * r;
      for (int a = 0; a < 7; ++a) {
        slope += float(4 + 2 * a) * s.a[a] * rd;
        rd *= r2;
      }
    }
  }
  float nx = r > 0 ? -slope * px / r : 0.f, ny = r > 0 ? -slope * py / r : 0.f, nz = 1;
  float inv = 1 / std::sqrt(nx * nx + ny * ny + nz * nz);
  nx *= inv, ny *= inv, nz *= inv;
  float cos_i = -(nx * dx + ny * dy + nz * dz);
  if (cos_i < 0) nx = -nx, ny = -ny, nz = -nz, cos_i = -cos_i;
  float n1 = Index(m_in, ray.lambda), n2 = Index(m_out, ray.lambda);
  float eta = n1 / n2, k2 = 1 - eta * eta * (1 - cos_i * cos_i);
  if (k2 < 0) return false;
  float cos_t = std::sqrt(k2), g = eta * cos_i - cos_t;
  dx = eta * dx + g * nx, dy = eta * dy + g * ny, dz = eta * dz + g * nz;
  float dl = 1 / std::sqrt(dx * dx + dy * dy + dz * dz);
  ray.dx = dx * dl, ray.dy = dy * dl, ray.dz = dz * dl;
  if (transmission) {
    float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    ray.transmittance *= 1 - 0.5f * (rs * rs + rp * rp);
  }
  return true;
}

void BatchLensTracer::Trace(RayBatch& rays, bool from_film, bool transmission) const {
  // Surfaces in the outer loop: every ray takes the same branches in turn, which runs about
  // twice as fast as tracing each ray through the whole lens.
  const int n = int(surfaces_.size());
  for (int k = 0; k < n; ++k) {
    const int i = from_film ? n - 1 - k : k;
    const int object_side = i > 0 ? surfaces_[i - 1].medium_after : -1, film_side = surfaces_[i].medium_after;
    const int m_in = from_film ? film_side : object_side, m_out = from_film ? object_side : film_side;
    for (size_t j = 0; j < rays.Size(); ++j) {
      if (!rays.alive[j]) continue;
      FloatRay r = rays.Get(j);
      rays.alive[j] = Refract(surfaces_[i], m_in, m_out, k > 0, transmission, r);
      rays.ox[j] = r.ox, rays.oy[j] = r.oy, rays.oz[j] = r.oz;
      rays.dx[j] = r.dx, rays.dy[j] = r.dy, rays.dz[j] = r.dz;
      rays.transmittance[j] = r.transmittance;
    }
  }
}

bool BatchLensTracer::TraceRay(FloatRay& ray, bool from_film, bool transmission) const {
  const int n = int(surfaces_.size());
  for (int k = 0; k < n; ++k) {
    const int i = from_film ? n - 1 - k : k;
    const int object_side = i > 0 ? surfaces_[i - 1].medium_after : -1, film_side = surfaces_[i].medium_after;
    if (!Refract(surfaces_[i], from_film ? film_side : object_side, from_film ? object_side : film_side, k > 0,
                 transmission, ray))
      return false;
  }
  return true;
}

}  // namespace objektiv
