// XY line plots as SVG (axes with round-number ticks, several named series, a legend).
#pragma once
#include <string>
#include <vector>

#include "io/svg.h"

namespace objektiv {

struct PlotSeries {
  std::string name, colour;
  std::vector<Vec2d> points;
  bool dashed = false;
};

Svg LinePlot(const std::string& title, const std::string& x_label, const std::string& y_label,
             const std::vector<PlotSeries>& series, double width = 640, double height = 420);

}  // namespace objektiv
