#include "app/lens_section.h"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>

namespace objektiv {

namespace {

// "#rrggbb" (else grey) with an opacity.
ImU32 Colour(const std::string& hex, double opacity) {
  unsigned v = 0x888888;
  if (hex.size() == 7 && hex[0] == '#') v = unsigned(std::strtoul(hex.c_str() + 1, nullptr, 16));
  return IM_COL32((v >> 16) & 255, (v >> 8) & 255, v & 255, int(255 * opacity));
}

}  // namespace

void DrawLensSection(const Svg& plot, float width) {
  const float scale = width / float(plot.width());
  const float height = float(plot.height()) * scale;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner(origin.x + width, origin.y + height);
  draw->AddRectFilled(origin, corner, IM_COL32(255, 255, 255, 255));
  draw->PushClipRect(origin, corner, true);  // rays traced beyond the drawing stay in it
  auto at = [&](const Vec2d& p) { return ImVec2(origin.x + float(p.x) * scale, origin.y + float(p.y) * scale); };
  for (const SvgShape& s : plot.shapes()) {
    std::vector<ImVec2> pts;
    for (const Vec2d& p : s.points) pts.push_back(at(p));
    switch (s.kind) {
      case SvgShape::kPolyline:
        draw->AddPolyline(pts.data(), int(pts.size()), Colour(s.stroke, s.opacity), 0, float(s.width) * scale);
        break;
      case SvgShape::kPolygon:
        draw->AddPolyline(pts.data(), int(pts.size()), Colour(s.stroke, 1), ImDrawFlags_Closed, float(s.width) * scale);
        break;
      case SvgShape::kCircle:
        draw->AddCircleFilled(pts[0], float(s.radius) * scale, Colour(s.fill, s.opacity));
        break;
      case SvgShape::kText: {
        const float size = std::max(11.f, float(s.size) * scale * 1.4f);  // legible, if it overlaps a little
        ImFont* font = ImGui::GetFont();
        ImVec2 p = pts[0];
        const ImVec2 extent = font->CalcTextSizeA(size, width, 0, s.text.c_str());
        if (s.anchor == "middle") p.x -= extent.x / 2;
        if (s.anchor == "end") p.x -= extent.x;
        p.y -= extent.y * 0.8f;
        draw->AddText(font, size, p, Colour(s.fill, 1), s.text.c_str());
        break;
      }
    }
  }
  draw->PopClipRect();
  ImGui::Dummy(ImVec2(width, height));
}

}  // namespace objektiv
