#include "optics/coating_tables.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

#include "base/catmull_rom.h"

namespace objektiv {

namespace {

// The cubic through a table's columns (base/catmull_rom.h) at fraction f of interval k.
double Cubic(const float* table, int columns, int k, double f) {
  auto column = [table](int c) { return double(table[c]); };
  double w[4];
  CatmullRomWeights(f, w);
  double sum = 0;
  for (int n = 0; n < 4; ++n) sum += w[n] * CatmullRomSample<double>(k - 1 + n, columns, column);
  return sum;
}

}  // namespace

CoatingTables::CoatingTables(const LensSystem& lens, std::span<const double> wavelengths)
    : wavelengths_(wavelengths.begin(), wavelengths.end()),
      interfaces_(size_t(lens.SurfaceCount())),
      offset_(size_t(lens.SurfaceCount()), -1) {
  const size_t bands = wavelengths_.size();
  // Every coated surface's tables: [toward film, toward object][band], kColumns each.
  std::vector<int> coated;
  for (int i = 0; i < lens.SurfaceCount(); ++i) {
    if (!lens.Coated(i)) continue;
    interfaces_[size_t(i)] = Interface{*lens.Coated(i), lens.CoatingFacesObject(i)};
    offset_[size_t(i)] = long(coated.size() * 2 * bands * kColumns);
    coated.push_back(i);
  }
  const size_t tables = coated.size() * 2 * bands;
  values_.assign(tables * kColumns, 0.f);
  exact_.assign(tables * kColumns, 0);
  constexpr double step = 1.0 / (kColumns - 1);
  tbb::parallel_for(size_t(0), tables, [&](size_t t) {
    const int i = coated[t / (2 * bands)];
    const bool toward_film = (t / bands) % 2 == 0;
    const double lambda = wavelengths_[t % bands];
    float* table = values_.data() + t * kColumns;
    for (int c = 0; c < kColumns; ++c) table[c] = float(lens.SurfaceReflectance(i, lambda, c * step, toward_film));
    for (int c = 0; c + 1 < kColumns; ++c) {
      const double middle = lens.SurfaceReflectance(i, lambda, (c + 0.5) * step, toward_film);
      exact_[t * kColumns + size_t(c)] = std::abs(Cubic(table, kColumns, c, 0.5) - middle) > kIntervalTolerance;
    }
  });
}

bool CoatingTables::Fits(const LensSystem& lens, std::span<const double> wavelengths) const {
  if (!std::equal(wavelengths.begin(), wavelengths.end(), wavelengths_.begin(), wavelengths_.end()) ||
      size_t(lens.SurfaceCount()) != interfaces_.size())
    return false;
  for (int i = 0; i < lens.SurfaceCount(); ++i) {
    const CoatedInterface* coated = lens.Coated(i);
    const std::optional<Interface>& mine = interfaces_[size_t(i)];
    if (bool(coated) != mine.has_value()) return false;
    if (coated && (lens.CoatingFacesObject(i) != mine->faces_object || !coated->SameResponse(mine->coated, wavelengths_)))
      return false;
  }
  return true;
}

std::shared_ptr<const CoatingTables> CoatingTables::Shared(const LensSystem& lens, std::span<const double> wavelengths) {
  static std::mutex mutex;
  static std::deque<std::shared_ptr<const CoatingTables>> kept;  // the newest first
  {
    const std::lock_guard lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if ((*it)->Fits(lens, wavelengths)) {
        std::shared_ptr<const CoatingTables> found = *it;
        kept.erase(it);
        kept.push_front(found);
        return found;
      }
  }
  // Made outside the lock (other lenses' tables stay at hand meanwhile).
  auto made = std::make_shared<const CoatingTables>(lens, wavelengths);
  const std::lock_guard lock(mutex);
  kept.push_front(made);
  if (kept.size() > kShared) kept.pop_back();
  return made;
}

double CoatingTables::Reflectance(int surface, bool toward_film, int band, double cos_i) const {
  const size_t bands = wavelengths_.size();
  const size_t at = size_t(offset_[size_t(surface)]) + ((toward_film ? 0 : bands) + size_t(band)) * kColumns;
  const double x = (cos_i > 0 ? std::min(cos_i, 1.0) : 0.0) * (kColumns - 1);  // (NaN: 0)
  const int k = std::min(int(x), kColumns - 2);
  if (exact_[at + size_t(k)]) {
    // LensSystem::SurfaceReflectance's stack, from the interface kept here.
    const Interface& i = *interfaces_[size_t(surface)];
    return i.coated.Reflectance(wavelengths_[size_t(band)], cos_i, toward_film == i.faces_object);
  }
  return std::max(0.0, Cubic(values_.data() + at, kColumns, k, x - k));
}

}  // namespace objektiv
