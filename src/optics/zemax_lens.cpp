#include "optics/zemax_lens.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "base/error.h"
#include "base/log.h"
#include "base/text_file.h"
#include "optics/coating_library.h"
#include "optics/glass_catalog.h"
#include "optics/lens_glasses.h"

namespace objektiv {
namespace {

// A surface's placement: the coordinate breaks' frame less its z (the vertex's place along the
// axis); none where that is the identity.
std::optional<SurfacePlacement> Placement(SurfacePlacement frame) {
  frame.offset.z = 0;
  const double e = 1e-12;
  auto near = [&](double a, double b) { return std::abs(a - b) <= e; };
  if (near(frame.offset.x, 0) && near(frame.offset.y, 0) && near(frame.offset.z, 0) && near(frame.ex.x, 1) &&
      near(frame.ey.y, 1) && near(frame.ez.z, 1))
    return std::nullopt;
  return frame;
}

struct ZSurface {
  int line = 0, glass_line = 0, coat_line = 0;
  std::string coat;  // COAT: a coating name (Zemax's COATING.DAT or I.xx)
  std::string type = "STANDARD";
  double curv = 0, disz = 0, diam = 0, coni = 0;
  double clear_aperture = 0;  // CLAP: the radius that clips, where the file sets one
  double obscuration = 0;     // OBSC: the radius of a central obstruction
  bool stop = false, infinite_thickness = false;
  std::string glass;
  double model_nd = 0, model_vd = 0;
  double parm[17] = {};  // PARM 0..16
  int parm_line[17] = {};  // where each was given (0: not)
};

// A thickness: Zemax writes an infinite one (the object at infinity) as a word. Every other
// value must be finite (an infinite curvature, diameter or conic would be a silently wrong
// lens).
double Thickness(const std::string& s, const std::string& path, int line) {
  if (s == "INFINITY" || s == "Infinity" || s == "inf") return INFINITY;
  return ParseFiniteNumber(s, path, line);
}

// A surface's glass (GLAS NAME ? ? nd Vd ...): Zemax's model glass ___BLANK through the stated nd
// and Vd, or a glass found by name (lens_glasses.h: LensGlasses::Resolve).
std::shared_ptr<const Glass> SurfaceGlass(const ZSurface& z, const LensGlasses& glasses, const std::string& path) {
  if (z.glass == "___BLANK") {
    if (z.model_nd < 1 || !(z.model_vd > 0))
      throw MakeInputError(path, z.glass_line, "model glass needs nd >= 1 and vd > 0, got nd {} vd {}", z.model_nd,
                           z.model_vd);
    return std::make_shared<const Glass>(Glass::Model(z.model_nd, z.model_vd));
  }
  // A catalog glass's line carries an nd and Vd too: the glass's own in some files, Zemax's
  // placeholder 1.5 and 40 or zeros in others (which state nothing).
  if ((z.model_nd != 0 && z.model_nd < 1) || z.model_vd < 0)
    throw MakeInputError(path, z.glass_line, "glass {}: the stated nd {} and vd {} are no glass's (nd >= 1, vd >= 0)",
                         Printable(z.glass), z.model_nd, z.model_vd);
  std::optional<StatedGlass> stated;
  if (z.model_nd >= 1 && z.model_vd > 0 && !(z.model_nd == 1.5 && z.model_vd == 40))
    stated = StatedGlass{z.model_nd, z.model_vd};
  return glasses.Resolve(z.glass, z.glass_line, stated);
}

}  // namespace

LensPrescription ReadZemaxLens(const std::string& path, const GlassCatalog& glasses) {
  return ParseZemaxLens(ReadTextFile(path, "Zemax file"), path, glasses);
}

LensPrescription ParseZemaxLens(const std::string& raw, const std::string& path, const GlassCatalog& glasses) {
  std::string text = DecodeToAscii(raw);
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  double unit = 1;  // to millimetres
  std::string name = std::filesystem::path(path).stem().string();
  std::vector<ZSurface> surfs;
  std::set<std::string> warned;
  auto warn_once = [&](const std::string& what, int at) {
    if (warned.insert(what).second) spdlog::warn("{}:{}: not supported, ignored: {}", path, at, Printable(what));
  };
  // Keywords that carry nothing for sequential refraction of a rotationally symmetric lens.
  static const std::set<std::string> kIgnored = {
      "VERS", "NOTE", "PFIL", "LANG", "GFAC", "RAIM", "PUSH", "SDMA", "FTYP", "ROPD",
      "PICB", "XFLN", "YFLN", "FWGN", "VDXN", "VDYN", "VCXN", "VCYN", "VANN", "WAVM", "PWAV", "GLRS", "GSTD", "NSCD",
      "COFN", "SUMM", "MOFF", "TOL", "MNCA", "MNEA", "MNCG", "MNEG", "MXCA", "MXCG", "RGLA", "TRAC",
      "HIDE", "SLAB", "MAZH", "COMM", "FLAP", "POPS", "BLNK", "TCEN", "XDAT", "YDAT", "FIMP", "OBNA", "ZVDX", "ZVDY",
      "ZVCX", "ZVCY", "ZVAN", "WAVN", "WWGN", "CONF", "DMFS", "OPDX", "MIRR", "XFIE", "YFIE",
      // Author and date; polarisation of analyses; the mechanical semi-diameter and chip zone
      // (they do not clip in Zemax; DIAM does here); pickups and variables, whose solved values
      // the file holds.
      "AUTH", "DBDT", "POLS", "MEMA", "OEMA", "PZUP", "PPAR", "VPAR", "VCUR", "VDSZ", "VCON"};
  std::vector<NamedCatalog> catalogs;  // GCAT: where glass names are looked up first
  ZSurface* cur = nullptr;
  while (std::getline(lines, line)) {
    ++number;
    std::vector<std::string> f = SplitFields(line);
    if (f.empty()) continue;
    const std::string key = f.front();
    f.erase(f.begin());
    auto need = [&](size_t n) {
      if (f.size() < n) throw MakeInputError(path, number, "{} needs {} value(s)", key, n);
    };
    if (key == "SURF") {
      need(1);
      surfs.emplace_back();
      cur = &surfs.back();
      cur->line = number;
      continue;
    }
    if (key == "NAME") {
      std::string rest;
      for (const auto& s : f) rest += (rest.empty() ? "" : " ") + s;
      if (!rest.empty()) name = rest;
      continue;
    }
    if (key == "MODE") {
      need(1);
      if (f[0] != "SEQ")
        throw MakeInputError(path, number, "MODE {}: not a sequential lens file (this reader takes MODE SEQ)", Printable(f[0]));
      continue;
    }
    if (key == "ENVD") {  // temperature (C) and pressure (atm) of the lens's surroundings
      need(2);
      double t = ParseFiniteNumber(f[0], path, number), p = ParseFiniteNumber(f[1], path, number);
      if (std::abs(t - 20) > 0.5 || std::abs(p - 1) > 0.01)
        spdlog::warn("{}:{}: ENVD: the lens at {} C and {} atm is not modelled: indices are the catalogs', at their "
                     "reference temperature in air at 1 atm", path, number, t, p);
      continue;
    }
    if (key == "MNUM") {  // configurations (zoom positions ...): the surfaces hold the active one's
      need(1);
      std::optional<int> n = ParseIntegerIn(f[0], 0, 1 << 20);
      if (!n) throw MakeInputError(path, number, "MNUM '{}' is not a number of configurations", Printable(f[0]));
      if (*n > 1)
        spdlog::warn("{}:{}: a file of {} configurations: the lens is read as stored (configuration {}); the other "
                     "configurations are ignored", path, number, *n, f.size() > 1 ? Printable(f[1]) : "1");
      continue;
    }
    if (key == "GCAT") {
      for (const std::string& c : f) catalogs.push_back({c, number});
      continue;
    }
    if (key == "UNIT") {
      need(1);
      if (f[0] == "MM") unit = 1;
      else if (f[0] == "CM") unit = 10;
      else if (f[0] == "IN") unit = 25.4;
      else if (f[0] == "METER" || f[0] == "M") unit = 1000;
      else throw MakeInputError(path, number, "unknown lens unit '{}'", Printable(f[0]));
      continue;
    }
    // The system aperture (entrance pupil diameter, image-space f-number, object-space NA,
    // float by stop size): here the stop's own DIAM sets it, and a scene or `lens info` sets
    // the f-number or the stop's diameter.
    if (key == "ENPD" || key == "FNUM" || key == "OBNA" || key == "FLOA") {
      std::string value = f.empty() ? "" : " " + f[0];
      if (warned.insert(key).second)
        spdlog::warn("{}:{}: the system aperture {}{} is not used: the stop's DIAM sets the aperture (a scene sets the "
                     "f-number or the stop's diameter)",
                     path, number, key, value);
      continue;
    }
    if (!cur) {
      if (!kIgnored.count(key)) warn_once(key, number);
      continue;
    }
    if (key == "TYPE") {
      need(1);
      cur->type = f[0];
      if (f[0] != "STANDARD" && f[0] != "EVENASPH" && f[0] != "TOROIDAL" && f[0] != "COORDBRK")
        throw MakeInputError(path, number, "surface type {} is not supported (STANDARD, EVENASPH, TOROIDAL and COORDBRK are; "
                             "a Q-type asphere can be written in the native lens format, qbfs= or qcon=, a gradient-index medium "
                             "grin_r=, grin_z=, grin_sphere= or selfoc=, a birefringent crystal optic_axis=)", Printable(f[0]));
    } else if (key == "CURV") {
      need(1);
      cur->curv = ParseFiniteNumber(f[0], path, number);
    } else if (key == "DISZ") {
      need(1);
      cur->disz = Thickness(f[0], path, number);
      cur->infinite_thickness = std::isinf(cur->disz);
    } else if (key == "DIAM") {
      need(1);
      cur->diam = ParseFiniteNumber(f[0], path, number);
    } else if (key == "CONI") {
      need(1);
      cur->coni = ParseFiniteNumber(f[0], path, number);
    } else if (key == "CLAP" || key == "OBSC") {
      // CLAP rmin rmax: a circular aperture, which clips (DIAM does not in Zemax); OBSC rmin
      // rmax: a circular obscuration (a mirror lens's secondary). Annular ones are not traced.
      need(2);
      const char* what = key == "CLAP" ? "aperture" : "obscuration";
      double rmin = ParseFiniteNumber(f[0], path, number), rmax = ParseFiniteNumber(f[1], path, number);
      if (rmin != 0)
        throw MakeInputError(path, number, "{} {} {}: an annular {} (inner radius above 0) is not supported", key, rmin,
                             rmax, what);
      if (!(rmax > 0)) throw MakeInputError(path, number, "{}: the {}'s radius must be above 0, got {}", key, what, rmax);
      (key == "CLAP" ? cur->clear_aperture : cur->obscuration) = rmax;
    } else if (key == "STOP") {
      for (const ZSurface& z : surfs)
        if (z.stop)
          throw MakeInputError(path, number, "a second STOP (the first is the surface on line {}): a lens has one stop",
                               z.line);
      cur->stop = true;
    } else if (key == "GLAS") {
      need(1);
      cur->glass = f[0];
      cur->glass_line = number;
      if (f.size() >= 5) {
        cur->model_nd = ParseFiniteNumber(f[3], path, number);
        cur->model_vd = ParseFiniteNumber(f[4], path, number);
      }
    } else if (key == "COAT") {
      need(1);
      cur->coat = f[0];
      cur->coat_line = number;
    } else if (key == "PARM") {
      need(2);
      std::optional<int> k = ParseIntegerIn(f[0], 0, 16);
      if (!k) throw MakeInputError(path, number, "PARM index '{}' is not an integer from 0 to 16", Printable(f[0]));
      if (cur->parm_line[*k])
        throw MakeInputError(path, number, "PARM {} is given twice for this surface (first on line {})", *k,
                             cur->parm_line[*k]);
      cur->parm[*k] = ParseFiniteNumber(f[1], path, number);
      cur->parm_line[*k] = number;
    } else if (!kIgnored.count(key)) {
      warn_once(key, number);
    }
  }
  if (surfs.size() < 3) throw MakeInputError(path, 0, "a lens needs an object surface, at least one surface and an image surface");

  const LensGlasses lens_glasses(path, glasses, catalogs);
  std::vector<int> coat_lines;  // per lens surface: its COAT line (0: none, or an iris)
  std::vector<int> surface_lines;  // per lens surface: its SURF line
  LensPrescription lens;
  lens.name = name;
  lens.source = path;
  lens.file = path;
  bool have_stop = false;
  // Surfaces 1 .. n-2 are the lens; the last thickness before the image is the back focus.
  // The object surface's glass is the medium the scene lies in (water for an underwater port).
  if (const ZSurface& object = surfs.front(); !object.glass.empty() && object.glass != "AIR") {
    if (object.glass == "MIRROR") throw MakeInputError(path, object.glass_line, "the object surface cannot be a mirror");
    lens.object_medium = SurfaceGlass(object, lens_glasses, path);
  }
  // Coordinate breaks: the frame the next surface is placed in (its origin and axes in the
  // object side's frame), moved along its z by every thickness. A surface's vertex z along the
  // axis is the frame's z there (each thickness the step to the next vertex, the last to the
  // film), its placement the frame's decentre and axes (optics/surface_placement.h).
  SurfacePlacement frame;
  double last_z = 0;   // the last surface's vertex z, in the frame's coordinates
  int break_line = 0;  // the last coordinate break's
  auto advance = [&](double disz) { frame.offset = frame.offset + frame.ez * disz; };
  auto place = [&](LensSurface& surface) {  // where the frame is now
    if (!lens.surfaces.empty()) lens.surfaces.back().thickness = frame.offset.z - last_z;
    last_z = frame.offset.z;
    surface.placement = Placement(frame);
  };
  for (size_t i = 1; i + 1 < surfs.size(); ++i) {
    const ZSurface& z = surfs[i];
    if (z.infinite_thickness) throw MakeInputError(path, z.line, "an infinite thickness inside the lens");
    if (z.type == "COORDBRK") {
      // PARM 1, 2: decentre x, y; PARM 3, 4, 5: tilts about x, y, z (degrees, right-handed);
      // PARM 6: order (0: decentre, then tilt x, y, z; else tilt z, y, x, then decentre).
      if (!z.glass.empty() && z.glass != "AIR")
        throw MakeInputError(path, z.glass_line, "a coordinate break (surface {}) has no glass", i);
      const double k = M_PI / 180;
      auto decentre = [&] { frame.offset = frame.offset + frame.ex * (z.parm[1] * unit) + frame.ey * (z.parm[2] * unit); };
      if (z.parm[6] == 0) {
        decentre();
        frame = frame.Turned(0, z.parm[3] * k).Turned(1, z.parm[4] * k).Turned(2, z.parm[5] * k);
      } else {
        frame = frame.Turned(2, z.parm[5] * k).Turned(1, z.parm[4] * k).Turned(0, z.parm[3] * k);
        decentre();
      }
      if (!(std::abs(z.disz * unit) <= kMaxLensLength) || !(frame.offset.x * frame.offset.x + frame.offset.y * frame.offset.y <=
                                                             kMaxLensLength * kMaxLensLength))
        throw MakeInputError(path, z.line, "coordinate break {} moves the lens beyond {} mm", i, kMaxLensLength);
      advance(z.disz * unit);
      break_line = z.line;
      continue;
    }
    const bool in_air = (z.glass.empty() || z.glass == "AIR") && !lens.MediumBefore(lens.surfaces.size());
    if (z.diam == 0 && z.clear_aperture == 0 && z.obscuration == 0 && in_air && z.curv == 0 && z.type == "STANDARD" &&
        !z.stop) {
      // A dummy plane in air without a semi-diameter (Zemax writes 0 where it computed none):
      // it neither refracts nor clips; its thickness joins the gap before it.
      if (!(std::abs(z.disz * unit) <= kMaxLensLength))
        throw MakeInputError(path, z.line, "thickness {} mm is beyond {} mm: not a lens", z.disz * unit, kMaxLensLength);
      advance(z.disz * unit);
      continue;
    }
    if (!(z.diam > 0) && !(z.clear_aperture > 0)) throw MakeInputError(path, z.line, "surface {} has no semi-diameter (DIAM)", i);
    LensSurface s;
    s.thickness = z.disz * unit;
    s.semi_diameter = (z.clear_aperture > 0 ? z.clear_aperture : z.diam) * unit;
    s.conic = z.coni;
    s.SetCurvature(z.curv / unit);
    if (z.type == "EVENASPH") {
      // PARM k multiplies r^(2k) in lens units: convert to mm.
      s.a2 = z.parm[1] / unit;
      for (int k = 2; k <= 8; ++k) s.aspheric[k - 2] = z.parm[k] / std::pow(unit, 2 * k - 1);
    } else if (z.type == "TOROIDAL") {
      // PARM 1: the radius of rotation (0: infinite, a cylinder flat in x); PARM 2..8: the
      // profile's terms in y^2, y^4, ..., y^14; PARM 13: the count of Zernike sag terms.
      if (z.parm[13] != 0)
        throw MakeInputError(path, z.parm_line[13], "TOROIDAL surface {} with {} Zernike sag terms (PARM 13): not supported",
                             i, z.parm[13]);
      // Flat in both sections without terms: a plane, whatever its type says.
      s.toroidal = z.curv != 0 || z.parm[1] != 0 || s.a2 != 0 || s.HasAsphericTerms() ||
                   std::any_of(z.parm + 2, z.parm + 9, [](double v) { return v != 0; });
      s.curvature_x = z.parm[1] != 0 ? 1 / (z.parm[1] * unit) : 0;
      s.a2 = z.parm[2] / unit;
      for (int k = 3; k <= 8; ++k) s.aspheric[k - 3] = z.parm[k] / std::pow(unit, 2 * (k - 1) - 1);
    }
    // A parameter the surface's type does not read changes nothing in Zemax either; one that
    // would matter for another type is said (a typo in TYPE would otherwise pass unseen).
    for (int k = 1; k <= 16; ++k) {
      const bool read = (z.type == "EVENASPH" && k <= 8) || (z.type == "TOROIDAL" && (k <= 8 || k == 13));
      if (z.parm[k] != 0 && !read)
        spdlog::warn("{}:{}: PARM {} = {} means nothing to a {} surface: ignored", path, z.parm_line[k], k, z.parm[k], z.type);
    }
    s.obscuration = z.obscuration * unit;
    if (s.obscuration >= s.semi_diameter)
      throw MakeInputError(path, z.line, "the obscuration's radius {} covers the whole surface (semi-diameter {})",
                           s.obscuration, s.semi_diameter);
    if (z.glass == "MIRROR") {
      // Light goes back into the medium it came from (a back-surface mirror: into the glass).
      s.mirror = true;
      s.medium = lens.MediumBefore(lens.surfaces.size());
    } else if (!z.glass.empty() && z.glass != "AIR") {
      s.medium = SurfaceGlass(z, lens_glasses, path);
    }
    if (!z.coat.empty() && s.mirror) {
      // A metal layer by Zemax's names (COATING.DAT's ALUM ...) or ours.
      std::string metal = z.coat;
      for (char& ch : metal) ch = char(std::toupper(static_cast<unsigned char>(ch)));
      if (metal.rfind("ALUM", 0) == 0 || metal == "AL") metal = "Al";
      else if (metal == "SILVER" || metal == "AG") metal = "Ag";
      else if (metal == "GOLD" || metal == "AU") metal = "Au";
      else if (metal == "COPPER" || metal == "CU") metal = "Cu";
      if (std::optional<MirrorMetal> m = MirrorMetal::Named(metal))
        s.mirror_metal = std::make_shared<const MirrorMetal>(std::move(*m));
      else
        spdlog::warn("{}:{}: coating {} on a mirror is not known (metals: {}): the mirror reflects all the light it gets",
                     path, z.coat_line, Printable(z.coat), MirrorMetalList());
    } else if (!z.coat.empty()) {
      // Zemax's MGF2 is a quarter wave of MgF2, as ours; its other COATING.DAT stacks are not known here.
      std::optional<std::shared_ptr<const Coating>> c;
      try {
        c = FindBuiltInCoating(z.coat);
      } catch (const InputError& e) {
        throw MakeInputError(path, z.coat_line, "{}", e.what());
      }
      if (c)
        s.coating = *c;
      else
        spdlog::warn("{}:{}: coating {} is unknown (known: {}); the surface is traced bare", path, z.coat_line, z.coat,
                     BuiltInCoatingNames());
    }
    CheckReachable(s, path, z.line);
    CheckSize(s, path, z.line);
    if (z.stop) {
      have_stop = true;
      if ((s.flat && !s.HasAsphericTerms() && !s.toroidal) || s.mirror) {
        // A plane: the stop itself (in air, in glass, or between two media). A mirror: its rim
        // (a mirror lens has no iris; an iris plane at its vertex would lie behind where the
        // light turns).
        s.is_stop = true;
      } else {
        // A curved (or aspheric) stop surface: the iris in a plane at its vertex, or, where its
        // rim lies before the vertex (a face concave to the object), in the rim's plane: the
        // surface then lies behind the iris over its whole aperture, and the iris clips where
        // the surface's rim does.
        LensSurface iris;
        iris.is_stop = true;
        iris.flat = true;
        iris.semi_diameter = s.semi_diameter;
        iris.medium = lens.MediumBefore(lens.surfaces.size());
        place(iris);
        double rim = 0;
        if (!iris.placement && !s.placement && s.SagAt(0, s.semi_diameter, rim) && rim < 0) {
          if (!lens.surfaces.empty()) lens.surfaces.back().thickness += rim;
          last_z += rim;  // the next place() gives the iris the thickness -rim to the surface
        }
        lens.surfaces.push_back(iris);
        coat_lines.push_back(0);
        surface_lines.push_back(z.line);
      }
    }
    place(s);
    if (std::string why = ToroidTurnMismatch(s); !why.empty()) throw MakeInputError(path, z.line, "{}", why);
    const double disz = s.thickness;
    lens.surfaces.push_back(std::move(s));
    coat_lines.push_back(z.coat_line);
    surface_lines.push_back(z.line);
    advance(disz);
  }
  if (!lens.surfaces.empty()) lens.surfaces.back().thickness = frame.offset.z - last_z;  // to the film
  if (!have_stop) throw MakeInputError(path, 0, "no STOP surface");
  if (break_line) {
    // The film stays across the axis: the breaks must bring the image surface back onto it
    // (a tilted or decentred image plane is not modelled); the film where the frame ends.
    const SurfacePlacement& end = frame;
    const double tilt = std::max({std::abs(end.ex.y), std::abs(end.ex.z), std::abs(end.ey.z), 1 - end.ex.x, 1 - end.ey.y});
    if (tilt > 1e-9 || std::hypot(end.offset.x, end.offset.y) > 1e-9 * (1 + std::abs(end.offset.z)))
      throw MakeInputError(path, break_line, "after the coordinate breaks the image surface lies tilted or decentred "
                           "(by {:.3g} mm across the axis): the film stays on the axis; undo the breaks before the image",
                           std::hypot(end.offset.x, end.offset.y));
    if (lens.MirrorCount() > 0)
      throw MakeInputError(path, break_line, "coordinate breaks in a lens with mirrors (folds) are not supported");
  }
  if (auto mismatch = FirstCoatingMismatch(lens)) throw MakeInputError(path, coat_lines[mismatch->first], "{}", mismatch->second);
  lens_glasses.WarnUnused();
  if (lens.surfaces.back().medium) throw MakeInputError(path, surfs[surfs.size() - 2].line, "the last surface must leave the lens into air");
  if (auto mismatch = FirstDirectionMismatch(lens)) throw MakeInputError(path, surface_lines[mismatch->first], "{}", mismatch->second);
  if (auto crossed = FirstCrossedGap(lens)) throw MakeInputError(path, surface_lines[crossed->first], "{}", crossed->second);
  return lens;
}

}  // namespace objektiv
