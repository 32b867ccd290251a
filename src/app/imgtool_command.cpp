// `objektiv imgtool diff A B`: image comparison metrics, as pbrt's imgtool diff.
#include <cmath>

#include "app/commands.h"
#include "base/error.h"
#include "io/image_io.h"

namespace objektiv {
namespace {

struct DiffArgs {
  std::string a, b, metric = "rmse";
  double threshold = -1;
};

int RunDiff(const DiffArgs& args) {
  Image a = ReadImageAny(args.a), b = ReadImageAny(args.b);
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "error: %s is %dx%d but %s is %dx%d\n", args.a.c_str(), a.width, a.height, args.b.c_str(),
                 b.width, b.height);
    return 2;
  }
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
  return [args] { return RunDiff(*args); };
}

}  // namespace objektiv
