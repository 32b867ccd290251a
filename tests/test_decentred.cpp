// Decentred and tilted surfaces (decenter=, tilt=, Zemax COORDBRK) and a scene's tilt lens: a
// decentred singlet's focus on its own axis, a tilted plate's lateral shift against its closed
// form, the batch tracer against the exact one, the pupil bounds of a lens without any
// symmetry, the placement's rotations, the f-number of a moved lens, and the readers' checks.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "base/error.h"
#include "batch_agreement.h"
#include "pupil_bound_checks.h"
#include "base/rng.h"
#include "camera/lens_camera_setup.h"
#include "camera/realistic_camera.h"
#include "io/scene_loader.h"
#include "optics/batch_tracer.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/pupil_bounds.h"
#include "optics/zemax_lens.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return ParseNativeLens(text, "test.lens", GlassCatalog::Default()); }

TEST(Placement, TiltsAreRightHandedAndApplyInTurn) {
  // About x: +y turns toward +z; then about the new y: the new z turns toward the new x.
  const SurfacePlacement a = SurfacePlacement::DecenterTilt(0, 0, 90, 0, 0);
  EXPECT_NEAR(Length(a.ey - Vec3d(0, 0, 1)), 0, 1e-15);
  EXPECT_NEAR(Length(a.ez - Vec3d(0, -1, 0)), 0, 1e-15);
  const SurfacePlacement b = SurfacePlacement::DecenterTilt(1, 2, 90, 90, 0);
  EXPECT_NEAR(Length(b.ez - a.ex), 0, 1e-15);  // the new z took the old x's place
  EXPECT_EQ(b.offset.x, 1);
  EXPECT_EQ(b.offset.y, 2);
  // Orthonormal and right-handed.
  const SurfacePlacement c = SurfacePlacement::DecenterTilt(0, 0, 13, -27, 41);
  EXPECT_NEAR(Dot(c.ex, c.ey), 0, 1e-15);
  EXPECT_NEAR(Length(Cross(c.ex, c.ey) - c.ez), 0, 1e-15);
  EXPECT_NEAR(Length(c.FromLocal(c.ToLocal(Vec3d(0.3, -2, 5))) - Vec3d(0.3, -2, 5)), 0, 1e-14);
}

TEST(Placement, ADecentredSingletFocusesOnItsOwnAxis) {
  // A plano-convex singlet decentred by 2 mm in x and 1 mm in y (both faces): a thin beam
  // along the lens's axis comes to focus on that axis, 2 mm and 1 mm from the lens space axis.
  const LensSystem lens(Parse("stop 1 air 20\n"
                              "surface 50 4 n=1.5 15 decenter=2,1\n"
                              "surface inf 97.33333333333333 air 15 decenter=2,1\n"));
  for (double h : {-0.3, 0.2, 0.4}) {
    for (int axis = 0; axis < 2; ++axis) {
      const Vec3d o(2 + (axis == 0 ? h : 0), 1 + (axis == 1 ? h : 0), -5);
      const TraceResult t = TraceFromObject(lens, {o, {0, 0, 1}}, 550);
      ASSERT_TRUE(t.ray);
      const Vec3d at = t.ray->o + t.ray->d * ((lens.FilmZ() - t.ray->o.z) / t.ray->d.z);
      // The paraxial focus of R 50, n 1.5, 4 mm thick, plane back: 100 mm from the front face's
      // principal plane, 97.33 mm behind the back face; a 0.4 mm zone's aberration is ~1e-4 mm.
      EXPECT_NEAR(at.x, 2, 2e-4) << h << " " << axis;
      EXPECT_NEAR(at.y, 1, 2e-4) << h << " " << axis;
    }
  }
}

TEST(Placement, ATiltedPlateShiftsARayAsItsClosedFormSays) {
  // Two parallel faces 10 mm apart along z, both tilted 20 degrees about y: a plate of
  // thickness t = 10 cos 20 at incidence 20 degrees. A ray along z leaves parallel to itself,
  // shifted sideways by t sin(i) (1 - cos(i) / sqrt(n^2 - sin^2(i))), in x.
  const double n = 1.5, i = 20 * M_PI / 180, t = 10 * std::cos(i);
  const LensSystem lens(Parse("stop 6 air 20\n"  // the tilted face's rim reaches 15 sin 20 = 5.1 mm forward
                              "surface inf 10 n=1.5 15 tilt=0,20\n"
                              "surface inf 20 air 15 tilt=0,20\n"));
  const TraceResult r = TraceFromObject(lens, {{0.5, -0.7, -5}, {0, 0, 1}}, 550);
  ASSERT_TRUE(r.ray);
  EXPECT_NEAR(Length(r.ray->d - Vec3d(0, 0, 1)), 0, 1e-12);
  const double expected = t * std::sin(i) * (1 - std::cos(i) / std::sqrt(n * n - std::sin(i) * std::sin(i)));
  EXPECT_NEAR(std::abs(r.ray->o.x - 0.5), expected, 1e-9);
  EXPECT_NEAR(r.ray->o.y, -0.7, 1e-12);
}

// The double Gauss with its rear pair decentred and its last face tilted (a decentring
// tolerance gone wrong): no symmetry left.
LensSystem Crooked() {
  const std::string text =
      "surface 29.475 3.76 n=1.67 12.6\nsurface 84.83 0.12 air 12.6\nsurface 19.275 4.025 n=1.67 11.5\n"
      "surface 40.77 3.275 n=1.699 11.5\nsurface 12.75 5.705 air 9\nstop 4.5 air 8.55\n"
      "surface -14.495 1.18 n=1.603 8.5\nsurface 40.77 6.065 n=1.658 10\nsurface -20.385 0.19 air 10\n"
      "surface 437.065 3.22 n=1.717 10 decenter=0.4,-0.3\nsurface -39.73 36.1 air 10 decenter=0.4,-0.3 tilt=2,-1.5\n";
  return AtParaxialInfinityFocus(Parse(text), 587.56);
}

TEST(Placement, BatchTracerFollowsTheExactOne) {
  const LensSystem lens = Crooked();
  EXPECT_FALSE(lens.prescription().Centred());
  const test::BatchAgreement a = test::CompareTracers(lens, 3000, 12, -50, 9, 9);
  test::ExpectAgreement(a, 300, 6, 2e-3);  // mm, 50 mm in front of the lens
}

TEST(Placement, PupilBoundsHoldAllTheLight) {
  SKIP_UNDER_SANITIZERS("Placement.CameraTakesTheCrookedLens");
  // As PupilBounds' TheBoundContainsAllTheLight, at film points in every quadrant (no mirror
  // symmetry: the x-y table covers the whole film).
  const LensSystem lens = Crooked();
  const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
  PCG32 rng(2, 7);
  for (Vec2d film : {Vec2d(0, 0), Vec2d(12.1, 7.3), Vec2d(-15.2, 9.9), Vec2d(-8.4, -11.1), Vec2d(16.9, -4.2)}) {
    const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 30, 40000, rng, 587.56);
    ASSERT_TRUE(a.has_bound);
    EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << film.x << ", " << film.y;
    EXPECT_GT(a.passed_share, 0.9) << film.x << ", " << film.y;  // few rays wasted
  }
}

TEST(Placement, MirrorSymmetryIsFoundAndTheHalfTableHoldsAllTheLight) {
  // Tilted about x and decentred along y: its own mirror image under x -> -x, not under y -> -y.
  const char* tilted_about_x = "stop 6 air 12\nsurface 60 7 n=1.6 14 decenter=0,0.8 tilt=3,0\n"
                               "surface -60 45 air 14 decenter=0,0.8 tilt=3,0\n";
  const LensSystem lens(Parse(tilted_about_x));
  EXPECT_TRUE(lens.prescription().MirrorSymmetric(0));
  EXPECT_FALSE(lens.prescription().MirrorSymmetric(1));
  EXPECT_FALSE(Parse("stop 6 air 12\nsurface 60 7 n=1.6 14 decenter=0.1,0\nsurface -60 45 air 14\n").MirrorSymmetric(0));
  EXPECT_TRUE(Parse("stop 6 air 12\nsurface 60 7 n=1.6 14 decenter=0.1,0\nsurface -60 45 air 14\n").MirrorSymmetric(1));
  EXPECT_FALSE(Parse("stop 6 air 12\nsurface 60 7 n=1.6 14 tilt=0,0,20\nsurface -60 45 air 14\n").MirrorSymmetric(1));
  EXPECT_TRUE(Parse("stop 6 air 12\nsurface 60 7 n=1.6 14 tilt=0,0,90\nsurface -60 45 air 14\n").MirrorSymmetric(1));
  SKIP_UNDER_SANITIZERS("Placement.CameraTakesTheCrookedLens");
  // The bounds of film points with x < 0 are the mirror images of those with x > 0.
  const PupilBounds bounds(lens, std::hypot(18.0, 12.0));
  PCG32 rng(4, 1);
  for (Vec2d film : {Vec2d(-11.3, 6.1), Vec2d(11.3, 6.1), Vec2d(-6.2, -10.4), Vec2d(-16.0, 0.5)}) {
    const test::AreaEstimates a = test::PassingArea(lens, bounds, film, 30, 40000, rng, 587.56);
    ASSERT_TRUE(a.has_bound);
    EXPECT_NEAR(a.bound, a.brute, 4 * a.se) << film.x << ", " << film.y;
    EXPECT_GT(a.passed_share, 0.85) << film.x << ", " << film.y;
  }
}

TEST(Placement, CameraTakesTheCrookedLensAndTheParaxialModelsRefuseIt) {
  LensCameraSpec spec;
  spec.lens = Crooked().prescription();
  // A small sensor: the x-y pupil table without symmetry, built quickly enough for the
  // sanitizers' run.
  spec.settings.sensor_width = 12, spec.settings.sensor_height = 8;
  EXPECT_NO_THROW(MakeLensCamera(Transform(), 48, 32, spec));
  // A lens's f-number is its own, whatever its placement: the double Gauss moved 3 mm across
  // the axis as a whole (a shift lens) still opens to f/2.03 (its axial cone, traced along the
  // film's normal, would have been vignetted to about f/2.8).
  const LensPrescription dgauss = LoadLens("dgauss.50mm", GlassCatalog::Default());
  SurfacePlacement shift;
  shift.offset = {3, 0, 0};
  StopRequest stop;
  stop.fnumber = 2.1;
  const LensSetup shifted = SetUpLens(MovedAsAWhole(dgauss, shift, 0), stop, {});
  const LensSetup centred = SetUpLens(dgauss, stop, {});
  EXPECT_NEAR(shifted.lens.StopSemiDiameter(), centred.lens.StopSemiDiameter(), 1e-12);
  EXPECT_FALSE(shifted.lens.prescription().Centred());
  spec.model = LensModel::kThick;
  try {
    MakeLensCamera(Transform(), 48, 32, spec);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("decentred or tilted"), std::string::npos) << e.what();
  }
}

TEST(Placement, CameraRefusesALensThatLetsNoLightThrough) {
  // The back face 30 mm off the axis: every ray misses its clear aperture (it rendered black).
  LensCameraSpec spec;
  spec.lens = ParseNativeLens("stop 0.5 air 10\nsurface 30 5 n=1.5 11\nsurface inf 50 air 11 decenter=0,30\n", "miss.lens",
                              GlassCatalog::Default());
  try {
    MakeLensCamera(Transform(), 64, 32, spec);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no light reaches the film"), std::string::npos) << e.what();
  }
}

TEST(Placement, ReaderChecksDecenterAndTilt) {
  auto error = [](const std::string& text) {
    try {
      Parse(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error("stop 5 air 8 decenter=0.5,0\nsurface 40 5 n=1.5 10 tilt=1,2,3\nsurface -40 40 air 10\n"), "accepted");
  EXPECT_NE(error("stop 5 air 8\nsurface 40 5 n=1.5 10 decenter=1,2,3\nsurface -40 40 air 10\n").find("test.lens:2: decenter=1,2,3"),
            std::string::npos);
  EXPECT_NE(error("stop 5 air 8\nsurface 40 5 n=1.5 10 tilt=95\nsurface -40 40 air 10\n").find("test.lens:2: tilt 95"),
            std::string::npos);
  EXPECT_NE(error("stop 5 air 8 k=1\nsurface 40 5 n=1.5 10\nsurface -40 40 air 10\n").find("test.lens:1: the stop takes"),
            std::string::npos);
  EXPECT_NE(error("stop 5 air 8\nsurface 40 5 n=1.5 10 decenter=,1\nsurface -40 40 air 10\n").find("test.lens:2:"),
            std::string::npos);
  EXPECT_NE(error("stop 5 air 8 decenter=1\nsurface 40 5 n=1.5 10\nsurface -40 40 air 10\n").find("test.lens:1: decenter=1: DX,DY"),
            std::string::npos);
  // A toroid turned a quarter about the axis is a toroid with its sections swapped; at 45
  // degrees its sections cross the film's axes, which paraxial optics here does not model.
  EXPECT_EQ(error("stop 5 air 8\nsurface inf 5 n=1.5 10 rx=40 tilt=0,0,90\nsurface -40 40 air 10\n"), "accepted");
  EXPECT_NE(error("stop 5 air 8\nsurface inf 5 n=1.5 10 rx=40 tilt=0,0,45\nsurface -40 40 air 10\n").find("test.lens:2: a toroid turned 45 degrees"),
            std::string::npos);
  // A zero placement is none.
  EXPECT_TRUE(Parse("stop 5 air 8 decenter=0,0 tilt=0\nsurface 40 5 n=1.5 10\nsurface -40 40 air 10\n").Centred());
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// A singlet decentred by 1 mm in y and tilted 5 degrees about x with Zemax coordinate breaks:
// a break before it, then back along its tilted axis to its front vertex, then the break
// undone (order 1: the tilt first, then the decentre), on to the film along the axis.
std::string BrokenZmx(const std::string& undo) {
  return "MODE SEQ\nUNIT MM X W X CM MR CPMM\n"
         "SURF 0\n  TYPE STANDARD\n  CURV 0.0\n  DISZ INFINITY\n"
         "SURF 1\n  STOP\n  TYPE STANDARD\n  CURV 0.0\n  DISZ 1\n  DIAM 20\n"
         "SURF 2\n  TYPE COORDBRK\n  PARM 2 1\n  PARM 3 5\n  DISZ 0\n"
         "SURF 3\n  TYPE STANDARD\n  CURV 0.02\n  GLAS ___BLANK 1 0 1.5 60\n  DISZ 4\n  DIAM 15\n"
         "SURF 4\n  TYPE STANDARD\n  CURV 0.0\n  DISZ 0\n  DIAM 15\n"
         "SURF 5\n  TYPE COORDBRK\n  DISZ -4\n"
         "SURF 6\n  TYPE COORDBRK\n" + undo + "  DISZ 101.33333333333333\n"
         "SURF 7\n  TYPE STANDARD\n  CURV 0.0\n  DISZ 0\n  DIAM 10\n";
}

TEST(Placement, ZemaxCoordinateBreaksBecomePlacements) {
  const LensPrescription z =
      ParseZemaxLens(BrokenZmx("  PARM 2 -1\n  PARM 3 -5\n  PARM 6 1\n"), "cb.zmx", GlassCatalog::Default());
  const double s = std::sin(5 * M_PI / 180), c = std::cos(5 * M_PI / 180);
  const LensPrescription native = Parse(fmt::format(
      "stop 1 air 20\nsurface 50 {} nd=1.5,vd=60 15 decenter=0,1 tilt=5\nsurface inf {} air 15 decenter=0,{} tilt=5\n", 4 * c,
      102.33333333333333 - (1 + 4 * c), 1 - 4 * s));
  ASSERT_EQ(z.surfaces.size(), native.surfaces.size());
  for (size_t i = 0; i < z.surfaces.size(); ++i) {
    EXPECT_NEAR(z.surfaces[i].thickness, native.surfaces[i].thickness, 1e-12) << i;
    ASSERT_EQ(bool(z.surfaces[i].placement), bool(native.surfaces[i].placement)) << i;
    if (!z.surfaces[i].placement) continue;
    const SurfacePlacement &a = *z.surfaces[i].placement, &b = *native.surfaces[i].placement;
    EXPECT_NEAR(Length(a.offset - b.offset), 0, 1e-12) << i;
    EXPECT_NEAR(Length(a.ez - b.ez), 0, 1e-15) << i;
    EXPECT_NEAR(Length(a.ey - b.ey), 0, 1e-15) << i;
  }
  // The same rays through both.
  const LensSystem lz(z), ln(native);
  for (double h : {-6.0, 0.0, 4.5}) {
    const TraceResult a = TraceFromObject(lz, {{0.3, h, -5}, Normalize(Vec3d(0.01, 0.02, 1))}, 550);
    const TraceResult b = TraceFromObject(ln, {{0.3, h, -5}, Normalize(Vec3d(0.01, 0.02, 1))}, 550);
    ASSERT_TRUE(a.ray && b.ray);
    EXPECT_NEAR(Length(a.ray->o - b.ray->o), 0, 1e-9);
  }
  // Breaks not undone leave the image plane off the axis: an error naming the last break.
  try {
    ParseZemaxLens(BrokenZmx("  PARM 3 -5\n  PARM 6 1\n"), "cb.zmx", GlassCatalog::Default());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cb.zmx:32: after the coordinate breaks the image surface lies tilted or decentred"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

std::string TiltScene(const std::string& tilt) {
  return R"(<scene version="3.0.0">
  <integrator type="path"/>
  <sensor type="realistic">
    <string name="lens" value="dgauss.50mm"/>
    <float name="fnumber" value="2.03"/>
    )" + tilt + R"(
    <float name="focus_distance" value="1.73"/>
    <film type="hdrfilm"><integer name="width" value="48"/><integer name="height" value="32"/></film>
  </sensor>
</scene>)";
}

TEST(Placement, SceneTiltTurnsTheWholeLensAndKeepsItsFNumber) {
  SKIP_UNDER_SANITIZERS("Placement.CameraTakesTheCrookedLensAndTheParaxialModelsRefuseIt");
  // tilt_x turns the lens about its entrance pupil: every surface placed, its axis turned by the
  // angle, the stop as wide as the straight lens's at the same f-number.
  const RenderSetup straight = LoadSceneFromString(TiltScene(""), "t.xml", {});
  const RenderSetup tilted = LoadSceneFromString(TiltScene(R"(<float name="tilt_x" value="-9.4"/>)"), "t.xml", {});
  const auto* a = dynamic_cast<const RealisticCamera*>(straight.camera.get());
  const auto* b = dynamic_cast<const RealisticCamera*>(tilted.camera.get());
  ASSERT_TRUE(a && b);
  EXPECT_TRUE(a->lens().prescription().Centred());
  for (const LensSurface& s : b->lens().prescription().surfaces) {
    ASSERT_TRUE(s.placement);
    EXPECT_NEAR(std::acos(s.placement->ez.z) * 180 / M_PI, 9.4, 1e-9);
    EXPECT_GT(s.placement->ez.y, 0);  // right-handed about x: -9.4 turns the axis toward +y at the film end: the front down
  }
  EXPECT_NEAR(b->lens().StopSemiDiameter(), a->lens().StopSemiDiameter(), 1e-12);
  // The paraxial models have no tilt: refused, not ignored.
  std::string thin = TiltScene(R"(<float name="tilt_x" value="-5"/><string name="lens_model" value="thin"/>)");
  EXPECT_THROW(LoadSceneFromString(thin, "t.xml", {}), InputError);
  try {
    LoadSceneFromString(TiltScene(R"(<float name="tilt_x" value="50"/>)"), "t.xml", {});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.xml:6:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace objektiv
