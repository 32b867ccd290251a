#include "render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace objektiv {

int NextAdaptiveCheck(const AdaptiveSettings& a, int count) {
  int c = std::max(1, a.min_samples);
  while (c <= count) c += std::max(1, (c + 3) / 4);
  return c;
}

bool IsAdaptiveCheck(const AdaptiveSettings& a, int count) {
  const int min = std::max(1, a.min_samples);
  return count >= min && NextAdaptiveCheck(a, count - 1) == count;
}

double PixelRelativeError(const Film::LuminanceMoments& m, double floor) {
  if (m.count < 2) return std::numeric_limits<double>::infinity();
  // The unbiased sample variance (n / (n - 1) of the film's second moment about the mean).
  const double se = std::sqrt(m.variance * m.count / (m.count - 1) / m.count);
  const double denom = std::max(std::abs(m.mean), floor);
  return denom > 0 ? se / denom : (se > 0 ? std::numeric_limits<double>::infinity() : 0);
}

bool PixelSamplingDone(const Film& film, Vec2i pixel, const Sampler& sampler, int spp) {
  const AdaptiveSettings& a = sampler.adaptive();
  const int count = int(film.SampleCount(pixel));
  switch (a.mode) {
    case AdaptiveMode::kWhitted: return count > 0;
    case AdaptiveMode::kStatistical:
      if (film.NextSample(pixel) >= spp) return true;
      if (!IsAdaptiveCheck(a, count)) return false;
      {
        const Film::LuminanceMoments m = film.Moments(pixel);
        // Samples that all agree (all black, most often) say nothing of the variance: a pixel
        // whose light comes in rare paths shows none in a pilot that missed them. Such a pixel
        // is judged only from kAgreeingSamplesFactor x the pilot on.
        const bool all_agree = m.variance <= 1e-12 * m.mean * m.mean;
        if (all_agree && count < kAgreeingSamplesFactor * std::max(1, a.min_samples)) return false;
        return PixelRelativeError(m, a.floor) <= a.threshold;
      }
    default: return film.NextSample(pixel) >= spp;
  }
}

uint64_t PixelsDone(const Film& film, const Sampler& sampler, int end) {
  if (sampler.adaptive().mode == AdaptiveMode::kNone) return film.PixelsWithSamplesTo(end);
  const CropWindow& c = film.crop();
  uint64_t done = 0;
  for (int y = c.y0; y < c.y1; ++y)
    for (int x = c.x0; x < c.x1; ++x) done += PixelSamplingDone(film, Vec2i(x, y), sampler, end);
  return done;
}

int WhittedMaxSamples(int max_depth) {
  // Every square of the deepest level: its corners, on a lattice 2^max_depth + 1 points a
  // side, and its centre.
  const int corners = (1 << max_depth) + 1;
  return corners * corners + (1 << (2 * max_depth));
}

}  // namespace objektiv
