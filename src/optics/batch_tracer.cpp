#include "optics/batch_tracer.h"

#include <algorithm>
#include <cmath>

#include "optics/lens_tracer.h"

namespace objektiv {

void RayBatch::Resize(size_t n) {
  for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz, &lambda}) v->resize(n);
  transmittance.assign(n, 1.f);
  alive.assign(n, 1);
  wave_choices.assign(n, 0);
  extraordinary.assign(n, 0);
}

namespace {
constexpr float kTableMin = 360.f, kTableMax = 830.f;
constexpr int kTableSize = 471;  // 1 nm steps
// The coatings' reflectance tables: rows evenly spaced in wavenumber 1/lambda over 360..830 nm
// (a layer's phase is linear in it, so the interference ripples are evenly spaced), columns
// in cos(incidence) over 0..1. Bilinear interpolation in them stays within 3e-5 of the exact
// stack for the built-in coatings at cos(incidence) >= 0.5.
constexpr int kCoatRows = 96, kCoatColumns = 129;
constexpr float kWavenumberMin = 1 / kTableMax, kWavenumberMax = 1 / kTableMin;

// Surface i's reflectance (a coating's, or a metal mirror's) over the table's grid.
std::vector<float> TabulateReflectance(const LensSystem& lens, int i, bool toward_film) {
  std::vector<float> table(kCoatRows * kCoatColumns);
  for (int r = 0; r < kCoatRows; ++r) {
    const double lambda = 1 / (kWavenumberMin + (double(kWavenumberMax) - kWavenumberMin) * r / (kCoatRows - 1));
    for (int c = 0; c < kCoatColumns; ++c) {
      const double cos_i = double(c) / (kCoatColumns - 1);
      table[r * kCoatColumns + c] = float(lens.surface(i).mirror ? lens.MirrorReflectance(i, lambda, cos_i)
                                                                 : lens.SurfaceReflectance(i, lambda, cos_i, toward_film));
    }
  }
  return table;
}

// A coated surface's reflectance for a ray in table row `row` (CoatingRows: its wavelength's,
// `weight` the next row's share) at cos(incidence) `cos_i`: bilinear in the table. Clamped so
// that a dead ray's garbage (NaN too) still indexes it.
inline float TableReflectance(const float* __restrict table, int32_t row, float weight, float cos_i) {
  cos_i = cos_i > 0.f ? (cos_i < 1.f ? cos_i : 1.f) : 0.f;
  const float y = cos_i * float(kCoatColumns - 1) * (1 - 1e-6f);
  const int32_t c = int32_t(y);
  const float fy = y - float(c);
  const float* row0 = table + row + c;
  const float* row1 = row0 + kCoatColumns;
  const float lo = row0[0] + fy * (row0[1] - row0[0]), hi = row1[0] + fy * (row1[1] - row1[0]);
  return lo + weight * (hi - lo);
}
}  // namespace

BatchLensTracer::BatchLensTracer(const LensSystem& lens_system)
    : film_z_(float(lens_system.FilmZ())), stop_shape_(lens_system.stop_shape()), stop_semi_(float(lens_system.StopSemiDiameter())) {
  const LensPrescription& lens = lens_system.prescription();
  index_tables_.push_back(std::vector<float>(kTableSize, 1.f));  // air
  absorption_tables_.push_back(std::vector<float>(kTableSize, 0.f));
  // A medium's tables, once per distinct medium (a surface between equal media, as a stop
  // inside glass, then has the same on both sides and does not refract): its number, -1 for
  // air (tables[0]).
  auto medium_tables = [&](const Glass* glass) {
    if (!glass) return -1;
    std::vector<float> n(kTableSize), alpha(kTableSize);
    for (int l = 0; l < kTableSize; ++l) {
      n[l] = float(glass->Index(kTableMin + l));
      // Absorption coefficient per mm from the transmittance over 1 mm.
      alpha[l] = float(-std::log(std::max(glass->InternalTransmittance(kTableMin + l, 1.0), 1e-30)));
    }
    size_t m = 1;
    while (m < index_tables_.size() && (index_tables_[m] != n || absorption_tables_[m] != alpha)) ++m;
    if (m == index_tables_.size()) {
      absorbing_ |= *std::max_element(alpha.begin(), alpha.end()) > 0;
      index_tables_.push_back(std::move(n));
      absorption_tables_.push_back(std::move(alpha));
    }
    return int(m) - 1;
  };
  object_medium_ = medium_tables(lens.object_medium.get());
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    Surface f;
    f.z = float(lens_system.VertexZ(int(i)));
    f.c = float(s.Curvature());
    f.k1 = float(1 + s.conic);
    double semi = s.is_stop ? lens_system.StopSemiDiameter() : s.semi_diameter;
    f.semi2 = float(semi * semi);
    f.obscuration2 = float(s.obscuration * s.obscuration);
    f.mirror = s.mirror;
    f.reflectance = float(s.mirror_reflectance);
    f.cx = float(s.curvature_x);
    // A cylinder curved in x (a flat profile) or in y (flat in x, a conic profile).
    const bool profile_plain = !s.HasAsphericTerms();
    f.cylinder = s.toroidal && profile_plain && ((s.Curvature() == 0) != (s.curvature_x == 0));
    if (f.cylinder && s.Curvature() == 0) f.c = f.cx, f.k1 = 1, f.my = 0;
    else if (f.cylinder) f.mx = 0;
    f.toroid = s.toroidal && !f.cylinder;
    f.plane = f.c == 0 && !s.toroidal;
    f.aspheric = s.HasAsphericTerms() && !s.toroidal;
    f.is_stop = s.is_stop;
    if (s.placement) {
      const SurfacePlacement& pl = *s.placement;
      f.placed = true;
      const Vec3d origin = Vec3d(0, 0, lens_system.VertexZ(int(i))) + pl.offset;
      const Vec3d axes[3] = {pl.ex, pl.ey, pl.ez};
      for (int a = 0; a < 3; ++a) {
        f.axes[a][0] = float(axes[a].x), f.axes[a][1] = float(axes[a].y), f.axes[a][2] = float(axes[a].z);
      }
      f.origin[0] = float(origin.x), f.origin[1] = float(origin.y), f.origin[2] = float(origin.z);
      f.z = 0;  // the kernel works in the surface's frame
    }
    f.a2 = float(s.a2);
    for (int k = 0; k < 7; ++k) f.a[k] = float(s.aspheric[k]);
    if (s.fresnel || s.form_error) f.scalar = std::make_shared<const LensSurface>(s);
    if (s.forbes) {
      const std::vector<double>& b = s.forbes->chebyshev();
      f.q_count = int(b.size());
      for (size_t k = 0; k < b.size(); ++k) f.q[k] = float(b[k]);
      f.inv_rn2 = float(1 / (s.forbes->norm_radius() * s.forbes->norm_radius()));
      f.qbfs = s.forbes->kind() == ForbesAsphere::Kind::kBestFitSphere;
    }
    f.medium_after = -1;
    f.coating = -1;
    if (lens_system.Coated(int(i)) || s.mirror_metal) {
      f.coating = int(coating_tables_.size() / 2);
      coating_tables_.push_back(TabulateReflectance(lens_system, int(i), true));
      coating_tables_.push_back(TabulateReflectance(lens_system, int(i), false));
    }
    f.medium_after = medium_tables(s.medium.get());
    f.exact_step = s.gradient || s.crystal || (i > 0 && (lens.surfaces[i - 1].gradient || lens.surfaces[i - 1].crystal));
    f.dirt = s.dirt;
    surfaces_.push_back(f);
  }
  if (lens.HasGradients() || lens.CrystalCount() > 0) exact_ = std::make_shared<const LensSystem>(lens_system);
  hood_ = lens_system.hood();
  first_vertex_z_ = float(lens_system.VertexZ(0));
  for (const std::vector<float>& tab : index_tables_)
    constant_index_.push_back(std::all_of(tab.begin(), tab.end(), [&](float v) { return v == tab[0]; }));
}

void BatchLensTracer::IgnoreRims() {
  for (Surface& s : surfaces_)
    if (!s.is_stop) s.semi2 = INFINITY;
  hood_.reset();  // mechanical vignetting too
  if (exact_) {  // the same for the exact tracer's surfaces: rims far beyond any ray
    LensPrescription rimless = exact_->prescription();
    for (LensSurface& s : rimless.surfaces)
      if (!s.is_stop) s.semi_diameter = kMaxLensLength;
    LensSystem lens(std::move(rimless));
    lens.SetStopSemiDiameter(exact_->StopSemiDiameter());
    lens.SetStopShape(exact_->stop_shape());
    lens.SetBackFocus(exact_->BackFocus());
    exact_ = std::make_shared<const LensSystem>(std::move(lens));
  }
}

void BatchLensTracer::ClipAtHood(RayBatch& rays) const {
  for (size_t j = 0; j < rays.Size(); ++j)
    if (rays.alive[j] && !hood_->Passes(Vec3d(rays.ox[j], rays.oy[j], rays.oz[j]), Vec3d(rays.dx[j], rays.dy[j], rays.dz[j]),
                                        first_vertex_z_))
      rays.alive[j] = 0;
}

void BatchLensTracer::ExactStep(int i, bool from_film, bool transmission, bool absorb, RayBatch& rays) const {
  const LensSystem& lens = *exact_;
  const Surface& sf = surfaces_[size_t(i)];
  const bool is_stop = sf.is_stop && rays.record_stop;
  // A coating's reflectance from its table, as the kernel's (the exact thin-film stack was two
  // thirds of a crystal lens's set-up time); a bare surface's from Fresnel's equations.
  const float* coating = transmission && sf.coating >= 0 ? coating_tables_[2 * sf.coating + (from_film ? 1 : 0)].data() : nullptr;
  if (is_stop) rays.stop_x.resize(rays.Size()), rays.stop_y.resize(rays.Size());
  for (size_t j = 0; j < rays.Size(); ++j) {
    if (!rays.alive[j]) continue;
    const LensRay ray{Vec3d(rays.ox[j], rays.oy[j], rays.oz[j]), Normalize(Vec3d(rays.dx[j], rays.dy[j], rays.dz[j])),
                      bool(rays.extraordinary[j]), rays.wave_choices[j]};
    const double lambda = rays.lambda[j];
    const SurfaceCrossing c =
        CrossSurface(lens, i, ray, lambda, !from_film, kGradientRenderTolerance, nullptr, transmission && !coating);
    std::optional<LensRay> out = Onward(c);
    if (c.failure == TraceFailure::kNone && c.interface) out = Refracted(c, c.d);
    if (c.failure != TraceFailure::kNone || !out) {
      rays.alive[j] = 0;
      continue;
    }
    double w = c.clean;
    if (absorb) w *= SegmentTransmittance(lens, i, from_film ? i + 1 : i - 1, lambda, c.t);
    if (transmission && c.interface)
      w *= 1 - (coating ? TableReflectance(coating, rays.coat_row[j], rays.coat_weight[j], float(c.cos_i)) : c.reflectance);
    rays.transmittance[j] *= float(w);
    if (is_stop) {
      const Vec3d local = lens.InSurfaceFrame(i, c.p);
      rays.stop_x[j] = float(local.x), rays.stop_y[j] = float(local.y);
    }
    rays.ox[j] = float(out->o.x), rays.oy[j] = float(out->o.y), rays.oz[j] = float(out->o.z);
    rays.dx[j] = float(out->d.x), rays.dy[j] = float(out->d.y), rays.dz[j] = float(out->d.z);
    rays.extraordinary[j] = out->extraordinary, rays.wave_choices[j] = out->wave_choices;
  }
}

void BatchLensTracer::TraceFromFilm(RayBatch& rays, bool transmission) const { Trace(rays, true, transmission); }
void BatchLensTracer::TraceFromObject(RayBatch& rays, bool transmission) const { Trace(rays, false, transmission); }

namespace {

// Per-surface constants of the kernel, and the tables of the media on both sides.
struct Step {
  float z, c, k1, semi2, obscuration2, reflectance, cx, mx, my, a2, a[7];
  // A Q-type asphere's sum as Chebyshev coefficients (Surface::q), 1 / r_n^2, Qbfs or Qcon.
  float q[ForbesAsphere::kMaxTerms];
  int q_count;
  float inv_rn2;
  bool qbfs;
  const LensSurface* scalar;  // a surface traced one ray at a time (Surface::scalar), else null
  // Per ray (contiguous, one value per ray of the batch): the media's indices on both sides
  // and the absorption coefficient of the medium just crossed (air: ones and zeros).
  const float *n_in, *n_out, *alpha_in;
  const float* coating;  // the coating's reflectance table for this direction (null: bare)
};

// Each ray's row in the coatings' tables (its wavelength's), and the next row's weight.
void CoatingRows(RayBatch& b) {
  const size_t n = b.Size();
  b.coat_row.resize(n);
  b.coat_weight.resize(n);
  b.coat_cos.resize(n);
  for (size_t j = 0; j < n; ++j) {
    const float x = std::min(std::max((1 / b.lambda[j] - kWavenumberMin) * (float(kCoatRows - 1) / (kWavenumberMax - kWavenumberMin)), 0.f),
                             float(kCoatRows - 1) - 1e-3f);
    b.coat_row[j] = int32_t(x) * kCoatColumns;
    b.coat_weight[j] = x - float(int32_t(x));
  }
}

// The coated surface's transmittance, 1 - R (a metal mirror's reflectance R), for every ray at
// the cos(incidence) the kernel left in coat_cos: bilinear in the surface's table (a separate
// loop: the kernel's stays vectorised without the table's gathers).
void ApplyCoating(const float* __restrict table, RayBatch& b, bool mirror) {
  const float sign = mirror ? -1.f : 1.f, offset = mirror ? 0.f : 1.f;
  const size_t n = b.Size();
  const int32_t* __restrict rows = b.coat_row.data();
  const float* __restrict weights = b.coat_weight.data();
  const float* __restrict cosines = b.coat_cos.data();
  float* __restrict trans = b.transmittance.data();
  for (size_t j = 0; j < n; ++j) trans[j] *= offset - sign * TableReflectance(table, rows[j], weights[j], cosines[j]);
}

// Which terms a surface of revolution adds to its conic; kScalar: a surface no kernel traces
// (a Fresnel surface, a form error), met one ray at a time by the exact tracer's intersection.
enum class Asphere { kNone, kEven, kQType, kScalar };

// Such a surface's crossing for one ray of the batch (o relative to the vertex): its t and the
// surface's gradient there; `ok` cleared where the ray misses it or meets a Fresnel riser.
void ScalarCrossing(const LensSurface& surface, float x0, float y0, float z0, float dx, float dy, float dz, float& t,
                    float& gx, float& gy, bool& ok) {
  t = 0, gx = gy = 0;
  if (!ok) return;
  const Vec3d o(x0, y0, z0), d(dx, dy, dz);
  bool blocked = false;
  const std::optional<double> hit = IntersectSurface(surface, o, d, blocked);
  const Vec3d p = o + d * hit.value_or(0.0);
  double z, sx, sy;
  if (!hit || blocked || !surface.SagAt(p.x, p.y, z, &sx, &sy)) {
    ok = false;
    return;
  }
  t = float(*hit), gx = float(sx), gy = float(sy);
}

// A surface of revolution's sag at radius r (r2 = r^2) and its slope dz/dr in single precision
// (LensSurface::Sag, SagSlope): the conic, the r^2 term and either the even terms a4..a16 or a
// Q-type departure (optics/forbes_asphere.h; a Qbfs surface's conic is 0, so the conic's root
// is its sqrt(1 - c^2 r^2)).
template <Asphere kAsphere>
inline void AsphereSag(const Step& s, float r2, float r, float& sag, float& slope) {
  const float root = std::sqrt(std::max(1 - s.k1 * s.c * s.c * r2, 1e-12f));
  sag = s.c * r2 / (1 + root) + s.a2 * r2, slope = s.c * r / root + 2 * s.a2 * r;
  if constexpr (kAsphere == Asphere::kEven) {
    float rp = r2 * r2, rd = r2 * r;
#pragma GCC unroll 7
    for (int a = 0; a < 7; ++a) {
      sag += s.a[a] * rp;
      slope += float(4 + 2 * a) * s.a[a] * rd;
      rp *= r2;
      rd *= r2;
    }
  } else if constexpr (kAsphere == Asphere::kQType) {
    const float x = r2 * s.inv_rn2, dx_dr = 2 * r * s.inv_rn2;
    float q, dq_dt;
    ChebyshevSum(s.q, s.q_count, 2 * x - 1, q, dq_dt);
    const float dq = 2 * dq_dt;
    if (s.qbfs) {
      const float w = x * (1 - x);
      sag += w * q / root;
      slope += ((1 - 2 * x) * q + w * dq) * dx_dr / root + w * q * s.c * s.c * r / (root * root * root);
    } else {
      sag += x * x * q;
      slope += (2 * x * q + x * x * dq) * dx_dr;
    }
  }
}

// A toroid's sag at (x, y) and its gradient (LensSurface::SagAt in single precision): the
// profile z_y(|y|), then z = z_y + x^2 e / (1 + q), e = c_x / (1 - c_x z_y) (1 / the x-z
// circle's radius), q = sqrt(1 - x^2 e^2); dz/dx = x e / q, dz/dy = z_y' / q. `ok` is cleared
// outside the surface (where the square roots' arguments were clamped).
inline void ToroidSag(const Step& s, float x, float y, float& z, float& gx, float& gy, bool& ok) {
  const float y2 = y * y, ay = std::abs(y);
  ok &= 1 - s.k1 * s.c * s.c * y2 > 0;
  float zy, slope;  // the profile, a conic with even terms, at |y|
  AsphereSag<Asphere::kEven>(s, y2, ay, zy, slope);
  const float u = 1 - s.cx * zy;
  ok &= u > 0;
  const float e = s.cx / std::max(u, 1e-12f);
  const float q2 = 1 - x * x * e * e;
  ok &= q2 > 0;
  const float q = std::sqrt(std::max(q2, 1e-12f));
  z = zy + x * x * e / (1 + q);
  gx = x * e / q;
  gy = (y < 0 ? -slope : slope) / q;
}

// kRefract: an interface between two media; kMirror: a mirror (reflects); neither: the ray
// only meets the surface (a stop or a plane between equal media), which may clip it.
// kToroid: a toroid (kPlane false, kAsphere kNone), met by Newton's method from the vertex plane;
// a cylinder is the conic's kernel with one coordinate's terms masked out (Step::mx, my).
template <bool kPlane, Asphere kAsphere, bool kToroid, bool kCylinder, bool kRefract, bool kMirror, bool kTransmission,
          bool kCoated>
void StepAll(const Step& s, RayBatch& b) {
  const size_t n = b.Size();
  float* __restrict ox = b.ox.data();
  float* __restrict oy = b.oy.data();
  float* __restrict oz = b.oz.data();
  float* __restrict dxs = b.dx.data();
  float* __restrict dys = b.dy.data();
  float* __restrict dzs = b.dz.data();
  float* __restrict trans = b.transmittance.data();
  float* __restrict depth = b.depth.data();
  uint8_t* __restrict alive = b.alive.data();
  [[maybe_unused]] float* __restrict coat_cos = b.coat_cos.data();
  const float* __restrict n_in = s.n_in;
  const float* __restrict n_out = s.n_out;
  const float* __restrict alpha_in = s.alpha_in;
#pragma omp simd
  for (size_t j = 0; j < n; ++j) {
    const float x0 = ox[j], y0 = oy[j], z0 = oz[j] - s.z;
    const float dx = dxs[j], dy = dys[j], dz = dzs[j];
    bool ok = alive[j] != 0;
    float t;
    [[maybe_unused]] float tgx = 0, tgy = 0;  // a toroid's gradient at the crossing
    if constexpr (kAsphere == Asphere::kScalar) {
      ScalarCrossing(*s.scalar, x0, y0, z0, dx, dy, dz, t, tgx, tgy, ok);
    } else if constexpr (kToroid) {
      t = -z0 / dz;
      float z, gx, gy;
#pragma GCC unroll 8
      for (int it = 0; it < 8; ++it) {
        bool inside = true;
        ToroidSag(s, x0 + t * dx, y0 + t * dy, z, gx, gy, inside);
        t -= (z0 + t * dz - z) / (dz - gx * dx - gy * dy);
      }
      // The last step's residual decides: the crossing must be on the surface.
      ToroidSag(s, x0 + t * dx, y0 + t * dy, z, tgx, tgy, ok);
      ok &= std::abs(z0 + t * dz - z) <= 1e-4f * (1 + std::abs(z));
    } else if constexpr (kPlane) {
      t = -z0 / dz;
    } else {
      // The conic through the vertex; C / q is the root on the vertex's sheet. (mx, my: 1 but
      // for a cylinder.)
      const float mx = kCylinder ? s.mx : 1.f, my = kCylinder ? s.my : 1.f;  // no multiply but for a cylinder
      float A = s.c * (mx * dx * dx + my * dy * dy) + s.k1 * s.c * dz * dz;
      float B = 2 * (s.c * (mx * x0 * dx + my * y0 * dy) + s.k1 * s.c * z0 * dz - dz);
      float C = s.c * (mx * x0 * x0 + my * y0 * y0) + s.k1 * s.c * z0 * z0 - 2 * z0;
      float disc = B * B - 4 * A * C;
      ok &= disc >= 0;
      float root = std::sqrt(std::max(disc, 0.f));
      // As the double tracer: the first positive root on the vertex's sheet ((1 + k) c z <= 1).
      float q = -0.5f * (B + (B >= 0 ? root : -root));
      float t1 = C / q, t2 = q / A;  // q or A zero: an infinity or NaN, rejected below
      bool ok1 = (t1 > -1e-6f) & (s.k1 * s.c * (z0 + t1 * dz) <= 1);
      bool ok2 = (t2 > -1e-6f) & (s.k1 * s.c * (z0 + t2 * dz) <= 1);
      ok &= ok1 | ok2;
      t = (ok1 & ok2) ? std::min(t1, t2) : (ok1 ? t1 : t2);
    }
    if constexpr (kAsphere == Asphere::kEven || kAsphere == Asphere::kQType) {
      // Newton on z(t) - sag(r(t)) from the conic's intersection (a fixed count of steps).
#pragma GCC unroll 6
      for (int it = 0; it < 6; ++it) {
        float px = x0 + t * dx, py = y0 + t * dy, pz = z0 + t * dz;
        float r2 = px * px + py * py, r = std::sqrt(r2);
        float sag, slope;
        AsphereSag<kAsphere>(s, r2, r, sag, slope);
        float drdt = (px * dx + py * dy) / std::max(r, 1e-30f);
        t -= (pz - sag) / (dz - slope * drdt);
      }
    }
    ok &= t >= -1e-6f;
    const float px = x0 + t * dx, py = y0 + t * dy, pz = z0 + t * dz;
    const float r2 = px * px + py * py;
    ok &= (r2 <= s.semi2) & (r2 >= s.obscuration2);
    // Absorption in the medium just crossed: its optical depth, summed (one exp at the end).
    if constexpr (kTransmission) depth[j] += alpha_in[j] * t;
    ox[j] = px, oy[j] = py, oz[j] = pz + s.z;
    if constexpr (kRefract || kMirror) {
      // Normal from the sag's slope (unit, toward +z), turned to face the incoming ray.
      float nx, ny, nz = 1;
      if constexpr (kToroid || kAsphere == Asphere::kScalar) {
        nx = -tgx, ny = -tgy;
      } else if constexpr (kCylinder) {
        // The implicit form's gradient: (-c mx x, -c my y, 1 - k1 c z).
        nx = -s.c * s.mx * px, ny = -s.c * s.my * py, nz = 1 - s.k1 * s.c * pz;
      } else {
        float r = std::sqrt(r2);
        float slope;
        if constexpr (kAsphere != Asphere::kNone) {
          float sag;
          AsphereSag<kAsphere>(s, r2, r, sag, slope);
        } else {
          slope = s.c * r / std::sqrt(std::max(1 - s.k1 * s.c * s.c * r2, 1e-12f)) + 2 * s.a2 * r;
        }
        float inv_r = 1 / std::max(r, 1e-30f);
        nx = -slope * px * inv_r, ny = -slope * py * inv_r;
      }
      float inv = 1 / std::sqrt(nx * nx + ny * ny + nz * nz);
      nx *= inv, ny *= inv, nz *= inv;
      float cos_i = -(nx * dx + ny * dy + nz * dz);
      float flip = cos_i < 0 ? -1.f : 1.f;
      nx *= flip, ny *= flip, nz *= flip, cos_i *= flip;
      if constexpr (kMirror) {
        dxs[j] = dx + 2 * cos_i * nx, dys[j] = dy + 2 * cos_i * ny, dzs[j] = dz + 2 * cos_i * nz;
        if constexpr (kTransmission && kCoated) coat_cos[j] = cos_i;  // a metal: ApplyCoating
        else if constexpr (kTransmission) trans[j] *= s.reflectance;
      } else {
        const float n1 = n_in[j], n2 = n_out[j];
        float eta = n1 / n2, k2 = 1 - eta * eta * (1 - cos_i * cos_i);
        ok &= k2 >= 0;
        float cos_t = std::sqrt(std::max(k2, 0.f)), g = eta * cos_i - cos_t;
        float ex = eta * dx + g * nx, ey = eta * dy + g * ny, ez = eta * dz + g * nz;
        float dl = 1 / std::sqrt(ex * ex + ey * ey + ez * ez);
        dxs[j] = ex * dl, dys[j] = ey * dl, dzs[j] = ez * dl;
        if constexpr (kTransmission && kCoated) {
          coat_cos[j] = cos_i;  // ApplyCoating looks the transmittance up
        } else if constexpr (kTransmission) {
          float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
          float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
          trans[j] *= 1 - 0.5f * (rs * rs + rp * rp);
        }
      }
    }
    alive[j] = ok;
  }
}

template <bool kPlane, Asphere kAsphere, bool kToroid, bool kCylinder, bool kRefract, bool kMirror>
void StepAll(const Step& s, bool transmission, RayBatch& b) {
  if (!transmission) StepAll<kPlane, kAsphere, kToroid, kCylinder, kRefract, kMirror, false, false>(s, b);
  else if ((kRefract || kMirror) && s.coating) StepAll<kPlane, kAsphere, kToroid, kCylinder, kRefract, kMirror, true, true>(s, b);
  else StepAll<kPlane, kAsphere, kToroid, kCylinder, kRefract, kMirror, true, false>(s, b);
}

// The kernel for a surface's shape and what it does to the ray.
template <bool kPlane, Asphere kAsphere, bool kToroid = false, bool kCylinder = false>
void StepShape(const Step& s, bool refract, bool mirror, bool transmission, RayBatch& b) {
  if (mirror) StepAll<kPlane, kAsphere, kToroid, kCylinder, false, true>(s, transmission, b);
  else if (refract) StepAll<kPlane, kAsphere, kToroid, kCylinder, true, false>(s, transmission, b);
  else StepAll<kPlane, kAsphere, kToroid, kCylinder, false, false>(s, transmission, b);
}

// A rigid motion of every ray of the batch: p -> m (p - before) + after, d -> m d (the matrix
// and the batch's arrays as locals and restricted pointers: the loop vectorises).
void MoveRays(const float (&m)[3][3], const float (&before)[3], const float (&after)[3], RayBatch& b) {
  const size_t n = b.Size();
  const float m00 = m[0][0], m01 = m[0][1], m02 = m[0][2], m10 = m[1][0], m11 = m[1][1], m12 = m[1][2], m20 = m[2][0],
              m21 = m[2][1], m22 = m[2][2];
  const float b0 = before[0], b1 = before[1], b2 = before[2], a0 = after[0], a1 = after[1], a2 = after[2];
  float *__restrict ox = b.ox.data(), *__restrict oy = b.oy.data(), *__restrict oz = b.oz.data();
  float *__restrict dx = b.dx.data(), *__restrict dy = b.dy.data(), *__restrict dz = b.dz.data();
#pragma omp simd
  for (size_t j = 0; j < n; ++j) {
    const float x = ox[j] - b0, y = oy[j] - b1, z = oz[j] - b2;
    ox[j] = a0 + m00 * x + m01 * y + m02 * z;
    oy[j] = a1 + m10 * x + m11 * y + m12 * z;
    oz[j] = a2 + m20 * x + m21 * y + m22 * z;
    const float u = dx[j], v = dy[j], w = dz[j];
    dx[j] = m00 * u + m01 * v + m02 * w;
    dy[j] = m10 * u + m11 * v + m12 * w;
    dz[j] = m20 * u + m21 * v + m22 * w;
  }
}

}  // namespace

void BatchLensTracer::ToSurfaceFrame(const Surface& s, RayBatch& b) {
  static constexpr float kZero[3] = {0, 0, 0};
  MoveRays(s.axes, s.origin, kZero, b);
}

void BatchLensTracer::FromSurfaceFrame(const Surface& s, RayBatch& b) {
  static constexpr float kZero[3] = {0, 0, 0};
  float transposed[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) transposed[r][c] = s.axes[c][r];
  MoveRays(transposed, kZero, s.origin, b);
}

void BatchLensTracer::Trace(RayBatch& rays, bool from_film, bool transmission) const {
  const size_t count = rays.Size();
  if (count == 0) return;  // e.g. a pixel outside a fisheye's image circle: no sample starts a ray
  // Each medium's index and absorption at each ray's wavelength, once for all surfaces (the
  // kernel then reads them as contiguous arrays, which vectorises better than table lookups).
  const size_t media = index_tables_.size();
  const bool absorbing = transmission && absorbing_;
  // Linear interpolation of a 1 nm table at every ray's wavelength.
  auto interpolate = [&](const std::vector<float>& tab, float* out) {
    for (size_t j = 0; j < count; ++j) {
      float x = std::min(std::max(rays.lambda[j] - kTableMin, 0.f), kTableMax - kTableMin - 1e-3f);
      int i0 = int(x);
      out[j] = tab[i0] + (x - float(i0)) * (tab[i0 + 1] - tab[i0]);
    }
  };
  rays.media_index.resize(media * count);
  for (size_t m = 0; m < media; ++m) {
    float* out = rays.media_index.data() + m * count;
    if (constant_index_[m]) std::fill(out, out + count, index_tables_[m][0]);
    else interpolate(index_tables_[m], out);
  }
  // Absorption coefficients only when some glass absorbs (else one block of zeros, air's).
  rays.media_alpha.assign((absorbing ? media : 1) * count, 0.f);
  if (absorbing)
    for (size_t m = 1; m < media; ++m) interpolate(absorption_tables_[m], rays.media_alpha.data() + m * count);
  rays.depth.assign(count, 0.f);
  const bool coated = transmission && !coating_tables_.empty();
  if (coated) CoatingRows(rays);
  if (hood_ && !from_film) ClipAtHood(rays);  // from the scene: through the hood's mouth first
  const int n = int(surfaces_.size());
  for (int k = 0; k < n; ++k) {
    const int i = from_film ? n - 1 - k : k;
    const Surface& sf = surfaces_[i];
    // Media on the incoming and outgoing sides of surface i, in the direction of travel.
    const int object_side = i > 0 ? surfaces_[i - 1].medium_after : object_medium_, film_side = sf.medium_after;
    const int m_in = from_film ? film_side : object_side, m_out = from_film ? object_side : film_side;
    // Air is medium 0 (index one, no absorption); the ray starts in air (no absorption before
    // the first surface).
    const bool absorb = k > 0;
    if (sf.exact_step) {
      ExactStep(i, from_film, transmission, absorb && transmission, rays);
      continue;
    }
    Step st{sf.z, sf.c, sf.k1, sf.semi2, sf.obscuration2, sf.reflectance, sf.cx, sf.mx, sf.my, sf.a2, {}, {},
            sf.q_count, sf.inv_rn2, sf.qbfs, sf.scalar.get(),
            rays.media_index.data() + (m_in + 1) * count,
            rays.media_index.data() + (m_out + 1) * count,
            rays.media_alpha.data() + (absorb && absorbing ? m_in + 1 : 0) * count,
            sf.coating < 0 ? nullptr : coating_tables_[2 * sf.coating + (from_film ? 1 : 0)].data()};
    std::copy(sf.a, sf.a + 7, st.a);
    std::copy(sf.q, sf.q + sf.q_count, st.q);
    const bool refract = m_in != m_out && !sf.mirror;  // the stop too, where it parts two media
    if (sf.placed) ToSurfaceFrame(sf, rays);
    if (sf.scalar) StepShape<false, Asphere::kScalar>(st, refract, sf.mirror, transmission, rays);
    else if (sf.toroid) StepShape<false, Asphere::kNone, true>(st, refract, sf.mirror, transmission, rays);
    else if (sf.cylinder) StepShape<false, Asphere::kNone, false, true>(st, refract, sf.mirror, transmission, rays);
    else if (sf.plane) StepShape<true, Asphere::kNone>(st, refract, sf.mirror, transmission, rays);
    else if (sf.q_count > 0) StepShape<false, Asphere::kQType>(st, refract, sf.mirror, transmission, rays);
    else if (sf.aspheric) StepShape<false, Asphere::kEven>(st, refract, sf.mirror, transmission, rays);
    else StepShape<false, Asphere::kNone>(st, refract, sf.mirror, transmission, rays);
    if (coated && (refract || sf.mirror) && st.coating) ApplyCoating(st.coating, rays, sf.mirror);
    if (sf.dirt && transmission)  // what dust and scratches let through where each ray met the surface (its frame)
      for (size_t j = 0; j < count; ++j)
        if (rays.alive[j]) rays.transmittance[j] *= float(sf.dirt->Transmittance(rays.ox[j], rays.oy[j]));
    if (sf.is_stop) {
      if (rays.record_stop) {
        rays.stop_x.assign(rays.ox.begin(), rays.ox.end());
        rays.stop_y.assign(rays.oy.begin(), rays.oy.end());
      }
      // Any other opening: the circle was tested above, the rest here.
      if (!stop_shape_.IsRound()) {
        const float inv = 1 / stop_semi_;
        for (size_t j = 0; j < count; ++j)
          if (rays.alive[j] && !stop_shape_.Contains(rays.ox[j] * inv, rays.oy[j] * inv)) rays.alive[j] = 0;
      }
    }
    if (sf.placed) FromSurfaceFrame(sf, rays);
  }
  if (hood_ && from_film) ClipAtHood(rays);  // toward the scene: through the hood's mouth last
  if (absorbing)
    for (size_t j = 0; j < count; ++j) rays.transmittance[j] *= std::exp(-rays.depth[j]);
}

}  // namespace objektiv
