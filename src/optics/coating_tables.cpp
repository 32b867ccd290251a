#include "optics/coating_tables.h"

#include <algorithm>
#include <cmath>

namespace objektiv {

CoatingTables::CoatingTables(const LensSystem& lens, std::span<const double> wavelengths)
    : lens_(&lens), wavelengths_(wavelengths.begin(), wavelengths.end()), offset_(size_t(lens.SurfaceCount()), -1) {
  const size_t bands = wavelengths_.size();
  constexpr double step = 1.0 / (kColumns - 1);
  for (int i = 0; i < lens.SurfaceCount(); ++i) {
    if (!lens.Coated(i)) continue;
    offset_[size_t(i)] = long(values_.size());
    for (bool toward_film : {true, false})
      for (size_t b = 0; b < bands; ++b) {
        const size_t first = values_.size();
        for (int c = 0; c < kColumns; ++c)
          values_.push_back(float(lens.SurfaceReflectance(i, wavelengths_[b], c * step, toward_film)));
        for (int c = 0; c < kColumns; ++c) {
          bool exact = false;
          if (c + 1 < kColumns) {
            const double middle = lens.SurfaceReflectance(i, wavelengths_[b], (c + 0.5) * step, toward_film);
            exact = std::abs(0.5 * (double(values_[first + c]) + values_[first + c + 1]) - middle) > kIntervalTolerance;
          }
          exact_.push_back(exact);
        }
      }
  }
}

double CoatingTables::Reflectance(int surface, bool toward_film, int band, double cos_i) const {
  const size_t bands = wavelengths_.size();
  const size_t at = size_t(offset_[size_t(surface)]) + ((toward_film ? 0 : bands) + size_t(band)) * kColumns;
  const float* table = values_.data() + at;
  const double x = (cos_i > 0 ? std::min(cos_i, 1.0) : 0.0) * (kColumns - 1);  // (NaN: 0)
  const int k = std::min(int(x), kColumns - 2);
  if (exact_[at + size_t(k)]) return lens_->SurfaceReflectance(surface, wavelengths_[size_t(band)], cos_i, toward_film);
  const double f = x - k;
  return table[k] + f * (table[k + 1] - table[k]);
}

}  // namespace objektiv
