// `objektiv imgtool diff A B`: image comparison metrics, as pbrt's imgtool diff.
#include <cmath>
#include <cstring>

#include "app/commands.h"
#include "base/error.h"
#include "io/image_io.h"

namespace objektiv {
namespace {

struct DiffArgs {
  std::string a, b, metric = "rmse";
  double threshold = -1;
  bool exact = false;
};

// --exact: the same channels, and every value of every channel the same bits.
int ExactDiff(const DiffArgs& args, const Image& a, const Image& b) {
  if (a.channels != b.channels) {
    std::printf("the channels differ: %zu against %zu\n", a.channels.size(), b.channels.size());
    return 1;
  }
  size_t differ = 0, first = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0 && differ++ == 0) first = i;
  if (differ == 0) {
    std::printf("identical: %zu channels of %dx%d pixels, bit for bit\n", a.channels.size(), a.width, a.height);
    return 0;
  }
  const size_t nc = a.channels.size(), px = first / nc;
  std::printf("%zu values differ; the first: pixel (%zu, %zu) channel %s, %.9g in %s against %.9g\n", differ,
              px % size_t(a.width), px / size_t(a.width), a.channels[first % nc].c_str(), a.pixels[first],
              args.a.c_str(), b.pixels[first]);
  return 1;
}

int RunDiff(const DiffArgs& args) {
  Image a = ReadImageAny(args.a), b = ReadImageAny(args.b);
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "error: %s is %dx%d but %s is %dx%d\n", args.a.c_str(), a.width, a.height, args.b.c_str(),
                 b.width, b.height);
    return 2;
  }
  if (args.exact) return ExactDiff(args, a, b);
  // Compare the colour channels both have (RGB, or one grey channel).
  int nc = std::min({a.NumChannels(), b.NumChannels(), 3});
  double se = 0, rel = 0, ae = 0;
  size_t n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < nc; ++c) {
        double va = a.At(x, y, c), vb = b.At(x, y, c);
        if (!std::isfinite(va) || !std::isfinite(vb)) {
          std::fprintf(stderr, "error: non-finite pixel at (%d, %d)\n", x, y);
          return 2;
        }
        double d = va - vb;
        se += d * d;
        rel += d * d / (vb * vb + 1e-2);  // relative MSE against B as the reference
        ae += std::abs(d);
        ++n;
      }
  double rmse = std::sqrt(se / n), relmse = rel / n, mae = ae / n;
  std::printf("rmse %.6g\nrelmse %.6g\nmae %.6g\n", rmse, relmse, mae);
  double value = args.metric == "rmse" ? rmse : args.metric == "relmse" ? relmse : mae;
  if (args.threshold >= 0 && value > args.threshold) {
    std::printf("%s %.6g is above the threshold %.6g\n", args.metric.c_str(), value, args.threshold);
    return 1;
  }
  return 0;
}

}  // namespace

std::function<int()> AddImgtoolCommand(CLI::App& app) {
  auto args = std::make_shared<DiffArgs>();
  CLI::App* tool = app.add_subcommand("imgtool", "Image utilities");
  tool->require_subcommand(1);
  CLI::App* diff = tool->add_subcommand("diff", "Compare two images (any format OpenImageIO reads); exit 1 above --threshold");
  diff->add_option("a", args->a, "Image A")->required()->check(CLI::ExistingFile);
  diff->add_option("b", args->b, "Image B (the reference for relmse)")->required()->check(CLI::ExistingFile);
  CLI::Option* threshold =
      diff->add_option("--threshold", args->threshold, "Exit with status 1 when the metric exceeds this value")
          ->check(CLI::NonNegativeNumber);
  // All three metrics are printed; the choice only matters against a threshold.
  diff->add_option("--metric", args->metric, "Metric compared with the threshold: rmse, relmse or mae")
      ->check(CLI::IsMember({"rmse", "relmse", "mae"}))
      ->needs(threshold);
  diff->add_flag("--exact", args->exact,
                 "Compare every channel bit for bit instead (exit 1 unless the channels and all values are the same)")
      ->excludes(threshold);
  return [args] { return RunDiff(*args); };
}

}  // namespace objektiv
