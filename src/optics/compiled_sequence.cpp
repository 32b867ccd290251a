#include "optics/compiled_sequence.h"

#include <algorithm>
#include <cmath>

#include "base/fresnel_dielectric.h"

namespace objektiv {

namespace {

// What CrossSurface traces beyond a centred surface between homogeneous isotropic media.
bool Plain(const LensSurface& s) {
  return !s.placement && !s.fresnel && !s.toroidal && !s.form_error && !s.gradient && !s.crystal && !s.mirror;
}

}  // namespace

std::optional<CompiledSequence> CompiledSequence::Compile(const LensSystem& lens, std::span<const SurfaceVisit> visits,
                                                          double lambda_nm, std::span<const double> bands,
                                                          const CoatingTables* tables, bool losses) {
  if (lens.hood() || bands.size() > size_t(kMaxBands)) return std::nullopt;
  CompiledSequence c;
  c.lens_ = &lens;
  c.lambda_ = lambda_nm;
  c.losses_ = losses;
  c.band_count_ = losses ? int(bands.size()) : 0;
  std::copy(bands.begin(), bands.end(), c.bands_.begin());
  if (tables && std::equal(bands.begin(), bands.end(), tables->wavelengths().begin(), tables->wavelengths().end()))
    c.tables_ = tables;
  int previous = -1;
  for (const SurfaceVisit& v : visits) {
    const LensSurface& s = lens.surface(v.surface);
    // The medium before the surface too (a gradient or a crystal there bends the ray into it).
    if (!Plain(s) || (v.surface > 0 && !Plain(lens.surface(v.surface - 1)))) return std::nullopt;
    Step step;
    step.surface = &s;
    step.index = v.surface;
    step.vertex_z = lens.VertexZ(v.surface);
    step.reflect = v.reflect, step.toward_film = v.toward_film;
    step.is_stop = s.is_stop;
    step.n_object = lens.prescription().IndexBefore(size_t(v.surface), lambda_nm);
    step.n_film = s.IndexAfter(lambda_nm);
    step.interface = step.n_object != step.n_film;
    step.eta = v.toward_film ? step.n_object / step.n_film : step.n_film / step.n_object;
    step.tabulated = c.tables_ && c.tables_->Has(v.surface);
    step.semi_diameter2 = s.semi_diameter * s.semi_diameter, step.obscuration2 = s.obscuration * s.obscuration;
    step.conic = !s.HasAsphericTerms();
    step.c = s.Curvature(), step.k1 = 1 + s.conic;
    step.bare = !lens.Coated(v.surface);
    step.alpha = 0;
    const Glass* medium = previous >= 0 ? lens.surface(std::min(previous, v.surface)).medium.get() : nullptr;
    if (medium) step.alpha = medium->AbsorptionCoefficient(lambda_nm);
    for (int b = 0; b < c.band_count_; ++b) {
      BandStep band;
      band.n_object = lens.prescription().IndexBefore(size_t(v.surface), bands[b]);
      band.n_film = s.IndexAfter(bands[b]);
      band.alpha = medium ? medium->AbsorptionCoefficient(bands[b]) : 0;
      band.fresnel_eta = v.toward_film ? band.n_film / band.n_object : band.n_object / band.n_film;
      c.band_steps_.push_back(band);
    }
    previous = v.surface;
    c.steps_.push_back(step);
  }
  return c;
}

CompiledSequence::Result CompiledSequence::Trace(const LensRay& in, std::vector<Vec3d>* stop_points,
                                                bool follow_blocked, std::span<double> band_transmittance) const {
  Result r;
  // The bands' losses only where asked for.
  const int bands = band_transmittance.empty() ? 0 : band_count_;
  std::fill_n(band_transmittance.begin(), bands, 1.0);
  std::array<double, kMaxBands> band_absorbance;  // Beer-Lambert's exponent so far
  std::fill_n(band_absorbance.begin(), bands, 0.0);
  bool held = false;  // blocked by an opening, and followed (follow_blocked)
  Vec3d o = in.o, d = in.d;
  for (size_t k = 0; k < steps_.size(); ++k) {
    const Step& st = steps_[k];
    const BandStep* at_bands = bands ? &band_steps_[k * size_t(band_count_)] : nullptr;
    const LensSurface& s = *st.surface;
    const Vec3d local = o - Vec3d(0, 0, st.vertex_z);
    bool blocked;
    std::optional<double> t;
    if (!st.conic) {
      t = IntersectSurface(s, local, d, blocked);
    } else if (st.c != 0) {
      t = IntersectConic(st.c, st.k1, local, d);
    } else if (d.z != 0) {
      t = -local.z / d.z;
    }
    if (!t || *t < -1e-9) return r;
    const Vec3d p = local + d * *t;
    const double r2 = p.x * p.x + p.y * p.y;  // the radius squared (against squared bounds: no root)
    if ((st.is_stop ? !lens_->InsideStop(p.x, p.y) : r2 > st.semi_diameter2) || r2 < st.obscuration2) {
      if (!follow_blocked) return r;
      held = true;
    }
    o = o + d * *t;
    if (st.is_stop && stop_points) stop_points->push_back(o);
    // Beer-Lambert along the segment just travelled (Glass::InternalTransmittance).
    if (st.alpha != 0 && *t > 0 && band_count_ == 0 && losses_) r.internal_transmittance *= std::exp(-st.alpha * *t);
    // At the bands, the exponents summed and taken once at the end (an exponential per band
    // and glass was a third of a ray's time).
    if (*t > 0)
      for (int b = 0; b < bands; ++b) band_absorbance[b] += at_bands[b].alpha * *t;
    if (!st.interface) {
      if (st.reflect) return r;  // nothing to reflect from
      continue;
    }
    Vec3d normal = st.conic ? ConicNormal(st.c, st.k1, p) : InterfaceNormal(s, p);
    if (Dot(normal, d) > 0) normal = -normal;
    const double cos_i = -Dot(normal, d);
    // With bands, the transmittance at lambda_ itself is not asked for (left 1).
    const double reflectance =
        band_count_ > 0 || !losses_ ? (st.reflect ? 1.0 : 0.0)
                                    : lens_->SurfaceReflectance(st.index, lambda_, cos_i, st.toward_film, st.n_object, st.n_film);
    for (int b = 0; b < bands; ++b) {
      // LensSystem::SurfaceReflectance, its choice made once.
      const BandStep& band = at_bands[b];
      const double rb = st.tabulated ? tables_->Reflectance(st.index, st.toward_film, b, cos_i)
                        : st.bare    ? (band.n_object == band.n_film
                                            ? 0.0
                                            : FresnelDielectric(std::clamp(cos_i, 0.0, 1.0), band.fresnel_eta))
                                     : lens_->SurfaceReflectance(st.index, bands_[b], cos_i, st.toward_film,
                                                                 band.n_object, band.n_film);
      band_transmittance[b] *= st.reflect ? rb : 1 - rb;
    }
    if (st.reflect) {
      r.surface_transmittance *= reflectance;
      d = ReflectedDirection(d, normal, cos_i);
      continue;
    }
    r.surface_transmittance *= 1 - reflectance;
    const std::optional<Vec3d> refracted = RefractedDirection(d, normal, st.eta, cos_i);
    if (!refracted) return r;  // total internal reflection
    d = *refracted;
  }
  for (int b = 0; b < bands; ++b)
    if (band_absorbance[b] != 0) band_transmittance[b] *= std::exp(-band_absorbance[b]);
  r.alive = !held;
  r.followed = held;
  r.ray = LensRay{o, d, false, in.wave_choices};
  return r;
}

}  // namespace objektiv
