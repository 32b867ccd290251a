// `objektiv lens list` and `objektiv lens info LENS`: the lens library's command-line face.
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/prescription_table.h"
#include "base/error.h"
#include "base/log.h"
#include "base/output_file.h"
#include "io/lens_analysis.h"
#include "io/image_io.h"
#include "io/lens_ghosts.h"
#include "io/lens_plot.h"
#include "io/lens_psf.h"
#include "optics/crystal_images.h"
#include "optics/anamorphic.h"
#include "optics/coating_library.h"
#include "optics/dispersion.h"
#include "optics/focusing.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/paraxial.h"
#include "optics/real_fnumber.h"
#include "optics/real_ray_analysis.h"

namespace objektiv {
namespace {

struct LensArgs {
  std::string lens, output;
  std::vector<double> fields;
  double wavelength = kLambdad;
  double focus_m = 0;  // 0: infinity
  std::string sensor = "36x24";
  std::optional<std::string> coating;  // every air-glass surface's, instead of the file's
  // lens psf, lens ghosts
  double fnumber = 0;          // 0: wide open
  double psf_wavelength = 0;   // 0: white light
  double field = 10, azimuth = 0;  // degrees: where the bright point lies
  int width = 768, grid = 64;
  int blades = 0, size = 256;
  double blade_curvature = 0, blade_rotation = 0;
  double pixel_um = 0;         // 0: a quarter of lambda N (550 nm for white light)
  bool json = false;
  std::string section = "y";  // lens plot, lens analyze: the principal section (x: an anamorphic lens's horizontal)
};

// "36x24" -> (36, 24) mm.
std::pair<double, double> ParseSensor(const std::string& s) {
  double w = 0, h = 0;
  char x = 0;
  int used = 0;
  if (std::sscanf(s.c_str(), "%lf%c%lf%n", &w, &x, &h, &used) != 3 || size_t(used) != s.size() || (x != 'x' && x != 'X') ||
      !(w > 0 && w <= 1e4) || !(h > 0 && h <= 1e4))
    throw CLI::ValidationError("--sensor", "expects WIDTHxHEIGHT in mm, each above 0 and at most 10000, e.g. 36x24");
  return {w, h};
}

// The lens commands describe imaging lenses (an afocal system has no finite first-order data),
// set up as AtParaxialInfinityFocus takes them: fully open, at the paraxial focus.
// --coating: every air-glass surface coated so (nothing asked: as the file says).
void Recoat(LensPrescription& lens, const std::optional<std::string>& coating) {
  if (!coating) return;
  try {
    Recoat(lens, CoatingForLens(*coating, lens));
  } catch (const InputError& e) {  // a bad command-line value: exit status 2
    throw CLI::ValidationError("--coating", e.what());
  }
}

LensSystem LoadImagingLens(const std::string& name, double lambda_nm, const std::optional<std::string>& coating = {}) {
  LensPrescription lens = LoadLens(name, GlassCatalog::Default());
  Recoat(lens, coating);
  double efl = ComputeParaxial(lens, lambda_nm).efl;
  if (!std::isfinite(efl) || std::abs(efl) > 1e12)
    throw InputError(fmt::format("{}: the lens has no optical power (afocal): it forms no image", name));
  return AtParaxialInfinityFocus(std::move(lens), lambda_nm);
}

// One row per shipped lens file: the name alone loads the first format of kLensFileExtensions,
// a lens shipped in another format too is listed again with its extension. The paraxial
// f-number (EFL / entrance pupil) and the real one (radiometric, what a scene's `fnumber`
// is compared with) both, since they differ for lenses with pupil aberration.
// How far the vertices of a folded (mirror) lens spread along the axis.
double VertexSpan(const LensSystem& lens) {
  double lo = 0, hi = 0;
  for (int i = 0; i < lens.SurfaceCount(); ++i) lo = std::min(lo, lens.VertexZ(i)), hi = std::max(hi, lens.VertexZ(i));
  return hi - lo;
}

int RunList() {
  std::printf("%-28s %10s %8s %8s  %s\n", "name", "EFL (mm)", "f/ parax", "f/ real", "source");
  const std::filesystem::path dir = std::filesystem::path(DataDirectory()) / "lenses";
  for (const std::string& name : ShippedLensNames()) {
    bool first = true;
    for (const char* ext : kLensFileExtensions) {
      if (!std::filesystem::is_regular_file(dir / (name + ext))) continue;
      const std::string shown = first ? name : name + ext;
      first = false;
      const LensSystem lens(LoadLens(shown, GlassCatalog::Default()));
      // An anamorphic's squeeze before its source (the EFL is its y-z section's).
      const std::string squeeze =
          lens.prescription().HasToroids()
              ? fmt::format("anamorphic, squeeze {:.2f}x; ", ComputeAnamorphosis(lens.prescription(), lens.paraxial()).squeeze)
              : "";
      std::printf("%-28s %10.3f %8.2f %8.2f  %s%s\n", shown.c_str(), lens.paraxial().efl, lens.paraxial().fnumber,
                  WideOpenFNumber(lens.prescription()), squeeze.c_str(), lens.prescription().source.c_str());
    }
  }
  return 0;
}

int RunInfo(const LensArgs& a) {
  const LensSystem system = LoadImagingLens(a.lens, a.wavelength, a.coating);
  const LensPrescription& lens = system.prescription();
  ParaxialData d = system.Paraxial(a.wavelength);
  int stop = system.StopIndex();
  double stop_diameter = 2 * system.StopSemiDiameter();
  std::optional<FocusSolution> focus;
  if (a.focus_m > 0) {
    focus = FocusAtDistance(lens, a.focus_m * 1000, a.wavelength);
    if (!focus)
      throw InputError(fmt::format("{}: cannot focus at {} m from the film (closer than the front focal point allows "
                                   "with unit focusing)",
                                   a.lens, a.focus_m));
  }
  auto [sw, sh] = ParseSensor(a.sensor);
  FieldOfView fov = SensorFieldOfView(system, sw, sh, a.wavelength);
  double real_bfl = RealBackFocus(system, a.wavelength);
  nlohmann::ordered_json j = {{"name", lens.name},
                              {"wavelength_nm", a.wavelength},
                              {"efl_mm", d.efl},
                              {"bfl_mm", d.bfl},
                              {"ffl_mm", d.ffl},
                              {"fnumber", d.fnumber},
                              {"entrance_pupil_diameter_mm", d.entrance_pupil_diameter},
                              {"entrance_pupil_position_mm", d.entrance_pupil_position},
                              {"exit_pupil_diameter_mm", d.exit_pupil_diameter},
                              {"exit_pupil_position_mm", d.exit_pupil_position},
                              {"front_principal_plane_mm", d.front_principal_plane},
                              {"back_principal_plane_mm", d.back_principal_plane},
                              {"stop_diameter_mm", stop_diameter},
                              {"total_track_mm", lens.TotalTrack()},
                              {"object_medium", lens.object_medium ? MediumLabel(lens.object_medium) : "air"},
                              {"object_index", d.object_index},
                              {"surfaces", lens.surfaces.size()},
                              {"prescription", PrescriptionJson(lens)},
                              {"real_bfl_mm", real_bfl},
                              {"sensor_mm", {sw, sh}},
                              {"fov_horizontal_deg", fov.horizontal},
                              {"fov_vertical_deg", fov.vertical},
                              {"fov_diagonal_deg", fov.diagonal}};
  if (!std::isfinite(fov.diagonal)) j["fov_diagonal_deg"] = nullptr;
  // An anamorphic lens: its x-z section's first-order data and the squeeze.
  std::optional<Anamorphosis> anamorphic;
  if (lens.HasToroids()) {
    anamorphic = ComputeAnamorphosis(lens, d, a.wavelength, system.StopSemiDiameter());
    j["squeeze"] = anamorphic->squeeze;
    j["efl_x_mm"] = anamorphic->x.efl;
    j["bfl_x_mm"] = anamorphic->x.bfl;
    j["fnumber_x"] = anamorphic->x.fnumber;
    j["entrance_pupil_diameter_x_mm"] = anamorphic->x.entrance_pupil_diameter;
  }
  const AxialTransmittance transmittance = AxialTransmittanceOf(system, a.wavelength);
  j["axial_transmittance"] = transmittance.Total();
  // A central obstruction's share of the on-axis cone (sines: an aplanatic lens's pupil area).
  const double hidden = ObstructionRatio(system, a.wavelength);
  const std::optional<double> hidden_from = ObstructionFNumber(system, a.wavelength);
  j["obstruction_share"] = hidden * hidden;
  j["axial_surface_transmittance"] = transmittance.surfaces;
  j["axial_glass_transmittance"] = transmittance.glass;
  // Birefringent crystals: each one's extraordinary image of an on-axis point, off the ordinary
  // one, and how far each spreads.
  const std::optional<CrystalImages> double_images = CrystalImagesOf(system, a.wavelength);
  if (double_images) {
    nlohmann::ordered_json offsets = nlohmann::ordered_json::array(), spreads = nlohmann::ordered_json::array();
    for (const std::optional<CrystalImage>& e : double_images->extraordinary) {
      offsets.push_back(e ? nlohmann::ordered_json{e->offset.x, e->offset.y} : nlohmann::ordered_json());
      spreads.push_back(e ? nlohmann::ordered_json(e->rms) : nlohmann::ordered_json());
    }
    j["extraordinary_image_offsets_mm"] = offsets;
    j["extraordinary_image_rms_mm"] = spreads;
    j["ordinary_image_rms_mm"] = double_images->ordinary_rms;
  }
  // Each coating and the surfaces (1-based rows) that carry it.
  std::vector<std::pair<std::shared_ptr<const Coating>, std::vector<int>>> coatings;
  for (int i = 0; i < system.SurfaceCount(); ++i) {
    const std::shared_ptr<const Coating>& c = lens.surfaces[i].coating;
    if (!c || !system.Coated(i)) continue;
    auto it = std::find_if(coatings.begin(), coatings.end(), [&](const auto& e) { return e.first->name() == c->name(); });
    if (it == coatings.end()) it = coatings.insert(coatings.end(), {c, {}});
    it->second.push_back(i + 1);
  }
  j["coatings"] = nlohmann::ordered_json::array();
  for (const auto& [c, rows] : coatings)
    j["coatings"].push_back({{"name", c->name()}, {"layers", c->Describe()}, {"surfaces", rows}});
  // The file's own metadata (native .lens files), where given.
  std::string design;
  auto add_design = [&](double v, const char* text, const char* key) {
    if (!(v > 0)) return;
    design += fmt::format(" {} {:g}", text, v);
    j[key] = v;
  };
  add_design(lens.design_focal_length, "focal length (mm)", "design_focal_length_mm");
  add_design(lens.design_fnumber, "f-number", "design_fnumber");
  add_design(lens.image_circle, "image circle (mm)", "image_circle_mm");
  if (focus) {
    j["focus_distance_m"] = a.focus_m;
    j["back_focus_mm"] = focus->back_focus;
    j["object_distance_mm"] = focus->object_to_first_vertex;
    j["magnification"] = focus->magnification;
    j["working_fnumber"] = focus->working_fnumber;
  }
  if (a.json) {
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  std::printf("%s (%s)\n", lens.name.c_str(), lens.source.c_str());
  if (!design.empty()) std::printf("  design (as the file states it):%s\n", design.c_str());
  std::printf("  %zu surfaces, stop at row %d (diameter %.3f mm), total track %.3f mm%s\n", lens.surfaces.size(),
              stop + 1, stop_diameter, lens.TotalTrack(),
              lens.MirrorCount() > 0 ? fmt::format(" (first to last vertex; folded by {} mirrors, the vertices span {:.3f} mm)",
                                                   lens.MirrorCount(), VertexSpan(system)).c_str() : "");
  if (lens.object_medium)
    std::printf("  object space: %s (n %.5f): field angles are the scene's, in that medium\n",
                MediumLabel(lens.object_medium).c_str(), d.object_index);
  std::printf("%s", PrescriptionTable(lens).c_str());
  if (!lens.Centred())
    std::printf("  decentred or tilted surfaces: the f-number, first-order data and field of view below are the lens's\n"
                "  centred on its axis\n");
  std::printf("  paraxial, object at infinity, %.2f nm:\n", a.wavelength);
  std::printf("  EFL %.4f mm   BFL %.4f mm   FFL %.4f mm   f/%.3f\n", d.efl, d.bfl, d.ffl, d.fnumber);
  // A pupil ten thousand focal lengths away is at infinity: the lens is telecentric on that side
  // (its diameter and position grow without bound as the chief ray's slope goes to zero).
  auto pupil = [&](const char* label, double diameter, double position, const char* vertex, const char* rays) {
    if (std::isfinite(position) && std::abs(position) <= 1e4 * std::max(1.0, std::abs(d.efl)))
      std::printf("  %s diameter %.4f mm, %.4f mm behind the %s vertex\n", label, diameter, position, vertex);
    else
      std::printf("  %s at infinity (telecentric: the chief rays %s parallel to the axis)\n", label, rays);
  };
  pupil("entrance pupil:", d.entrance_pupil_diameter, d.entrance_pupil_position, "first", "enter");
  pupil("exit pupil:    ", d.exit_pupil_diameter, d.exit_pupil_position, "last", "leave");
  std::printf("  principal planes: front %.4f mm from the first vertex, back %.4f mm from the last\n",
              d.front_principal_plane, d.back_principal_plane);
  std::printf("  real back focus (smallest on-axis spot): %.4f mm\n", real_bfl);
  if (anamorphic) {
    const double q = anamorphic->squeeze;
    const std::string effect =
        std::abs(q - 1) < 5e-4 ? "no squeeze: both sections have the same focal length"
        : q > 1 ? fmt::format("squeeze {:.3f}x, the scene is squeezed horizontally on the film (a scene's\n"
                              "  desqueeze=\"lens\" stretches the picture back)", q)
                : fmt::format("squeeze {:.3f}x, the scene is stretched horizontally on the film (a scene's\n"
                              "  desqueeze=\"lens\" squeezes the picture back)", q);
    std::printf("  anamorphic: the paraxial data above are the y-z section's (vertical); the x-z section's (horizontal):\n"
                "  EFL %.4f mm   BFL %.4f mm (its focus %.4f mm from the y-z one's)   f/%.3f, entrance pupil %.4f mm wide\n"
                "  %s\n",
                anamorphic->x.efl, anamorphic->x.bfl, anamorphic->focus_split, anamorphic->x.fnumber,
                anamorphic->x.entrance_pupil_diameter, effect.c_str());
  }
  if (std::isfinite(fov.diagonal))
    std::printf("  field of view on %gx%g mm (real chief rays): %.2f x %.2f deg, %.2f deg diagonal\n", sw, sh,
                fov.horizontal, fov.vertical, fov.diagonal);
  else
    std::printf("  field of view on %gx%g mm (real chief rays in each section): %.2f x %.2f deg\n", sw, sh,
                fov.horizontal, fov.vertical);
  if (transmittance.Total() > 0)
    std::printf("  on-axis transmittance at %.2f nm: %.1f%% (surfaces: reflections and mirrors %.1f%%, glass absorption %.1f%%)\n",
                a.wavelength, 100 * transmittance.Total(), 100 * transmittance.surfaces, 100 * transmittance.glass);
  else
    std::printf("  on-axis transmittance at %.2f nm: no ray parallel to the axis gets through\n", a.wavelength);
  if (double_images) {
    // -0.0000 printed as 0.0000.
    auto mm = [](double v) { return std::abs(v) < 5e-5 ? 0.0 : v; };
    std::printf("  birefringent crystals: the data above are the ordinary waves'; an on-axis point's ordinary image spreads "
                "%.4f mm RMS on the film; its extraordinary image\n", double_images->ordinary_rms);
    for (size_t k = 0, row = 0; k < double_images->extraordinary.size(); ++k, ++row) {
      while (!lens.surfaces[row].crystal) ++row;
      if (const std::optional<CrystalImage>& e = double_images->extraordinary[k])
        std::printf("    crystal after row %zu: %.4f mm from the ordinary one (x %.4f, y %.4f mm), spread %.4f mm RMS\n",
                    row + 1, mm(std::hypot(e->offset.x, e->offset.y)), mm(e->offset.x), mm(e->offset.y), e->rms);
      else
        std::printf("    crystal after row %zu: no ray parallel to the axis reaches the film\n", row + 1);
    }
  }
  if (hidden > 0 && hidden_from)
    std::printf("  central obstruction: hides %.1f%% of the on-axis cone (the f-number's light, a T-stop effect); "
                "stopped down to f/%.3g it hides all\n", 100 * hidden * hidden, *hidden_from);
  if (coatings.empty()) std::printf("  coatings: none (bare glass)\n");
  for (const auto& [c, rows] : coatings) {
    std::string list;
    for (int r : rows) list += fmt::format("{}{}", list.empty() ? "" : ", ", r);
    std::printf("  coating %s on row%s %s: %s\n", c->name().c_str(), rows.size() > 1 ? "s" : "", list.c_str(), c->Describe().c_str());
  }
  if (focus)
    std::printf("  focused at %.4g m from the film (unit focusing): back focus %.4f mm, object %.2f mm in front of the\n"
                "  first vertex, magnification %.6f, working f-number %.3f\n",
                a.focus_m, focus->back_focus, focus->object_to_first_vertex, focus->magnification, focus->working_fnumber);
  return 0;
}

// The lens in the principal section asked for: as it is for y (the vertical, the analyses'
// own plane), turned a quarter about its axis for x (optics/anamorphic.h: its x-z section
// then lies in the analyses' plane; the same film). A rotationally symmetric lens is the same.
LensSystem InSection(LensSystem lens, const std::string& section) {
  if (section == "y") return lens;
  if (lens.prescription().RotationallySymmetric())
    spdlog::info("{} is rotationally symmetric: its x-z section is its y-z section", lens.prescription().name);
  return XSectionSystem(lens);
}

// Analyses that trace each ray once follow the crystals' ordinary waves: said where it applies.
void WarnOrdinaryWavesOnly(const LensSystem& lens, const char* what) {
  if (lens.prescription().CrystalCount() > 0)
    spdlog::warn("{} has birefringent crystals: {} traced for their ordinary waves only (lens info gives where each "
                 "extraordinary image lies)", lens.prescription().name, what);
}

int RunAnalyze(const LensArgs& a) {
  const LensSystem lens = InSection(LoadImagingLens(a.lens, kLambdad), a.section);
  WarnOrdinaryWavesOnly(lens, "the analyses are");
  WriteLensAnalysis(lens, a.output);
  return 0;
}

int RunPlot(const LensArgs& a) {
  // An output that cannot be written is a bad command-line value (exit status 2), as for render.
  try {
    CheckOutputFile(a.output);
  } catch (const InputError& e) {
    throw CLI::ValidationError(fmt::format("the plot cannot be written: {}", e.what()));
  }
  const LensSystem system = InSection(LoadImagingLens(a.lens, a.wavelength), a.section);
  std::vector<double> fields = a.fields.empty() ? DefaultFields(system, a.wavelength) : a.fields;
  PlotLensLayout(system, fields, a.wavelength).Write(a.output);
  return 0;
}

// An EXR output (the pictures' values are linear fractions of the light: no other format
// keeps them) that can be written; else a bad command-line value (exit status 2).
void CheckExrOutput(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".exr") throw CLI::ValidationError("-o", fmt::format("'{}': the output is an OpenEXR file (.exr)", path));
  try {
    CheckOutputFile(path);
  } catch (const InputError& e) {
    throw CLI::ValidationError(fmt::format("the picture cannot be written: {}", e.what()));
  }
}

// The lens with its stop as asked (f-number, blades) and coated as asked, at its paraxial
// focus for infinity.
LensSetup SetUpStop(const LensArgs& a) {
  if (a.blades == 1 || a.blades == 2) throw CLI::ValidationError("--blades", "blades must be 0 (round) or at least 3");
  if (a.blades == 0 && (a.blade_curvature != 0 || a.blade_rotation != 0))
    spdlog::warn("--blade-curvature and --blade-rotation do nothing without --blades: the stop is round");
  // Degrees reduced first: a turn by whole circles changes nothing, however large.
  const StopShape opening = StopShape::Iris(a.blades, a.blade_curvature, std::fmod(a.blade_rotation, 360.0) * M_PI / 180);
  LensPrescription lens = LoadLens(a.lens, GlassCatalog::Default());
  const double efl = ComputeParaxial(lens, kLambdad).efl;
  if (!std::isfinite(efl) || std::abs(efl) > 1e12)
    throw InputError(fmt::format("{}: the lens has no optical power (afocal): it forms no image", a.lens));
  if (efl < 0)
    throw InputError(fmt::format("{}: a negative EFL ({:.4g} mm): the lens forms no real image of a distant point", a.lens, efl));
  Recoat(lens, a.coating);
  try {
    return SetUpLens(std::move(lens), {a.fnumber, 0, opening}, {INFINITY, FocusRequest::From::kFilm, false});
  } catch (const InputError& e) {
    if (a.fnumber > 0) throw CLI::ValidationError("--fnumber", e.what());
    throw;
  }
}

// The ghosts of a distant bright point in the field.
int RunGhosts(const LensArgs& a) {
  CheckExrOutput(a.output);
  const LensSetup setup = SetUpStop(a);
  WarnOrdinaryWavesOnly(setup.lens, "the ghosts and the direct image are");
  GhostPictureRequest q;
  q.field_deg = a.field;
  q.azimuth_deg = a.azimuth;
  std::tie(q.sensor_width, q.sensor_height) = ParseSensor(a.sensor);
  q.width = a.width;
  // The height follows the sensor's aspect: bounded as the width is.
  if (double(a.width) * q.sensor_height / q.sensor_width > 16384)
    throw CLI::ValidationError("--width", fmt::format("the picture would be {:.0f} pixels high for the {} sensor (at most 16384)",
                                                      double(a.width) * q.sensor_height / q.sensor_width, a.sensor));
  q.grid = a.grid;
  if (a.psf_wavelength > 0) q.lambda_nm = a.psf_wavelength;
  const GhostPicture picture = PictureGhosts(setup.lens, q);
  // What the picture is, in its header (wavelength 0: white light).
  WriteExr(a.output, picture.image,
           {{"objektiv:fnumber", setup.fnumber}, {"objektiv:field_deg", a.field}, {"objektiv:azimuth_deg", a.azimuth},
            {"objektiv:wavelength_nm", a.psf_wavelength}, {"objektiv:blades", a.blades},
            {"objektiv:sensor_width_mm", q.sensor_width}, {"objektiv:sensor_height_mm", q.sensor_height},
            {"objektiv:grid", a.grid}, {"objektiv:total_share", picture.total_share},
            {"objektiv:direct_share", picture.direct_share}});
  nlohmann::ordered_json ghosts = nlohmann::ordered_json::array();
  for (const GhostShare& g : picture.ghosts)
    ghosts.push_back({{"surfaces", {g.ghost.first + 1, g.ghost.second + 1}}, {"share", g.share}});
  nlohmann::ordered_json j = {{"lens", a.lens},
                              {"fnumber", setup.fnumber},
                              {"field_deg", a.field},
                              {"azimuth_deg", a.azimuth},
                              {"wavelength_nm", a.psf_wavelength > 0 ? nlohmann::ordered_json(a.psf_wavelength) : nlohmann::ordered_json("white (D65, 400-700 nm)")},
                              {"blades", a.blades},
                              {"blade_curvature", a.blade_curvature},
                              {"blade_rotation_deg", a.blade_rotation},
                              {"coating", a.coating ? nlohmann::ordered_json(*a.coating) : nlohmann::ordered_json("as the lens file says")},
                              {"sensor", a.sensor},
                              {"width", a.width},
                              {"grid", a.grid},
                              {"direct_share", picture.direct_share},
                              {"total_share", picture.total_share},
                              {"ghosts", ghosts},
                              {"output", a.output}};
  if (a.json) {
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  std::printf("%s at f/%.3g%s%s, a distant point %g deg off the axis: of the light it sends onto the front element, "
              "%zu two-reflection ghosts carry %.4g%% (its own image %.4g%%) -> %s\n",
              a.lens.c_str(), setup.fnumber, a.coating ? ", coating " : "", a.coating ? a.coating->c_str() : "", a.field,
              picture.ghosts.size(), 100 * picture.total_share, 100 * picture.direct_share, a.output.c_str());
  for (size_t i = 0; i < std::min<size_t>(8, picture.ghosts.size()); ++i)
    std::printf("  rows %2d and %2d: %.4g%%\n", picture.ghosts[i].ghost.first + 1, picture.ghosts[i].ghost.second + 1,
                100 * picture.ghosts[i].share);
  return 0;
}

// The stop's diffraction pattern at the f-number asked for (set as a scene sets it: the
// radiometric f-number, which is the working f-number for an object at infinity).
int RunPsf(const LensArgs& a) {
  CheckExrOutput(a.output);
  LensSetup setup = SetUpStop(a);
  const StopShape& opening = setup.lens.stop_shape();
  const double n = setup.fnumber;
  const double reference_nm = a.psf_wavelength > 0 ? a.psf_wavelength : 550.0;
  const double pitch = a.pixel_um > 0 ? a.pixel_um : reference_nm * 1e-3 * n / 4;
  // A mirror lens's central obstruction takes the middle out of the pupil.
  const double hidden = ObstructionRatio(setup.lens);
  const PupilFunction pupil = [&opening, hidden](double u, double v) {
    return u * u + v * v >= hidden * hidden && opening.Contains(u, v) ? 1.0 : 0.0;
  };
  Image image;
  try {
    image = DiffractionImage(pupil, n, a.psf_wavelength > 0 ? std::optional<double>(a.psf_wavelength) : std::nullopt, pitch, a.size);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--size/--pixel", e.what());
  }
  // What the picture is, in its header (wavelength 0: white light).
  WriteExr(a.output, image,
           {{"objektiv:fnumber", n}, {"objektiv:wavelength_nm", a.psf_wavelength}, {"objektiv:blades", a.blades},
            {"objektiv:pixel_um", pitch}, {"objektiv:axis_pixel", a.size / 2}});
  const double ring = FirstDarkRingUm(pupil, reference_nm, n);
  nlohmann::ordered_json j = {{"lens", a.lens},
                              {"fnumber", n},
                              {"wavelength_nm", a.psf_wavelength > 0 ? nlohmann::ordered_json(a.psf_wavelength) : nlohmann::ordered_json("white (D65, 400-700 nm)")},
                              {"blades", a.blades},
                              {"pixel_um", pitch},
                              {"size", a.size},
                              {"first_dark_ring_um", ring},
                              {"obstruction_ratio", hidden},
                              {"first_dark_ring_wavelength_nm", reference_nm},
                              {"output", a.output}};
  if (a.json) {
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("%s at f/%.3g, %s: %d x %d pixels of %.4g um -> %s\n", a.lens.c_str(), n,
                a.psf_wavelength > 0 ? fmt::format("{:g} nm", a.psf_wavelength).c_str() : "white light", a.size, a.size,
                pitch, a.output.c_str());
    if (std::isfinite(ring))
      std::printf("  first dark ring (azimuthal mean) at %.3f um for %g nm (1.22 lambda N = %.3f um)\n", ring, reference_nm,
                  1.22 * reference_nm * 1e-3 * n);
    else
      std::printf("  no dark ring in the azimuthal mean within 4 lambda N (%.3f um)\n", 4 * reference_nm * 1e-3 * n);
  }
  return 0;
}

}  // namespace

// A number that is finite (CLI::Range lets NaN through).
const CLI::Validator kFinite(
    [](std::string& text) {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      return std::isfinite(v) ? std::string() : std::string("not a finite number: ") + text;
    },
    "FINITE");

// The stop and coating options of `lens psf` and `lens ghosts`.
void AddStopOptions(CLI::App* cmd, LensArgs& a) {
  cmd->add_option("--fnumber", a.fnumber, "f-number, as a scene sets it (default: wide open)")->check(kFinite)->check(CLI::Range(0.1, 1e4));
  cmd->add_option("--blades", a.blades, "Iris blades (0: round)")->check(CLI::Range(0, 64));
  cmd->add_option("--blade-curvature", a.blade_curvature, "0 straight .. 1 round")->check(kFinite)->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--blade-rotation", a.blade_rotation, "Degrees from +x to the iris's first corner")->check(kFinite);
}

std::function<int()> AddLensCommand(CLI::App& app) {
  auto args = std::make_shared<LensArgs>();
  CLI::App* lens = app.add_subcommand("lens", "The lens library: shipped lenses and first-order data");
  lens->require_subcommand(1);
  CLI::App* list = lens->add_subcommand("list", "List the shipped lenses with focal length, f-number and source");
  CLI::App* info = lens->add_subcommand("info", "Paraxial data of a lens (a file, or a shipped lens by name)");
  const std::string lens_help =
      fmt::format("Lens file ({}) or shipped lens name, e.g. dgauss.50mm", LensFileExtensionList());
  info->add_option("lens", args->lens, lens_help)->required();
  info->add_option("--wavelength", args->wavelength, "Wavelength in nm (default: the d line, 587.56)")
      ->check(kFinite)->check(CLI::Range(300.0, 2500.0));
  info->add_option("--focus", args->focus_m, "Also focus on an object this many metres from the film (unit focusing)")
      ->check(CLI::PositiveNumber);
  info->add_option("--sensor", args->sensor, "Sensor size WIDTHxHEIGHT in mm for the field of view (default 36x24)");
  info->add_option("--coating", args->coating,
                   "Coat every air-glass surface so (none, MgF2[@NM], multi[@NM], I.xx, or one the lens file defines)");
  info->add_flag("--json", args->json, "Print the figures as a JSON object");
  CLI::App* plot = lens->add_subcommand("plot", "Draw the lens layout (elements, stop, ray fans) as SVG");
  plot->add_option("lens", args->lens, lens_help)->required();
  plot->add_option("-o,--output", args->output, "Output SVG file")->required();
  plot->add_option("--fields", args->fields, "Field angles in degrees (default: 0, 70% and 100% of the field)")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 89.0));
  plot->add_option("--wavelength", args->wavelength, "Wavelength in nm")->check(kFinite)->check(CLI::Range(300.0, 2500.0));
  const char* section_help = "Principal section: y (vertical, default) or x (horizontal: an anamorphic lens's other one)";
  plot->add_option("--section", args->section, section_help)->check(CLI::IsMember({"x", "y"}));
  CLI::App* analyze = lens->add_subcommand(
      "analyze", "Real-ray analysis: spot diagrams, distortion, field curvature, relative illumination, colour (SVG + JSON)");
  analyze->add_option("lens", args->lens, lens_help)->required();
  analyze->add_option("-o,--output", args->output, "Output directory")->required();
  analyze->add_option("--section", args->section, section_help)->check(CLI::IsMember({"x", "y"}));
  CLI::App* psf = lens->add_subcommand("psf", "The stop's diffraction pattern (Fraunhofer PSF) as an EXR, with its first dark ring");
  psf->add_option("lens", args->lens, lens_help)->required();
  psf->add_option("-o,--output", args->output, "Output EXR file")->required();
  AddStopOptions(psf, *args);
  psf->add_option("--wavelength", args->psf_wavelength, "One wavelength in nm (default: white light, 400-700 nm)")
      ->check(kFinite)->check(CLI::Range(300.0, 2500.0));
  psf->add_option("--pixel", args->pixel_um, "Pixel pitch in micrometres on the sensor (default: lambda N / 4)")
      ->check(kFinite)->check(CLI::Range(1e-3, 1e4));
  psf->add_option("--size", args->size, "Pixels per side (default 256)")->check(CLI::Range(1, 2048));
  psf->add_flag("--json", args->json, "Print the figures as a JSON object");
  CLI::App* ghosts = lens->add_subcommand("ghosts", "The two-reflection ghosts of a distant bright point, as an EXR, with each ghost's share of the light");
  ghosts->add_option("lens", args->lens, lens_help)->required();
  ghosts->add_option("-o,--output", args->output, "Output EXR file")->required();
  ghosts->add_option("--field", args->field, "Degrees off the axis (default 10)")->check(kFinite)->check(CLI::Range(0.0, 89.0));
  ghosts->add_option("--azimuth", args->azimuth, "Degrees: the direction in the picture (0: left, 90: up)")->check(kFinite);
  AddStopOptions(ghosts, *args);
  ghosts->add_option("--coating", args->coating, "Coat every air-glass surface so (none, MgF2[@NM], multi[@NM], I.xx, ...)");
  ghosts->add_option("--sensor", args->sensor, "Sensor size WIDTHxHEIGHT in mm (default 36x24)");
  ghosts->add_option("--width", args->width, "Picture width in pixels (default 768)")->check(CLI::Range(1, 16384));
  ghosts->add_option("--grid", args->grid, "Rays per side of each ghost's bundle (default 64)")->check(CLI::Range(2, 1024));
  ghosts->add_option("--wavelength", args->psf_wavelength, "One wavelength in nm (default: white light)")->check(kFinite)->check(CLI::Range(300.0, 2500.0));
  ghosts->add_flag("--json", args->json, "Print the figures as a JSON object");
  return [args, list, plot, analyze, psf, ghosts] {
    if (list->parsed()) return RunList();
    if (ghosts->parsed()) return RunGhosts(*args);
    if (psf->parsed()) return RunPsf(*args);
    if (plot->parsed()) return RunPlot(*args);
    if (analyze->parsed()) return RunAnalyze(*args);
    return RunInfo(*args);
  };
}

}  // namespace objektiv
