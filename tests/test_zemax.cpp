// Zemax .zmx sequential files.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "base/error.h"
#include "log_capture.h"
#include "optics/lens_file.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/pbrt_lens.h"
#include "optics/zemax_lens.h"

namespace objektiv {
namespace {

// dgauss.50mm.dat written as a Zemax file: the indices become model glasses (nd = the file's
// index), so at the d line the lens is the same.
std::string DoubleGaussZmx(const std::string& unit = "MM", double scale = 1) {
  LensPrescription dat = LoadLens("dgauss.50mm", GlassCatalog::Default());
  std::string z = fmt::format("VERS 140101\nMODE SEQ\nNAME Double Gauss test\nUNIT {} X W X CM MR CPMM\n", unit);
  z += "SURF 0\n  TYPE STANDARD\n  CURV 0.0 0 0 0 0 \"\"\n  DISZ INFINITY\n";
  int i = 1;
  for (const LensSurface& s : dat.surfaces) {
    z += fmt::format("SURF {}\n", i++);
    if (s.is_stop) z += "  STOP\n";
    z += fmt::format("  TYPE STANDARD\n  CURV {:.17g} 0 0 0 0 \"\"\n", s.is_stop ? 0.0 : scale / s.radius);
    z += "  HIDE 0 0 0 0 0 0 0 0 0 0\n";
    if (s.medium) z += fmt::format("  GLAS ___BLANK 1 0 {:.6f} 50.0 0 0 0 0 0 0\n", s.medium->Index(587.5618));
    z += fmt::format("  DISZ {:.17g}\n  DIAM {:.17g} 1 0 0 1 \"\"\n", s.thickness / scale, s.semi_diameter / scale);
  }
  z += fmt::format("SURF {}\n  TYPE STANDARD\n  CURV 0.0\n  DISZ 0\n  DIAM 20\n", i);
  return z;
}

TEST(Zemax, ReadsASequentialLensAsItsPbrtTwin) {
  ParaxialData ref = ComputeParaxial(LoadLens("dgauss.50mm", GlassCatalog::Default()));
  LensPrescription z = ParseZemaxLens(DoubleGaussZmx(), "dg.zmx", GlassCatalog::Default());
  EXPECT_EQ(z.name, "Double Gauss test");
  EXPECT_EQ(z.StopIndex(), 5);
  EXPECT_NEAR(ComputeParaxial(z).efl, ref.efl, 1e-9 * ref.efl);
  EXPECT_NEAR(ComputeParaxial(z).bfl, ref.bfl, 1e-9 * ref.efl);
  // Lens units: the same file in centimetres describes the same lens.
  LensPrescription cm = ParseZemaxLens(DoubleGaussZmx("CM", 10), "dg_cm.zmx", GlassCatalog::Default());
  EXPECT_NEAR(ComputeParaxial(cm).efl, ref.efl, 1e-9 * ref.efl);
}

TEST(Zemax, ReadsUtf16) {
  std::string ascii = DoubleGaussZmx(), utf16 = "\xff\xfe";
  for (char c : ascii) {
    utf16 += c;
    utf16 += '\0';
  }
  EXPECT_NEAR(ComputeParaxial(ParseZemaxLens(utf16, "u.zmx", GlassCatalog::Default())).efl, ComputeParaxial(LoadLens("dgauss.50mm", GlassCatalog::Default())).efl, 1e-9);
}

// The system aperture of a .zmx (ENPD, FNUM, OBNA, FLOA) is not what sets the stop here: each
// is named in a warning with its value (ENPD was ignored silently).
TEST(Zemax, SystemApertureIsWarnedAboutByName) {
  test::LogCapture log;
  ParseZemaxLens("UNIT MM\nENPD 10\nFNUM 4 0\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\n"
                 "SURF 2\n CURV 0.02\n GLAS N-BK7\n DISZ 5\n DIAM 10\nSURF 3\n DISZ 40\n DIAM 10\nSURF 4\n",
                 "ap.zmx", GlassCatalog::Default());
  EXPECT_TRUE(log.Has("ap.zmx:2: the system aperture ENPD 10 is not used")) << log.Text();
  EXPECT_TRUE(log.Has("ap.zmx:3: the system aperture FNUM 4 is not used")) << log.Text();
}

TEST(Zemax, EvenAsphereCoefficientsBecomeTheSag) {
  std::string z =
      "UNIT MM\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\n"
      "SURF 2\n TYPE EVENASPH\n CURV 0.02\n CONI -0.5\n PARM 1 0.001\n PARM 2 1e-6\n PARM 3 -2e-9\n GLAS N-BK7\n"
      " DISZ 5\n DIAM 10\nSURF 3\n CURV 0\n DISZ 40\n DIAM 10\nSURF 4\n DISZ 0\n DIAM 10\n";
  LensPrescription l = ParseZemaxLens(z, "a.zmx", GlassCatalog::Default());
  double r = 6, c = 0.02, k = -0.5;
  double expected = c * r * r / (1 + std::sqrt(1 - (1 + k) * c * c * r * r)) + 0.001 * r * r + 1e-6 * std::pow(r, 4) -
                    2e-9 * std::pow(r, 6);
  EXPECT_NEAR(l.surfaces[1].Sag(r), expected, 1e-12);
  // The r^2 term changes the paraxial curvature: c + 2 a2.
  EXPECT_NEAR(l.surfaces[1].ParaxialCurvature(), 0.022, 1e-15);
}

// Found by fuzzing: a curvature so small that its radius overflows (a subnormal number) gave
// a surface of infinite radius that was not flat.
TEST(Zemax, CurvatureTooSmallForARadiusIsAPlane) {
  for (const char* curv : {"0", "-0", "4.9406564584124654e-324"}) {
    std::string z = fmt::format(
        "UNIT MM\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV {}\n GLAS N-BK7\n"
        " DISZ 5\n DIAM 10\nSURF 3\n CURV -0.02\n DISZ 40\n DIAM 10\nSURF 4\n DISZ 0\n DIAM 10\n",
        curv);
    LensPrescription l = ParseZemaxLens(z, "plane.zmx", GlassCatalog::Default());
    ASSERT_EQ(l.surfaces.size(), 3u);
    EXPECT_TRUE(l.surfaces[1].flat) << curv;
    EXPECT_EQ(l.surfaces[1].radius, 0) << curv;
  }
}

TEST(Zemax, UnsupportedThingsAreNamed) {
  std::string bad_type = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n TYPE BICONICX\n DISZ 1\n DIAM 4\nSURF 2\n DISZ 0\n DIAM 4\n";
  try {
    ParseZemaxLens(bad_type, "t.zmx", GlassCatalog::Default());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.zmx:5: surface type BICONICX"), std::string::npos) << e.what();
  }
  std::string no_stop = "SURF 0\n DISZ INFINITY\nSURF 1\n DISZ 1\n DIAM 4\nSURF 2\n DISZ 0\n DIAM 4\n";
  EXPECT_THROW(ParseZemaxLens(no_stop, "n.zmx", GlassCatalog::Default()), InputError);
  std::string unknown_glass = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS NOPE\n"
                              " DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n DISZ 0\n DIAM 4\n";
  try {
    ParseZemaxLens(unknown_glass, "g.zmx", GlassCatalog::Default());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("g.zmx:9: glass NOPE is in no catalog (searched SCHOTT, OHARA, HOYA, CDGM, SUMITA, HIKARI, CRYSTALS); give it in "
                                                 "g.glass beside the lens (a line 'glass NOPE nd=N vd=V'"), std::string::npos) << e.what();
  }
  // An unknown keyword is a warning, not an error.
  std::string odd = "WEIRD 1 2 3\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\n ODDITY 5\nSURF 2\n CURV 0.01\n"
                    " GLAS N-BK7\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n DISZ 0\n DIAM 4\n";
  EXPECT_NO_THROW(ParseZemaxLens(odd, "o.zmx", GlassCatalog::Default()));
}

// MODE, ENVD and MNUM were ignored silently: a non-sequential file loaded, a lens at 60 C and a
// zoom's other configurations went unmentioned.
TEST(Zemax, ModeEnvironmentAndConfigurationsAreReadOrWarnedAbout) {
  const std::string lens = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS N-BK7\n"
                           " DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n";
  try {
    ParseZemaxLens("MODE NSC\n" + lens, "n.zmx", GlassCatalog::Default());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("n.zmx:1: MODE NSC: not a sequential lens file"), std::string::npos) << e.what();
  }
  try {
    ParseZemaxLens("MNUM abc\n" + lens, "m.zmx", GlassCatalog::Default());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("m.zmx:1: MNUM 'abc' is not a number of configurations"), std::string::npos)
        << e.what();
  }
  test::LogCapture log;
  ParseZemaxLens("MODE SEQ\nENVD 2.0E+1 1 0\nMNUM 1 1\n" + lens, "q.zmx", GlassCatalog::Default());
  EXPECT_TRUE(log.Text().empty()) << log.Text();
  ParseZemaxLens("ENVD 60 1 1\nMNUM 3 2\n" + lens, "e.zmx", GlassCatalog::Default());
  EXPECT_TRUE(log.Has("e.zmx:1: ENVD: the lens at 60 C and 1 atm is not modelled")) << log.Text();
  EXPECT_TRUE(log.Has("e.zmx:2: a file of 3 configurations: the lens is read as stored (configuration 2)")) << log.Text();
}

// A thickness of 1e300 gave an EFL of 0 and a lens that renders nothing, in every format.
TEST(LensFiles, LengthsBeyondAHundredMetresAreErrors) {
  struct Case {
    std::string text, path, part;
  };
  for (const Case& k : std::vector<Case>{
           {"surface 50 1e300 N-BK7 10\nstop 1 air 5\nsurface -50 40 air 10\n", "a.lens", "a.lens:1: thickness 1e+300 mm"},
           {"surface inf 5 N-BK7 2e5\nstop 1 air 5\nsurface -50 40 air 10\n", "b.lens", "b.lens:1: semi-diameter 200000 mm"},
           {"50 1e300 1.5 10\n0 1 1 8\n-50 40 1 10\n", "c.dat", "c.dat:1: thickness 1e+300 mm"},
           {"SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS N-BK7\n DISZ 3\n"
            " DIAM 4\nSURF 3\n DISZ 1e300\n DIAM 4\nSURF 4\n", "d.zmx", "d.zmx:12: thickness 1e+300 mm"},
           {"UNIT M\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 0.001\n DIAM 0.004\nSURF 2\n CURV 10\n GLAS N-BK7\n"
            " DISZ 0.003\n DIAM 0.004\nSURF 3\n DISZ 0.01\n DIAM 0.004\nSURF 4\n DISZ 200\n DIAM 0\nSURF 5\n", "e.zmx",
            "e.zmx:16: thickness 200000 mm"},
       }) {
    std::string e;
    try {
      if (k.path.ends_with(".zmx")) ParseZemaxLens(k.text, k.path, GlassCatalog::Default());
      else if (k.path.ends_with(".dat")) ParsePbrtLens(k.text, k.path);
      else ParseNativeLens(k.text, k.path, GlassCatalog::Default());
    } catch (const InputError& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(k.part), std::string::npos) << k.path << ": " << e;
  }
}

// A second STOP was dropped in silence (the first won, and the f-number changed).
TEST(Zemax, ASecondStopIsAnError) {
  const std::string two = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n STOP\n CURV 0.01\n"
                          " GLAS N-BK7\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n";
  try {
    ParseZemaxLens(two, "s.zmx", GlassCatalog::Default());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.zmx:8: a second STOP (the first is the surface on line 3)"), std::string::npos)
        << e.what();
  }
}

// Bytes of a binary file reach messages escaped, not raw (they garbled the terminal).
TEST(Zemax, RawBytesInMessagesAreEscaped) {
  test::LogCapture log;
  std::string junk = std::string("W\x01\x1b[31mRD 1\n") + "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\n"
                     "SURF 2\n CURV 0.01\n GLAS N-BK7\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n";
  ParseZemaxLens(junk, "j.zmx", GlassCatalog::Default());
  EXPECT_TRUE(log.Has("j.zmx:1: not supported, ignored: W\\x01\\x1b[31mRD")) << log.Text();
}

// A dummy plane in air with DIAM 0 (Zemax computed no semi-diameter) neither refracts nor
// clips: it is left out and its thickness joins the gap before it (it was an error).
TEST(Zemax, DummyPlaneWithoutSemiDiameterIsLeftOut) {
  const std::string with_dummy = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n"
                                 " GLAS N-BK7\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 4\n DIAM 4\nSURF 4\n DISZ 6\n DIAM 0\nSURF 5\n";
  LensPrescription lens = ParseZemaxLens(with_dummy, "d.zmx", GlassCatalog::Default());
  ASSERT_EQ(lens.surfaces.size(), 3u);
  EXPECT_DOUBLE_EQ(lens.surfaces.back().thickness, 10);
  // In glass, or curved, DIAM 0 is still an error.
  std::string in_glass = with_dummy;
  in_glass.replace(in_glass.find(" DISZ 4"), 7, " GLAS N-BK7\n DISZ 4");
  EXPECT_THROW(ParseZemaxLens(in_glass, "d.zmx", GlassCatalog::Default()), InputError);
}

// CLAP rmin rmax is a circular aperture that clips (Zemax's DIAM does not): the semi-diameter.
TEST(Zemax, CircularApertureIsTheSemiDiameter) {
  const std::string lens = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS N-BK7\n"
                           " DISZ 3\n DIAM 4\n CLAP 0 3.5 0\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n";
  LensPrescription l = ParseZemaxLens(lens, "c.zmx", GlassCatalog::Default());
  EXPECT_DOUBLE_EQ(l.surfaces[1].semi_diameter, 3.5);
  EXPECT_DOUBLE_EQ(l.surfaces[2].semi_diameter, 4);
  std::string annular = lens;
  annular.replace(annular.find("CLAP 0 3.5"), 10, "CLAP 1 3.5");
  try {
    ParseZemaxLens(annular, "c.zmx", GlassCatalog::Default());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.zmx:12: CLAP 1 3.5: an annular aperture"), std::string::npos) << e.what();
  }
}

TEST(Zemax, NonFiniteValuesAndIndicesBelowOneNameTheLine) {
  // The double Gauss with line 11 (its first CURV), 13 (GLAS) or 15 (DIAM) replaced, or a line
  // put before line 15. CURV INFINITY made a surface of radius 0 and an EFL of 131 mm instead
  // of 50 mm; DIAM and CONI INFINITY and model indices below 1 were taken as they came.
  std::vector<std::string> base;
  for (size_t b = 0, e; b < DoubleGaussZmx().size(); b = e + 1) {
    e = DoubleGaussZmx().find('\n', b);
    base.push_back(DoubleGaussZmx().substr(b, e - b));
  }
  ASSERT_EQ(base[10].substr(0, 6), "  CURV");
  ASSERT_EQ(base[12].substr(0, 6), "  GLAS");
  ASSERT_EQ(base[14].substr(0, 6), "  DIAM");
  struct Bad {
    int line;
    std::string text;
    bool insert;
    std::string part;
  };
  std::vector<Bad> cases = {
      {11, "  CURV INFINITY 0 0 0 0 \"\"", false, "'INFINITY' is not a finite number"},
      {11, "  CURV -inf", false, "not a finite number"},
      {11, "  CURV nan", false, "not a finite number"},
      {11, "  CURV NAN(0x7ff)", false, "not a finite number"},
      {11, "  CURV 1e400", false, "not a finite number"},
      {11, "  CURV 0x1p99999", false, "not a finite number"},
      {15, "  DIAM INFINITY 1 0 0 1 \"\"", false, "not a finite number"},
      {15, "  CONI INFINITY", true, "not a finite number"},
      {15, "  DISZ nan", true, "not a finite number"},
      {13, "  GLAS ___BLANK 1 0 0.5 50", false, "model glass needs nd >= 1 and vd > 0, got nd 0.5"},
      {13, "  GLAS ___BLANK 1 0 1.67 -50", false, "model glass needs nd >= 1 and vd > 0"},
      {13, "  GLAS ___BLANK 1 0 1.67 Infinity", false, "not a finite number"},
      {13, "  GLAS NOT-A-GLASS 1 0 0.9 50", false, "glass NOT-A-GLASS: the stated nd 0.9 and vd 50 are no glass's"},
      {13, "  GLAS N-SF5 1 0 0.9 50", false, "glass N-SF5: the stated nd 0.9 and vd 50 are no glass's"},
      {15, "  PARM 2.5 1", true, "PARM index '2.5' is not an integer from 0 to 16"},
      {15, "  PARM 1e10 1", true, "PARM index '1e10'"},
      {15, "  PARM -2147483649 1", true, "PARM index"},
      {15, "  PARM 1 INFINITY", true, "not a finite number"},
  };
  for (const Bad& b : cases) {
    std::vector<std::string> lines = base;
    if (b.insert) lines.insert(lines.begin() + (b.line - 1), b.text);
    else lines[b.line - 1] = b.text;
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    try {
      ParseZemaxLens(text, "bad.zmx", GlassCatalog::Default());
      ADD_FAILURE() << "no error for line " << b.line << ": " << b.text;
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind(fmt::format("bad.zmx:{}:", b.line), 0), 0u) << msg;
      EXPECT_NE(msg.find(b.part), std::string::npos) << msg;
    }
  }
  // The object at infinity stays allowed, in each of Zemax's spellings.
  for (const char* word : {"INFINITY", "Infinity", "inf"}) {
    std::string text = DoubleGaussZmx();
    text.replace(text.find("DISZ INFINITY"), 13, std::string("DISZ ") + word);
    EXPECT_NO_THROW(ParseZemaxLens(text, "ok.zmx", GlassCatalog::Default())) << word;
  }
}

}  // namespace
}  // namespace objektiv
