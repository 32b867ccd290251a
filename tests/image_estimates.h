// Two renderers' images of the same scene compared within their measured noise: the image
// summed in blocks of 8 x 8 pixels, over renders of 8 seeds (32 x 32 pixel films).
#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render_helpers.h"

namespace objektiv::test {

constexpr int kSize = 32, kBlock = 8, kBlocks = (kSize / kBlock) * (kSize / kBlock);

// Y summed per block of 8 x 8 pixels.
inline std::vector<double> Blocks(const Image& img) {
  std::vector<double> b(kBlocks, 0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double Y = 0.2126 * img.At(x, y, 0) + 0.7152 * img.At(x, y, 1) + 0.0722 * img.At(x, y, 2);
      b[(y / kBlock) * (kSize / kBlock) + x / kBlock] += Y;
    }
  return b;
}

// An integrator's block sums over renders of 8 seeds: their mean, and the variance of the mean
// per block (from the 8 renders' spread in that block).
struct Estimate {
  std::vector<double> mean, var;
};
// Any block sums (one vector per seed) over 8 seeds.
inline Estimate EstimatedBlocks(const std::function<std::vector<double>(int seed)>& blocks) {
  constexpr int kSeeds = 8;
  std::vector<std::vector<double>> runs;
  for (int seed = 1; seed <= kSeeds; ++seed) runs.push_back(blocks(seed));
  const size_t n = runs[0].size();
  Estimate e{std::vector<double>(n, 0), std::vector<double>(n, 0)};
  for (size_t k = 0; k < n; ++k) {
    for (const auto& run : runs) e.mean[k] += run[k] / kSeeds;
    for (const auto& run : runs) e.var[k] += (run[k] - e.mean[k]) * (run[k] - e.mean[k]) / (kSeeds - 1) / kSeeds;
  }
  return e;
}
// The 8 x 8 blocks of a 32 x 32 render of scene(seed).
inline Estimate Estimated(const std::function<std::string(int seed)>& scene) {
  return EstimatedBlocks([&](int seed) { return Blocks(RenderXml(scene(seed)).image); });
}

// Two estimates of the same image agree block by block and in total within their measured
// noise; the total must be able to tell an error of `resolution`.
inline void ExpectSameImage(const Estimate& a, const Estimate& b, double resolution, const std::string& what) {
  double total_a = 0, total_b = 0, total_var = 0;
  for (size_t k = 0; k < a.mean.size(); ++k) {
    const double var = a.var[k] + b.var[k];
    EXPECT_NEAR(b.mean[k], a.mean[k], 5 * std::sqrt(var) + 1e-9) << "block " << k << "\n" << what;
    total_a += a.mean[k];
    total_b += b.mean[k];
    total_var += var;
  }
  EXPECT_GT(total_a, 0);
  EXPECT_NEAR(total_b, total_a, 4 * std::sqrt(total_var)) << what;
  EXPECT_LT(4 * std::sqrt(total_var), resolution * total_a) << what;
}

}  // namespace objektiv::test
