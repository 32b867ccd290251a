#include "optics/lens_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "base/error.h"
#include "base/log.h"
#include "base/text_file.h"
#include "optics/coating_library.h"
#include "optics/crystal_checks.h"
#include "optics/element_tolerances.h"
#include "optics/glass_catalog.h"
#include "optics/gradient_checks.h"
#include "optics/lens_glasses.h"

namespace objektiv {

namespace {
// "a,b,c" -> {"a", "b", "c"} (an empty part stays, to be refused as a number).
std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (;;) {
    const size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

namespace fs = std::filesystem;

std::shared_ptr<const Glass> ParseMedium(const std::string& m, const LensGlasses& glasses, const std::string& path,
                                         int line) {
  if (m == "air") return nullptr;
  if (m.empty()) throw MakeInputError(path, line, "no medium given (air, a glass name, n=N or nd=N,vd=V)");
  if (m.rfind("n=", 0) == 0) {
    double n = ParseFiniteNumber(m.substr(2), path, line);
    if (n < 1 || n > 5) throw MakeInputError(path, line, "index {} is not a medium's (1 to 5)", n);
    return std::make_shared<const Glass>(Glass::Constant(n));
  }
  if (m.rfind("nd=", 0) == 0) {
    size_t comma = m.find(",vd=");
    if (comma == std::string::npos) throw MakeInputError(path, line, "a model glass is written nd=N,vd=V, got '{}'", Printable(m));
    double nd = ParseFiniteNumber(m.substr(3, comma - 3), path, line);
    double vd = ParseFiniteNumber(m.substr(comma + 4), path, line);
    if (nd < 1 || nd > 5 || vd <= 0) throw MakeInputError(path, line, "model glass needs nd from 1 to 5 and vd > 0");
    return std::make_shared<const Glass>(Glass::Model(nd, vd));
  }
  return glasses.Resolve(m, line);
}

// The coatings a lens file defines (`coating NAME ...` lines), and which of them it used.
struct FileCoatings {
  struct Defined {
    std::shared_ptr<const Coating> coating;
    int line;
    bool used = false;
  };
  std::vector<Defined> defined;

  void Define(const std::vector<std::string>& f, const GlassCatalog& glasses, const std::string& path, int line) {
    if (f.size() < 3) throw MakeInputError(path, line, "a coating line is: coating NAME [design=NM] MATERIAL:THICKNESS...");
    const std::string& name = f[1];
    if (BuiltIn(name, path, line)) throw MakeInputError(path, line, "coating '{}' is built in; give yours another name", name);
    for (const Defined& d : defined)
      if (SameCoatingName(d.coating->name(), name))
        throw MakeInputError(path, line, "coating '{}' is defined twice (first on line {}; names compare without case)", name, d.line);
    defined.push_back({ParseCoatingDefinition(name, std::span(f).subspan(2), glasses, path, line), line});
  }
  // A coating by name: the file's, then the built-in ones (null: none/uncoated).
  std::shared_ptr<const Coating> Find(const std::string& name, const std::string& path, int line) {
    for (Defined& d : defined)
      if (SameCoatingName(d.coating->name(), name)) {
        d.used = true;
        return d.coating;
      }
    if (std::optional<std::shared_ptr<const Coating>> c = BuiltIn(name, path, line)) return *c;
    std::string mine;
    for (const Defined& d : defined) mine += (mine.empty() ? "" : ", ") + d.coating->name();
    throw MakeInputError(path, line, "unknown coating '{}' (built in: {}{}{}; a coating line must define it before use)",
                         name, BuiltInCoatingNames(), mine.empty() ? "" : "; defined in this file: ", mine);
  }
  // A built-in coating, with this line named on a bad parameter.
  static std::optional<std::shared_ptr<const Coating>> BuiltIn(const std::string& name, const std::string& path, int line) {
    try {
      return FindBuiltInCoating(name);
    } catch (const InputError& e) {
      throw MakeInputError(path, line, "{}", e.what());
    }
  }
  void WarnUnused(const std::string& path) const {
    for (const Defined& d : defined)
      if (!d.used) spdlog::warn("{}:{}: coating '{}' is defined but no surface uses it", path, d.line, d.coating->name());
  }
};

}  // namespace

LensPrescription ParseNativeLens(const std::string& text, const std::string& path, const GlassCatalog& glasses) {
  const LensGlasses lens_glasses(path, glasses);
  LensPrescription lens;
  lens.name = fs::path(path).stem().string();
  lens.source = path;
  lens.file = path;
  std::istringstream lines(text);
  std::string line;
  int number = 0, stop_line = 0, last_line = 0;
  FileCoatings coatings;
  std::shared_ptr<const Coating> default_coating;
  std::vector<size_t> explicitly_coated;  // surfaces with their own coating=
  int default_line = 0, focus_gap_line = 0;
  std::map<std::string, int> metadata_lines;  // each metadata key's line
  ElementTolerances tolerances;  // tolerance_decenter:, tolerance_tilt:, tolerance_seed:
  int tolerance_line = 0, tolerance_seed_line = 0;
  std::vector<int> coating_lines;  // the lines of explicitly_coated
  std::vector<int> surface_lines;  // per surface
  while (std::getline(lines, line)) {
    ++number;
    if (size_t h = line.find('#'); h != std::string::npos) line.resize(h);
    std::vector<std::string> f = SplitFields(line);
    if (f.empty()) continue;
    if (f[0].back() == ':') {
      if (!lens.surfaces.empty()) throw MakeInputError(path, number, "metadata must come before the surfaces");
      std::string key = f[0].substr(0, f[0].size() - 1), value;
      for (size_t i = 1; i < f.size(); ++i) value += (i > 1 ? " " : "") + f[i];
      // Each key once (the last one would win in silence).
      if (const auto seen = metadata_lines.find(key); seen != metadata_lines.end())
        throw MakeInputError(path, number, "{} is given twice (first on line {})", Printable(key), seen->second);
      metadata_lines[key] = number;
      if (key == "name") lens.name = value;
      else if (key == "source") lens.source = value;
      else if (key == "focal_length") lens.design_focal_length = ParseFiniteNumber(value, path, number);
      else if (key == "fnumber") lens.design_fnumber = ParseFiniteNumber(value, path, number);
      else if (key == "image_circle") lens.image_circle = ParseFiniteNumber(value, path, number);
      else if (key == "object_medium") {  // the scene's side: air, water (n=1.333), oil ...
        lens.object_medium = ParseMedium(value, lens_glasses, path, number);
      }
      else if (key == "focus_gap") {  // an anamorphic's own focusing: the gap after this row
        const std::optional<int> row = ParseIntegerIn(value, 1, 1000);
        if (!row) throw MakeInputError(path, number, "focus_gap '{}': the row (1, 2, ...) after which the gap changes", Printable(value));
        lens.focus_gap = *row - 1;
        focus_gap_line = number;
      }
      else if (key == "default_coating") {
        default_coating = coatings.Find(value, path, number);
        default_line = number;
      }
      else if (key == "tolerance_decenter" || key == "tolerance_tilt") {  // an as-built copy (optics/element_tolerances.h)
        const double v = ParseFiniteNumber(value, path, number);
        if (!(v >= 0 && v <= 10))
          throw MakeInputError(path, number, "{} {}: from 0 to 10 ({})", key, Printable(value),
                               key == "tolerance_decenter" ? "mm" : "degrees");
        (key == "tolerance_decenter" ? tolerances.decenter_mm : tolerances.tilt_deg) = v;
        tolerance_line = number;
      }
      else if (key == "tolerance_seed") {
        const std::optional<int> seed = ParseIntegerIn(value, 0, 1000000000);
        if (!seed) throw MakeInputError(path, number, "tolerance_seed {}: an integer from 0 to 1000000000", Printable(value));
        tolerances.seed = uint64_t(*seed);
        tolerance_seed_line = number;
      }
      else throw MakeInputError(path, number, "unknown key '{}' (name, source, focal_length, fnumber, image_circle, default_coating, object_medium, focus_gap, tolerance_decenter, tolerance_tilt, tolerance_seed)", key);
      continue;
    }
    if (f[0] == "coating") {
      coatings.Define(f, glasses, path, number);
      continue;
    }
    LensSurface s;
    size_t next;
    if (f[0] == "stop") {
      if (f.size() < 4) throw MakeInputError(path, number, "a stop line is: stop THICKNESS MEDIUM SEMI_DIAMETER [decenter= tilt=]");
      if (stop_line) throw MakeInputError(path, number, "a second stop (the first is on line {})", stop_line);
      s.is_stop = true;
      s.flat = true;
      stop_line = number;
      next = 1;
    } else if (f[0] == "surface" || f[0] == "mirror") {
      s.mirror = f[0] == "mirror";
      if (s.mirror && f.size() < 4)
        throw MakeInputError(path, number, "a mirror line is: mirror RADIUS THICKNESS SEMI_DIAMETER [options]");
      if (!s.mirror && f.size() < 5)
        throw MakeInputError(path, number, "a surface line is: surface RADIUS THICKNESS MEDIUM SEMI_DIAMETER [options]");
      if (f[1] == "inf") {
        s.flat = true;
      } else if (f[1].rfind("c=", 0) == 0) {
        s.SetCurvature(ParseFiniteNumber(f[1].substr(2), path, number));
      } else {
        s.radius = ParseFiniteNumber(f[1], path, number);
        if (s.radius == 0) throw MakeInputError(path, number, "radius 0: write inf for a plane (the stop is its own line)");
      }
      next = 2;
    } else {
      throw MakeInputError(path, number, "unknown line '{}' (surface, mirror, stop, coating, or key: value)", f[0]);
    }
    // Thicknesses are signed z steps: negative where light travels toward the object (after an
    // odd number of mirrors), checked for the whole lens below.
    s.thickness = ParseFiniteNumber(f[next], path, number);
    if (s.mirror) {
      // Light goes back into the medium it came from; the line names none.
      if (!ParseFiniteNumber(f[next + 1]))
        throw MakeInputError(path, number, "'{}': a mirror line names no medium (light goes back into the one it came "
                             "from): mirror RADIUS THICKNESS SEMI_DIAMETER [options]", Printable(f[next + 1]));
      s.medium = lens.MediumBefore(lens.surfaces.size());
      --next;
    } else {
      s.medium = ParseMedium(f[next + 1], lens_glasses, path, number);
    }
    s.semi_diameter = ParseFiniteNumber(f[next + 2], path, number);
    if (!(s.semi_diameter > 0)) throw MakeInputError(path, number, "semi-diameter must be positive");
    std::vector<std::string> keys;  // each option once
    double decenter[2] = {0, 0}, tilt[3] = {0, 0, 0};
    // A Q-type asphere: qbfs= or qcon= (its terms), qnorm= (the normalisation radius).
    std::optional<ForbesAsphere::Kind> q_kind;
    std::vector<double> q_terms;
    double q_norm = 0;
    double zone_pitch = 0;  // zones=: a Fresnel surface's pitch
    double form_pv_um = 0;  // form_error_um=, form_seed=: the figure's irregularity
    std::optional<uint64_t> form_seed;
    // A gradient-index medium after the surface: grin_r= and grin_z= (polynomial), grin_sphere=
    // or selfoc=, each a list of terms.
    std::map<std::string, std::vector<double>> grin;
    std::optional<Vec3d> optic_axis;  // optic_axis=, extraordinary=: a birefringent crystal after the surface
    std::string extraordinary;
    double dust = 0;  // dust=, scratches=, dirt_seed=: what absorbs light on the surface
    int scratches = 0;
    std::optional<uint64_t> dirt_seed;
    for (size_t i = next + 3; i < f.size(); ++i) {
      size_t eq = f[i].find('=');
      if (eq == std::string::npos) throw MakeInputError(path, number, "option '{}' is not key=value", f[i]);
      std::string key = f[i].substr(0, eq), value = f[i].substr(eq + 1);
      if (f[0] == "stop" && key != "decenter" && key != "tilt")
        throw MakeInputError(path, number, "the stop takes no options but decenter= and tilt=");
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) throw MakeInputError(path, number, "option '{}' is given twice", key);
      keys.push_back(key);
      if (key == "decenter" || key == "tilt") {  // mm in x, y; degrees about x, y, z
        const std::vector<std::string> parts = SplitCommas(value);
        if (key == "decenter" ? parts.size() != 2 : (parts.empty() || parts.size() > 3))
          throw MakeInputError(path, number, "{}={}: {}", key, Printable(value),
                               key == "decenter" ? "DX,DY in mm" : "AX[,AY[,AZ]] in degrees");
        for (size_t k = 0; k < parts.size(); ++k) {
          const double v = ParseFiniteNumber(parts[k], path, number);
          if (key == "decenter" && !(std::abs(v) <= kMaxLensLength))
            throw MakeInputError(path, number, "decenter {} mm is beyond {} mm: not a lens", v, kMaxLensLength);
          // Tilts about x and y below 90 degrees (the surface still faces the light); any turn about z.
          if (key == "tilt" && !(std::abs(v) < (k == 2 ? 180.000001 : 90)))
            throw MakeInputError(path, number, "tilt {} degrees about {}: {}", v, "xyz"[k],
                                 k == 2 ? "a turn about z lies within 180 degrees either way"
                                        : "the surface must still face the light (less than 90 degrees)");
          (key == "decenter" ? decenter[k] : tilt[k]) = v;
        }
      } else if (key == "qbfs" || key == "qcon") {  // a Q-type asphere's terms a0,a1,... (mm)
        if (q_kind) throw MakeInputError(path, number, "qbfs= and qcon= together: a Q-type surface is one or the other");
        q_kind = key == "qbfs" ? ForbesAsphere::Kind::kBestFitSphere : ForbesAsphere::Kind::kConic;
        const std::vector<std::string> parts = SplitCommas(value);
        if (value.empty() || parts.size() > size_t(ForbesAsphere::kMaxTerms))
          throw MakeInputError(path, number, "{}={}: 1 to {} terms a0,a1,... in mm", key, Printable(value), ForbesAsphere::kMaxTerms);
        for (const std::string& part : parts) {
          q_terms.push_back(ParseFiniteNumber(part, path, number));
          if (!(std::abs(q_terms.back()) <= kMaxLensLength))
            throw MakeInputError(path, number, "{} term {} mm is beyond {} mm: not a lens", key, q_terms.back(), kMaxLensLength);
        }
      } else if (key == "zones") {  // a Fresnel surface: the profile cut into zones this wide (mm)
        zone_pitch = ParseFiniteNumber(value, path, number);
        if (!(zone_pitch > 0)) throw MakeInputError(path, number, "zones={}: the zones' radial width (mm) must be positive", Printable(value));
        if (s.semi_diameter / zone_pitch > 100000)
          throw MakeInputError(path, number, "zones={}: {:.3g} zones over the semi-diameter {}; at most 100000", Printable(value),
                               std::ceil(s.semi_diameter / zone_pitch), s.semi_diameter);
        if (zone_pitch >= s.semi_diameter)
          spdlog::warn("{}:{}: zones={} is as wide as the semi-diameter {} or wider: one zone, the profile itself", path, number,
                       Printable(value), s.semi_diameter);
      } else if (key == "grin_r" || key == "grin_z" || key == "grin_sphere" || key == "selfoc") {
        if (s.mirror) throw MakeInputError(path, number, "{}= on a mirror: a gradient-index medium follows a refracting surface", key);
        const std::vector<std::string> parts = SplitCommas(value);
        const size_t least = key == "grin_sphere" ? 2 : 1;
        if (parts.size() < least || parts.size() > 3)
          throw MakeInputError(path, number, "{}={}: {}", key, Printable(value),
                               key == "grin_r"      ? "NR2[,NR4[,NR6]], per mm^2, mm^4, mm^6"
                               : key == "grin_z"    ? "NZ1[,NZ2[,NZ3]], per mm, mm^2, mm^3"
                               : key == "grin_sphere" ? "R,S1[,S2]: the shells' centre (mm from the vertex), per mm, per mm^2"
                                                      : "G[,H4[,H6]]: g per mm, h4 and h6 without units");
        std::vector<double>& terms = grin[key];
        for (const std::string& part : parts) terms.push_back(ParseFiniteNumber(part, path, number));
        terms.resize(3, 0.0);
      } else if (key == "optic_axis") {  // a crystal's optic axis, in the surface's frame
        const std::vector<std::string> parts = SplitCommas(value);
        if (parts.size() != 3) throw MakeInputError(path, number, "optic_axis={}: AX,AY,AZ, a direction", Printable(value));
        Vec3d a;
        for (int k = 0; k < 3; ++k) a[k] = ParseFiniteNumber(parts[size_t(k)], path, number);
        // Normalised by its largest component first (1e308 or 1e-300 components are fine).
        const double largest = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
        if (!(largest > 0)) throw MakeInputError(path, number, "optic_axis={}: a direction, not zero", Printable(value));
        a = a / largest;
        optic_axis = a / Length(a);
      } else if (key == "extraordinary") {  // a crystal's extraordinary index: a glass, n= or nd=,vd=
        if (value.empty()) throw MakeInputError(path, number, "extraordinary= names no index (a glass, n=N or nd=N,vd=V)");
        extraordinary = value;
      } else if (key == "dust") {  // the share of the aperture's area its particles cover
        dust = ParseFiniteNumber(value, path, number);
        if (!(dust > 0 && dust <= SurfaceDirt::kMaxCoverage))
          throw MakeInputError(path, number, "dust={}: the share of the clear aperture covered, above 0 and at most {}",
                               Printable(value), SurfaceDirt::kMaxCoverage);
      } else if (key == "scratches") {
        const std::optional<int> n = ParseIntegerIn(value, 1, SurfaceDirt::kMaxScratches);
        if (!n) throw MakeInputError(path, number, "scratches={}: a count from 1 to {}", Printable(value), SurfaceDirt::kMaxScratches);
        scratches = *n;
      } else if (key == "dirt_seed") {
        const std::optional<int> seed = ParseIntegerIn(value, 0, 1000000000);
        if (!seed) throw MakeInputError(path, number, "dirt_seed={}: an integer from 0 to 1000000000", Printable(value));
        dirt_seed = uint64_t(*seed);
      } else if (key == "form_error_um") {  // peak-to-valley of a smooth random figure error
        form_pv_um = ParseFiniteNumber(value, path, number);
        if (!(form_pv_um > 0 && form_pv_um <= 1000))
          throw MakeInputError(path, number, "form_error_um={}: a peak-to-valley in micrometres, above 0 and at most 1000",
                               Printable(value));
      } else if (key == "form_seed") {
        const std::optional<int> seed = ParseIntegerIn(value, 0, 1000000000);
        if (!seed) throw MakeInputError(path, number, "form_seed={}: an integer from 0 to 1000000000", Printable(value));
        form_seed = uint64_t(*seed);
      } else if (key == "qnorm") {
        q_norm = ParseFiniteNumber(value, path, number);
        if (!(q_norm > 0 && q_norm <= kMaxLensLength))
          throw MakeInputError(path, number, "qnorm {} mm: the normalisation radius must be positive (and at most {} mm)", q_norm,
                               kMaxLensLength);
      } else if (key == "k") {
        s.conic = ParseFiniteNumber(value, path, number);
      } else if (key == "rx") {  // a toroid: its x-z section's radius (inf: a cylinder curved in y)
        s.toroidal = true;
        if (value != "inf") {
          const double rx = ParseFiniteNumber(value, path, number);
          if (rx == 0) throw MakeInputError(path, number, "rx=0: write rx=inf for a section flat in x");
          s.curvature_x = 1 / rx;
        }
      } else if (key == "obscuration") {  // a central obstruction's radius
        s.obscuration = ParseFiniteNumber(value, path, number);
        if (!(s.obscuration > 0 && s.obscuration < s.semi_diameter))
          throw MakeInputError(path, number, "obscuration {} must lie between 0 and the semi-diameter {}", s.obscuration,
                               s.semi_diameter);
      } else if (key == "reflectance" && s.mirror) {  // a metal by name, or a constant share
        if (std::optional<MirrorMetal> metal = MirrorMetal::Named(value)) {
          s.mirror_metal = std::make_shared<const MirrorMetal>(std::move(*metal));
        } else {
          char* end = nullptr;
          s.mirror_reflectance = std::strtod(value.c_str(), &end);
          if (end != value.c_str() + value.size() || !(s.mirror_reflectance > 0 && s.mirror_reflectance <= 1))
            throw MakeInputError(path, number, "reflectance={}: a mirror reflects a metal's share ({}) or a number in (0, 1]",
                                 Printable(value), MirrorMetalList());
        }
      } else if (key == "stop" && s.mirror) {  // the mirror's rim is the aperture stop
        if (value != "yes") throw MakeInputError(path, number, "stop=yes makes a mirror the stop; got stop={}", Printable(value));
        if (stop_line) throw MakeInputError(path, number, "a second stop (the first is on line {})", stop_line);
        s.is_stop = true;
        stop_line = number;
      } else if (key == "coating" && s.mirror) {
        throw MakeInputError(path, number, "a mirror takes no anti-reflection coating (its reflectance= sets what it reflects)");
      } else if (key == "coating") {
        s.coating = coatings.Find(value, path, number);
        explicitly_coated.push_back(lens.surfaces.size());
        coating_lines.push_back(number);
      } else if (key.size() >= 2 && key[0] == 'a' && std::all_of(key.begin() + 1, key.end(), ::isdigit)) {
        std::optional<int> order = ParseIntegerIn(key.substr(1), 4, 16);
        if (!order || *order % 2) throw MakeInputError(path, number, "aspheric terms are a4, a6, ..., a16");
        s.aspheric[(*order - 4) / 2] = ParseFiniteNumber(value, path, number);
      } else {
        throw MakeInputError(path, number, "unknown option '{}' ({})", key,
                             s.mirror ? "k, a4..a16, qbfs, qcon, qnorm, zones, form_error_um, form_seed, rx, decenter, tilt, "
                                        "obscuration, dust, scratches, dirt_seed, reflectance, stop"
                                      : "k, a4..a16, qbfs, qcon, qnorm, zones, form_error_um, form_seed, rx, decenter, tilt, "
                                        "coating, obscuration, dust, scratches, dirt_seed, grin_r, grin_z, grin_sphere, selfoc, "
                                        "optic_axis, extraordinary");
      }
    }
    if (q_kind) {
      if (s.HasAsphericTerms())
        throw MakeInputError(path, number, "a Q-type surface takes no a4..a16 terms (its polynomials replace them)");
      if (s.toroidal) throw MakeInputError(path, number, "a Q-type surface is a figure of revolution: no rx=");
      if (*q_kind == ForbesAsphere::Kind::kBestFitSphere && s.conic != 0)
        throw MakeInputError(path, number, "qbfs= departs from the best-fit sphere (the line's radius): no k= (qcon= "
                             "departs from a conic)");
      // Forbes's polynomials are orthogonal over the disc they are normalised to: by default
      // the clear aperture.
      s.forbes = std::make_shared<const ForbesAsphere>(*q_kind, q_norm > 0 ? q_norm : s.semi_diameter, std::move(q_terms));
    } else if (q_norm > 0) {
      throw MakeInputError(path, number, "qnorm= without qbfs= or qcon=: it normalises a Q-type surface's polynomials");
    }
    if (zone_pitch > 0) {
      if (s.toroidal) throw MakeInputError(path, number, "a Fresnel surface (zones=) is cut from a figure of revolution: no rx=");
      if (s.Curvature() == 0 && !s.HasAsphericTerms())
        throw MakeInputError(path, number, "zones= on a plane: a Fresnel surface cuts a curved profile (give its radius or "
                             "aspheric terms)");
      CheckReachable(s, path, number);  // the profile must be whole before it is cut
      s.fresnel = std::make_shared<const FresnelZones>(s, zone_pitch);
    }
    if (form_pv_um > 0) {
      if (s.fresnel) throw MakeInputError(path, number, "form_error_um= on a Fresnel surface (zones=) is not modelled");
      // The seed defaults to the row's number: each surface its own shape.
      s.form_error = std::make_shared<const FormError>(form_pv_um * 1e-3, form_seed.value_or(lens.surfaces.size() + 1),
                                                       s.semi_diameter);
    } else if (form_seed) {
      throw MakeInputError(path, number, "form_seed= without form_error_um=: it chooses a form error's shape");
    }
    if (dust > 0 || scratches > 0) {
      // The seed defaults to the row's number: each surface its own pattern.
      const double particles = SurfaceDirt::ParticleCount(dust, s.semi_diameter);
      if (particles > SurfaceDirt::kMaxParticles)
        throw MakeInputError(path, number, "dust={} over a semi-diameter of {} mm is {:.3g} particles; at most {}", dust,
                             s.semi_diameter, particles, SurfaceDirt::kMaxParticles);
      if (dust > 0 && particles < 0.5)
        spdlog::warn("{}:{}: dust={} over a semi-diameter of {} mm is {:.2g} particles: none", path, number, dust,
                     s.semi_diameter, particles);
      s.dirt = std::make_shared<const SurfaceDirt>(dust, scratches, dirt_seed.value_or(lens.surfaces.size() + 1), s.semi_diameter);
    } else if (dirt_seed) {
      throw MakeInputError(path, number, "dirt_seed= without dust= or scratches=: it chooses their pattern");
    }
    if (!grin.empty()) {
      if (!s.medium) throw MakeInputError(path, number, "a gradient-index medium needs its glass (the medium column names air)");
      if (grin.size() > 1 && !(grin.size() == 2 && grin.count("grin_r") && grin.count("grin_z")))
        throw MakeInputError(path, number, "one gradient profile a surface: grin_r= with grin_z= (polynomial), grin_sphere= "
                             "or selfoc=");
      if (grin.count("selfoc")) {
        const std::vector<double>& t = grin["selfoc"];
        if (!(t[0] > 0 && t[0] <= 100)) throw MakeInputError(path, number, "selfoc g {} per mm: above 0 and at most 100", t[0]);
        s.gradient = std::make_shared<const GradientIndex>(GradientIndex::Selfoc(t[0], t[1], t[2]));
      } else if (grin.count("grin_sphere")) {
        const std::vector<double>& t = grin["grin_sphere"];
        if (t[0] == 0 || !(std::abs(t[0]) <= kMaxLensLength))
          throw MakeInputError(path, number, "grin_sphere centre {} mm: nonzero (the shells' centre on the axis) and within {} mm",
                               t[0], kMaxLensLength);
        s.gradient = std::make_shared<const GradientIndex>(GradientIndex::Spherical(t[0], t[1], t[2]));
      } else {
        std::array<double, 3> r{}, z{};
        if (grin.count("grin_r")) std::copy_n(grin["grin_r"].begin(), 3, r.begin());
        if (grin.count("grin_z")) std::copy_n(grin["grin_z"].begin(), 3, z.begin());
        s.gradient = std::make_shared<const GradientIndex>(GradientIndex::Polynomial(r, z));
      }
      const std::array<double, 6>& c = s.gradient->coefficients();
      const bool flat = s.gradient->kind() == GradientIndex::Kind::kSpherical ? c[1] == 0 && c[2] == 0
                                                                             : std::all_of(c.begin(), c.end(), [](double v) { return v == 0; });
      if (flat) spdlog::warn("{}:{}: the gradient's terms are all zero: the medium is its glass, the same everywhere", path, number);
    }
    if (optic_axis) {
      if (s.mirror) throw MakeInputError(path, number, "optic_axis= on a mirror: a crystal follows a refracting surface");
      if (!s.medium)
        throw MakeInputError(path, number, "optic_axis={},{},{}: a crystal needs its glass (the medium column names air)",
                             optic_axis->x, optic_axis->y, optic_axis->z);
      // The extraordinary index: named, or the ordinary glass's name with -E (as the crystal
      // catalogs pair them: CALCITE, CALCITE-E).
      const std::string name = extraordinary.empty() ? f[next + 1] + "-E" : extraordinary;
      std::shared_ptr<const Glass> ne;
      try {
        ne = ParseMedium(name, lens_glasses, path, number);
      } catch (const InputError& e) {
        if (!extraordinary.empty()) throw;
        throw MakeInputError(path, number, "optic_axis= makes {} a crystal, but there is no extraordinary index (no glass {}); give it with "
                             "extraordinary=GLASS, n=N or nd=N,vd=V", Printable(f[next + 1]), Printable(name));
      }
      if (!ne) throw MakeInputError(path, number, "extraordinary=air: a crystal's extraordinary index is a glass's");
      s.crystal = std::make_shared<const UniaxialCrystal>(UniaxialCrystal{*optic_axis, ne});
    } else if (!extraordinary.empty()) {
      throw MakeInputError(path, number, "extraordinary= without optic_axis=: it is a crystal's second index");
    } else if (s.medium && s.medium->catalog() == "CRYSTALS") {
      spdlog::warn("{}:{}: {} is one index of a birefringent crystal; without optic_axis= it is traced as an isotropic glass "
                   "of that index", path, number, s.medium->name());
    }
    const SurfacePlacement placed = SurfacePlacement::DecenterTilt(decenter[0], decenter[1], tilt[0], tilt[1], tilt[2]);
    if (!placed.IsIdentity()) s.placement = placed;
    if (std::string why = ToroidTurnMismatch(s); !why.empty()) throw MakeInputError(path, number, "{}", why);
    CheckReachable(s, path, number);
    CheckSize(s, path, number);
    lens.surfaces.push_back(std::move(s));
    surface_lines.push_back(number);
    last_line = number;
  }
  if (lens.surfaces.empty()) throw MakeInputError(path, 0, "no surfaces");
  if (!stop_line) throw MakeInputError(path, 0, "no stop line (or a mirror with stop=yes)");
  if (lens.surfaces.back().medium) throw MakeInputError(path, last_line, "the last surface must leave the lens into air");
  if (auto mismatch = FirstDirectionMismatch(lens)) throw MakeInputError(path, surface_lines[mismatch->first], "{}", mismatch->second);
  if (focus_gap_line) {
    if (lens.focus_gap + 1 >= int(lens.surfaces.size()))
      throw MakeInputError(path, focus_gap_line, "focus_gap {}: the gap after row {} lies inside the lens only for rows 1 to {}",
                           lens.focus_gap + 1, lens.focus_gap + 1, lens.surfaces.size() - 1);
    if (!lens.HasToroids())
      throw MakeInputError(path, focus_gap_line, "focus_gap: the lens has no toroidal surface; only an anamorphic focuses "
                           "its sections apart (the whole lens moves to focus)");
    if (!(lens.surfaces[size_t(lens.focus_gap)].thickness > 0))
      throw MakeInputError(path, focus_gap_line, "focus_gap {}: the gap after that row is {} mm; it must be positive",
                           lens.focus_gap + 1, lens.surfaces[size_t(lens.focus_gap)].thickness);
  }
  // A coating where the medium does not change coats nothing.
  for (size_t k = 0; k < explicitly_coated.size(); ++k) {
    const size_t i = explicitly_coated[k];
    const LensSurface& s = lens.surfaces[i];
    if (s.coating && lens.MediumBefore(i) == s.medium)
      spdlog::warn("{}:{}: coating '{}' does nothing here: the medium is the same on both sides of the surface", path,
                   coating_lines[k], s.coating->name());
  }
  // The default on the other air-glass surfaces (a surface's own coating=none stays bare).
  if (default_coating) {
    std::vector<std::shared_ptr<const Coating>> own;
    for (size_t i : explicitly_coated) own.push_back(lens.surfaces[i].coating);
    LensPrescription bare = lens;
    for (LensSurface& s : bare.surfaces) s.coating = nullptr;
    CoatAirGlassSurfaces(bare, default_coating, false);
    CoatAirGlassSurfaces(lens, default_coating, true);
    for (size_t k = 0; k < explicitly_coated.size(); ++k) lens.surfaces[explicitly_coated[k]].coating = own[k];
    // Warned where every surface it would coat has a coating of its own.
    bool applies = false;
    for (size_t i = 0; i < lens.surfaces.size(); ++i)
      applies |= bare.surfaces[i].coating && std::find(explicitly_coated.begin(), explicitly_coated.end(), i) == explicitly_coated.end();
    if (!applies)
      spdlog::warn("{}:{}: default_coating '{}' coats no surface: every air-glass surface names its own", path, default_line,
                   default_coating->name());
  }
  if (auto mismatch = FirstCoatingMismatch(lens)) {
    auto own = std::find(explicitly_coated.begin(), explicitly_coated.end(), mismatch->first);
    throw MakeInputError(path, own != explicitly_coated.end() ? coating_lines[size_t(own - explicitly_coated.begin())]
                                                              : default_line,
                         "surface {}: {}", mismatch->first + 1, mismatch->second);
  }
  if (auto crossed = FirstCrossedGap(lens)) throw MakeInputError(path, surface_lines[crossed->first], "{}", crossed->second);
  if (auto grin = FirstGradientMismatch(lens)) throw MakeInputError(path, surface_lines[grin->first], "{}", grin->second);
  if (auto crystal = FirstCrystalMismatch(lens)) throw MakeInputError(path, surface_lines[crystal->first], "{}", crystal->second);
  if (tolerances.Any()) {
    if (lens.MirrorCount() > 0 || lens.HasToroids())
      throw MakeInputError(path, tolerance_line, "element tolerances are not modelled for a lens with {}",
                           lens.MirrorCount() > 0 ? "mirrors" : "toroids (a tilt would turn their sections)");
    if (LensElements(lens).empty()) throw MakeInputError(path, tolerance_line, "element tolerances: the lens has no element in air");
    lens = WithToleranceSample(lens, tolerances);
    if (auto crossed = FirstCrossedGap(lens))
      throw MakeInputError(path, surface_lines[crossed->first], "{} (as tolerance_seed {} placed the elements)", crossed->second,
                           tolerances.seed);
  } else if (tolerance_seed_line) {
    throw MakeInputError(path, tolerance_seed_line,
                         "tolerance_seed: without a positive tolerance_decenter or tolerance_tilt it moves nothing");
  }
  coatings.WarnUnused(path);
  lens_glasses.WarnUnused();
  for (const FileCoatings::Defined& d : coatings.defined) lens.defined_coatings.push_back(d.coating);
  return lens;
}

}  // namespace objektiv
