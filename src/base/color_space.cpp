#include "base/color_space.h"

#include "base/cie.h"

namespace objektiv {

Mat3 Mul(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

Vec3f Mul(const Mat3& m, const Vec3f& v) {
  return Vec3f(float(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z),
               float(m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z),
               float(m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z));
}

Mat3 Inverse3(const Mat3& m) {
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  double inv = 1 / det;
  Mat3 r;
  r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * inv;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv;
  r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * inv;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv;
  r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * inv;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv;
  return r;
}

Vec3d D65WhiteXYZ() {
  static const Vec3d white = [] {
    // Integrate at 1 nm over the piecewise-linear tables (exact to rounding).
    Vec3d s(0.0);
    for (int l = int(kLambdaMin); l <= int(kLambdaMax); ++l) {
      double w = (l == int(kLambdaMin) || l == int(kLambdaMax)) ? 0.5 : 1.0;
      Vec3f c = CieXyz(float(l));
      s += Vec3d(c) * (w * D65Raw(float(l)));
    }
    return s / s.y;
  }();
  return white;
}

namespace {
// Scale that gives D65 a luminance of 1; computed during static initialisation so that the
// hot-path lookup carries no initialisation guard.
const float kD65Scale = [] {
  double y = 0;
  for (int l = int(kLambdaMin); l <= int(kLambdaMax); ++l) {
    double w = (l == int(kLambdaMin) || l == int(kLambdaMax)) ? 0.5 : 1.0;
    y += w * CieXyz(float(l)).y * D65Raw(float(l));
  }
  return float(CieYIntegral() / y);
}();
}  // namespace

float D65Normalized(float lambda) { return D65Raw(lambda) * kD65Scale; }

namespace {

// Standard construction: columns are the primaries' XYZ scaled so that RGB (1,1,1) = white.
Mat3 RgbToXyzFromPrimaries(Vec2<double> r, Vec2<double> g, Vec2<double> b, const Vec3d& white) {
  auto xyz = [](Vec2<double> c) { return Vec3d(c.x / c.y, 1.0, (1 - c.x - c.y) / c.y); };
  Vec3d pr = xyz(r), pg = xyz(g), pb = xyz(b);
  Mat3 p = {{{pr.x, pg.x, pb.x}, {pr.y, pg.y, pb.y}, {pr.z, pg.z, pb.z}}};
  Mat3 pinv = Inverse3(p);
  Vec3d s(pinv[0][0] * white.x + pinv[0][1] * white.y + pinv[0][2] * white.z,
          pinv[1][0] * white.x + pinv[1][1] * white.y + pinv[1][2] * white.z,
          pinv[2][0] * white.x + pinv[2][1] * white.y + pinv[2][2] * white.z);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p[i][j] *= s[j];
  return p;
}

// Bradford chromatic adaptation from white `from` to white `to` (both XYZ).
Mat3 Bradford(const Vec3d& from, const Vec3d& to) {
  const Mat3 m = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
  Mat3 minv = Inverse3(m);
  auto lms = [&](const Vec3d& w) {
    return Vec3d(m[0][0] * w.x + m[0][1] * w.y + m[0][2] * w.z, m[1][0] * w.x + m[1][1] * w.y + m[1][2] * w.z,
                 m[2][0] * w.x + m[2][1] * w.y + m[2][2] * w.z);
  };
  Vec3d a = lms(from), b = lms(to);
  Mat3 d = {{{b.x / a.x, 0, 0}, {0, b.y / a.y, 0}, {0, 0, b.z / a.z}}};
  return Mul(minv, Mul(d, m));
}

}  // namespace

const ColorSpace& ColorSpace::Rec709() {
  static const ColorSpace cs = [] {
    ColorSpace c;
    c.white_xyz = D65WhiteXYZ();
    c.rgb_to_xyz = RgbToXyzFromPrimaries({0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, c.white_xyz);
    c.xyz_to_rgb = Inverse3(c.rgb_to_xyz);
    return c;
  }();
  return cs;
}

const ColorSpace& ColorSpace::ACEScg() {
  static const ColorSpace cs = [] {
    ColorSpace c;
    Vec3d aces_white(0.32168 / 0.33767, 1.0, (1 - 0.32168 - 0.33767) / 0.33767);
    Mat3 ap1_to_xyz = RgbToXyzFromPrimaries({0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}, aces_white);
    // Scene XYZ is D65-referred: adapt to the ACES white before the AP1 matrix.
    Mat3 adapt = Bradford(D65WhiteXYZ(), aces_white);
    c.xyz_to_rgb = Mul(Inverse3(ap1_to_xyz), adapt);
    c.rgb_to_xyz = Inverse3(c.xyz_to_rgb);
    c.white_xyz = D65WhiteXYZ();
    return c;
  }();
  return cs;
}

}  // namespace objektiv
