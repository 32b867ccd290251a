#include "io/lens_analysis.h"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/error.h"
#include "base/output_file.h"
#include "io/lens_plot.h"
#include "optics/dispersion.h"
#include "io/line_plot.h"
#include "optics/paraxial.h"
#include "optics/real_ray_analysis.h"

namespace objektiv {

namespace {


std::vector<double> FieldSamples(double max_field, int n) {
  std::vector<double> f;
  for (int i = 0; i <= n; ++i) f.push_back(max_field * i / n);
  return f;
}

Svg SpotPlot(const LensSystem& lens, const std::vector<double>& fields, nlohmann::ordered_json* json) {
  const double lambdas[3] = {kLambdaF, kLambdad, kLambdaC};
  const char* colours[3] = {"#1f5fd1", "#1a9e3a", "#d12f1f"};
  const double panel = 210, pad = 30;
  Svg svg(pad + 3 * panel + 20, 60 + fields.size() * panel + 40);
  svg.Text({20, 26}, fmt::format("{}: spot diagrams (object at infinity)", lens.prescription().name), 15);
  // One scale for all panels: the largest spot sets it.
  std::vector<std::vector<Spot>> spots(fields.size());
  double extent = 1e-4;
  for (size_t f = 0; f < fields.size(); ++f)
    for (double l : lambdas) {
      spots[f].push_back(SpotDiagram(lens, fields[f], l, 31));
      extent = std::max(extent, spots[f].back().geometric_radius * 1.1);
    }
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (size_t f = 0; f < fields.size(); ++f) {
    Vec2d reference = spots[f][1].centroid;  // the d line's centroid
    for (int w = 0; w < 3; ++w) {
      const Spot& s = spots[f][w];
      Vec2d origin(pad + w * panel + panel / 2, 60 + f * panel + panel / 2);
      svg.Line(origin - Vec2d(panel / 2 - 8, 0), origin + Vec2d(panel / 2 - 8, 0), "#ddd", 1);
      svg.Line(origin - Vec2d(0, panel / 2 - 8), origin + Vec2d(0, panel / 2 - 8), "#ddd", 1);
      double scale = (panel / 2 - 12) / extent;
      for (const Vec2d& p : s.points)
        svg.Circle(origin + Vec2d((p.x - reference.x) * scale, -(p.y - reference.y) * scale), 0.9, colours[w], 0.7);
      svg.Text(origin + Vec2d(-panel / 2 + 10, -panel / 2 + 16),
               fmt::format("{:.1f} deg, {:.0f} nm", fields[f], lambdas[w]), 10, "start", colours[w]);
      svg.Text(origin + Vec2d(-panel / 2 + 10, panel / 2 - 6),
               fmt::format("RMS {:.2f} um, GEO {:.2f} um", s.rms_radius * 1000, s.geometric_radius * 1000), 10);
      rows.push_back({{"field_deg", fields[f]},
                      {"wavelength_nm", lambdas[w]},
                      {"rms_radius_um", s.rms_radius * 1000},
                      {"geometric_radius_um", s.geometric_radius * 1000},
                      {"transmitted", s.transmitted}});
    }
  }
  (*json)["spots"] = std::move(rows);
  svg.Text({pad, 60 + fields.size() * panel + 24},
           fmt::format("panel half-width {:.1f} um; spots centred on the d-line centroid", extent * 1000), 11);
  return svg;
}

}  // namespace

void WriteLensAnalysis(const LensSystem& lens, const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw InputError(fmt::format("{}: cannot create the directory: {}", directory, ec.message()));
  const LensPrescription& rx = lens.prescription();
  const ParaxialData& p = lens.paraxial();
  std::vector<double> fields3 = DefaultFields(lens, kLambdad);
  double max_field = fields3.back();
  // Absent values (rays that do not get through) are null.
  auto value = [](std::optional<double> v, double scale = 1) {
    return v ? nlohmann::ordered_json(*v * scale) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json json = {
      {"name", rx.name}, {"efl_mm", p.efl}, {"bfl_mm", p.bfl}, {"fnumber", p.fnumber}, {"max_field_deg", max_field},
      {"object_index", p.object_index}};

  SpotPlot(lens, fields3, &json).Write((fs::path(directory) / "spots.svg").string());

  std::vector<double> fields = FieldSamples(max_field, 24);
  PlotSeries dist{"distortion", "#1f5fd1", {}}, tan{"tangential", "#d12f1f", {}}, sag{"sagittal", "#1f5fd1", {}};
  PlotSeries ri{"relative illumination", "#1a9e3a", {}}, cos4{"cos^4", "#999", {}, true};
  nlohmann::ordered_json field_rows = nlohmann::ordered_json::array();
  for (size_t i = 0; i < fields.size(); ++i) {
    double f = fields[i];
    std::optional<double> d = f > 0 ? Distortion(lens, p.object_index * p.efl, f, kLambdad) : std::optional<double>(0.0);
    std::optional<FieldCurvature> fc = FieldCurvatureAt(lens, f, kLambdad);
    std::optional<double> r = RelativeIllumination(lens, f, kLambdad);
    std::optional<double> hf = RealImageHeight(lens, f, kLambdaF), hc = RealImageHeight(lens, f, kLambdaC);
    if (d) dist.points.push_back({f, *d * 100});
    if (fc) {
      tan.points.push_back({fc->tangential, f});
      sag.points.push_back({fc->sagittal, f});
    }
    if (r) ri.points.push_back({f, *r});
    double c = std::cos(f * M_PI / 180);
    cos4.points.push_back({f, c * c * c * c});
    field_rows.push_back({{"field_deg", f},
                          {"image_height_mm", value(RealImageHeight(lens, f, kLambdad))},
                          {"paraxial_image_height_mm", p.object_index * p.efl * std::tan(f * M_PI / 180)},
                          {"distortion_percent", value(d, 100)},
                          {"tangential_focus_mm", value(fc ? std::optional(fc->tangential) : std::nullopt)},
                          {"sagittal_focus_mm", value(fc ? std::optional(fc->sagittal) : std::nullopt)},
                          {"relative_illumination", value(r)},
                          {"lateral_colour_um", value(hf && hc ? std::optional(*hf - *hc) : std::nullopt, 1000)}});
  }
  json["fields"] = std::move(field_rows);
  LinePlot(rx.name + ": distortion", "field angle (deg)", "distortion (%)", {dist})
      .Write((fs::path(directory) / "distortion.svg").string());
  LinePlot(rx.name + ": field curvature", "focus relative to the film (mm)", "field angle (deg)", {tan, sag})
      .Write((fs::path(directory) / "field_curvature.svg").string());
  LinePlot(rx.name + ": relative illumination", "field angle (deg)", "relative illumination", {ri, cos4})
      .Write((fs::path(directory) / "relative_illumination.svg").string());

  // Axial colour: paraxial focus against wavelength, relative to the d line's, and the
  // longitudinal aberration across the pupil at three wavelengths.
  PlotSeries axial{"paraxial focus shift", "#a31fd1", {}};
  nlohmann::ordered_json colour_rows = nlohmann::ordered_json::array();
  for (int l = 400; l <= 700; l += 10) {
    double shift = lens.Paraxial(l).bfl - p.bfl;
    axial.points.push_back({shift, double(l)});
    colour_rows.push_back({{"wavelength_nm", l}, {"focus_shift_mm", shift}});
  }
  json["axial_colour"] = std::move(colour_rows);
  LinePlot(rx.name + ": axial colour", "focus shift from the d-line focus (mm)", "wavelength (nm)", {axial})
      .Write((fs::path(directory) / "axial_colour.svg").string());

  const double lambdas[3] = {kLambdaF, kLambdad, kLambdaC};
  const char* colours[3] = {"#1f5fd1", "#1a9e3a", "#d12f1f"};
  std::vector<PlotSeries> lsa;
  nlohmann::ordered_json lsa_rows = nlohmann::ordered_json::array();
  for (int w = 0; w < 3; ++w) {
    PlotSeries s{fmt::format("{:.0f} nm", lambdas[w]), colours[w], {}};
    for (int k = 1; k <= 20; ++k) {
      double h = p.entrance_pupil_diameter / 2 * k / 20;
      std::optional<double> a = LongitudinalAberration(lens, h, lambdas[w]);
      // Relative to the d-line paraxial focus, so the curves also show axial colour.
      double shift = lens.Paraxial(lambdas[w]).bfl - p.bfl;
      if (a) s.points.push_back({*a + shift, double(k) / 20});
      if (a) lsa_rows.push_back({{"wavelength_nm", lambdas[w]}, {"pupil", double(k) / 20}, {"focus_mm", *a + shift}});
    }
    lsa.push_back(s);
  }
  json["longitudinal_aberration"] = std::move(lsa_rows);
  LinePlot(rx.name + ": longitudinal aberration", "focus relative to the d-line paraxial focus (mm)",
           "pupil height (relative)", lsa)
      .Write((fs::path(directory) / "longitudinal_aberration.svg").string());

  WriteTextFileAtomically((fs::path(directory) / "analysis.json").string(), json.dump(2) + "\n");
}

}  // namespace objektiv
