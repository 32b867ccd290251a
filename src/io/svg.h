// A minimal SVG document builder for plots (lines, polylines, polygons, text).
#pragma once
#include <string>
#include <vector>

#include "base/vec.h"

namespace objektiv {

// What was drawn, for another canvas (the viewer draws the lens layout in its panel).
struct SvgShape {
  enum Kind { kPolyline, kPolygon, kCircle, kText } kind = kPolyline;
  std::vector<Vec2d> points;  // a polyline's or a polygon's; a circle's centre; a text's anchor point
  std::string stroke, fill;   // "#rrggbb" (or "none")
  double width = 1, opacity = 1;
  bool dashed = false;
  double radius = 0;  // a circle's
  std::string text, anchor;  // a text's ("start", "middle", "end")
  double size = 12;          // a text's font size
};

class Svg {
 public:
  Svg(double width, double height) : width_(width), height_(height) {}
  void Line(Vec2d a, Vec2d b, const std::string& stroke, double width = 1, const std::string& dash = "");
  void Polyline(const std::vector<Vec2d>& points, const std::string& stroke, double width = 1, double opacity = 1,
                const std::string& dash = "");
  void Polygon(const std::vector<Vec2d>& points, const std::string& fill, const std::string& stroke, double width = 1);
  void Circle(Vec2d centre, double radius, const std::string& fill, double opacity = 1);
  void Text(Vec2d at, const std::string& text, double size = 12, const std::string& anchor = "start",
            const std::string& fill = "#222");
  std::string ToString() const;
  double width() const { return width_; }
  double height() const { return height_; }
  const std::vector<SvgShape>& shapes() const { return shapes_; }
  // Written atomically (base/output_file.h); throws InputError naming the file on failure.
  void Write(const std::string& path) const;

 private:
  double width_, height_;
  std::vector<std::string> items_;
  std::vector<SvgShape> shapes_;
};

}  // namespace objektiv
