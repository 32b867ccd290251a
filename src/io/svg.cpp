#include "io/svg.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "base/output_file.h"

namespace objektiv {

namespace {
std::string Points(const std::vector<Vec2d>& pts) {
  std::string s;
  for (const Vec2d& p : pts) s += fmt::format("{:.3f},{:.3f} ", p.x, p.y);
  return s;
}
std::string Escape(const std::string& t) {
  std::string r;
  for (char c : t) {
    if (c == '&') r += "&amp;";
    else if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else r += c;
  }
  return r;
}
}  // namespace

void Svg::Line(Vec2d a, Vec2d b, const std::string& stroke, double width, const std::string& dash) {
  shapes_.push_back({SvgShape::kPolyline, {a, b}, stroke, "none", width, 1, !dash.empty()});
  items_.push_back(fmt::format(R"(<line x1="{:.3f}" y1="{:.3f}" x2="{:.3f}" y2="{:.3f}" stroke="{}" stroke-width="{}"{}/>)",
                               a.x, a.y, b.x, b.y, stroke, width,
                               dash.empty() ? "" : fmt::format(R"( stroke-dasharray="{}")", dash)));
}

void Svg::Polyline(const std::vector<Vec2d>& pts, const std::string& stroke, double width, double opacity,
                   const std::string& dash) {
  shapes_.push_back({SvgShape::kPolyline, pts, stroke, "none", width, opacity, !dash.empty()});
  const std::string dashes = dash.empty() ? "" : fmt::format(R"( stroke-dasharray="{}")", dash);
  items_.push_back(fmt::format(R"(<polyline points="{}" fill="none" stroke="{}" stroke-width="{}" stroke-opacity="{}"{}/>)",
                               Points(pts), stroke, width, opacity, dashes));
}

void Svg::Polygon(const std::vector<Vec2d>& pts, const std::string& fill, const std::string& stroke, double width) {
  shapes_.push_back({SvgShape::kPolygon, pts, stroke, fill, width});
  items_.push_back(fmt::format(R"(<polygon points="{}" fill="{}" stroke="{}" stroke-width="{}"/>)", Points(pts), fill,
                               stroke, width));
}

void Svg::Circle(Vec2d c, double r, const std::string& fill, double opacity) {
  shapes_.push_back({SvgShape::kCircle, {c}, "none", fill, 0, opacity, false, r});
  items_.push_back(fmt::format(R"(<circle cx="{:.2f}" cy="{:.2f}" r="{:.2f}" fill="{}" fill-opacity="{}"/>)", c.x, c.y, r,
                               fill, opacity));
}

void Svg::Text(Vec2d at, const std::string& text, double size, const std::string& anchor, const std::string& fill) {
  // A line that would run past the right edge (a long lens name in a title) is set smaller: a
  // sans-serif glyph is about 0.56 of the font size wide on average.
  if (anchor == "start") {
    size_t glyphs = 0;
    for (unsigned char c : text) glyphs += (c & 0xC0) != 0x80;  // UTF-8 lead bytes
    const double wide = 0.56 * size * double(glyphs), room = width_ - at.x - 8;
    if (wide > room && room > 0) size = std::max(7.0, std::floor(size * room / wide * 10) / 10);
  }
  shapes_.push_back({SvgShape::kText, {at}, "none", fill, 0, 1, false, 0, text, anchor, size});
  items_.push_back(fmt::format(R"(<text x="{:.2f}" y="{:.2f}" font-family="sans-serif" font-size="{}" text-anchor="{}" fill="{}">{}</text>)",
                               at.x, at.y, size, anchor, fill, Escape(text)));
}

std::string Svg::ToString() const {
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      width_, height_);
  for (const std::string& i : items_) s += i + "\n";
  return s + "</svg>\n";
}

void Svg::Write(const std::string& path) const { WriteTextFileAtomically(path, ToString()); }

}  // namespace objektiv
