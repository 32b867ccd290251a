// Real-ray analysis: aberrations behave as third-order theory predicts for small fields and
// apertures; signs of distortion; spots; chromatic aberration of a singlet.
#include <gtest/gtest.h>

#include "optics/lens_file.h"
#include "optics/paraxial.h"
#include "optics/real_ray_analysis.h"

namespace objektiv {
namespace {

LensSystem Focused(const std::string& name) {
  LensPrescription lens = LoadLens(name, GlassCatalog::Default());
  LensSystem t(lens);
  t.SetBackFocus(ComputeParaxial(lens).bfl);
  return t;
}

TEST(RealRays, ChiefRayCrossesTheStopCentre) {
  LensSystem t = Focused("dgauss.50mm");
  for (double field : {0.0, 5.0, 15.0}) {
    auto chief = ChiefRay(t, field, 587.6);
    ASSERT_TRUE(chief) << field;
    EXPECT_NEAR(chief->d.y, std::sin(field * M_PI / 180), 1e-12);
  }
  // On axis the real image height is zero.
  EXPECT_NEAR(*RealImageHeight(t, 0, 587.6), 0, 1e-12);
}

TEST(RealRays, DistortionGrowsAsTheSquareOfTheField) {
  // (Not the Tessar: its third-order distortion is corrected almost to zero, -1e-6 at 2
  // degrees, so higher orders dominate even there.)
  for (const char* name : {"dgauss.50mm", "wide.22mm", "fisheye.10mm"}) {
    LensSystem t = Focused(name);
    double efl = ComputeParaxial(t.prescription()).efl;
    double d1 = *Distortion(t, efl, 1.0, 587.6), d2 = *Distortion(t, efl, 2.0, 587.6);
    EXPECT_LT(std::abs(d1), 1e-3) << name;
    // Third order: D ~ theta^2 (higher orders perturb the ratio slightly).
    EXPECT_NEAR(d2 / d1, 4.0, 0.1) << name;
  }
  // The retrofocus wide angle is barrel-distorted, the telephoto pincushion-distorted.
  LensSystem wide = Focused("wide.22mm");
  EXPECT_LT(*Distortion(wide, ComputeParaxial(wide.prescription()).efl, 15, 587.6), 0);
  LensSystem tele = Focused("telephoto.250mm");
  EXPECT_GT(*Distortion(tele, ComputeParaxial(tele.prescription()).efl, 4, 587.6), 0);
}

TEST(RealRays, LongitudinalAberrationGrowsAsTheSquareOfTheHeight) {
  for (const char* name : {"dgauss.50mm", "telephoto.250mm"}) {
    LensSystem t = Focused(name);
    double a1 = *LongitudinalAberration(t, 1.0, 587.6), a2 = *LongitudinalAberration(t, 2.0, 587.6);
    EXPECT_NEAR(a2 / a1, 4.0, 0.15) << name;
    EXPECT_NEAR(*LongitudinalAberration(t, 1e-3, 587.6), 0, 1e-6) << name;
  }
}

TEST(RealRays, SpotsShrinkWhenStoppingDownAndAreTinyForAnIdealSurface) {
  LensSystem t = Focused("dgauss.50mm");
  Spot open = SpotDiagram(t, 0, 587.6);
  t.SetStopSemiDiameter(t.StopSemiDiameter() / 4);  // about f/8
  Spot closed = SpotDiagram(t, 0, 587.6);
  ASSERT_FALSE(open.points.empty());
  ASSERT_FALSE(closed.points.empty());
  EXPECT_LT(closed.rms_radius, open.rms_radius);
  EXPECT_NEAR(open.centroid.x, 0, 1e-9);
  EXPECT_NEAR(open.centroid.y, 0, 1e-9);
  // Off axis, the beam is cut by the rims: optical vignetting.
  t.SetStopSemiDiameter(1e9);
  Spot axis = SpotDiagram(t, 0, 587.6), edge = SpotDiagram(t, 20, 587.6);
  EXPECT_LT(edge.transmitted, axis.transmitted);

  LensSystem hyperbola(ParseNativeLens("stop 0 air 12\nsurface inf 8 n=1.5 12\nsurface -50 100 air 12 k=-2.25\n", "h.lens", GlassCatalog::Default()));
  Spot ideal = SpotDiagram(hyperbola, 0, 587.6);
  ASSERT_GT(ideal.points.size(), 100u);
  EXPECT_LT(ideal.geometric_radius, 1e-3);  // below 1 um
}

TEST(RealRays, AxialColourOfAThinSingletIsFOverV) {
  // Thin N-BK7 biconvex lens: the F and C foci are f / Vd apart (to first order). Its faces do
  // not cross within their 0.3 mm (the sags there: 0.00045 mm each).
  LensPrescription l = ParseNativeLens("stop 0 air 0.3\nsurface 100 0.001 N-BK7 0.3\nsurface -100 200 air 0.3\n", "s.lens", GlassCatalog::Default());
  ParaxialData d = ComputeParaxial(l, 587.5618);
  double lca = ComputeParaxial(l, 656.2725).bfl - ComputeParaxial(l, 486.1327).bfl;
  EXPECT_NEAR(lca, d.efl / 64.17, 0.01 * d.efl / 64.17);
}

}  // namespace
}  // namespace objektiv

#include "io/lens_plot.h"

namespace objektiv {
namespace {
TEST(LensPlot, LayoutHasOneShapePerElementAndRayFans) {
  LensSystem t = Focused("dgauss.50mm");
  std::string svg = PlotLensLayout(t, {0, 10}).ToString();
  auto count = [&](const std::string& what) {
    size_t n = 0;
    for (size_t p = svg.find(what); p != std::string::npos; p = svg.find(what, p + 1)) ++n;
    return n;
  };
  // dgauss.50mm: 7 glass spaces (rows followed by glass), drawn as 7 polygons.
  size_t glass = 0;
  for (const LensSurface& s : t.prescription().surfaces) glass += s.medium != nullptr;
  EXPECT_EQ(count("<polygon"), glass);
  EXPECT_EQ(count("<polyline"), 10u);  // five rays per field
  std::vector<double> fields = DefaultFields(t);
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_GT(fields[2], 20.0);  // the double Gauss covers full frame (23.2 degrees)
}
}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// A thin biconvex N-BK7 lens with a small stop in contact (f ~ 193 mm).
LensSystem ThinLensAtStop() {
  // Semi-diameters just above the stop's (the faces do not cross there: sags of 0.012 mm each).
  LensPrescription l = ParseNativeLens("stop 0 air 2\nsurface 200 0.03 N-BK7 2.2\nsurface -200 190 air 2.2\n", "thin.lens", GlassCatalog::Default());
  LensSystem t(l);
  t.SetBackFocus(ComputeParaxial(l).bfl);
  return t;
}

TEST(RealRays, RelativeIlluminationOfAThinLensIsCos4) {
  LensSystem t = ThinLensAtStop();
  EXPECT_NEAR(*RelativeIllumination(t, 0, 587.6), 1, 1e-12);
  for (double field : {10.0, 20.0, 30.0}) {
    double c = std::cos(field * M_PI / 180);
    // The area estimate counts rays on a 61 x 61 grid (edge effects ~1%).
    EXPECT_NEAR(*RelativeIllumination(t, field, 587.6), c * c * c * c, 0.015) << field;
  }
  // Vignetting by rims lowers it further: the double Gauss at full aperture, 20 degrees.
  LensSystem dg = Focused("dgauss.50mm");
  double c20 = std::pow(std::cos(20 * M_PI / 180), 4);
  EXPECT_LT(*RelativeIllumination(dg, 20, 587.6), c20);
}

TEST(RealRays, FieldCurvatureOfAThinLensMatchesThirdOrderTheory) {
  LensSystem t = ThinLensAtStop();
  ParaxialData p = ComputeParaxial(t.prescription());
  double n = t.prescription().surfaces[1].medium->Index(587.5618);
  double field = 4, h = p.efl * std::tan(field * M_PI / 180);
  FieldCurvature fc = *FieldCurvatureAt(t, field, 587.5618);
  EXPECT_NEAR(fc.tangential, -(3 + 1 / n) * h * h / (2 * p.efl), 0.03 * (3 + 1 / n) * h * h / (2 * p.efl));
  EXPECT_NEAR(fc.sagittal, -(1 + 1 / n) * h * h / (2 * p.efl), 0.03 * (1 + 1 / n) * h * h / (2 * p.efl));
  // On axis both foci are on the film (placed at the paraxial focus for the same wavelength).
  FieldCurvature axis = *FieldCurvatureAt(t, 0.0, 587.5618);
  EXPECT_NEAR(axis.tangential, 0, 1e-6);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

TEST(RealRays, BallLensMatchesItsClosedForm) {
  // A glass sphere of radius R: EFL = n R / (2 (n - 1)) from its centre, BFL = EFL - R.
  const double R = 5, n = 1.5;
  LensPrescription ball = ParseNativeLens("stop 0 air 3\nsurface 5 10 n=1.5 5\nsurface -5 5 air 5\n", "ball.lens", GlassCatalog::Default());
  ParaxialData d = ComputeParaxial(ball);
  EXPECT_NEAR(d.efl, n * R / (2 * (n - 1)), 1e-12);
  EXPECT_NEAR(d.bfl, n * R / (2 * (n - 1)) - R, 1e-12);
}

TEST(RealRays, RealBackFocusAndFieldOfView) {
  // Spherical aberration of a plain singlet pulls the best focus in front of the paraxial one;
  // an aberration-free surface keeps it there.
  LensSystem sphere(ParseNativeLens("stop 0 air 10\nsurface inf 8 n=1.5 12\nsurface -50 100 air 12\n", "s.lens", GlassCatalog::Default()));
  ParaxialData p = ComputeParaxial(sphere.prescription());
  EXPECT_LT(RealBackFocus(sphere, 587.6), p.bfl - 0.1);
  // A fast singlet whose best focus lies more than 5% of the EFL before the paraxial one (the
  // search's first window): the minimum of a scan of the spot's RMS radius.
  LensSystem fast(ParseNativeLens("stop 0.5 air 18\nsurface 26 12 n=1.5 19\nsurface inf 40 air 19\n", "f.lens", GlassCatalog::Default()));
  const double found = RealBackFocus(fast, 587.6);
  double scan = 0, least = INFINITY;
  for (double b = 30; b <= 46; b += 0.005) {
    LensSystem t = fast;
    t.SetBackFocus(b);
    if (const double rms = SpotDiagram(t, 0, 587.6, 41).rms_radius; rms < least) least = rms, scan = b;
  }
  EXPECT_LT(scan, ComputeParaxial(fast.prescription()).bfl - 0.05 * 52);
  EXPECT_NEAR(found, scan, 0.01);
  LensSystem hyperbola(ParseNativeLens("stop 0 air 10\nsurface inf 8 n=1.5 12\nsurface -50 100 air 12 k=-2.25\n", "h.lens", GlassCatalog::Default()));
  EXPECT_NEAR(RealBackFocus(hyperbola, 587.6), ComputeParaxial(hyperbola.prescription()).bfl, 1e-4);
  // Field of view of the double Gauss on full frame: close to 2 atan(21.63 / 50.36) = 46.5
  // degrees diagonally, a little more with its slight barrel distortion.
  LensSystem dg = Focused("dgauss.50mm");
  FieldOfView fov = SensorFieldOfView(dg, 36, 24, 587.6);
  double paraxial = 2 * std::atan(std::hypot(36.0, 24.0) / 2 / 50.358) * 180 / M_PI;
  EXPECT_GT(fov.diagonal, paraxial);
  EXPECT_LT(fov.diagonal, paraxial + 1.0);
  EXPECT_NEAR(fov.horizontal, 2 * std::atan(18 / 50.358) * 180 / M_PI, 0.5);
  EXPECT_LT(fov.vertical, fov.horizontal);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(RealRays, FisheyeFieldIsLimitedByItsImageCircle) {
  // The Muller fisheye is a 155.9 degree design: on a full-frame sensor its image circle, not
  // the sensor, bounds the field; the vertical field never exceeds the horizontal one.
  LensSystem f = Focused("fisheye.10mm");
  FieldOfView fov = SensorFieldOfView(f, 36, 24, 587.6);
  EXPECT_LE(fov.vertical, fov.horizontal);
  EXPECT_LE(fov.horizontal, fov.diagonal);
  EXPECT_GT(fov.diagonal, 150);
  EXPECT_LT(fov.diagonal, 180);
  // Chief rays exist far off axis: strong barrel distortion at 60 degrees.
  ParaxialData p = ComputeParaxial(f.prescription());
  EXPECT_LT(*Distortion(f, p.efl, 60, 587.6), -0.3);
}
}  // namespace
}  // namespace objektiv
