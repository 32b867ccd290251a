// Anti-reflection coatings: the thin-film stack against closed forms, the coating formats, and
// the coated lens in both tracers and in the camera.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "base/error.h"
#include "base/fresnel_dielectric.h"
#include "base/rng.h"
#include "camera/lens_camera_setup.h"
#include "log_capture.h"
#include "optics/batch_tracer.h"
#include "optics/coating_library.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"
#include "optics/lens_tracer.h"
#include "optics/thin_film.h"
#include "optics/zemax_lens.h"

namespace objektiv {
namespace {

const GlassCatalog& Glasses() { return GlassCatalog::Default(); }
std::shared_ptr<const Glass> Catalog(const char* name) {
  return std::shared_ptr<const Glass>(std::shared_ptr<const Glass>(), Glasses().Find(name));
}
std::shared_ptr<const Coating> BuiltIn(const char* name) { return *FindBuiltInCoating(name); }

// The mean reflectance over 420..680 nm on the axis.
double VisibleMean(const CoatedInterface& c) {
  double sum = 0;
  int n = 0;
  for (double l = 420; l <= 680; l += 5, ++n) sum += c.Reflectance(l, 1, true);
  return sum / n;
}

TEST(ThinFilm, NoLayersIsFresnel) {
  for (double n2 : {1.5, 1.9})
    for (double cos_i : {1.0, 0.8, 0.5, 0.2, 0.01}) {
      EXPECT_NEAR(ThinFilmStack(1, {}, n2, 550, cos_i).Reflectance(), FresnelDielectric(cos_i, n2), 1e-12);
      EXPECT_NEAR(ThinFilmStack(n2, {}, 1, 550, cos_i).Reflectance(), FresnelDielectric(cos_i, 1 / n2), 1e-12);
    }
}

TEST(ThinFilm, LosslessStacksConserveEnergy) {
  // R and T come from different expressions (the amplitude reflectance, and the substrate's
  // admittance over the denominator): their sum is 1 only if the matrices are right. Random
  // stacks, at every angle, from both sides, with layers beyond their critical angle too.
  PCG32 rng(3, 11);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<ThinFilmLayer> layers(1 + trial % 7);
    for (ThinFilmLayer& l : layers) l = {1.3 + 1.1 * rng.UniformFloat(), 20 + 400 * rng.UniformFloat()};
    const double n0 = trial % 2 ? 1.0 : 1.45 + 0.4 * rng.UniformFloat(), ns = trial % 2 ? 1.5 + 0.4 * rng.UniformFloat() : 1.0;
    const double cos_i = 0.02 + 0.98 * rng.UniformFloat(), lambda = 380 + 400 * rng.UniformFloat();
    ThinFilmResponse r = ThinFilmStack(n0, layers, ns, lambda, cos_i);
    const double sin_s = n0 * std::sqrt(1 - cos_i * cos_i) / ns;
    if (sin_s >= 1) {  // total internal reflection at the substrate
      EXPECT_NEAR(r.Reflectance(), 1, 1e-9);
      EXPECT_EQ(r.Transmittance(), 0);
      continue;
    }
    ++checked;
    EXPECT_NEAR(r.rs + r.ts, 1, 1e-9) << trial;
    EXPECT_NEAR(r.rp + r.tp, 1, 1e-9) << trial;
    EXPECT_GT(r.ts, 0);
  }
  EXPECT_GT(checked, 200);
}

TEST(ThinFilm, ThickEvanescentLayerReflectsEverythingAndStaysFinite) {
  // From glass (1.8) at 60 degrees into a layer of index 1 (beyond its critical angle) 100 um
  // thick and on into glass again: cosh of the layer's phase would overflow to inf / inf.
  const ThinFilmLayer gap{1.0, 1e5};
  ThinFilmResponse r = ThinFilmStack(1.8, {&gap, 1}, 1.8, 400, 0.5);
  EXPECT_NEAR(r.Reflectance(), 1, 1e-12);
  EXPECT_NEAR(r.Transmittance(), 0, 1e-12);
  // A thin gap lets some through (frustrated total internal reflection), R + T = 1.
  const ThinFilmLayer thin{1.0, 50};
  ThinFilmResponse f = ThinFilmStack(1.8, {&thin, 1}, 1.8, 400, 0.5);
  EXPECT_GT(f.Transmittance(), 0.05);
  EXPECT_NEAR(f.Reflectance() + f.Transmittance(), 1, 1e-12);
}

TEST(ThinFilm, QuarterWaveMgF2OnNBK7HasTheClosedFormReflectance) {
  // At the design wavelength, on the axis, a quarter-wave layer of index n1 turns the
  // substrate's admittance ns into n1^2 / ns: R = ((n0 ns - n1^2) / (n0 ns + n1^2))^2.
  auto interface = CoatedInterface(BuiltIn("MgF2@550"), nullptr, Catalog("N-BK7"));
  const double n1 = FindCoatingMaterial("MgF2")->Index(550), ns = Glasses().Find("N-BK7")->Index(550);
  const double closed = std::pow((ns - n1 * n1) / (ns + n1 * n1), 2);
  EXPECT_NEAR(interface.Reflectance(550, 1, true), closed, 1e-12);
  EXPECT_NEAR(closed, 0.0126, 2e-4);  // the textbook 1.3% of MgF2 on crown glass
  // Away from the design wavelength it reflects more (a minimum at 550 nm).
  EXPECT_GT(interface.Reflectance(450, 1, true), closed);
  EXPECT_GT(interface.Reflectance(650, 1, true), closed);
  // And bare N-BK7 reflects 4.2%.
  EXPECT_NEAR(FresnelDielectric(1.0, ns), 0.0426, 5e-4);
}

TEST(ThinFilm, HalfWaveLayerIsAbsentAtItsDesignWavelength) {
  const double n = 2.05, ns = 1.52;
  const ThinFilmLayer half{n, 0.5 * 600 / n};
  EXPECT_NEAR(ThinFilmStack(1, {&half, 1}, ns, 600, 1).Reflectance(), FresnelDielectric(1.0, ns), 1e-12);
  EXPECT_GT(ThinFilmStack(1, {&half, 1}, ns, 450, 1).Reflectance(), FresnelDielectric(1.0, ns) + 0.05);
}

TEST(Coating, ReflectsTheSameFromBothSides) {
  // A lossless stack: light from the glass at the angle Snell's law pairs with the outer
  // side's reflects as much (T is reciprocal, and R = 1 - T).
  for (const char* name : {"MgF2", "multi", "multi@480"}) {
    CoatedInterface c(BuiltIn(name), nullptr, Catalog("N-SF6"));
    for (double lambda : {420.0, 550.0, 690.0})
      for (double cos_air : {1.0, 0.9, 0.6, 0.3}) {
        const double n = Glasses().Find("N-SF6")->Index(lambda);
        const double cos_glass = std::sqrt(1 - (1 - cos_air * cos_air) / (n * n));
        EXPECT_NEAR(c.Reflectance(lambda, cos_air, true), c.Reflectance(lambda, cos_glass, false), 1e-12) << name;
      }
  }
}

TEST(Coating, MatchedDesignsReflectNothingOnTheAxisAtTheDesignWavelength) {
  for (const char* glass : {"N-BK7", "N-SF6", "N-LASF9"}) {
    CoatedInterface multi(BuiltIn("multi@520"), nullptr, Catalog(glass));
    EXPECT_LT(multi.Reflectance(520, 1, true), 1e-12) << glass;
    EXPECT_LT(multi.Reflectance(520, 1, false), 1e-12) << glass;
  }
  auto single = ParseCoatingDefinition("ideal1", std::vector<std::string>{"design=600", "matched:0.25"}, Glasses(), "t.lens", 1);
  EXPECT_LT(CoatedInterface(single, nullptr, Catalog("N-BK7")).Reflectance(600, 1, true), 1e-12);
}

TEST(Coating, MultiReflectsLessThanMgF2LessThanBareOverTheVisible) {
  for (const char* glass : {"N-BK7", "N-SF6", "N-LASF9"}) {
    const double mgf2 = VisibleMean(CoatedInterface(BuiltIn("MgF2"), nullptr, Catalog(glass))),
                 multi = VisibleMean(CoatedInterface(BuiltIn("multi"), nullptr, Catalog(glass)));
    const double fresnel = FresnelDielectric(1.0, Glasses().Find(glass)->Index(550));
    EXPECT_LT(mgf2, 0.5 * fresnel) << glass;
    EXPECT_LT(multi, mgf2) << glass;
    EXPECT_LT(multi, 0.005) << glass;
  }
}

TEST(Coating, IdealCoatingHasItsTransmittanceAtEveryWavelengthAndAngle) {
  CoatedInterface c(BuiltIn("I.95"), nullptr, Catalog("N-BK7"));
  for (double l : {400.0, 700.0})
    for (double cos_i : {1.0, 0.3}) EXPECT_NEAR(c.Reflectance(l, cos_i, true), 0.05, 1e-15);
  EXPECT_EQ(c.Reflectance(550, 0.3, false), 1);  // beyond the critical angle from the glass
  EXPECT_THROW(FindBuiltInCoating("I.0"), InputError);     // said so, not "unknown"
  EXPECT_THROW(FindBuiltInCoating("MgF2@9"), InputError);
  EXPECT_THROW(FindBuiltInCoating("multi@x"), InputError);
  EXPECT_FALSE(FindBuiltInCoating("MgF2x"));
  EXPECT_TRUE(FindBuiltInCoating("mgf2"));        // names compare without case
  EXPECT_FALSE(*FindBuiltInCoating("uncoated"));  // bare: no coating object
}

// A doublet in air: coatings from the file's definitions, its default, and its own overrides.
constexpr const char* kCoatedLens =
    "name: coated doublet\n"
    "coating V2 design=510 MgF2:0.25 matched:0.25\n"
    "coating thick SiO2:120nm N-BK7:0.5 n=2.1:0.25\n"
    "default_coating: V2\n"
    "surface 60 6 N-BK7 12\n"
    "surface -40 2 N-SF6 12\n"
    "surface -150 3 air 12 coating=none\n"
    "stop 40 air 8\n"
    "surface inf 2 N-BK7 10 coating=thick\n"
    "surface inf 20 air 10 coating=I.99\n";

TEST(CoatedLens, FileDefinesDefaultsAndOverrides) {
  test::LogCapture log;
  LensPrescription lens = ParseNativeLens(kCoatedLens, "c.lens", Glasses());
  ASSERT_EQ(lens.surfaces.size(), 6u);
  ASSERT_TRUE(lens.surfaces[0].coating);
  EXPECT_EQ(lens.surfaces[0].coating->name(), "V2");  // the default on an air-glass surface
  EXPECT_FALSE(lens.surfaces[1].coating);              // cemented: the default does not apply
  EXPECT_FALSE(lens.surfaces[2].coating);              // its own coating=none
  EXPECT_FALSE(lens.surfaces[3].coating);              // the stop, in air
  EXPECT_EQ(lens.surfaces[4].coating->name(), "thick");
  EXPECT_EQ(lens.surfaces[5].coating->name(), "I.99");
  EXPECT_EQ(lens.surfaces[4].coating->layers().size(), 3u);
  EXPECT_EQ(lens.surfaces[4].coating->layers()[0].thickness_nm, 120);
  EXPECT_EQ(log.Text(), "");
  // The coatings reach the lens as set up: surface 5 (glass to air) reflects 1%, surface 1
  // its V coat's nothing at 510 nm on the axis, surface 3 bare Fresnel.
  LensSystem system(lens);
  EXPECT_NEAR(system.SurfaceReflectance(5, 600, 1, true), 0.01, 1e-15);
  EXPECT_LT(system.SurfaceReflectance(0, 510, 1, true), 1e-12);
  const double n = Glasses().Find("N-SF6")->Index(600);
  EXPECT_NEAR(system.SurfaceReflectance(2, 600, 1, true), std::pow((n - 1) / (n + 1), 2), 1e-12);
  EXPECT_EQ(system.SurfaceReflectance(3, 600, 1, true), 0);  // air on both sides
}

TEST(CoatedLens, CoatingsThatDoNothingAreWarnedWithTheirLines) {
  test::LogCapture log;
  LensPrescription lens = ParseNativeLens(
      "coating spare MgF2:0.25\ndefault_coating: multi\nsurface inf 1 air 6 coating=MgF2\nstop 1 air 4\n"
      "surface 50 3 N-BK7 6 coating=I.98\nsurface inf 40 air 6 coating=none\n",
      "u.lens", Glasses());
  EXPECT_TRUE(log.Has("u.lens:1: coating 'spare' is defined but no surface uses it")) << log.Text();
  EXPECT_TRUE(log.Has("u.lens:3: coating 'MgF2' does nothing here: the medium is the same on both sides")) << log.Text();
  EXPECT_TRUE(log.Has("u.lens:2: default_coating 'multi' coats no surface")) << log.Text();
  // A coating the file defines is there to be chosen, used or not, whatever its case.
  ASSERT_EQ(lens.defined_coatings.size(), 1u);
  EXPECT_EQ(CoatingForLens("SPARE", lens)->name(), "spare");
}

TEST(CoatedLens, BadCoatingsNameTheFileAndLine) {
  const std::string body = "stop 1 air 4\nsurface 50 3 N-BK7 6\nsurface inf 40 air 6\n";
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"coating X MgF2\n", "u.lens:1: a layer is MATERIAL:THICKNESS"},
      {"coating X Unobtainium:0.25\n", "u.lens:1: unknown layer material 'Unobtainium'"},
      {"coating X MgF2:-1\n", "u.lens:1: layer thickness '-1' must be positive"},
      {"coating X MgF2:0.25nm2\n", "u.lens:1:"},
      {"coating X design=5 MgF2:0.25\n", "u.lens:1: design wavelength 5 nm"},
      {"coating X matched:0.25 MgF2:0.25\n", "u.lens:1: coating 'X': a matched layer"},
      {"coating X\n", "u.lens:1: a coating line is"},
      {"coating multi MgF2:0.25\n", "u.lens:1: coating 'multi' is built in"},
      {"coating X MgF2:0.25\ncoating X SiO2:0.25\n", "u.lens:2: coating 'X' is defined twice (first on line 1"},
      {"coating Foo MgF2:0.25\ncoating foo SiO2:0.25\n", "u.lens:2: coating 'foo' is defined twice (first on line 1"},
      {"coating X design=500 design=600 MgF2:0.25\n", "u.lens:1: design= is given twice"},
      {"default_coating: MgF2\ndefault_coating: multi\n", "u.lens:2: default_coating is given twice (first on line 1)"},
      {"default_coating: Y\n", "u.lens:1: unknown coating 'Y'"},
      {"default_coating: MgF2@100\n", "u.lens:1: coating 'MgF2@100': the design wavelength after @ is a number of nm from 200 to 2000"},
  };
  for (const Case& c : cases) {
    try {
      ParseNativeLens(c.text + body, "u.lens", Glasses());
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
  try {
    ParseNativeLens("stop 1 air 4\nsurface 50 3 N-BK7 6 coating=MgF2 coating=multi\nsurface inf 40 air 6\n", "u.lens", Glasses());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("u.lens:2: option 'coating' is given twice"), std::string::npos) << e.what();
  }
  try {
    ParseNativeLens("stop 1 air 4\nsurface 50 3 N-BK7 6 coating=Y\nsurface inf 40 air 6\n", "u.lens", Glasses());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("u.lens:2: unknown coating 'Y' (built in: none, MgF2[@NM], multi[@NM], I.xx"),
              std::string::npos)
        << e.what();
  }
}

TEST(CoatedLens, ZemaxCoatIsReadOrWarnedAbout) {
  test::LogCapture log;
  LensPrescription z = ParseZemaxLens(
      "UNIT MM\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.02\n DISZ 3\n GLAS N-BK7\n"
      " COAT MGF2\n DIAM 6\nSURF 3\n DISZ 40\n COAT HEAR1\n DIAM 6\nSURF 4\n DIAM 10\n",
      "c.zmx", Glasses());
  ASSERT_EQ(z.surfaces.size(), 3u);
  ASSERT_TRUE(z.surfaces[1].coating);
  EXPECT_EQ(z.surfaces[1].coating->layers().size(), 1u);
  EXPECT_FALSE(z.surfaces[2].coating);
  EXPECT_TRUE(log.Has("c.zmx:16: coating HEAR1 is unknown")) << log.Text();
}

TEST(CoatedLens, BatchTracerFollowsTheExactTracer) {
  for (const char* coating : {"MgF2", "multi", "I.97"}) {
    LensPrescription lens = LoadLens("dgauss.50mm", Glasses());
    CoatAirGlassSurfaces(lens, BuiltIn(coating), false);
    LensSystem exact = AtParaxialInfinityFocus(lens);
    BatchLensTracer fast(exact);
    PCG32 rng(5, 3);
    const int n = 3000;
    RayBatch b;
    b.Resize(n);
    std::vector<LensRay> in(n);
    for (int i = 0; i < n; ++i) {
      Vec3d film((rng.UniformFloat() - 0.5) * 30, (rng.UniformFloat() - 0.5) * 20, exact.FilmZ());
      double a = 2 * M_PI * rng.UniformFloat(), r = 12 * std::sqrt(rng.UniformFloat());
      Vec3d target(r * std::cos(a), r * std::sin(a), exact.VertexZ(exact.SurfaceCount() - 1));
      in[i] = {film, Normalize(target - film)};
      b.ox[i] = float(film.x), b.oy[i] = float(film.y), b.oz[i] = float(film.z);
      b.dx[i] = float(in[i].d.x), b.dy[i] = float(in[i].d.y), b.dz[i] = float(in[i].d.z);
      b.lambda[i] = 380 + 400 * rng.UniformFloat();
    }
    fast.TraceFromFilm(b);
    int both = 0;
    double worst = 0, bare_difference = 0;
    for (int i = 0; i < n; ++i) {
      TraceResult e = TraceFromFilm(exact, in[i], b.lambda[i]);
      if (!e.ray || !b.alive[i]) continue;
      ++both;
      worst = std::max(worst, std::abs(e.surface_transmittance * e.internal_transmittance - b.transmittance[i]));
      TraceResult bare = TraceFromFilm(AtParaxialInfinityFocus(LoadLens("dgauss.50mm", Glasses())), in[i], b.lambda[i]);
      if (bare.ray) bare_difference = std::max(bare_difference, e.surface_transmittance - bare.surface_transmittance);
    }
    EXPECT_GT(both, n / 4) << coating;
    // The tables' 3e-5 per surface (optics/batch_tracer.cpp) over 9 coated surfaces.
    EXPECT_LT(worst, 9 * 3e-5) << coating;
    EXPECT_GT(bare_difference, 0.1) << coating;  // the coating changes the transmittance a lot
  }
}

TEST(CoatedLens, CoatedCameraIsBrighterByTheAxialTransmittance) {
  // The realistic camera's image on the axis at f/8 (a narrow cone) scales with the lens's
  // transmittance along the axis: about 0.59 bare, 0.87 with MgF2 and 0.91 multi-coated.
  auto axial = [](const LensPrescription& lens) {
    TraceResult r = TraceFromObject(AtParaxialInfinityFocus(lens), {{0, 0, -10}, {0, 0, 1}}, 550);
    return r.surface_transmittance * r.internal_transmittance;
  };
  auto irradiance = [](const LensPrescription& lens) {
    LensCameraSpec s;
    s.lens = lens;
    s.fnumber = 8;
    auto camera = MakeLensCamera(Transform(), 101, 101, s);
    PCG32 rng(9, 1);
    double sum = 0;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
      SampledWavelengths l = SampledWavelengths::Single(550);
      auto r = camera->GenerateRay({Vec2f(50.5f, 50.5f), Vec2f(rng.UniformFloat(), rng.UniformFloat())}, l);
      sum += r ? r->weight[0] : 0;
    }
    return sum / n;
  };
  const LensPrescription bare = LoadLens("dgauss.50mm", Glasses());
  const double bare_t = axial(bare), bare_e = irradiance(bare);
  EXPECT_NEAR(bare_t, 0.59, 0.02);
  for (const char* coating : {"MgF2", "multi"}) {
    LensPrescription coated = bare;
    CoatAirGlassSurfaces(coated, BuiltIn(coating), false);
    const double ratio_t = axial(coated) / bare_t, ratio_e = irradiance(coated) / bare_e;
    EXPECT_GT(ratio_t, 1.4) << coating;
    EXPECT_NEAR(ratio_e, ratio_t, 0.01 * ratio_t) << coating;
  }
}

// A coating designed where a glass's formula has no index (N-SF6 at 240 nm: its Sellmeier
// formula covers 370-2500 nm) gave NaN reflectances (found by fuzz_lens_native): an error
// naming the coating's line, in every format and for a coating chosen by a scene.
TEST(CoatedLens, ACoatingDesignedWhereTheGlassHasNoIndexIsAnError) {
  auto error_of = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string lens = "surface 60 6 N-BK7 12\nsurface -40 2 N-SF6 12 coating=multi@240\nsurface -150 3 air 12\n"
                           "stop 40 air 9\n";
  EXPECT_NE(error_of([&] { ParseNativeLens(lens, "c.lens", Glasses()); })
                .find("c.lens:2: surface 2: coating multi@240: the glass N-SF6 has no index at its design wavelength "
                      "240 nm (its formula covers 370 to 2500 nm)"),
            std::string::npos);
  const std::string sf6 = "surface 60 6 N-SF6 12\nsurface -150 3 air 12\nstop 40 air 9\n";
  EXPECT_NE(error_of([&] { ParseNativeLens("default_coating: MgF2@240\n" + sf6, "d.lens", Glasses()); })
                .find("d.lens:1: surface 1: coating MgF2@240: the glass N-SF6"),
            std::string::npos);
  const std::string zmx = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS N-SF6\n"
                          " COAT MGF2@240\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n";
  EXPECT_NE(error_of([&] { ParseZemaxLens(zmx, "z.zmx", Glasses()); }).find("z.zmx:10: coating MGF2@240: the glass N-SF6"),
            std::string::npos) << error_of([&] { ParseZemaxLens(zmx, "z.zmx", Glasses()); });
  LensPrescription bare = ParseNativeLens(sf6, "b.lens", Glasses());
  EXPECT_NE(error_of([&] { Recoat(bare, CoatingForLens("multi@240", bare)); })
                .find("lens surface 1: coating multi@240: the glass N-SF6 has no index at its design"),
            std::string::npos);
  // Where every medium has an index there, the coating is taken.
  LensPrescription dgauss = LoadLens("dgauss.50mm", Glasses());
  EXPECT_NO_THROW(Recoat(dgauss, CoatingForLens("multi@240", dgauss)));
}

TEST(CoatedLens, ConstantIndexGlassKeepsTheCoatingsColour) {
  // Glass without dispersion sends every wavelength of a sample along one path, but a coating
  // transmits each differently: the camera traces the ray at each of the sample's wavelengths
  // for its transmittance, so every wavelength goes on with its own weight. (Carrying the others
  // at the hero's transmittance made every coated .dat lens grey and too dark; keeping the hero
  // alone left colour noise.)
  LensCameraSpec s;
  s.lens = ParseNativeLens("surface 50 3 n=1.9 10\nstop 1 air 8\nsurface inf 45 air 10\n", "c.lens", Glasses());
  s.fnumber = 8;
  for (const char* coating : {"none", "MgF2@700"}) {
    Recoat(s.lens, CoatingForLens(coating, s.lens));
    auto camera = MakeLensCamera(Transform(), 11, 11, s);
    const CameraSample sample{Vec2f(5.5f, 5.5f), Vec2f(0.4f, 0.6f)};
    SampledWavelengths l = SampledWavelengths::SampleVisible(0.3f);
    auto r = camera->GenerateRay(sample, l);
    ASSERT_TRUE(r);
    EXPECT_FALSE(l.SecondaryTerminated()) << coating;
    double spread = 0;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      // The same sample at that wavelength alone: the same ray, the same weight.
      SampledWavelengths one = SampledWavelengths::Single(l[k]);
      auto rk = camera->GenerateRay(sample, one);
      ASSERT_TRUE(rk);
      EXPECT_NEAR(r->weight[k], rk->weight[0], 1e-5 * rk->weight[0]) << coating << " " << l[k];
      spread = std::max(spread, std::abs(double(r->weight[k]) / r->weight[0] - 1));
    }
    if (std::string(coating) == "none") EXPECT_LT(spread, 1e-3);  // bare n=1.9: the same at every wavelength
    else EXPECT_GT(spread, 0.01) << coating;                        // a quarter wave at 700 nm: not
  }
}

}  // namespace
}  // namespace objektiv
