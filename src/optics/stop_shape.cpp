#include "optics/stop_shape.h"

#include <algorithm>
#include <cmath>

#include "base/sampling.h"

namespace objektiv {

namespace {

// x - sin(x) cos(x) = (2x - sin 2x) / 2, without cancellation for small x.
double ChordDeficit(double x) {
  if (std::abs(x) < 1e-2) {
    double x3 = x * x * x;
    return 2 * x3 / 3 - 2 * x3 * x * x / 15;
  }
  return x - std::sin(x) * std::cos(x);
}

// Area of the part of a disc of radius r beyond a chord at distance s from its centre.
double SegmentArea(double r, double s) { return r * r * ChordDeficit(std::acos(std::clamp(s / r, -1.0, 1.0))); }

}  // namespace

StopShape StopShape::Iris(int blades, double curvature, double rotation) {
  StopShape s;
  curvature = std::clamp(curvature, 0.0, 1.0);
  if (blades < 3 || curvature >= 1) return s;  // fully curved blades make the circle
  s.blades_ = blades;
  s.curvature_ = curvature;
  s.rotation_ = rotation;
  const double half = M_PI / blades;
  s.arc_.apothem = std::cos(half);
  s.arc_.half_chord = std::sin(half);
  s.curved_ = curvature > 0;
  if (s.curved_) {
    // The circle through both corners (apothem, +-half_chord) and the bulge m on the bisector.
    const double m = s.arc_.apothem + curvature * (1 - s.arc_.apothem);
    s.arc_.xc = (1 - m * m) / (2 * (s.arc_.apothem - m));
    s.arc_.radius = m - s.arc_.xc;
    s.arc_.segment_area = SegmentArea(s.arc_.radius, s.arc_.apothem - s.arc_.xc);
  }
  return s;
}

void StopShape::Cut(ConvexPolygon polygon) {
  cut_ = true;
  cut_polygon_ = std::move(polygon);
}

StopShape StopShape::Rotated(double angle) const {
  StopShape s = *this;
  s.rotation_ += angle;
  if (cut_) {
    const double c = std::cos(angle), sn = std::sin(angle);
    for (Vec2d& v : s.cut_polygon_.vertices) v = Vec2d(c * v.x - sn * v.y, sn * v.x + c * v.y);
  }
  return s;
}

bool StopShape::InsideIris(double x, double y) const {
  const double r2 = x * x + y * y;
  if (r2 > 1) return false;
  if (blades_ == 0) return true;
  // Into the frame of the blade the point faces: its edge's bisector becomes +x.
  const double sector = 2 * M_PI / blades_, half = sector / 2;
  double phi = std::atan2(y, x) - rotation_;
  phi -= sector * std::floor(phi / sector);
  const double a = phi - half, r = std::sqrt(r2);
  const double px = r * std::cos(a), py = r * std::sin(a);
  if (!curved_) return px <= arc_.apothem;
  return (px - arc_.xc) * (px - arc_.xc) + py * py <= arc_.radius * arc_.radius;
}

bool StopShape::Contains(double x, double y) const {
  return InsideIris(x, y) && (!cut_ || cut_polygon_.Contains(Vec2d(x, y)));
}

StopShape::Symmetry StopShape::symmetry() const {
  if (cut_) return {1, false, 0};
  if (blades_ == 0) return {0, false, 0};
  return {blades_, true, rotation_};
}

double StopShape::IrisArea() const {
  if (blades_ == 0) return M_PI;
  return blades_ * (arc_.apothem * arc_.half_chord + arc_.segment_area);
}

Vec2d StopShape::SampleSegment(double u, double v) const {
  // The segment's width across the bisector at distance s from the arc's centre is
  // 2 sqrt(R^2 - s^2); the area beyond s is SegmentArea(R, s), decreasing in s. Choose s with
  // the area beyond it a fraction (1 - u) of the whole (bisection in double precision: exact
  // to the last bits in 60 steps), then the height uniformly.
  const double R = arc_.radius, target = (1 - u) * arc_.segment_area;
  double lo = arc_.apothem - arc_.xc, hi = R;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (SegmentArea(R, mid) > target ? lo : hi) = mid;
  }
  const double s = 0.5 * (lo + hi), h = std::sqrt(std::max(R * R - s * s, 0.0));
  return {arc_.xc + s, (2 * v - 1) * h};
}

Vec2d StopShape::SampleIris(Vec2d u) const {
  if (blades_ == 0) {
    Vec2f d = SampleUniformDiskConcentric(Vec2f(float(u.x), float(u.y)));
    return {d.x, d.y};
  }
  // One of the n congruent sectors (u.x reused after the choice): the triangle from the
  // centre to the blade's corners, or, for curved blades, the segment beyond its chord, in
  // proportion to their areas.
  double scaled = u.x * blades_;
  const int k = std::min(int(scaled), blades_ - 1);
  double ux = scaled - k;
  const double triangle = arc_.apothem * arc_.half_chord;
  const double p_triangle = triangle / (triangle + arc_.segment_area);
  Vec2d p;  // in the bisector frame
  if (!curved_ || ux < p_triangle) {
    ux /= p_triangle;
    Vec2f b = SampleUniformTriangle(Vec2f(float(std::min(ux, 0.99999994)), float(u.y)));
    p = Vec2d(arc_.apothem * (b.x + b.y), arc_.half_chord * (b.y - b.x));  // corners k, k + 1 at -+half_chord
  } else {
    p = SampleSegment((ux - p_triangle) / (1 - p_triangle), u.y);
  }
  const double a = rotation_ + (k + 0.5) * 2 * M_PI / blades_, c = std::cos(a), s = std::sin(a);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

}  // namespace objektiv
