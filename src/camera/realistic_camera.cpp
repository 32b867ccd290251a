#include "camera/realistic_camera.h"

#include <bit>
#include <cmath>

#include "base/error.h"
#include "base/log.h"
#include "base/rng.h"
#include "optics/dispersion.h"
#include "optics/front_element.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"

namespace objektiv {

namespace {

// Whether any glass's index changes with the wavelength.
bool IsDispersive(const LensPrescription& lens) {
  if (lens.object_medium && lens.object_medium->IsDispersive()) return true;
  for (const LensSurface& s : lens.surfaces)
    if ((s.medium && s.medium->IsDispersive()) || (s.crystal && s.crystal->extraordinary->IsDispersive())) return true;
  return false;
}

// The waves a ray takes in the lens's birefringent crystals (LensRay::wave_choices): unpolarised
// light divides evenly between a crystal's two, so each is chosen with probability 1/2 and the
// ray keeps its weight; the bits hash the ray's own sample numbers (independent of the choices
// made with them).
template <typename... Floats>
uint32_t WaveChoices(Floats... v) {
  return uint32_t(Hash(std::bit_cast<uint32_t>(v)...) >> 32);
}

// Where the scene lies in another medium (index n0, an underwater port), radiance there is n0^2
// times the radiance it becomes in the air before the film (n^2 L is unchanged along a ray
// through lossless interfaces): a camera ray measures the scene's radiance over n0^2.
void ScaleForObjectMedium(const LensPrescription& lens, const SampledWavelengths& lambda, SampledSpectrum& weight) {
  if (!lens.object_medium) return;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const double n0 = lens.object_medium->Index(lambda[k]);
    weight[k] *= float(1 / (n0 * n0));
  }
}

// Whether a camera ray's transmittance depends on its wavelength without the path doing so:
// a coated surface's reflectance changes with the wavelength, and so does a metal mirror's
// and the absorption of a glass with transmittance data (a colour filter of constant index),
// so one wavelength's transmittance cannot stand for the others'.
bool TransmittanceVariesWithWavelength(const LensSystem& lens) {
  for (int i = 0; i < lens.SurfaceCount(); ++i)
    if (lens.Coated(i) || lens.surface(i).mirror_metal || (lens.surface(i).medium && lens.surface(i).medium->Absorbs()))
      return true;
  return false;
}

BatchLensTracer MakeFastTracer(const LensSystem& lens, Vignetting v) {
  BatchLensTracer fast(lens);
  if (v == Vignetting::kNatural || v == Vignetting::kNone) fast.IgnoreRims();
  return fast;
}

PupilBoundsOptions BoundsOptions(const LensSystem& lens, Vignetting v) {
  PupilBoundsOptions o;
  // The pupil's edge moves a little with the wavelength: bound the light of the whole range.
  if (IsDispersive(lens.prescription())) o.wavelengths = {360.0, kLambdad, 830.0};
  o.rims = !(v == Vignetting::kNatural || v == Vignetting::kNone);
  return o;
}

}  // namespace

RealisticCamera::RealisticCamera(const Transform& to_world, int width, int height, const LensSystem& lens,
                                 const LensCameraSettings& settings)
    : LensCamera(to_world, width, height, settings), lens_(lens), fast_(MakeFastTracer(lens, settings.vignetting)),
      bounds_(lens, FilmRadius(), BoundsOptions(lens, settings.vignetting)), film_z_(lens.FilmZ()),
      stop_radius_(float(lens.StopSemiDiameter())), dispersive_(IsDispersive(lens.prescription())),
      birefringent_(lens.prescription().CrystalCount() > 0),
      per_wavelength_transmittance_(!dispersive_ && settings.transmission && TransmittanceVariesWithWavelength(lens)) {
  const ParaxialData& p = lens.paraxial();
  SetOriginZ(lens.VertexZ(0) + p.entrance_pupil_position);
  // A lens that lets light reach no point of the film (an element decentred off the beam) would
  // render black in silence: a 9 x 9 grid over the film centred on the axis is asked (a film
  // shifted off the image is the user's choice: it renders black, with no pass rate).
  int lit = 0;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j)
      lit += bounds_.BoundAt(Vec2d(settings.sensor_width * (i / 8.0 - 0.5), settings.sensor_height * (j / 8.0 - 0.5))) != nullptr;
  const bool light = lit > 0;
  // (A fisheye's round image leaves the corners dark: a quarter of the points, not more.)
  if (light && lit < 20)
    spdlog::warn("light reaches only {} of 81 points over the film through {} as it is set up (its image circle, a hood, "
                 "rims or decentres): most of the picture will be black", lit, lens.prescription().Described());
  if (!light)
    throw InputError(fmt::format("no light reaches the film through {} as it is placed: its rims, mirrors or "
                                 "obstruction block every ray (check its decentres, tilts and semi-diameters)",
                                 lens.prescription().Described()));
}

double RealisticCamera::WorkingFNumber() const {
  const ParaxialData& p = lens_.paraxial();
  const double exit_pupil_z = lens_.VertexZ(lens_.SurfaceCount() - 1) + p.exit_pupil_position;
  return std::abs(lens_.FilmZ() - exit_pupil_z) / p.exit_pupil_diameter;
}

bool RealisticCamera::StartRay(const CameraSample& s, SampledWavelengths& lambda, FloatRay& ray, float& weight, Vec2d& aim,
                               double& pdf, bool spectral) const {
  Vec2d film = FilmPoint(s.p_film);
  PupilBounds::Sample ps = bounds_.SampleRear(film, Vec2d(s.p_lens.x, s.p_lens.y));
  if (ps.pdf == 0) return false;
  aim = Vec2d(ps.point.x, ps.point.y);
  pdf = ps.pdf;
  // Single precision from here: the direction toward the pupil point.
  float fx = float(film.x), fy = float(film.y), dz = float(bounds_.rear_z() - film_z_);
  float dx = float(ps.point.x) - fx, dy = float(ps.point.y) - fy;
  float inv = 1 / std::sqrt(dx * dx + dy * dy + dz * dz);
  weight = Weight(film, -dz * inv, -dz, ps.pdf);
  // Each wavelength takes its own path through dispersive glass: only the hero goes on, unless
  // the others are weighed by spectral MIS.
  if (dispersive_ && !spectral) lambda.TerminateSecondary();
  ray = {fx, fy, float(film_z_), dx * inv, dy * inv, dz * inv, lambda[0], 1.f};
  if (birefringent_) ray.wave_choices = WaveChoices(s.p_film.x, s.p_film.y, s.p_lens.x, s.p_lens.y);
  return true;
}

CameraRay RealisticCamera::Finish(const FloatRay& r, float weight) const {
  CameraRay cr;
  cr.ray = WorldRay(Vec3d(r.ox, r.oy, r.oz), Vec3d(r.dx, r.dy, r.dz));
  cr.weight = SampledSpectrum(weight * r.transmittance);
  return cr;
}

std::optional<CameraRay> RealisticCamera::GenerateRay(const CameraSample& s, SampledWavelengths& lambda) const {
  std::optional<CameraRay> out;
  CameraRayCount count;
  GenerateRays(std::span(&s, 1), std::span(&lambda, 1), std::span(&out, 1), count);
  return out;
}

void RealisticCamera::GenerateRays(std::span<const CameraSample> samples, std::span<SampledWavelengths> lambdas,
                                   std::span<std::optional<CameraRay>> out, CameraRayCount& count) const {
  // Traced together (surfaces in the outer loop), which is about twice as fast as one by one.
  thread_local RayBatch batch;
  thread_local std::vector<float> weights;
  thread_local std::vector<uint32_t> index;
  thread_local std::vector<Vec2d> films, aims;
  thread_local std::vector<double> pdfs;
  thread_local std::vector<uint8_t> spectral;
  batch.Resize(0);
  weights.clear();
  index.clear();
  films.clear(), aims.clear(), pdfs.clear(), spectral.clear();
  for (size_t i = 0; i < samples.size(); ++i) {
    out[i].reset();
    FloatRay r;
    float w;
    Vec2d aim;
    double pdf;
    // Spectral MIS where the caller weighs the wavelengths (not through crystals, whose waves
    // the way back would have to retrace).
    const bool mis = dispersive_ && !birefringent_ && settings_.spectral_mis && samples[i].spectral_mis;
    if (!StartRay(samples[i], lambdas[i], r, w, aim, pdf, mis)) continue;
    batch.Push(r);
    weights.push_back(w);
    index.push_back(uint32_t(i));
    films.push_back(FilmPoint(samples[i].p_film)), aims.push_back(aim), pdfs.push_back(pdf), spectral.push_back(mis);
    if (per_wavelength_transmittance_)
      for (int k = 1; k < kSpectrumSamples; ++k) {  // the copies right after the hero's
        r.lambda = lambdas[i][k];
        batch.Push(r);
      }
  }
  const ApertureMask* mask = settings_.aperture_mask.get();
  batch.record_stop = mask != nullptr;
  fast_.TraceFromFilm(batch, settings_.transmission);
  const size_t copies = per_wavelength_transmittance_ ? kSpectrumSamples : 1;
  count.traced += batch.Size() / copies;
  const float inv_stop = 1 / stop_radius_;
  thread_local std::vector<MisHero> heroes;
  heroes.clear();
  for (size_t n = 0; n < weights.size(); ++n) {
    const size_t j = n * copies;  // the hero's copy
    if (!batch.alive[j]) continue;
    ++count.passed;
    float w = weights[n];
    const float m = mask ? mask->Transmittance(batch.stop_x[j] * inv_stop, batch.stop_y[j] * inv_stop) : 1.f;
    out[index[n]] = Finish(batch.Get(j), w * m);
    if (copies > 1) out[index[n]]->weight = PerWavelengthWeight(batch, j, w * m);
    ScaleForObjectMedium(lens_.prescription(), lambdas[index[n]], out[index[n]]->weight);
    if (spectral[n]) heroes.push_back({j, index[n], films[n], aims[n], pdfs[n], m});
  }
  if (heroes.empty()) return;
  thread_local std::vector<SpectralMisTerms> terms;
  SpectralTerms(batch, heroes, lambdas, terms);
  for (size_t h = 0; h < heroes.size(); ++h) {
    std::optional<CameraRay>& cr = out[heroes[h].sample];
    ScaleForObjectMedium(lens_.prescription(), lambdas[heroes[h].sample], terms[h].numerator);
    cr->spectral = terms[h];
    // Until the caller weighs them with its filter: as with a filter flat over the four.
    cr->weight = SpectralMisWeight(terms[h], Vec2f(0, 0), [](Vec2f) { return 1.f; });
  }
}

SampledSpectrum RealisticCamera::PerWavelengthWeight(const RayBatch& batch, size_t first, float weight) const {
  SampledSpectrum out;
  for (int k = 0; k < kSpectrumSamples; ++k)
    out[k] = batch.alive[first + k] ? weight * batch.Get(first + k).transmittance : 0.f;
  return out;
}

std::optional<CameraImportance> RealisticCamera::SampleImportance(const Vec3f& p, Vec2f u,
                                                                  SampledWavelengths& lambda) const {
  const FrontPoint front = SampleFrontElement(lens_, Vec2d(u.x, u.y));
  const Vec3d from = LensSpacePoint(p);
  Vec3d d = front.p - from;
  const double distance = Length(d);  // mm
  if (!(distance > 0)) return std::nullopt;
  d = d / distance;
  const double projected = front.ProjectedCosine(d);
  if (projected <= 0) return std::nullopt;
  if (dispersive_) lambda.TerminateSecondary();
  // From just in front of the surface point (the scene point may be far away).
  std::vector<Vec3d> path;
  const bool masked = settings_.aperture_mask != nullptr;
  const uint32_t waves = birefringent_ ? WaveChoices(p.x, p.y, p.z, u.x, u.y) : 0;
  const TraceResult r = TraceFromObject(lens_, {front.p - d, d, false, waves}, lambda[0], masked ? &path : nullptr);
  if (!r.ray || !(r.ray->d.z > 0)) return std::nullopt;
  const double t = (film_z_ - r.ray->o.z) / r.ray->d.z;
  const Vec2d film(r.ray->o.x + t * r.ray->d.x, r.ray->o.y + t * r.ray->d.y);
  const Vec2d pixel = PixelOf(film);
  if (!(pixel.x >= 0 && pixel.x < width_ && pixel.y >= 0 && pixel.y < height_)) return std::nullopt;
  const double hero_transmittance = settings_.transmission ? r.Transmittance() : r.dirt;
  double w = 1;
  if (masked && lens_.StopIndex() >= 0 && path.size() > size_t(lens_.StopIndex())) {
    const Vec3d s = lens_.InSurfaceFrame(lens_.StopIndex(), path[size_t(lens_.StopIndex())]);
    w *= settings_.aperture_mask->Transmittance(float(s.x / stop_radius_), float(s.y / stop_radius_));
  }
  // The flux through the front element toward this film point, J projected pi r^2 / distance^2,
  // over the sensor's area, as the pixel's (4 / pi) exposure_scale irradiance (camera/lens_camera.h)
  // for one light path per pixel: scene units cancel but for the sensor's area.
  const double mm_to_units = 1e-3 / settings_.metres_per_unit;
  const double sensor = settings_.sensor_width * settings_.sensor_height * mm_to_units * mm_to_units;
  w *= 4 / M_PI * settings_.exposure_scale * projected * FrontElementArea(lens_) / (distance * distance) / sensor;
  w /= ChiefRayFactor(film, bounds_.rear_z() - film_z_);
  CameraImportance out;
  out.p_film = Vec2f(float(pixel.x), float(pixel.y));
  out.p_lens = WorldPoint(front.p);
  out.weight = SampledSpectrum(float(w * hero_transmittance));
  if (per_wavelength_transmittance_)  // the same path at the sample's other wavelengths
    for (int k = 1; k < kSpectrumSamples; ++k) {
      const TraceResult rk = TraceFromObject(lens_, {front.p - d, d, false, waves}, lambda[k]);
      out.weight[k] = rk.ray ? float(w * rk.Transmittance()) : 0.f;
    }
  // (No 1 / n0^2 here: this weight takes flux through the lens to the film, and flux, unlike
  // radiance, is the same on both sides of the port.)
  return out;
}

}  // namespace objektiv
