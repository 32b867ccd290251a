// The realistic camera's part of spectral MIS (camera/spectral_mis.h): each wavelength's film
// point, transmittance and technique density for a hero ray's world ray.
#include <cmath>

#include "camera/aperture_mask.h"
#include "camera/realistic_camera.h"

namespace objektiv {

RealisticCamera::Technique RealisticCamera::TechniqueAt(Vec2d x, Vec2d u, double pdf) const {
  const double dz = film_z_ - bounds_.rear_z();  // from the sampling plane to the film, positive
  const double d2 = (u.x - x.x) * (u.x - x.x) + (u.y - x.y) * (u.y - x.y) + dz * dz;
  const double cos_theta = dz / std::sqrt(d2);
  const double g = cos_theta * cos_theta * cos_theta * cos_theta / (dz * dz);  // G = cos^4 / dz^2
  // Weight() with pdf 1 is s G / c(x): over G, s / c(x).
  return {float(Weight(x, cos_theta, dz, 1.0) / g), float(pdf / g)};
}

void RealisticCamera::SpectralTerms(const RayBatch& batch, std::span<const MisHero> heroes,
                                    std::span<const SampledWavelengths> lambdas, std::vector<SpectralMisTerms>& terms) const {
  terms.assign(heroes.size(), SpectralMisTerms{});
  // The other wavelengths: each hero's world ray, reversed, from 1 mm in front of where it left
  // the lens back toward the film.
  constexpr int others = kSpectrumSamples - 1;
  thread_local RayBatch back;
  back.Resize(0);
  for (const MisHero& h : heroes) {
    const FloatRay r = batch.Get(h.j);
    for (int k = 1; k < kSpectrumSamples; ++k)
      back.Push({r.ox + r.dx, r.oy + r.dy, r.oz + r.dz, -r.dx, -r.dy, -r.dz, lambdas[h.sample][k], 1.f});
  }
  const ApertureMask* mask = settings_.aperture_mask.get();
  back.record_stop = mask != nullptr;
  fast_.TraceFromObject(back, settings_.transmission);
  const float inv_stop = 1 / stop_radius_;
  const double rear_z = bounds_.rear_z();
  for (size_t n = 0; n < heroes.size(); ++n) {
    const MisHero& h = heroes[n];
    SpectralMisTerms& t = terms[n];
    const Vec2d pixel0 = PixelOf(h.film);
    const Technique hero = TechniqueAt(h.film, h.aim, h.pdf);
    t.numerator[0] = hero.scale * batch.transmittance[h.j] * h.mask;
    t.density[0] = hero.density;
    for (int k = 1; k < kSpectrumSamples; ++k) {
      const size_t j = n * others + size_t(k - 1);
      if (!back.alive[j] || !(back.dz[j] > 0)) continue;  // lambda_k's lens cannot make this ray
      const double ox = back.ox[j], oy = back.oy[j], oz = back.oz[j], dx = back.dx[j], dy = back.dy[j], dz = back.dz[j];
      const double to_film = (film_z_ - oz) / dz, to_plane = (rear_z - oz) / dz;
      const Vec2d film(ox + dx * to_film, oy + dy * to_film), aim(ox + dx * to_plane, oy + dy * to_plane);
      const Technique tk = TechniqueAt(film, aim, bounds_.PdfRear(film, aim));
      const float m = mask ? mask->Transmittance(back.stop_x[j] * inv_stop, back.stop_y[j] * inv_stop) : 1.f;
      t.numerator[k] = tk.scale * back.transmittance[j] * m;
      t.density[k] = tk.density;
      const Vec2d pixel = PixelOf(film);
      t.shift[k] = Vec2f(float(pixel.x - pixel0.x), float(pixel.y - pixel0.y));
    }
  }
}

}  // namespace objektiv
