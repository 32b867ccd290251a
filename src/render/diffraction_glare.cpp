#include "render/diffraction_glare.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "base/cie.h"
#include "optics/fftw_arrays.h"

namespace objektiv {

namespace {

constexpr double kLongest = 780, kShortest = 380;
constexpr int kMaxGrid = 4096;

// The smallest size >= n whose only prime factors are 2, 3, 5 and 7 (FFTW's fast sizes).
int FastFftSize(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int r = m;
    for (int p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}


}  // namespace

DiffractionKernel MakeDiffractionKernel(const PupilFunction& pupil, double fnumber, double pitch_x_um,
                                        double pitch_y_um, int max_radius, int wavelengths) {
  if (!(fnumber > 0) || !(pitch_x_um > 0) || !(pitch_y_um > 0) || max_radius < 0 || wavelengths < 1)
    throw std::invalid_argument("diffraction kernel: the f-number, pitches and counts must be positive");
  const double scale0 = kLongest * 1e-3 * fnumber;  // lambda N at the longest wavelength, um
  const double pitch = std::min(pitch_x_um, pitch_y_um);
  // Fine samples: unaliased (at most lambda N / 2), at least 4 per pixel, yet the pupil at
  // least 128 samples across in the largest grid.
  const double step = std::max(std::min(scale0 / 2, pitch / 4), 128 * scale0 / kMaxGrid);
  // The shortest wavelength's copy is the smallest: the reach every wavelength shares.
  const double shrink = kShortest / kLongest;
  const int n = std::clamp(NextPowerOfTwo(2 * (max_radius + 1) * pitch / (step * shrink)), 256, kMaxGrid);
  const std::vector<double> fine = SampledPattern(pupil, kLongest * 1e-3, fnumber, step, n);
  DiffractionKernel k;
  k.radius = std::min(max_radius, int(std::floor(0.5 * n * step * shrink / std::max(pitch_x_um, pitch_y_um))));
  const int size = k.Size();
  // Each wavelength band's colour: the matching functions integrated over the band (so that
  // few bands still make white light white), its pattern at the band's middle.
  std::vector<double> lambdas, weights[3];
  const double dl = (kLongest - kShortest) / wavelengths;
  for (int i = 0; i < wavelengths; ++i) {
    const double l0 = kShortest + i * dl;
    lambdas.push_back(l0 + 0.5 * dl);
    const Vec3d c = CieXyzOverBand(l0, l0 + dl, [](double) { return 1.0; });
    weights[0].push_back(c.x), weights[1].push_back(c.y), weights[2].push_back(c.z);
  }
  // Each wavelength's copy of the fine pattern, shrunk by lambda / 780, into the pixels: each
  // fine sample stands for its cell (a fraction of a pixel wide), split between the pixels
  // the cell overlaps in proportion to the overlap (a midpoint rule, so that a pixel's share
  // does not depend on how many sample centres happen to fall in it). The kernel's rows are
  // shared out in bands, each band taking every wavelength's cells that reach its rows: no
  // accumulator per thread (zeroing and summing size^2 x 3 doubles per thread was a third of a
  // small flare render's time), and every pixel summed in the same order on any thread count.
  std::vector<double> sum(size_t(size) * size * 3, 0.0);
  // The pixels (index from the kernel's corner) and shares a cell [c - h, c + h] overlaps.
  struct Split {
    int first;
    double share_first;  // the rest goes to first + 1
  };
  auto split = [&](double c, double h) {
    const double a = c - h + k.radius, b = c + h + k.radius;  // pixel p covers [p - 0.5, p + 0.5)
    const int i0 = int(std::floor(a + 0.5)), i1 = int(std::floor(b + 0.5));
    return Split{i0, i0 == i1 ? 1.0 : (i0 + 0.5 - a) / (b - a)};
  };
  constexpr int kBand = 8;  // kernel rows a task takes
  tbb::parallel_for(0, (size + kBand - 1) / kBand, [&](int band) {
    const int y0 = band * kBand, y1 = std::min(size, y0 + kBand);
    for (int w = 0; w < wavelengths; ++w) {
      const double s = lambdas[w] / kLongest;
      const double fx = step * s / pitch_x_um, fy = step * s / pitch_y_um;  // pixels per fine index
      const double cie[3] = {weights[0][w], weights[1][w], weights[2][w]};
      auto deposit = [&](int px, int py, double e) {
        if (px < 0 || py < y0 || px >= size || py >= y1 || e == 0) return;
        double* a = &sum[(size_t(py) * size + px) * 3];
        a[0] += cie[0] * e, a[1] += cie[1] * e, a[2] += cie[2] * e;
      };
      for (int j = 0; j < n; ++j) {
        const Split sy = split((j < n / 2 ? j : j - n) * fy, fy / 2);
        if (sy.first + 1 < y0 || sy.first >= y1) continue;
        const double* row = &fine[size_t(j) * n];
        for (int i = 0; i < n; ++i) {
          const double e = row[i];
          if (e == 0) continue;
          const Split sx = split((i < n / 2 ? i : i - n) * fx, fx / 2);
          const double ey0 = e * sy.share_first, ey1 = e - ey0;
          deposit(sx.first, sy.first, ey0 * sx.share_first);
          deposit(sx.first + 1, sy.first, ey0 * (1 - sx.share_first));
          deposit(sx.first, sy.first + 1, ey1 * sx.share_first);
          deposit(sx.first + 1, sy.first + 1, ey1 * (1 - sx.share_first));
        }
      }
    }
  });
  // Faded out over the outer quarter of the radius, every wavelength alike: a pattern cut
  // off sharply (at a square, or at a radius that differs with the wavelength) would draw its
  // edge, in colours.
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double r = std::hypot(x - k.radius, y - k.radius) / std::max(k.radius, 1);
      const double fade = r <= 0.75 ? 1 : r >= 1 ? 0 : std::pow(std::cos(0.5 * M_PI * (r - 0.75) / 0.25), 2);
      for (int c = 0; c < 3; ++c) sum[(size_t(y) * size + x) * 3 + c] *= fade;
    }
  double total[3] = {0, 0, 0};
  for (size_t i = 0; i < sum.size(); ++i) total[i % 3] += sum[i];
  k.xyz.resize(sum.size());
  for (size_t i = 0; i < sum.size(); ++i) k.xyz[i] = total[i % 3] > 0 ? float(sum[i] / total[i % 3]) : 0.f;
  return k;
}

void ApplyDiffraction(std::vector<float>& xyz, int width, int height, const DiffractionKernel& kernel) {
  const int r = kernel.radius, ks = kernel.Size();
  const int pw = FastFftSize(width + 2 * r), ph = FastFftSize(height + 2 * r);
  const int cw = pw / 2 + 1;
  const size_t real_size = size_t(pw) * ph, complex_size = size_t(ph) * cw;
  auto data = FftwArray<double>(real_size);
  auto image_f = FftwArray<fftw_complex>(complex_size);
  auto kernel_f = FftwArray<fftw_complex>(complex_size);
  fftw_plan forward_image, forward_kernel, backward;
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    forward_image = fftw_plan_dft_r2c_2d(ph, pw, data.get(), image_f.get(), FFTW_ESTIMATE);
    forward_kernel = fftw_plan_dft_r2c_2d(ph, pw, data.get(), kernel_f.get(), FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_2d(ph, pw, image_f.get(), data.get(), FFTW_ESTIMATE);
  }
  for (int c = 0; c < 3; ++c) {
    // The kernel, its centre at (0, 0), wrapped.
    std::fill(data.get(), data.get() + real_size, 0.0);
    for (int y = 0; y < ks; ++y)
      for (int x = 0; x < ks; ++x) {
        const int wx = (x - r + pw) % pw, wy = (y - r + ph) % ph;
        data[size_t(wy) * pw + wx] = kernel.xyz[(size_t(y) * ks + x) * 3 + c];
      }
    fftw_execute(forward_kernel);
    // The image at the padded grid's origin (the padding after it takes what spreads past).
    std::fill(data.get(), data.get() + real_size, 0.0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) data[size_t(y) * pw + x] = xyz[(size_t(y) * width + x) * 3 + c];
    fftw_execute(forward_image);
    const double norm = 1.0 / double(real_size);
    for (size_t i = 0; i < complex_size; ++i) {
      const double a = image_f[i][0], b = image_f[i][1], p = kernel_f[i][0], q = kernel_f[i][1];
      image_f[i][0] = (a * p - b * q) * norm;
      image_f[i][1] = (a * q + b * p) * norm;
    }
    fftw_execute(backward);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) xyz[(size_t(y) * width + x) * 3 + c] = float(data[size_t(y) * pw + x]);
  }
  std::lock_guard<std::mutex> lock(FftwPlannerMutex());
  fftw_destroy_plan(forward_image);
  fftw_destroy_plan(forward_kernel);
  fftw_destroy_plan(backward);
}

}  // namespace objektiv
