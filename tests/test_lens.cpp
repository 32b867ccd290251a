// Lens prescriptions and first-order optics.
#include <gtest/gtest.h>

#include "base/error.h"
#include "optics/glass_catalog.h"
#include "optics/paraxial.h"
#include "optics/pbrt_lens.h"

namespace objektiv {
namespace {

struct Published {
  const char* file;
  double efl, bfl;
};

TEST(Paraxial, ShippedLensesMatchTheirPublishedFocalLengths) {
  // data/lenses/README.md: paraxial EFL and BFL at the files' indices, to 3 decimals.
  const Published lenses[] = {{"dgauss.50mm", 50.358, 36.106},
                              {"wide.22mm", 22.023, 14.318},
                              {"fisheye.10mm", 9.991, 23.161},
                              {"telephoto.250mm", 249.567, 105.070},
                              {"tessar.brendel.100mm", 100.076, 79.895}};
  for (const Published& p : lenses) {
    LensPrescription lens = ReadPbrtLens(DataDirectory() + "/lenses/" + p.file + ".dat");
    ParaxialData d = ComputeParaxial(lens);
    EXPECT_NEAR(d.efl, p.efl, 1e-4 * p.efl) << p.file;
    EXPECT_NEAR(d.bfl, p.bfl, 1e-4 * p.efl) << p.file;
    EXPECT_GE(lens.StopIndex(), 0) << p.file;
  }
}

LensPrescription Singlet(double r1, double r2, double t, double n) {
  LensPrescription l;
  auto glass = std::make_shared<const Glass>(Glass::Constant(n));
  LensSurface stop;
  stop.is_stop = true;
  stop.semi_diameter = 5;
  stop.thickness = 1;
  LensSurface a, b;
  a.radius = r1;
  a.flat = r1 == 0;
  a.thickness = t;
  a.semi_diameter = 10;
  a.medium = glass;
  b.radius = r2;
  b.flat = r2 == 0;
  b.semi_diameter = 10;
  l.surfaces = {stop, a, b};
  return l;
}

TEST(Paraxial, ThickLensMatchesTheLensmakersEquation) {
  for (auto [r1, r2, t, n] : {std::tuple{50.0, -50.0, 5.0, 1.5}, {30.0, 200.0, 8.0, 1.7}, {-40.0, -15.0, 3.0, 1.6}}) {
    double phi = (n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2));
    double f = 1 / phi;
    double bfl = f * (1 - (n - 1) * t / (n * r1));
    double ffl = -f * (1 + (n - 1) * t / (n * r2));
    ParaxialData d = ComputeParaxial(Singlet(r1, r2, t, n));
    EXPECT_NEAR(d.efl, f, 1e-9 * std::abs(f));
    EXPECT_NEAR(d.bfl, bfl, 1e-9 * std::abs(f));
    // d.ffl is measured from the first row (the stop, 1 mm in front of the first refracting
    // surface); the closed form from that surface.
    EXPECT_NEAR(d.ffl - 1, ffl, 1e-9 * std::abs(f));
  }
}

TEST(Paraxial, PlaneParallelPlateHasNoPower) {
  ParaxialData d = ComputeParaxial(Singlet(0, 0, 10, 1.5));
  EXPECT_TRUE(std::isinf(d.efl));
}

TEST(PbrtLens, BadFilesNameTheLine) {
  struct Bad {
    std::string text;
    int line;
    std::string part;
  };
  std::vector<Bad> cases = {
      {"# header\n10 2 1.5 8\n0 1 0\n", 3, "needs 4 numbers"},
      {"10 2 1.5 8\n0 1 0 6\n0 1 0 6\n-10 5 1 8\n", 3, "second aperture stop"},
      {"10 2 1.5 8\n-10 5 1 8\n", 0, "no aperture stop"},
      {"10 2 1.5 30\n0 1 0 6\n-10 5 1 8\n", 1, "larger than the radius"},
      {"10 2 abc 8\n", 1, "not a finite number"},
      {"10 2 1.5 8\n0 1 0 6\n-10 5 1 -8\n", 3, "must be positive"},
      {"10 2 0.5 8\n0 1 0 6\n-10 5 1 8\n", 1, "below 1"},
  };
  for (const Bad& b : cases) {
    try {
      ParsePbrtLens(b.text, "bad.dat");
      ADD_FAILURE() << "no error for:\n" << b.text;
    } catch (const InputError& e) {
      std::string msg = e.what();
      std::string prefix = b.line > 0 ? "bad.dat:" + std::to_string(b.line) + ":" : "bad.dat:";
      EXPECT_EQ(msg.rfind(prefix, 0), 0u) << msg;
      EXPECT_NE(msg.find(b.part), std::string::npos) << msg;
    }
  }
}

}  // namespace
}  // namespace objektiv

#include "optics/lens_file.h"

namespace objektiv {
namespace {

TEST(NativeLens, TessarWithCatalogGlassesHasItsPatentFocalLength) {
  // data/lenses/README.md: with HIKARI LAK9, OHARA PBL7 and HIKARI SF7, EFL 100.00 mm and
  // BFL 79.82 mm at the d line.
  LensPrescription t = LoadLens("tessar.brendel.100mm", GlassCatalog::Default());
  ASSERT_EQ(t.surfaces.size(), 8u);
  EXPECT_EQ(t.StopIndex(), 3);
  ParaxialData d = ComputeParaxial(t, 587.5618);
  EXPECT_NEAR(d.efl, 100.00, 0.005);
  EXPECT_NEAR(d.bfl, 79.82, 0.005);
  EXPECT_EQ(t.design_focal_length, 100);
  // Dispersion: blue focuses closer than red (undercorrected axial colour of a simple design
  // would be larger; the Tessar is achromatised, so the difference is small but present).
  EXPECT_NE(ComputeParaxial(t, 486.1327).bfl, ComputeParaxial(t, 656.2725).bfl);
}

TEST(NativeLens, ShippedLensesAreFoundByName) {
  std::vector<std::string> names = ShippedLensNames();
  for (const char* n : {"dgauss.50mm", "wide.22mm", "fisheye.10mm", "telephoto.250mm", "tessar.brendel.100mm"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  EXPECT_THROW(LoadLens("no.such.lens", GlassCatalog::Default()), InputError);
}

TEST(NativeLens, BadFilesNameTheLine) {
  struct Bad {
    std::string text;
    int line;
    std::string part;
  };
  const std::string stop = "stop 2 air 5\n";
  std::vector<Bad> cases = {
      {"surface 50 5 N-NOPE 10\n" + stop + "surface -50 40 air 10\n", 1, "glass N-NOPE is in no catalog"},
      // Two surfaces that cross within their clear apertures (a sag deeper than the thickness).
      {stop + "surface 10 1 N-BK7 9\nsurface inf 20 air 9\n", 3, "crosses surface 2"},
      // A tilted element whose rim reaches back through the plane before it.
      {"surface inf 0.2 N-BK7 12\nsurface inf 5 air 12\n" + stop + "surface inf 0.2 N-BK7 12 tilt=6\nsurface inf 20 air 12\n",
       5, "crosses surface 4"},
      // Two menisci that interpenetrate around a small stop between them.
      {"surface 15 1.5 N-BK7 10\nsurface 20 0.5 air 10\nstop 0.5 air 2\nsurface -20 1.5 N-BK7 10\nsurface -15 40 air 10\n", 4,
       "crosses surface 1"},
      // Metadata given twice; a hexadecimal number.
      {"focal_length: 50\nfocal_length: 60\n" + stop + "surface 50 5 N-BK7 10\nsurface -50 40 air 10\n", 2,
       "focal_length is given twice (first on line 1)"},
      {stop + "surface 0x32 5 N-BK7 10\nsurface -50 40 air 10\n", 2, "'0x32' is not a finite number"},
      {"surface 50 5 N-BK7 10\nsurface -50 40 air 10\n", 0, "no stop"},
      {stop + stop + "surface 50 5 N-BK7 10\nsurface -50 40 air 10\n", 2, "second stop"},
      {stop + "surface 8 5 N-BK7 10\nsurface -50 40 air 10\n", 2, "larger than the surface can reach"},
      {stop + "surface 50 5 N-BK7 10 k=abc\nsurface -50 40 air 10\n", 2, "not a finite number"},
      {stop + "surface 50 5 N-BK7 10 a5=1\nsurface -50 40 air 10\n", 2, "a4, a6"},
      {stop + "surface 50 5 N-BK7 10 a99999999999999999999=1\nsurface -50 40 air 10\n", 2, "a4, a6"},
      {stop + "surface 50 5 N-BK7 10\nsurface -50 40 N-BK7 10\n", 3, "into air"},
      {"focal: 50\n" + stop, 1, "unknown key"},
      {stop + "lens 50 5 air 10\n", 2, "unknown line"},
      {stop + "surface 0 5 N-BK7 10\n", 2, "write inf"},
      {stop + "surface 50 5 nd=1.5 10\nsurface -50 40 air 10\n", 2, "nd=N,vd=V"},
  };
  for (const Bad& b : cases) {
    try {
      ParseNativeLens(b.text, "bad.lens", GlassCatalog::Default());
      ADD_FAILURE() << "no error for:\n" << b.text;
    } catch (const InputError& e) {
      std::string msg = e.what();
      std::string prefix = b.line > 0 ? "bad.lens:" + std::to_string(b.line) + ":" : "bad.lens:";
      EXPECT_EQ(msg.rfind(prefix, 0), 0u) << msg;
      EXPECT_NE(msg.find(b.part), std::string::npos) << msg;
    }
  }
}

// Found by fuzzing: "c=0.0" or a subnormal curvature gave a surface of infinite radius that
// was not flat.
TEST(NativeLens, AnyZeroCurvatureIsAPlane) {
  for (const char* c : {"c=0", "c=0.0", "c=-0", "c=.0e3", "c=4.9406564584124654e-324"}) {
    LensPrescription l = ParseNativeLens(fmt::format("stop 1 air 4\nsurface {} 5 n=1.5 10\nsurface -50 40 air 10\n", c), "c.lens", GlassCatalog::Default());
    EXPECT_TRUE(l.surfaces[1].flat) << c;
    EXPECT_EQ(l.surfaces[1].radius, 0) << c;
  }
}

TEST(NativeLens, ConicsAspheresCurvaturesAndModelGlasses) {
  LensPrescription l = ParseNativeLens(
      "stop 1 air 4\nsurface c=0.02 5 nd=1.5168,vd=64.17 10 k=-1 a4=1e-6 a6=-2e-9 coating=MgF2\n"
      "surface inf 40 air 10\n",
      "ok.lens", GlassCatalog::Default());
  ASSERT_EQ(l.surfaces.size(), 3u);
  EXPECT_NEAR(l.surfaces[1].radius, 50, 1e-12);
  EXPECT_EQ(l.surfaces[1].conic, -1);
  EXPECT_EQ(l.surfaces[1].aspheric[0], 1e-6);
  EXPECT_EQ(l.surfaces[1].aspheric[1], -2e-9);
  ASSERT_TRUE(l.surfaces[1].coating);
  EXPECT_EQ(l.surfaces[1].coating->name(), "MgF2");
  EXPECT_TRUE(l.surfaces[2].flat);
  EXPECT_NEAR(l.surfaces[1].medium->ComputedNd(), 1.5168, 1e-12);
  // Plano-convex with the flat side toward the film: EFL = R / (n - 1).
  EXPECT_NEAR(ComputeParaxial(l, 587.5618).efl, 50 / 0.5168, 1e-9);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

struct PupilData {
  const char* file;
  double epd, ep_position, fnumber;
};

TEST(Paraxial, PupilsMatchThePublishedValues) {
  // data/lenses/README.md: EPD, entrance pupil behind the first vertex, f-number = EFL / EPD.
  const PupilData lenses[] = {{"dgauss.50mm", 24.805, 19.95, 2.03},
                              {"wide.22mm", 8.206, 12.09, 2.68},
                              {"fisheye.10mm", 2.532, 11.54, 3.95},
                              {"telephoto.250mm", 46.016, 15.29, 5.42},
                              {"tessar.brendel.100mm", 36.651, 13.84, 2.73}};
  for (const PupilData& p : lenses) {
    ParaxialData d = ComputeParaxial(ReadPbrtLens(DataDirectory() + "/lenses/" + p.file + ".dat"));
    EXPECT_NEAR(d.entrance_pupil_diameter, p.epd, 0.0015) << p.file;
    EXPECT_NEAR(d.entrance_pupil_position, p.ep_position, 0.006) << p.file;
    EXPECT_NEAR(d.fnumber, p.fnumber, 0.006) << p.file;
  }
}

TEST(Paraxial, PupilsOfAThinLensWithAStopBehind) {
  // Stop d behind a thin lens: the entrance pupil is the stop seen through the lens, virtual
  // at d f / (f - d) behind it, magnified f / (f - d).
  const double f = 100, dist = 30, semi = 5;
  LensPrescription l;
  auto glass = std::make_shared<const Glass>(Glass::Constant(1.5));
  LensSurface a, b, stop;
  a.radius = 100;
  a.medium = glass;
  a.semi_diameter = 20;
  b.radius = -100;
  b.thickness = dist;
  b.semi_diameter = 20;
  stop.is_stop = true;
  stop.semi_diameter = semi;
  stop.thickness = 50;
  l.surfaces = {a, b, stop};
  ParaxialData d = ComputeParaxial(l);
  EXPECT_NEAR(d.efl, f, 1e-9);
  EXPECT_NEAR(d.entrance_pupil_position, dist * f / (f - dist), 1e-9);
  EXPECT_NEAR(d.entrance_pupil_diameter, 2 * semi * f / (f - dist), 1e-9);
  EXPECT_NEAR(d.exit_pupil_position, 0, 1e-12);
}

TEST(Paraxial, PupilsOfAThinLensWithAStopInFront) {
  // A thin lens with the stop d in front: the exit pupil is the stop's image; for d < f it is
  // virtual, at s' = d f / (d - f) from the lens (negative: in front), magnified f / (f - d).
  const double R = 100, n = 1.5, f = 100, dist = 30, semi = 5;
  LensPrescription l = Singlet(R, -R, 0, n);  // thin: zero thickness
  l.surfaces[0].thickness = dist;
  l.surfaces[0].semi_diameter = semi;
  ParaxialData d = ComputeParaxial(l);
  EXPECT_NEAR(d.efl, f, 1e-9);
  EXPECT_NEAR(d.entrance_pupil_position, 0, 1e-12);
  EXPECT_NEAR(d.entrance_pupil_diameter, 2 * semi, 1e-12);
  EXPECT_NEAR(d.exit_pupil_position, dist * f / (dist - f), 1e-9);
  EXPECT_NEAR(d.exit_pupil_diameter, 2 * semi * f / (f - dist), 1e-9);
  EXPECT_NEAR(d.fnumber, f / (2 * semi), 1e-12);
  // Principal planes of a thin lens: both at the lens.
  EXPECT_NEAR(d.back_principal_plane, 0, 1e-9);
  EXPECT_NEAR(d.front_principal_plane, dist, 1e-9);
}

}  // namespace
}  // namespace objektiv

#include "optics/focusing.h"
#include "optics/lens_tracer.h"

namespace objektiv {
namespace {

TEST(Focusing, UnitFocusObeysNewtonsEquation) {
  // x x' = f^2 with x the object's distance from the front focal point and x' the image's
  // from the back focal point: true for any thick lens in air.
  for (const char* name : {"dgauss.50mm", "tessar.brendel.100mm", "telephoto.250mm"}) {
    LensPrescription lens = LoadLens(name, GlassCatalog::Default());
    ParaxialData p = ComputeParaxial(lens);
    for (double distance_m : {0.8, 2.0, 10.0}) {
      double D = distance_m * 1000 * (p.efl / 50);  // keep closer than minimum focus away
      std::optional<FocusSolution> f = FocusAtDistance(lens, D);
      ASSERT_TRUE(f) << name << " at " << D;
      EXPECT_NEAR(f->object_to_first_vertex + lens.TotalTrack() + f->back_focus, D, 1e-6 * D);
      double x = f->object_to_first_vertex + p.ffl, xp = f->back_focus - p.bfl;
      EXPECT_NEAR(x * xp, p.efl * p.efl, 1e-7 * p.efl * p.efl) << name;
      EXPECT_NEAR(f->magnification, -p.efl / x, 1e-7) << name;
      // Real rays near the axis from the object meet on the film.
      LensSystem t(lens);
      t.SetBackFocus(f->back_focus);
      double h = 1e-4;
      Vec3d from(0, 0, -f->object_to_first_vertex);
      TraceResult r = TraceFromObject(t, {from, Normalize(Vec3d(h, 0, f->object_to_first_vertex))}, 587.5618);
      ASSERT_TRUE(r.ray);
      Vec3d hit = r.ray->o + r.ray->d * ((t.FilmZ() - r.ray->o.z) / r.ray->d.z);
      EXPECT_NEAR(hit.x, 0, 1e-6) << name;
    }
    // Too close: inside the front focal point there is no real image.
    EXPECT_FALSE(FocusAtDistance(lens, lens.TotalTrack() + p.bfl + 0.5 * p.efl));
    // At infinity the working f-number tends to EFL / EPD; closer it grows as (1 + |m|) N.
    FocusSolution far = ImageObject(lens, 1e9);
    EXPECT_NEAR(far.working_fnumber, p.fnumber, 1e-5 * p.fnumber) << name;
  }
}

TEST(Focusing, ScalingKeepsTheFNumberAndHitsTheFocalLength) {
  LensPrescription lens = LoadLens("tessar.brendel.100mm", GlassCatalog::Default());
  LensPrescription s = ScaledToFocalLength(lens, 35);
  ParaxialData a = ComputeParaxial(lens), b = ComputeParaxial(s);
  EXPECT_NEAR(b.efl, 35, 1e-9);
  EXPECT_NEAR(b.fnumber, a.fnumber, 1e-9);
  EXPECT_NEAR(b.bfl, a.bfl * 35 / a.efl, 1e-9);
  // Aspheric terms scale so that the sag scales with the lens.
  LensPrescription asph = ParseNativeLens("stop 1 air 4\nsurface 50 5 N-BK7 10 k=-0.5 a4=1e-5 a6=-1e-8\n"
                                          "surface inf 40 air 10\n", "a.lens", GlassCatalog::Default());
  EXPECT_NEAR(asph.Scaled(3).surfaces[1].Sag(3 * 7.0), 3 * asph.surfaces[1].Sag(7.0), 1e-12);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(Paraxial, SingleRefractingSphere) {
  // Air into glass through one sphere of radius R: the rear focus lies n' R / (n' - 1) behind
  // the vertex, the focal length (EFL = f' / n') is R / (n' - 1).
  const double R = 20, n = 1.6;
  LensPrescription l;
  LensSurface stop, s;
  stop.is_stop = true;
  stop.semi_diameter = 2;
  s.radius = R;
  s.semi_diameter = 10;
  s.thickness = n * R / (n - 1);
  s.medium = std::make_shared<const Glass>(Glass::Constant(n));
  l.surfaces = {stop, s};
  ParaxialData d = ComputeParaxial(l);
  EXPECT_NEAR(d.efl, R / (n - 1), 1e-12);
  EXPECT_NEAR(d.bfl, n * R / (n - 1), 1e-12);
  // Real rays near the axis meet there too.
  LensSystem t(l);
  TraceResult r = TraceFromObject(t, {{1e-4, 0, -5}, {0, 0, 1}}, 550);
  ASSERT_TRUE(r.ray);
  double z = r.ray->o.z - r.ray->o.x * r.ray->d.z / r.ray->d.x;
  EXPECT_NEAR(z, n * R / (n - 1), 1e-6);
}
}  // namespace
}  // namespace objektiv
