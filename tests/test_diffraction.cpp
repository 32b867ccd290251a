// The stop's Fraunhofer diffraction pattern against the closed forms of the Airy pattern and
// the spikes of a bladed iris.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/lens_psf.h"
#include "optics/diffraction_psf.h"
#include "optics/stop_shape.h"

namespace objektiv {
namespace {

PupilFunction Opening(const StopShape& shape) {
  return [shape](double u, double v) { return shape.Contains(u, v) ? 1.0 : 0.0; };
}

TEST(Diffraction, RoundStopsFirstDarkRingIsAt1point22LambdaN) {
  for (auto [lambda, n] : {std::pair{550.0, 8.0}, std::pair{450.0, 4.0}, std::pair{650.0, 16.0}}) {
    const double expected = 1.22 * lambda * 1e-3 * n;
    EXPECT_NEAR(FirstDarkRingUm(Opening(StopShape()), lambda, n), expected, 0.01 * expected) << lambda << " nm f/" << n;
  }
}

TEST(Diffraction, AiryPeakAndTotalAreThePhysicalOnes) {
  // The peak irradiance pi / (4 lambda^2 N^2) per unit of the light (um^-2): the pattern's
  // scale on the film is right, not only its shape.
  const double lambda = 0.55, n = 5.6, pitch = lambda * n / 16;
  PsfImage fine = FraunhoferPsf(Opening(StopShape()), lambda * 1e3, n, pitch, 65);
  const double peak = fine.At(32, 32) / (pitch * pitch);
  EXPECT_NEAR(peak, M_PI / (4 * lambda * lambda * n * n), 0.01 * peak);
  // Over a window 128 lambda N wide all but the far tails (0.3% beyond 64 lambda N).
  PsfImage wide = FraunhoferPsf(Opening(StopShape()), lambda * 1e3, n, lambda * n / 2, 256);
  double sum = 0;
  for (double e : wide.energy) sum += e;
  EXPECT_GT(sum, 0.99);
  EXPECT_LE(sum, 1 + 1e-9);
  // A coarse pitch (two dark rings per pixel) sums the finer pattern: the same total.
  PsfImage coarse = FraunhoferPsf(Opening(StopShape()), lambda * 1e3, n, lambda * n * 3, 43);
  double coarse_sum = 0;
  for (double e : coarse.energy) coarse_sum += e;
  EXPECT_NEAR(coarse_sum, sum, 0.002);
  EXPECT_GT(coarse.At(21, 21), 0.85);  // the central pixel holds the Airy disc
}

TEST(Diffraction, PixelsHoldTheLightOverTheirWholeArea) {
  // Pixels as wide as half the Airy disc: the centre pixel holds the Airy pattern integrated
  // over its square (by quadrature of 2 J1(v) / v squared here), not its peak times its area.
  const double lambda = 0.55, n = 4, pitch = 1.1;
  PsfImage psf = FraunhoferPsf(Opening(StopShape()), lambda * 1e3, n, pitch, 33);
  const int q = 400;
  double sum = 0;
  for (int j = 0; j < q; ++j)
    for (int i = 0; i < q; ++i) {
      const double x = ((i + 0.5) / q - 0.5) * pitch, y = ((j + 0.5) / q - 0.5) * pitch;
      const double v = M_PI * std::hypot(x, y) / (lambda * n);
      const double a = v < 1e-9 ? 1 : 2 * std::cyl_bessel_j(1.0, v) / v;
      sum += a * a;
    }
  const double expected = sum * M_PI / (4 * lambda * lambda * n * n) * (pitch / q) * (pitch / q);
  EXPECT_NEAR(psf.At(16, 16), expected, 0.005 * expected);
  EXPECT_NEAR(expected, 0.1773, 0.001);  // well below the peak times the area (0.197)
}

// The number of spikes: peaks of the light's distribution over direction (1 degree bins) in
// the annulus 14..20 lambda N from the axis that stand above a third of the strongest and
// twice the median (a spike's side lobes hold a few percent of it), the highest within 5
// degrees (spikes are 20 degrees apart or more).
int Spikes(const StopShape& shape) {
  const double lambda = 0.55, n = 8, pitch = lambda * n / 4;
  const int size = 169, c = size / 2, bins = 360;
  PsfImage psf = FraunhoferPsf(Opening(shape), lambda * 1e3, n, pitch, size);
  std::vector<double> light(bins);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double r = std::hypot(x - c, y - c) * pitch / (lambda * n);
      if (r < 14 || r > 20) continue;
      const double phi = std::atan2(y - c, x - c) + M_PI;
      light[std::min(bins - 1, int(phi / (2 * M_PI) * bins))] += psf.At(x, y);
    }
  std::vector<double> sorted = light;
  std::nth_element(sorted.begin(), sorted.begin() + bins / 2, sorted.end());
  const double median = sorted[bins / 2], top = *std::max_element(light.begin(), light.end());
  int peaks = 0;
  for (int a = 0; a < bins; ++a) {
    const double v = light[a];
    bool highest = true;  // within 5 degrees (a spike spans several bins)
    for (int d = 1; d <= 5; ++d) highest &= v >= light[(a + bins - d) % bins] && v > light[(a + d) % bins];
    if (v > top / 3 && v > 2 * median && highest) ++peaks;
  }
  return peaks;
}

TEST(Diffraction, BladesGiveNSpikesForEvenNAnd2NForOdd) {
  for (int blades : {5, 6, 7, 8, 9}) {
    const int expected = blades % 2 ? 2 * blades : blades;
    EXPECT_EQ(Spikes(StopShape::Iris(blades, 0, 0.3)), expected) << blades << " blades";
  }
  EXPECT_EQ(Spikes(StopShape()), 0);  // round: no spikes, rings only
}

TEST(Diffraction, WhiteLightPatternIsWhiteInTotalAndRedderOutside) {
  // Each wavelength's pattern scales with it: summed over 400..700 nm under D65 the whole
  // pattern is white (1, 1, 1), its core bluer than its rings.
  const double n = 8, pitch = 0.55 * n / 4;
  Image image = DiffractionImage(Opening(StopShape()), n, std::nullopt, pitch, 257);
  Vec3f total(0.f), core(0.f);
  for (int y = 0; y < 257; ++y)
    for (int x = 0; x < 257; ++x) {
      total += image.Rgb(x, y);
      if (std::hypot(x - 128, y - 128) <= 3) core += image.Rgb(x, y);
    }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], 1, 0.01) << c;
  EXPECT_GT(core[2] / core[0], 1.02);  // blue's Airy disc is the smallest: more of it in the core
}

}  // namespace
}  // namespace objektiv
