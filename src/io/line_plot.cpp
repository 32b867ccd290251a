#include "io/line_plot.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace objektiv {

namespace {
// A tick spacing of 1, 2 or 5 times a power of ten giving about `target` ticks.
double NiceStep(double range, int target) {
  double raw = range / target, p = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}
}  // namespace

Svg LinePlot(const std::string& title, const std::string& x_label, const std::string& y_label,
             const std::vector<PlotSeries>& series, double W, double H) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const PlotSeries& s : series)
    for (const Vec2d& p : s.points) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  if (x0 > x1) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (y1 - y0 < 1e-12 * std::max(1.0, std::abs(y0))) y0 -= 1, y1 += 1;
  if (x1 == x0) x1 = x0 + 1;
  // Include zero when the data come close to it, and round the range to ticks.
  if (y0 > 0 && y0 < 0.3 * y1) y0 = 0;
  if (y1 < 0 && y1 > 0.3 * y0) y1 = 0;
  double xs = NiceStep(x1 - x0, 6), ys = NiceStep(y1 - y0, 6);
  x0 = std::floor(x0 / xs) * xs, x1 = std::ceil(x1 / xs) * xs;
  y0 = std::floor(y0 / ys) * ys, y1 = std::ceil(y1 / ys) * ys;
  const double left = 70, right = 20, top = 40, bottom = 50;
  auto map = [&](Vec2d p) {
    return Vec2d(left + (p.x - x0) / (x1 - x0) * (W - left - right), H - bottom - (p.y - y0) / (y1 - y0) * (H - top - bottom));
  };
  Svg svg(W, H);
  svg.Text({W / 2, 22}, title, 15, "middle");
  for (double x = x0; x <= x1 + 1e-9 * xs; x += xs) {
    svg.Line(map({x, y0}), map({x, y1}), "#e4e4e4", 1);
    svg.Text(map({x, y0}) + Vec2d(0, 16), fmt::format("{:g}", std::abs(x) < 1e-12 * xs ? 0.0 : x), 11, "middle");
  }
  for (double y = y0; y <= y1 + 1e-9 * ys; y += ys) {
    svg.Line(map({x0, y}), map({x1, y}), "#e4e4e4", 1);
    svg.Text(map({x0, y}) + Vec2d(-6, 4), fmt::format("{:g}", std::abs(y) < 1e-12 * ys ? 0.0 : y), 11, "end");
  }
  svg.Line(map({x0, y0}), map({x1, y0}), "#333", 1.2);
  svg.Line(map({x0, y0}), map({x0, y1}), "#333", 1.2);
  if (y0 < 0 && y1 > 0) svg.Line(map({x0, 0}), map({x1, 0}), "#999", 1);
  svg.Text({(left + W - right) / 2, H - 12}, x_label, 12, "middle");
  svg.Text({14, top - 14}, y_label, 12, "start");
  for (size_t i = 0; i < series.size(); ++i) {
    std::vector<Vec2d> pts;
    for (const Vec2d& p : series[i].points) pts.push_back(map(p));
    if (series[i].dashed) {
      for (size_t k = 0; k + 1 < pts.size(); k += 2) svg.Line(pts[k], pts[k + 1], series[i].colour, 1.5);
    } else {
      svg.Polyline(pts, series[i].colour, 1.8);
    }
    svg.Text({W - right - 4, top + 14.0 * (i + 1)}, series[i].name, 11, "end", series[i].colour);
  }
  return svg;
}

}  // namespace objektiv
