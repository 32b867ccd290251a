// RGB colour spaces defined by primaries and a white illuminant, with the XYZ<->RGB
// matrices derived from this project's own CIE tables, so that an RGB of (1,1,1) under
// the space's illuminant round-trips exactly.
#pragma once
#include <array>

#include "base/vec.h"

namespace objektiv {

using Mat3 = std::array<std::array<double, 3>, 3>;
Mat3 Mul(const Mat3& a, const Mat3& b);
Vec3f Mul(const Mat3& m, const Vec3f& v);
Mat3 Inverse3(const Mat3& m);

struct ColorSpace {
  Mat3 rgb_to_xyz, xyz_to_rgb;
  Vec3d white_xyz;  // Y = 1

  // Linear Rec.709 / sRGB primaries, D65 white.
  static const ColorSpace& Rec709();
  // ACES AP1 primaries with the ACES white; XYZ (D65-referred) is adapted with Bradford.
  static const ColorSpace& ACEScg();

  Vec3f ToRGB(const Vec3f& xyz) const { return Mul(xyz_to_rgb, xyz); }
  Vec3f ToXYZ(const Vec3f& rgb) const { return Mul(rgb_to_xyz, rgb); }
};

// XYZ tristimulus of the D65 illuminant normalised to Y = 1, from the tables in cie.cpp.
Vec3d D65WhiteXYZ();
// Luminance-normalised D65: D65Raw scaled so that its Y (with CieYIntegral) is 1.
float D65Normalized(float lambda);

}  // namespace objektiv
