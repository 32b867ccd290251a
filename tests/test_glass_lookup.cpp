// Glass names as lens designers write them: GCAT catalogs first, withdrawn names and their
// successors, names shared by different glasses, and glasses the user supplies beside the lens.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "camera/lens_camera_setup.h"
#include "log_capture.h"
#include "optics/glass_file.h"
#include "optics/glass_lookup.h"
#include "optics/glass_aliases.h"
#include "optics/lens_file.h"
#include "optics/zemax_lens.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

fs::path FreshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("objektiv_glass_lookup_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void Write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// A singlet in Zemax form: the stop, then one element of glass line `glas` (e.g. "GLAS BK7 1 0
// 1.5168 64.17"), after the `head` lines (GCAT ...).
std::string Singlet(const std::string& head, const std::string& glas) {
  return head + "UNIT MM\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n " + glas +
         "\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n DISZ 0\n DIAM 4\n";
}

// The first element's glass; shared, as the lens owns a glass its own files brought.
std::shared_ptr<const Glass> ElementGlass(const LensPrescription& lens) {
  for (const LensSurface& s : lens.surfaces)
    if (s.medium) return s.medium;
  throw std::runtime_error("no glass");
}

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(GlassSuccessors, EachMakersEcoPrefixAndSchottsOldInfix) {
  EXPECT_EQ(SuccessorCandidates("SCHOTT", "BK7"), std::vector<std::string>{"N-BK7"});
  EXPECT_EQ(SuccessorCandidates("SCHOTT", "LAKN22"), (std::vector<std::string>{"N-LAKN22", "N-LAK22"}));
  EXPECT_EQ(SuccessorCandidates("SCHOTT", "SF56A"), (std::vector<std::string>{"N-SF56", "N-SF56A"}));
  EXPECT_EQ(SuccessorCandidates("OHARA", "BSL7"), std::vector<std::string>{"S-BSL7"});
  EXPECT_EQ(SuccessorCandidates("CDGM", "ZF52"), std::vector<std::string>{"H-ZF52"});
  EXPECT_TRUE(SuccessorCandidates("SCHOTT", "N-BK7").empty());  // already a successor's name
  EXPECT_TRUE(SuccessorCandidates("SUMITA", "BK7").empty());    // no rule for that maker
}

TEST(GlassLookup, WithdrawnNamesFindTheirSuccessorsAndUnknownNamesNothing) {
  GlassLookup lookup(GlassCatalog::Default());
  auto bk7 = lookup.Find("BK7");
  ASSERT_TRUE(bk7);
  EXPECT_EQ(bk7->glass->name(), "N-BK7");
  EXPECT_EQ(bk7->how, GlassMatch::How::kSuccessor);
  EXPECT_EQ(SubstitutionNote("BK7", *bk7), "glass BK7 is withdrawn; its successor SCHOTT:N-BK7 is used");
  EXPECT_EQ(lookup.Find("schott:bk7")->glass->name(), "N-BK7");
  auto exact = lookup.Find("N-BK7");
  ASSERT_TRUE(exact);
  EXPECT_EQ(exact->how, GlassMatch::How::kExactName);
  EXPECT_EQ(SubstitutionNote("N-BK7", *exact), "");
  auto lak22 = lookup.Find("LAKN22");  // Schott's old infix name
  ASSERT_TRUE(lak22);
  EXPECT_EQ(lak22->glass->name(), "N-LAK22");
  EXPECT_EQ(lookup.Find("SSKN8")->glass->name(), "N-SSK8");
  // Zemax's generic material names: the same material in a shipped catalog.
  auto silica = lookup.Find("SILICA");
  ASSERT_TRUE(silica);
  EXPECT_EQ(silica->how, GlassMatch::How::kSameMaterial);
  EXPECT_EQ(SubstitutionNote("SILICA", *silica), "glass SILICA is read as SCHOTT:LITHOSIL-Q (the same material)");
  // Malitson's fused silica (the formula Zemax's SILICA is) at d: 1.458462.
  EXPECT_NEAR(silica->glass->Index(587.5618), 1.458462, 3e-5);
  EXPECT_EQ(lookup.Find("CaF2")->glass->name(), "LITHOTEC-CAF2");
  EXPECT_FALSE(lookup.Find("LLF7"));  // in no catalog: never a guess
  EXPECT_FALSE(lookup.Find("OHARA:N-BK7"));
  EXPECT_FALSE(lookup.Find("NOSUCH:N-BK7"));
}

TEST(GlassLookup, ANameOfTwoGlassesIsTheOneWhoseStatedValuesAgreeOrTheFileCatalogs) {
  // CDGM's F2 (1.6129/36.99) is not Schott's F2 (1.62004/36.37).
  GlassLookup lookup(GlassCatalog::Default());
  EXPECT_EQ(lookup.Find("F2")->glass->catalog(), "SCHOTT");
  EXPECT_EQ(lookup.Find("F2", StatedGlass{1.6129, 36.99})->glass->catalog(), "CDGM");
  EXPECT_EQ(lookup.Find("F2", StatedGlass{1.62004, 36.37})->glass->catalog(), "SCHOTT");
  // No glass of the name agrees: the first of the search order (the caller warns).
  EXPECT_EQ(lookup.Find("F2", StatedGlass{1.7, 30})->glass->catalog(), "SCHOTT");
  lookup.Prefer({"CDGM"}, nullptr);
  EXPECT_EQ(lookup.Find("F2")->glass->catalog(), "CDGM");
  EXPECT_EQ(lookup.SearchedCatalogs(), "CDGM, SCHOTT, OHARA, HOYA, SUMITA, HIKARI, CRYSTALS");
  // SK16 is HIKARI's (a Nikon glass under the old Schott name) unless the file names SCHOTT:
  // then Schott's successor N-SK16.
  GlassLookup plain(GlassCatalog::Default());
  EXPECT_EQ(plain.Find("SK16")->glass->catalog(), "HIKARI");
  plain.Prefer({"SCHOTT"}, nullptr);
  auto sk16 = plain.Find("SK16");
  EXPECT_EQ(sk16->glass->name(), "N-SK16");
  EXPECT_EQ(sk16->how, GlassMatch::How::kSuccessor);
}

TEST(GlassFile, ModelConstantAndTableGlasses) {
  // Five rows of N-BK7's catalog formula: the fitted formula gives its nd to 2e-6 and Vd to 0.05
  // (four terms through five points of a smooth curve), and the table's range.
  const Glass& bk7 = *GlassCatalog::Default().Find("N-BK7");
  std::string table = "# measured\nglass MY-BK7\n";
  for (double nm : {435.8343, 486.1327, 546.0740, 587.5618, 656.2725})
    table += fmt::format("{:.7f} {:.7f}\n", nm * 1e-3, bk7.Index(nm));
  GlassCatalog c;
  ParseGlassFile(c, table + "glass B270 nd=1.5230 vd=58.5\nglass SAPPHIRE n=1.768\nglass OLD nd=1.6,vd=40\n", "t.glass",
                 "t.glass");
  const Glass* mine = c.Find("my-bk7");
  ASSERT_TRUE(mine);
  EXPECT_NEAR(mine->ComputedNd(), bk7.ComputedNd(), 2e-6);
  EXPECT_NEAR(mine->ComputedVd(), bk7.ComputedVd(), 0.05);
  EXPECT_NEAR(mine->Index(500), bk7.Index(500), 5e-6);
  EXPECT_DOUBLE_EQ(mine->lambda_min_um, 0.4358343);
  EXPECT_DOUBLE_EQ(mine->lambda_max_um, 0.6562725);
  EXPECT_NEAR(c.Find("B270")->ComputedNd(), 1.523, 1e-12);
  EXPECT_NEAR(c.Find("B270")->ComputedVd(), 58.5, 1e-9);
  EXPECT_EQ(c.Find("SAPPHIRE")->Index(450), 1.768);
  EXPECT_NEAR(c.Find("OLD")->ComputedVd(), 40, 1e-9);
  // Two rows: Cauchy's form through both.
  std::array<double, 10> two = FitSchottFormula({{0.5, 1.52}, {0.6, 1.515}});
  Glass cauchy("two", "t", DispersionFormula::kSchott, two);
  EXPECT_NEAR(cauchy.Index(500), 1.52, 1e-12);
  EXPECT_NEAR(cauchy.Index(600), 1.515, 1e-12);
}

// A filter's glass: a transmittance curve over a thickness, on a value glass or a table glass.
TEST(GlassFile, TransmittanceRowsGiveTheInternalTransmittance) {
  GlassCatalog c;
  ParseGlassFile(c,
                 "glass RED n=1.52\ntransmittance 2\n0.40 1e-6\n0.58 1e-6\n0.62 0.9\n0.80 0.9\n"
                 "glass T\n0.5 1.52\n0.6 1.515\ntransmittance 10  # over 10 mm\n0.5 0.81\n",
                 "f.glass", "f.glass");
  const Glass& red = *c.Find("RED");
  EXPECT_FALSE(red.IsDispersive());
  EXPECT_TRUE(red.Absorbs());
  EXPECT_NEAR(red.InternalTransmittance(700, 2), 0.9, 1e-12);
  EXPECT_NEAR(red.InternalTransmittance(700, 4), 0.81, 1e-12);  // Beer-Lambert in the thickness
  EXPECT_NEAR(red.InternalTransmittance(450, 2), 1e-6, 1e-12);
  EXPECT_NEAR(c.Find("T")->InternalTransmittance(500, 5), 0.9, 1e-12);
  EXPECT_NEAR(c.Find("T")->Index(500), 1.52, 1e-12);
}

// A constant-index filter plate in front of a lens: every wavelength takes one path, but the
// plate transmits each differently, so the camera weighs each of a sample's wavelengths by the
// plate's transmittance at it.
TEST(GlassFile, AFilterPlateWeighsEachWavelengthOfTheCameraRay) {
  fs::path dir = FreshDir("filter");
  Write(dir / "f.glass", "glass RED n=1.52\ntransmittance 2\n0.40 1e-6\n0.58 1e-6\n0.62 0.9\n0.80 0.9\n");
  Write(dir / "f.lens", "surface inf 2 RED 12\nsurface inf 1 air 12\nsurface 50 3 n=1.9 10\nstop 1 air 8\n"
                        "surface inf 45 air 10\n");
  LensCameraSpec s;
  s.lens = ReadLensFile((dir / "f.lens").string(), GlassCatalog::Default());
  s.fnumber = 8;
  auto camera = MakeLensCamera(Transform(), 11, 11, s);
  SampledWavelengths l = SampledWavelengths::SampleVisible(0.05f);
  auto r = camera->GenerateRay({Vec2f(5.5f, 5.5f), Vec2f(0.4f, 0.6f)}, l);
  ASSERT_TRUE(r);
  EXPECT_FALSE(l.SecondaryTerminated());
  float red = 0, blue = INFINITY;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    if (l[k] > 620) red = std::max(red, r->weight[k]);
    if (l[k] < 580) blue = std::min(blue, r->weight[k]);
  }
  ASSERT_GT(red, 0) << "no red wavelength among the sample's";
  EXPECT_LT(blue, 1e-5 * red);
  fs::remove_all(dir);
}

// N-BK7's indices at eight wavelengths with one typing error (5e-4 too high): the warning names
// that row alone (the formula fitted to the other rows misses it most).
TEST(GlassFile, ATableRowTheFormulaMissesIsWarnedAboutByLine) {
  const Glass& bk7 = *GlassCatalog::Default().Find("N-BK7");
  const double nm[] = {404.6561, 435.8343, 479.9914, 486.1327, 546.0740, 587.5618, 643.8469, 656.2725};
  for (int bad = 0; bad < 8; ++bad) {
    std::string table = "glass X\n";
    for (int i = 0; i < 8; ++i) table += fmt::format("{:.7f} {:.6f}\n", nm[i] * 1e-3, bk7.Index(nm[i]) + (i == bad ? 5e-4 : 0));
    test::LogCapture log;
    GlassCatalog c;
    ParseGlassFile(c, table, "x.glass", "x.glass");
    EXPECT_EQ(log.Count("the dispersion formula fitted to the other rows misses this row"), 1) << log.Text();
    EXPECT_TRUE(log.Has(fmt::format("x.glass:{}: glass X", bad + 2))) << bad << ": " << log.Text();
  }
  // Without the error, no warning.
  std::string good = "glass X\n";
  for (double l : nm) good += fmt::format("{:.7f} {:.6f}\n", l * 1e-3, bk7.Index(l));
  test::LogCapture log;
  GlassCatalog c;
  ParseGlassFile(c, good, "x.glass", "x.glass");
  EXPECT_TRUE(log.Text().empty()) << log.Text();
}

// A table whose fitted formula is not an index that falls with the wavelength across the
// visible (rows only in the infrared, a three-row typo, two rows 0.1 nm apart) is an error: the
// renderer would extrapolate it into nonsense.
TEST(GlassFile, ATableThatDoesNotDescribeTheVisibleIsAnError) {
  for (const char* table : {"glass X\n10 2.4\n12 2.39\n", "glass X\n0.4861327 1.52238\n0.5875618 1.79100\n0.6562725 1.51432\n",
                            "glass X\n0.4861327 1.52238\n0.5875618 1.51100\n0.6562725 1.51432\n"}) {
    GlassCatalog c;
    EXPECT_NE(ErrorOf([&] { ParseGlassFile(c, table, "x.glass", "x.glass"); })
                  .find("x.glass:1: glass X: the dispersion formula fitted to its index table gives n"),
              std::string::npos) << table << " -> " << ErrorOf([&] { ParseGlassFile(c, table, "x.glass", "x.glass"); });
  }
  // A table of the visible's middle only is extrapolated, with a warning; a dispersion no
  // optical material has (two rows 0.1 nm apart) is warned about.
  test::LogCapture log;
  GlassCatalog c;
  ParseGlassFile(c, "glass Y\n0.5 1.521\n0.55 1.519\n0.6 1.5175\nglass Z\n0.5875 1.5168\n0.5876 1.5167\n", "y.glass",
                 "y.glass");
  EXPECT_TRUE(log.Has("y.glass:1: glass Y: its index table covers 0.5 to 0.6 um; the renderer extrapolates")) << log.Text();
  EXPECT_TRUE(log.Has("y.glass:5: glass Z: the index table gives an Abbe number Vd of ")) << log.Text();
}

TEST(GlassFile, NamesALensFileCouldNotUseAreErrorsAndAnEmptyFileIsNoted) {
  for (const char* bad : {"glass A:B n=1.5\n", "glass air n=1.5\n", "glass n=1.6 n=1.5\n"}) {
    GlassCatalog c;
    EXPECT_NE(ErrorOf([&] { ParseGlassFile(c, bad, "n.glass", "n.glass"); }).find("cannot name a glass"), std::string::npos)
        << bad;
  }
  test::LogCapture log;
  GlassCatalog c;
  ParseGlassFile(c, "# nothing yet\n", "e.glass", "e.glass");
  EXPECT_TRUE(log.Has("e.glass: no glass in this glass file")) << log.Text();
}

TEST(GlassFile, BadLinesNameFileAndLine) {
  struct Case {
    std::string text, part;
  };
  for (const Case& k : std::vector<Case>{
           {"glass A nd=1.5 vd=60\nglass a n=1.6\n", "g.glass:2: glass a is given twice (first on line 1)"},
           {"glass A\n0.5 1.5\n", "g.glass:1: glass A needs an index table of 2 or more rows"},
           {"glass A\n486.1 1.52\n", "g.glass:2: wavelength 486.1 is not in micrometres"},
           {"glass A\n0.5 1.52\n0.5 1.53\n", "g.glass:3: glass A: the index table gives wavelength 0.5 um twice (first on line 2)"},
           {"glass A\n0.5 0.9\n", "g.glass:2: index 0.9 is not between 1 and 5"},
           {"0.5 1.52\n", "g.glass:1: expected 'glass NAME"},
           {"glass A nd=0.5 vd=60\n", "g.glass:1: glass A needs nd from 1 to 5"},
           {"glass A nd=1.5 vd=nan\n", "not a finite number"},
           {"glass A vd=60 nd=1.5\n", "g.glass:1: glass A: expected nd=N vd=V"},
           {"glass\n", "g.glass:1: a glass line needs a name"},
           {"glass A\n0.5 1.52 7\n", "g.glass:2: expected"},
           {"transmittance 2\n0.5 0.5\n", "g.glass:1: a transmittance line belongs after a glass line"},
           {"glass A n=1.5\n0.5 0.5\n", "g.glass:2: expected"},
           {"glass A n=1.5\ntransmittance 2\n", "g.glass:2: glass A: a transmittance line needs rows"},
           {"glass A n=1.5\ntransmittance 2\n0.5 0\n", "g.glass:3: transmittance 0 is not above 0"},
           {"glass A n=1.5\ntransmittance 2\n0.5 1.5\n", "g.glass:3: transmittance 1.5 is not above 0"},
           {"glass A n=1.5\ntransmittance 0\n", "g.glass:2: thickness 0 mm is not above 0"},
           {"glass A n=1.5\ntransmittance\n", "g.glass:2: a transmittance line is 'transmittance THICKNESS_MM'"},
           {"glass A n=1.5\ntransmittance 2\n0.5 0.5\ntransmittance 3\n", "g.glass:4: glass A: a second transmittance"},
           {"glass A n=1.5\ntransmittance 2\n0.5 0.5\n0.5 0.6\n",
            "g.glass:4: glass A: the transmittance gives wavelength 0.5 um twice (first on line 3)"},
       }) {
    GlassCatalog c;
    EXPECT_NE(ErrorOf([&] { ParseGlassFile(c, k.text, "g.glass", "g.glass"); }).find(k.part), std::string::npos)
        << k.text << " -> " << ErrorOf([&] { ParseGlassFile(c, k.text, "g.glass", "g.glass"); });
  }
}

TEST(ZemaxGlasses, WithdrawnNameIsItsSuccessorWithAWarning) {
  test::LogCapture log;
  LensPrescription lens = ParseZemaxLens(Singlet("", "GLAS BK7 1 0 1.5168 64.17 0 0"), "w.zmx", GlassCatalog::Default());
  EXPECT_EQ(ElementGlass(lens)->name(), "N-BK7");
  EXPECT_TRUE(log.Has("w.zmx:10: glass BK7 is withdrawn; its successor SCHOTT:N-BK7 is used")) << log.Text();
  EXPECT_FALSE(log.Has("another glass")) << log.Text();
}

TEST(ZemaxGlasses, ASubstitutionIsNotedOncePerName) {
  test::LogCapture log;
  std::string two = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS PSK3\n DISZ 3\n"
                    " DIAM 4\nSURF 3\n DISZ 1\n DIAM 4\nSURF 4\n CURV 0.01\n GLAS PSK3\n DISZ 3\n DIAM 4\nSURF 5\n DISZ 10\n"
                    " DIAM 4\nSURF 6\n";
  ParseZemaxLens(two, "t.zmx", GlassCatalog::Default());
  EXPECT_EQ(log.Count("glass PSK3 is withdrawn"), 1) << log.Text();
  EXPECT_TRUE(log.Has("t.zmx:9: glass PSK3 is withdrawn; its successor SCHOTT:N-PSK3 is used")) << log.Text();
}

TEST(ZemaxGlasses, GcatOrderAndStatedValuesPickAmongGlassesOfOneName) {
  test::LogCapture log;
  EXPECT_EQ(ElementGlass(ParseZemaxLens(Singlet("GCAT CDGM SCHOTT\n", "GLAS F2"), "c.zmx", GlassCatalog::Default()))
                ->catalog(), "CDGM");
  EXPECT_EQ(ElementGlass(ParseZemaxLens(Singlet("", "GLAS F2 1 0 1.6129 36.99"), "c.zmx", GlassCatalog::Default()))
                ->catalog(), "CDGM");
  EXPECT_TRUE(log.Text().empty()) << log.Text();
  // Zemax's placeholder values (1.5, 40) and zeros state nothing.
  ParseZemaxLens(Singlet("", "GLAS N-BK7 0 0 1.50E+00 4.00E+01 0 0"), "p.zmx", GlassCatalog::Default());
  ParseZemaxLens(Singlet("", "GLAS N-BK7 0 0 0 0 0 0"), "p.zmx", GlassCatalog::Default());
  EXPECT_TRUE(log.Text().empty()) << log.Text();
  // A found glass that disagrees a little with the file's own values is warned about; one that
  // is clearly another material is an error.
  ParseZemaxLens(Singlet("", "GLAS N-BK7 1 0 1.519 64.17"), "d.zmx", GlassCatalog::Default());
  EXPECT_TRUE(log.Has("d.zmx:10: glass N-BK7: the file states nd 1.519 vd 64.17, but SCHOTT:N-BK7 has nd 1.51680 vd "
                      "64.17")) << log.Text();
  EXPECT_NE(ErrorOf([] { ParseZemaxLens(Singlet("", "GLAS BAF2 0 0 1.474 81.8"), "m.zmx", GlassCatalog::Default()); })
                .find("m.zmx:10: glass BAF2: the file states nd 1.474 vd 81.8, but "),
            std::string::npos);
  // A glass of the name outside the GCAT catalogs that agrees with the stated values is taken,
  // with a warning.
  std::shared_ptr<const Glass> f2 = ElementGlass(
      ParseZemaxLens(Singlet("GCAT SCHOTT\n", "GLAS F2 0 0 1.6129 36.99"), "x.zmx", GlassCatalog::Default()));
  EXPECT_EQ(f2->catalog(), "CDGM");
  EXPECT_TRUE(log.Has("x.zmx:11: glass F2 is read as CDGM:F2, whose nd and Vd agree with the file's")) << log.Text();
}

TEST(ZemaxGlasses, AGlassInNoCatalogIsAnErrorThatSaysHowToSupplyIt) {
  std::string e = ErrorOf([] { ParseZemaxLens(Singlet("", "GLAS B270 1 0 1.5230 58.5"), "v.zmx", GlassCatalog::Default()); });
  EXPECT_NE(e.find("v.zmx:10: glass B270 is in no catalog (searched SCHOTT, OHARA, HOYA, CDGM, SUMITA, HIKARI, CRYSTALS). The file "
                   "states nd 1.523 vd 58.5; the nearest shipped glasses are "),
            std::string::npos) << e;
  EXPECT_NE(e.find("give it in v.glass beside the lens (a line 'glass B270 nd=1.523 vd=58.5'"), std::string::npos) << e;
}

TEST(ZemaxGlasses, GlassFileAndCatalogsBesideTheLens) {
  fs::path dir = FreshDir("beside");
  Write(dir / "vendor.zmx", Singlet("GCAT SCHOTT LIGHTPATH MISC\n", "GLAS D-ZK3M 1 0 1.5891 61.2"));
  // No glass file yet, and no LIGHTPATH.AGF: MISC and LIGHTPATH are named and missing.
  {
    test::LogCapture log;
    EXPECT_NE(ErrorOf([&] { ReadLensFile((dir / "vendor.zmx").string(), GlassCatalog::Default()); })
                  .find("glass D-ZK3M is in no catalog"), std::string::npos);
    EXPECT_TRUE(log.Has("vendor.zmx:1: glass catalog LIGHTPATH is not shipped")) << log.Text();
    EXPECT_TRUE(log.Has("glass catalog MISC is not shipped")) << log.Text();
  }
  // The maker's catalog beside the lens (any case of name), named by GCAT.
  Write(dir / "lightpath.agf", "NM D-ZK3M 1 589612 1.5891 61.2 0 0 0\nCD 2.4787781648 0 0.0160395560 0 0 0 0 0 0 0\n");
  {
    test::LogCapture log;
    std::shared_ptr<const Glass> g =
        ElementGlass(ReadLensFile((dir / "vendor.zmx").string(), GlassCatalog::Default()));
    EXPECT_EQ(g->catalog(), "LIGHTPATH");
    EXPECT_FALSE(log.Has("LIGHTPATH is not shipped")) << log.Text();
  }
  // A glass file beside the lens comes first; its unused glasses are named.
  Write(dir / "vendor.glass", "glass D-ZK3M nd=1.5891 vd=61.2\nglass SPARE n=1.5\n");
  {
    test::LogCapture log;
    std::shared_ptr<const Glass> g =
        ElementGlass(ReadLensFile((dir / "vendor.zmx").string(), GlassCatalog::Default()));
    EXPECT_EQ(g->catalog(), "vendor.glass");
    EXPECT_NEAR(g->ComputedNd(), 1.5891, 1e-12);
    EXPECT_TRUE(log.Has("vendor.glass: 1 glass(es) that no surface of ")) << log.Text();
    EXPECT_TRUE(log.Has("vendor.zmx uses: SPARE")) << log.Text();
  }
  // A bad glass file is an error naming it, not a lens without its glasses.
  Write(dir / "vendor.glass", "glass D-ZK3M nd=1.5891\n");
  EXPECT_NE(ErrorOf([&] { ReadLensFile((dir / "vendor.zmx").string(), GlassCatalog::Default()); })
                .find("vendor.glass:1: glass D-ZK3M: expected nd=N vd=V"), std::string::npos);
  fs::remove_all(dir);
}

// A glass file or a named catalog beside the lens that is not a regular file (a directory), or
// two files naming one catalog, is an error; they were passed over in silence.
TEST(ZemaxGlasses, OddFilesBesideTheLensAreErrorsAndDatedCatalogsTheShippedOnes) {
  fs::path dir = FreshDir("odd");
  const std::string lens = Singlet("GCAT MYCAT\n", "GLAS N-BK7");
  Write(dir / "a.zmx", lens);
  fs::create_directories(dir / "a.glass");
  EXPECT_NE(ErrorOf([&] { ReadLensFile((dir / "a.zmx").string(), GlassCatalog::Default()); })
                .find("a.glass: the glass file beside the lens is not a regular file"), std::string::npos);
  fs::remove_all(dir / "a.glass");
  fs::create_directories(dir / "MYCAT.AGF");
  EXPECT_NE(ErrorOf([&] { ReadLensFile((dir / "a.zmx").string(), GlassCatalog::Default()); })
                .find("catalog MYCAT named on line 1 of"), std::string::npos);
  fs::remove_all(dir / "MYCAT.AGF");
  const std::string agf = "NM N-BK7 1 0 1.5 60\nCD 2.25\n";
  Write(dir / "MYCAT.AGF", agf);
  Write(dir / "mycat.agf", agf);
  EXPECT_NE(ErrorOf([&] { ReadLensFile((dir / "a.zmx").string(), GlassCatalog::Default()); })
                .find("a.zmx:1: catalog MYCAT: two files beside the lens name it"), std::string::npos);
  fs::remove(dir / "mycat.agf");
  EXPECT_EQ(ElementGlass(ReadLensFile((dir / "a.zmx").string(), GlassCatalog::Default()))->catalog(), "MYCAT");
  // A catalog file that is no AGF (no NM line) is an error naming it.
  Write(dir / "MYCAT.AGF", "<svg></svg>\n");
  EXPECT_NE(ErrorOf([&] { ReadLensFile((dir / "a.zmx").string(), GlassCatalog::Default()); })
                .find("MYCAT.AGF: no glass in this catalog (no NM line)"), std::string::npos);
  // A dated edition of a shipped catalog is the shipped one, with a warning.
  test::LogCapture log;
  std::shared_ptr<const Glass> g =
      ElementGlass(ParseZemaxLens(Singlet("GCAT CDGM_2015\n", "GLAS F2"), "d.zmx", GlassCatalog::Default()));
  EXPECT_EQ(g->catalog(), "CDGM");
  EXPECT_TRUE(log.Has("d.zmx:1: glass catalog CDGM_2015 is read as the shipped CDGM")) << log.Text();
  fs::remove_all(dir);
}

// An AGF catalog whose formula disagrees with its own nd, or has a pole in the visible, is an
// error at the glass's NM line (a CD line of zeros gave n = 1 in silence).
TEST(GlassCatalog, AFormulaThatIsNotItsGlassIsAnError) {
  struct Case {
    std::string text, part;
  };
  for (const Case& k : std::vector<Case>{
           {"NM A 2 0 1.5 60\nCD 0 0 0 0 0 0\n", "c.agf:1: glass A: its dispersion formula gives nd 1, its NM line says 1.5"},
           {"NM A 2 0 1.5 60\n", "c.agf:1: glass A: its dispersion formula gives nd 1"},
           {"NM A 1 0 1.5 60\nCD 2.25\nNM B 2 0 1.5 60\nCD 0.34486 0.25\n", "c.agf:3: glass B: its dispersion formula gives n"},
           {"CC nothing here\n", "c.agf: no glass in this catalog"},
       }) {
    GlassCatalog c;
    EXPECT_NE(ErrorOf([&] { c.LoadAgfText(k.text, "c.agf", "C"); }).find(k.part), std::string::npos)
        << k.text << " -> " << ErrorOf([&] { c.LoadAgfText(k.text, "c.agf", "C"); });
  }
}

TEST(NativeLensGlasses, WithdrawnNamesAndAGlassFileBesideTheLens) {
  fs::path dir = FreshDir("native");
  const std::string lens = "surface 50 5 BK7 10\nsurface -50 5 air 10\nstop 40 air 5\n";
  Write(dir / "old.lens", lens);
  {
    test::LogCapture log;
    EXPECT_EQ(ElementGlass(ReadLensFile((dir / "old.lens").string(), GlassCatalog::Default()))->name(), "N-BK7");
    EXPECT_TRUE(log.Has("old.lens:1: glass BK7 is withdrawn; its successor SCHOTT:N-BK7 is used")) << log.Text();
  }
  Write(dir / "old.glass", "glass BK7 nd=1.5168 vd=64.17\n");
  EXPECT_EQ(ElementGlass(ReadLensFile((dir / "old.lens").string(), GlassCatalog::Default()))->catalog(), "old.glass");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace objektiv
