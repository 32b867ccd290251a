#include "render/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace objektiv {

double RelativeNoise(const Film& film) {
  const size_t n = film.PixelCount();
  if (n == 0) return 0;
  std::vector<Film::LuminanceMoments> m(n);
  double mean_sum = 0;
  for (size_t i = 0; i < n; ++i) {
    m[i] = film.Moments(i);
    mean_sum += std::abs(m[i].mean);
  }
  const double floor = 0.01 * mean_sum / double(n);
  std::vector<double> e(n);
  for (size_t i = 0; i < n; ++i) {
    if (m[i].count < 2) {
      e[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    const double denom = std::abs(m[i].mean) + floor;
    const double se = std::sqrt(m[i].variance / m[i].count);
    e[i] = denom > 0 ? se / denom : (se > 0 ? std::numeric_limits<double>::infinity() : 0);
  }
  const size_t k = std::min(n - 1, size_t(std::ceil(0.95 * double(n))) - (n > 0 ? 1 : 0));
  std::nth_element(e.begin(), e.begin() + k, e.end());
  return e[k];
}

}  // namespace objektiv
