#include "app/lens_section.h"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

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
  std::vector<const SvgShape*> texts;
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
      case SvgShape::kText:
        // Below the drawing (its legend and caption, at the panel's text size, wrapped): drawn at
        // their places and sizes they were too small to read or, enlarged, overlapped and ran
        // past the panel's edges.
        texts.push_back(&s);
        break;
    }
  }
  draw->PopClipRect();
  ImGui::Dummy(ImVec2(width, height));
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
  for (const SvgShape* t : texts) {
    ImGui::PushStyleColor(ImGuiCol_Text, Colour(t->fill, 1));
    ImGui::TextUnformatted(t->text.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PopTextWrapPos();
}

}  // namespace objektiv
