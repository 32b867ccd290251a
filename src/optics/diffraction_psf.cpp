#include "optics/diffraction_psf.h"
#include "optics/fftw_arrays.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

namespace objektiv {

std::mutex& FftwPlannerMutex() {
  static std::mutex m;
  return m;
}

namespace {

constexpr int kMaxFft = 4096;


}  // namespace

// The pupil is sampled with spacing delta = 2 lambda N / (n step) stop radii: the FFT's
// frequency step then lands on the film at `step_um`.
std::vector<double> SampledPattern(const PupilFunction& pupil, double lambda_um, double fnumber, double step_um, int n) {
  const double delta = 2 * lambda_um * fnumber / (n * step_um);  // stop radii per pupil sample
  const int half = n / 2;
  const int reach = std::min(half - 1, int(std::ceil(1 / delta)) + 1);  // samples from the centre to the rim
  std::unique_ptr<double[], FftwFree> in(static_cast<double*>(fftw_malloc(sizeof(double) * n * n)));
  std::unique_ptr<fftw_complex[], FftwFree> out(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n * (n / 2 + 1))));
  if (!in || !out) throw std::invalid_argument("not enough memory for the diffraction FFT");
  std::fill(in.get(), in.get() + size_t(n) * n, 0.0);
  // The corners of the cells around the centre, then each cell: the corners' value where they
  // agree, else the mean of 4 x 4 points (an edge crosses the cell).
  const int corners = 2 * reach + 2;
  std::vector<double> corner(size_t(corners) * corners);
  for (int j = 0; j < corners; ++j)
    for (int i = 0; i < corners; ++i) corner[size_t(j) * corners + i] = pupil((i - reach - 0.5) * delta, (j - reach - 0.5) * delta);
  // Each sample: the cell's mean amplitude (the square root of the transmittance); `light`
  // sums the cells' mean transmittance, the light the stop passes. An edge cell's grey
  // amplitude sends less light far out than the sharp edge does (its power, the amplitude
  // squared, falls short of its light): normalising by the light keeps the core exact and
  // leaves that shortfall to the far tails, where it belongs.
  double light = 0;
  for (int j = 0; j < corners - 1; ++j)
    for (int i = 0; i < corners - 1; ++i) {
      const double* c0 = &corner[size_t(j) * corners + i];
      const double* c1 = c0 + corners;
      double t = c0[0], v = std::sqrt(std::max(t, 0.0));
      if (c0[1] != t || c1[0] != t || c1[1] != t) {
        t = v = 0;
        for (int b = 0; b < 4; ++b)
          for (int a = 0; a < 4; ++a) {
            const double s = std::max(0.0, pupil((i - reach - 0.5 + (a + 0.5) / 4) * delta, (j - reach - 0.5 + (b + 0.5) / 4) * delta));
            t += s;
            v += std::sqrt(s);
          }
        t /= 16;
        v /= 16;
      }
      in[size_t(j - reach + half) * n + (i - reach + half)] = v;
      light += t;
    }
  if (!(light > 0)) throw std::invalid_argument("the stop lets no light through");
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    plan = fftw_plan_dft_r2c_2d(n, n, in.get(), out.get(), FFTW_ESTIMATE);
  }
  fftw_execute(plan);
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    fftw_destroy_plan(plan);
  }
  // Parseval: the sum of |DFT|^2 over the grid is n^2 times the pupil's power.
  const double norm = 1 / (double(n) * n * light);
  std::vector<double> pattern(size_t(n) * n);
  const int w = n / 2 + 1;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      // The real input's transform is Hermitian: F(-k) = conj F(k).
      const bool stored = x < w;
      const int sx = stored ? x : n - x, sy = stored ? y : (n - y) % n;
      const fftw_complex& f = out[size_t(sy) * w + sx];
      pattern[size_t(y) * n + x] = (f[0] * f[0] + f[1] * f[1]) * norm;
    }
  return pattern;
}

namespace {

// The pattern averaged over a square of `width` samples about each sample (exactly, for the
// band-limited intensity: its spectrum times the box's, sinc(pi f width) per axis).
void BoxFilter(std::vector<double>& pattern, int n, double width) {
  std::unique_ptr<double[], FftwFree> data(static_cast<double*>(fftw_malloc(sizeof(double) * n * n)));
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n * (n / 2 + 1))));
  if (!data || !spectrum) throw std::invalid_argument("not enough memory for the diffraction FFT");
  fftw_plan forward, backward;
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    forward = fftw_plan_dft_r2c_2d(n, n, data.get(), spectrum.get(), FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_2d(n, n, spectrum.get(), data.get(), FFTW_ESTIMATE);
  }
  std::copy(pattern.begin(), pattern.end(), data.get());
  fftw_execute(forward);
  auto box = [&](int index) {
    const double f = double(index) / n, x = M_PI * f * width;
    return x == 0 ? 1.0 : std::sin(x) / x;
  };
  const int w = n / 2 + 1;
  for (int y = 0; y < n; ++y) {
    const double hy = box(y < n / 2 ? y : y - n) / (double(n) * n);  // c2r leaves a factor n^2
    for (int x = 0; x < w; ++x) {
      const double h = hy * box(x);
      spectrum[size_t(y) * w + x][0] *= h;
      spectrum[size_t(y) * w + x][1] *= h;
    }
  }
  fftw_execute(backward);
  std::copy(data.get(), data.get() + size_t(n) * n, pattern.begin());
  std::lock_guard<std::mutex> lock(FftwPlannerMutex());
  fftw_destroy_plan(forward);
  fftw_destroy_plan(backward);
}


}  // namespace

PsfImage FraunhoferPsf(const PupilFunction& pupil, double lambda_nm, double fnumber, double pitch_um, int size) {
  if (!(lambda_nm > 0) || !(fnumber > 0) || !(pitch_um > 0) || size < 1)
    throw std::invalid_argument("the wavelength, f-number, pitch and size must be positive");
  const double lambda_um = lambda_nm * 1e-3, scale = lambda_um * fnumber;
  // Finer steps (k per pixel, k odd so that one lands on each pixel's centre) until the pupil
  // fits in half the grid: the pattern (the pupil's autocorrelation) is then not aliased.
  int k = std::max(1, int(std::ceil(pitch_um / (scale / 2))));
  if (k % 2 == 0) ++k;
  const double step = pitch_um / k;
  // The grid covers twice the image (the pattern's tails wrap around less), and the pupil
  // spans at least 128 samples.
  if (128 * scale / step > kMaxFft)
    throw std::invalid_argument(fmt::format("a pitch of {:g} um is too fine to sample the pupil at f/{:g} and {:g} nm: at least {:.3g} um",
                                            pitch_um, fnumber, lambda_nm, 128 * scale / kMaxFft));
  if (2.0 * size * k > kMaxFft)
    throw std::invalid_argument(fmt::format("{} pixels of {:g} um need an FFT over 4096^2 at f/{:g} and {:g} nm: at most {} pixels",
                                            size, pitch_um, fnumber, lambda_nm, kMaxFft / (2 * k)));
  const int n = NextPowerOfTwo(std::max({2.0 * size * k, 128 * scale / step, 256.0}));
  std::vector<double> pattern = SampledPattern(pupil, lambda_um, fnumber, step, n);
  // Each pixel's light: the pattern averaged over the pixel (k samples wide) at its centre,
  // times the k^2 samples it spans.
  BoxFilter(pattern, n, k);
  PsfImage psf;
  psf.size = size;
  psf.pitch_um = pitch_um;
  psf.energy.assign(size_t(size) * size, 0);
  const int centre = size / 2;
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px) {
      const int gx = (((px - centre) * k) % n + n) % n, gy = (((py - centre) * k) % n + n) % n;
      psf.energy[size_t(py) * size + px] = std::max(0.0, pattern[size_t(gy) * n + gx]) * k * k;
    }
  return psf;
}

double FirstDarkRingUm(const PupilFunction& pupil, double lambda_nm, double fnumber) {
  // Point samples 1/16 of lambda N apart out to 4 lambda N; the azimuthal mean by bilinear
  // interpolation along 720 directions; its first minimum refined by a parabola.
  const double scale = lambda_nm * 1e-3 * fnumber, step = scale / 16;
  const int n = 1024;
  const std::vector<double> pattern = SampledPattern(pupil, lambda_nm * 1e-3, fnumber, step, n);
  auto at = [&](int x, int y) { return pattern[size_t((y + n) % n) * n + size_t((x + n) % n)]; };
  auto mean_at = [&](double radius_steps) {
    double sum = 0;
    const int directions = 720;
    for (int a = 0; a < directions; ++a) {
      const double phi = 2 * M_PI * (a + 0.5) / directions;
      const double x = radius_steps * std::cos(phi), y = radius_steps * std::sin(phi);
      const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
      const double fx = x - x0, fy = y - y0;
      sum += (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
    }
    return sum / directions;
  };
  const double dr = 0.05;  // steps
  double previous = mean_at(0), current = mean_at(dr);
  for (double r = 2 * dr; r < 64; r += dr) {
    const double next = mean_at(r);
    if (current <= previous && current < next) {
      // Parabola through the three values about the minimum at r - dr.
      const double denominator = previous - 2 * current + next;
      const double offset = denominator > 0 ? 0.5 * (previous - next) / denominator : 0;
      return (r - dr + offset * dr) * step;
    }
    previous = current;
    current = next;
  }
  return NAN;  // no minimum within 4 lambda N
}

}  // namespace objektiv
