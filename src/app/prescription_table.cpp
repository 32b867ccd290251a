#include "app/prescription_table.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace objektiv {

std::string MediumLabel(const LensSurface& s) { return MediumLabel(s.medium); }

std::string MediumLabel(const std::shared_ptr<const Glass>& medium) {
  if (!medium) return "air";
  const Glass& g = *medium;
  // Glasses made from numbers carry their numbers in their name.
  if (g.catalog() == "MODEL" || g.catalog() == "CONSTANT" || g.catalog() == "FORMULA") return g.name();
  return g.catalog() + ":" + g.name();
}

namespace {
// The angle (degrees) between a placed surface's axis and the lens's.
double AxisTilt(const SurfacePlacement& p) { return std::acos(std::clamp(p.ez.z, -1.0, 1.0)) * 180 / M_PI; }
// " decentred (x, y) mm, axis (x, y, z)" (its direction in lens space where tilted), or the turn
// about the axis where only turned (a toroid's sections).
std::string PlacementLabel(const SurfacePlacement& p) {
  auto clean = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
  std::string out;
  if (clean(p.offset.x) != 0 || clean(p.offset.y) != 0)
    out += fmt::format(" decentred ({:.4g}, {:.4g}) mm", clean(p.offset.x), clean(p.offset.y));
  if (AxisTilt(p) > 1e-9)
    out += fmt::format(" axis ({:.4f}, {:.4f}, {:.4f}), tilted {:.4g} deg", clean(p.ez.x), clean(p.ez.y), p.ez.z, AxisTilt(p));
  else if (clean(p.ex.y) != 0)
    out += fmt::format(" turned {:.4g} deg about the axis", std::atan2(p.ex.y, p.ex.x) * 180 / M_PI);
  return out;
}
}  // namespace

std::string PrescriptionTable(const LensPrescription& lens) {
  size_t width = 12;  // the medium column: as wide as its longest label
  for (const LensSurface& s : lens.surfaces) width = std::max(width, MediumLabel(s).size());
  std::string out = fmt::format("  {:>3}  {:>11}  {:>10}  {:<{}} {:>8} {:>6}  {:>10}\n", "row", "radius (mm)",
                                "thickness", "medium after", width, "nd", "Vd", "semi-diam.");
  for (size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    const bool iris = s.is_stop && !s.mirror;  // a mirror that is the stop keeps its radius
    const std::string radius = iris ? "stop" : s.flat || s.radius == 0 ? "inf" : fmt::format("{:.4f}", s.radius);
    std::string nd, vd;
    if (s.medium) {
      nd = fmt::format("{:.5f}", s.medium->ComputedNd());
      if (s.medium->IsDispersive()) vd = fmt::format("{:.2f}", s.medium->ComputedVd());
    }
    std::string extra;
    if (s.mirror) extra += s.is_stop ? " mirror (the stop)" : " mirror";
    if (s.mirror && s.mirror_metal) extra += " reflectance=" + s.mirror_metal->name();
    if (s.mirror && !s.mirror_metal && s.mirror_reflectance != 1) extra += fmt::format(" reflectance={:g}", s.mirror_reflectance);
    if (s.obscuration > 0) extra += fmt::format(" obscuration={:g}", s.obscuration);
    if (s.conic != 0) extra += fmt::format(" k={:g}", s.conic);
    if (s.forbes)
      extra += fmt::format(" {} ({} term{}, norm {:g})", s.forbes->Name(), s.forbes->terms().size(),
                           s.forbes->terms().size() == 1 ? "" : "s", s.forbes->norm_radius());
    else if (s.HasAsphericTerms()) extra += " aspheric";
    if (s.fresnel) extra += fmt::format(" Fresnel (zones {:g} mm)", s.fresnel->pitch());
    if (s.form_error)
      extra += fmt::format(" form error {:g} um PV (seed {})", s.form_error->peak_to_valley() * 1000, s.form_error->seed());
    if (s.toroidal) extra += s.curvature_x == 0 ? " rx=inf (cylinder)" : fmt::format(" rx={:.4f}", 1 / s.curvature_x);
    if (s.dirt) {
      if (s.dirt->coverage() > 0) extra += fmt::format(" dust {:g} ({} particles)", s.dirt->coverage(), s.dirt->particle_count());
      if (s.dirt->scratch_count() > 0)
        extra += fmt::format(" {} scratch{}", s.dirt->scratch_count(), s.dirt->scratch_count() == 1 ? "" : "es");
      extra += fmt::format(" (seed {}, {:.2f}% clear)", s.dirt->seed(), 100 * s.dirt->MeanTransmittance());
    }
    if (s.gradient) extra += fmt::format(" gradient index after: {} ({})", s.gradient->KindName(), s.gradient->Terms());
    if (s.crystal)
      extra += fmt::format(" crystal after: extraordinary {} (nd {:.5f}), optic axis ({:.4g}, {:.4g}, {:.4g})",
                           MediumLabel(s.crystal->extraordinary), s.crystal->extraordinary->ComputedNd(), s.crystal->axis.x,
                           s.crystal->axis.y, s.crystal->axis.z);
    if (s.placement) extra += PlacementLabel(*s.placement);
    out += fmt::format("  {:>3}  {:>11}  {:>10.4f}  {:<{}} {:>8} {:>6}  {:>10.4f}{}\n", i + 1, radius, s.thickness,
                       MediumLabel(s), width, nd, vd, s.semi_diameter, extra);
  }
  return out;
}

nlohmann::ordered_json PrescriptionJson(const LensPrescription& lens) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const LensSurface& s : lens.surfaces) {
    nlohmann::ordered_json r;
    r["stop"] = s.is_stop;
    r["radius_mm"] = (s.is_stop && !s.mirror) || s.flat || s.radius == 0 ? nlohmann::ordered_json()
                                                                          : nlohmann::ordered_json(s.radius);
    if (s.mirror) {
      r["mirror"] = true;
      if (s.mirror_metal) r["mirror_metal"] = s.mirror_metal->name();
      else r["mirror_reflectance"] = s.mirror_reflectance;
    }
    if (s.obscuration > 0) r["obscuration_mm"] = s.obscuration;
    if (s.placement) {
      r["decenter_mm"] = {s.placement->offset.x, s.placement->offset.y};
      r["axis_tilt_deg"] = AxisTilt(*s.placement);
      r["axes"] = {{s.placement->ex.x, s.placement->ex.y, s.placement->ex.z},
                   {s.placement->ey.x, s.placement->ey.y, s.placement->ey.z},
                   {s.placement->ez.x, s.placement->ez.y, s.placement->ez.z}};
    }
    if (s.toroidal)  // the x-z section's radius (null: flat in x)
      r["rx_mm"] = s.curvature_x == 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(1 / s.curvature_x);
    r["thickness_mm"] = s.thickness;
    r["medium"] = MediumLabel(s);
    if (s.medium) {
      r["nd"] = s.medium->ComputedNd();
      if (s.medium->IsDispersive()) r["vd"] = s.medium->ComputedVd();
    }
    r["semi_diameter_mm"] = s.semi_diameter;
    if (s.conic != 0) r["conic"] = s.conic;
    if (s.fresnel) r["fresnel_pitch_mm"] = s.fresnel->pitch();
    if (s.form_error) {
      r["form_error_pv_um"] = s.form_error->peak_to_valley() * 1000;
      r["form_seed"] = s.form_error->seed();
    }
    if (s.dirt) {
      r["dust_coverage"] = s.dirt->coverage();
      r["dirt_clear_share"] = s.dirt->MeanTransmittance();
      r["dust_particles"] = s.dirt->particle_count();
      r["scratches"] = s.dirt->scratch_count();
      r["dirt_seed"] = s.dirt->seed();
    }
    if (s.gradient) {  // the medium after: its profile and terms in the lens file's order
      const std::array<double, 6>& c = s.gradient->coefficients();
      r["gradient"] = s.gradient->KindName();
      r["gradient_terms"] = s.gradient->kind() == GradientIndex::Kind::kPolynomial
                                ? nlohmann::ordered_json{{"nr2", c[0]}, {"nr4", c[1]}, {"nr6", c[2]},
                                                         {"nz1", c[3]}, {"nz2", c[4]}, {"nz3", c[5]}}
                            : s.gradient->kind() == GradientIndex::Kind::kSpherical
                                ? nlohmann::ordered_json{{"centre_mm", c[0]}, {"s1", c[1]}, {"s2", c[2]}}
                                : nlohmann::ordered_json{{"g", c[0]}, {"h4", c[1]}, {"h6", c[2]}};
    }
    if (s.crystal) {  // the medium after is birefringent: its extraordinary index and optic axis
      r["extraordinary"] = MediumLabel(s.crystal->extraordinary);
      r["extraordinary_nd"] = s.crystal->extraordinary->ComputedNd();
      r["optic_axis"] = {s.crystal->axis.x, s.crystal->axis.y, s.crystal->axis.z};
    }
    if (s.forbes) {
      r["q_type"] = s.forbes->Name();
      r["q_norm_mm"] = s.forbes->norm_radius();
      r["q_terms_mm"] = s.forbes->terms();
    }
    rows.push_back(r);
  }
  return rows;
}

}  // namespace objektiv
