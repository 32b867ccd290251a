#include "optics/fresnel_zones.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "optics/lens_prescription.h"

namespace objektiv {

FresnelZones::FresnelZones(const LensSurface& profile, double pitch) : pitch_(pitch) {
  // Each facet sampled finely over the clear aperture (its height is monotonic for a conic,
  // nearly so for aspheres; beyond the semi-diameter rays are clipped), the slab grown by a
  // little more than the samples could miss. A pitch wider than the aperture: one zone.
  const double semi = profile.semi_diameter;
  const int zones = int(std::ceil(semi / pitch));
  for (int k = 0; k <= zones; ++k) base_.push_back(profile.Sag(k * pitch));  // k < zones: inside the aperture
  for (int k = 0; k < zones; ++k) {
    const double base = base_[size_t(k)], from = k * pitch, to = std::min((k + 1) * pitch, semi);
    for (int j = 1; j <= 32; ++j) {
      const double h = profile.Sag(from + (to - from) * j / 32.0) - base;
      lo_ = std::min(lo_, h), hi_ = std::max(hi_, h);
    }
  }
  const double margin = 0.01 * (hi_ - lo_) + 1e-9;
  lo_ -= margin, hi_ += margin;
}

int FresnelZones::Zone(double r) const { return int(std::floor(r / pitch_)); }

double FresnelZones::BaseHeight(const LensSurface& profile, int zone) const {
  return zone >= 0 && size_t(zone) < base_.size() ? base_[size_t(zone)] : profile.Sag(zone * pitch_);
}

std::optional<FresnelZones::Hit> FresnelZones::Intersect(const LensSurface& s, const Vec3d& o, const Vec3d& d) const {
  if (d.z == 0) return std::nullopt;
  double ta = (lo_ - o.z) / d.z, tb = (hi_ - o.z) / d.z;
  if (ta > tb) std::swap(ta, tb);
  ta = std::max(ta, 0.0);
  if (!(tb >= ta)) return std::nullopt;
  // r(t)^2 = A t^2 + B t + C.
  const double A = d.x * d.x + d.y * d.y, B = 2 * (o.x * d.x + o.y * d.y), C = o.x * o.x + o.y * o.y;
  auto radius = [&](double t) { return std::sqrt(std::max((A * t + B) * t + C, 0.0)); };
  double r_lo = std::min(radius(ta), radius(tb)), r_hi = std::max(radius(ta), radius(tb));
  if (A > 0) {
    const double closest = -B / (2 * A);
    if (closest > ta && closest < tb) r_lo = radius(closest);
  }
  // The cuts: where the path crosses a zone's radius (k > 0), and its ends (k = 0).
  struct Cut {
    double t;
    int k;
  };
  thread_local std::vector<Cut> cuts;
  cuts.clear();
  cuts.push_back({ta, 0});
  cuts.push_back({tb, 0});
  const int k_first = Zone(r_lo) + 1, k_last = Zone(r_hi);
  if (k_last - k_first > 100000) return std::nullopt;  // a ray along the slab: not through a lens
  for (int k = k_first; k <= k_last && A > 0; ++k) {
    const double rk = k * pitch_, c = C - rk * rk, disc = B * B - 4 * A * c;
    if (disc < 0) continue;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    for (double t : {q / A, q != 0 ? c / q : -1.0})
      if (t > ta && t < tb) cuts.push_back({t, k});
  }
  std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.t < b.t; });
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double u0 = cuts[i].t, u1 = cuts[i + 1].t;
    if (const int k = cuts[i].k; k > 0) {
      // Crossing the radius r_k: the riser stands there from the vertex plane to h_(k-1).
      const double h = BaseHeight(s, k) - BaseHeight(s, k - 1), z = o.z + u0 * d.z;
      if (z >= std::min(0.0, h) && z <= std::max(0.0, h)) return Hit{u0, true};
    }
    if (!(u1 > u0)) continue;
    const int zone = Zone(radius(0.5 * (u0 + u1)));
    const double base = BaseHeight(s, zone);
    auto gap = [&](double t) { return o.z + t * d.z - (s.Sag(radius(t)) - base); };
    double a = u0, b = u1, fa = gap(a), fb = gap(b);
    if (fa == 0) return Hit{a, false};
    if ((fa > 0) == (fb > 0)) continue;
    // Newton's method kept inside the bracket (a step that leaves it bisects instead; the facet
    // is smooth within its zone), to the double's limit.
    double t = 0.5 * (a + b);
    for (int it = 0; it < 100; ++it) {
      const double r = radius(t);
      double sag, slope;
      s.SagWithSlope(r, sag, slope);
      const double ft = o.z + t * d.z - (sag - base);
      if (ft == 0) break;
      if ((ft > 0) == (fa > 0)) a = t, fa = ft;
      else b = t;
      const double dfdt = d.z - (r > 0 ? slope * ((A * t + 0.5 * B) / r) : 0.0), newton = t - ft / dfdt;
      const double next = (dfdt != 0 && newton > a && newton < b) ? newton : 0.5 * (a + b);
      const bool done = std::abs(next - t) <= 1e-15 * (1 + std::abs(t)) || b - a <= 1e-15 * (1 + std::abs(a));
      t = next;
      if (done) break;
    }
    return Hit{t, false};
  }
  return std::nullopt;
}

}  // namespace objektiv
