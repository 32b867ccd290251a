// Zemax .zmx sequential files.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "base/error.h"
#include "optics/lens_file.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/zemax_lens.h"

namespace objektiv {
namespace {

// dgauss.50mm.dat written as a Zemax file: the indices become model glasses (nd = the file's
// index), so at the d line the lens is the same.
std::string DoubleGaussZmx(const std::string& unit = "MM", double scale = 1) {
  LensPrescription dat = LoadLens("dgauss.50mm");
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
  ParaxialData ref = ComputeParaxial(LoadLens("dgauss.50mm"));
  LensPrescription z = ParseZemaxLens(DoubleGaussZmx(), "dg.zmx");
  EXPECT_EQ(z.name, "Double Gauss test");
  EXPECT_EQ(z.StopIndex(), 5);
  EXPECT_NEAR(ComputeParaxial(z).efl, ref.efl, 1e-9 * ref.efl);
  EXPECT_NEAR(ComputeParaxial(z).bfl, ref.bfl, 1e-9 * ref.efl);
  // Lens units: the same file in centimetres describes the same lens.
  LensPrescription cm = ParseZemaxLens(DoubleGaussZmx("CM", 10), "dg_cm.zmx");
  EXPECT_NEAR(ComputeParaxial(cm).efl, ref.efl, 1e-9 * ref.efl);
}

TEST(Zemax, ReadsUtf16) {
  std::string ascii = DoubleGaussZmx(), utf16 = "\xff\xfe";
  for (char c : ascii) {
    utf16 += c;
    utf16 += '\0';
  }
  EXPECT_NEAR(ComputeParaxial(ParseZemaxLens(utf16, "u.zmx")).efl, ComputeParaxial(LoadLens("dgauss.50mm")).efl, 1e-9);
}

TEST(Zemax, EvenAsphereCoefficientsBecomeTheSag) {
  std::string z =
      "UNIT MM\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\n"
      "SURF 2\n TYPE EVENASPH\n CURV 0.02\n CONI -0.5\n PARM 1 0.001\n PARM 2 1e-6\n PARM 3 -2e-9\n GLAS N-BK7\n"
      " DISZ 5\n DIAM 10\nSURF 3\n CURV 0\n DISZ 40\n DIAM 10\nSURF 4\n DISZ 0\n DIAM 10\n";
  LensPrescription l = ParseZemaxLens(z, "a.zmx");
  LensTracer t(l);
  double r = 6, c = 0.02, k = -0.5;
  double expected = c * r * r / (1 + std::sqrt(1 - (1 + k) * c * c * r * r)) + 0.001 * r * r + 1e-6 * std::pow(r, 4) -
                    2e-9 * std::pow(r, 6);
  EXPECT_NEAR(t.Sag(1, r), expected, 1e-12);
  // The r^2 term changes the paraxial curvature: c + 2 a2.
  EXPECT_NEAR(l.surfaces[1].ParaxialCurvature(), 0.022, 1e-15);
}

// Found by fuzzing: a curvature so small that its radius overflows (a subnormal number) gave
// a surface of infinite radius that was not flat.
TEST(Zemax, CurvatureTooSmallForARadiusIsAPlane) {
  for (const char* curv : {"0", "-0", "0x1p-1074"}) {
    std::string z = fmt::format(
        "UNIT MM\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV {}\n GLAS N-BK7\n"
        " DISZ 5\n DIAM 10\nSURF 3\n CURV -0.02\n DISZ 40\n DIAM 10\nSURF 4\n DISZ 0\n DIAM 10\n",
        curv);
    LensPrescription l = ParseZemaxLens(z, "plane.zmx");
    ASSERT_EQ(l.surfaces.size(), 3u);
    EXPECT_TRUE(l.surfaces[1].flat) << curv;
    EXPECT_EQ(l.surfaces[1].radius, 0) << curv;
  }
}

TEST(Zemax, UnsupportedThingsAreNamed) {
  std::string bad_type = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n TYPE TOROIDAL\n DISZ 1\n DIAM 4\nSURF 2\n DISZ 0\n DIAM 4\n";
  try {
    ParseZemaxLens(bad_type, "t.zmx");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.zmx:5: surface type TOROIDAL"), std::string::npos) << e.what();
  }
  std::string no_stop = "SURF 0\n DISZ INFINITY\nSURF 1\n DISZ 1\n DIAM 4\nSURF 2\n DISZ 0\n DIAM 4\n";
  EXPECT_THROW(ParseZemaxLens(no_stop, "n.zmx"), InputError);
  std::string unknown_glass = "SURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\nSURF 2\n CURV 0.01\n GLAS NOPE\n"
                              " DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n DISZ 0\n DIAM 4\n";
  try {
    ParseZemaxLens(unknown_glass, "g.zmx");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("g.zmx:7: unknown glass 'NOPE'"), std::string::npos) << e.what();
  }
  // An unknown keyword is a warning, not an error.
  std::string odd = "WEIRD 1 2 3\nSURF 0\n DISZ INFINITY\nSURF 1\n STOP\n DISZ 1\n DIAM 4\n ODDITY 5\nSURF 2\n CURV 0.01\n"
                    " GLAS N-BK7\n DISZ 3\n DIAM 4\nSURF 3\n DISZ 10\n DIAM 4\nSURF 4\n DISZ 0\n DIAM 4\n";
  EXPECT_NO_THROW(ParseZemaxLens(odd, "o.zmx"));
}

}  // namespace
}  // namespace objektiv
