// Lenses whose aperture stop lies inside glass (pbrt-v4 reads a .dat row with radius 0 as the
// stop whatever its index): first-order data against hand computation, real rays meeting the
// paraxial focus, the same lens in the three file formats, the layout plot and a render.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "optics/lens_tracer.h"
#include "io/lens_plot.h"
#include "log_capture.h"
#include "optics/batch_tracer.h"
#include "optics/lens_file.h"
#include "optics/paraxial.h"
#include "optics/pbrt_lens.h"
#include "optics/real_focus.h"
#include "optics/zemax_lens.h"
#include "render_helpers.h"

namespace objektiv {
namespace {

// A: a thick biconvex singlet (n = 1.5, R1 = 50, R2 = -50, 10 mm thick) with the stop (20 mm)
// in the middle of the glass: the stop row carries the glass's index, as pbrt-v4 reads it.
const char* kSinglet = "# thick singlet, stop inside the glass\n50\t5\t1.5\t24\n0\t5\t1.5\t20\n-50\t0\t1\t24\n";
// B: a cemented doublet whose flat cemented face is the stop: n = 1.5 before it, 1.7 after.
const char* kDoublet = "# doublet, stop on the cemented face\n50\t4\t1.5\t24\n0\t4\t1.7\t20\n-60\t0\t1\t24\n";

struct Expected {
  double efl, bfl, ffl, ep_position, ep_diameter, xp_position, xp_diameter;
};

// A by hand. Surface powers phi1 = (n - 1) / R1 = 0.01, phi2 = (1 - n) / R2 = 0.01 (per mm);
// thick lens: phi = phi1 + phi2 - phi1 phi2 d / n = 0.02 - 0.0001 * 10 / 1.5 = 29/1500, so
//   EFL = 1500/29 = 51.7241 mm, BFL = EFL (1 - phi1 d / n) = 1400/29, FFL = -1400/29.
// Entrance pupil: the stop, 5 mm inside the glass, imaged by the first surface into air:
//   n'/s' - n/s = phi1 with n' = 1.5, s' = 5, n = 1: 1/s = 0.3 - 0.01, s = 100/29 = 3.448 mm
//   behind the first vertex. A ray parallel to the axis at height y meets the stop at
//   y (1 - 5 phi1 / n) = 29 y / 30, so EPD = 20 * 30/29 = 600/29 = 20.690 mm (f/2.5).
// Exit pupil: the mirror image (the lens is symmetric): 100/29 in front of the last vertex,
//   600/29 across.
const Expected kSingletByHand = {1500.0 / 29, 1400.0 / 29, -1400.0 / 29, 100.0 / 29, 600.0 / 29, -100.0 / 29, 600.0 / 29};

// B by hand (y-nu: nu' = nu - y c (n' - n), y' = y + t nu / n), a ray at y = 1 from infinity:
//   surface 1: nu = -0.5/50 = -1/100; 4 mm of n = 1.5: y = 1 - 4/150 = 73/75;
//   the flat stop keeps nu (n u is conserved across a flat face); 4 mm of n = 1.7:
//   y = 73/75 - 4/170 = 1211/1275; surface 3 (c = -1/60, 1.7 -> 1): nu = -1/100 - y 0.7/60
//   = -16127/765000. EFL = -1/nu = 765000/16127 = 47.436 mm; BFL = -y/nu = 726600/16127.
//   FFL, backward from the film side: surface 3 (air -> 1.7, c = 1/60 seen from behind):
//   nu = -0.7/60 = -7/600; 4 mm of 1.7: y = 1 - 28/1020 = 248/255; the stop; 4 mm of 1.5:
//   y = 248/255 - 28/900 = 14404/15300; surface 1 (c = -1/50 seen from behind, 1.5 -> 1):
//   nu = -7/600 - y 0.5/50; FFL = y / nu.
// Entrance pupil: 1.5/4 - 1/s = 0.01, s = 200/73 = 2.740 mm; the parallel ray meets the stop
//   at 73/75 of its height: EPD = 1500/73 = 20.548 mm.
// Exit pupil: from the stop's centre at slope 1 in n = 1.7 (nu = 1.7), 4 mm: y = 4; surface 3:
//   nu' = 1.7 - 4 * 0.7/60 = 124/75; position -y/nu' = -75/31 = -2.419 mm; diameter by the
//   Lagrange invariant 20 * 1.7 / nu' = 1275/62 = 20.565 mm.
Expected DoubletByHand() {
  double y = 14404.0 / 15300, nu = -7.0 / 600 - y * 0.5 / 50;
  return {765000.0 / 16127, 726600.0 / 16127, y / nu, 200.0 / 73, 1500.0 / 73, -75.0 / 31, 1275.0 / 62};
}

void ExpectParaxial(const LensPrescription& lens, const Expected& e, const std::string& what) {
  ParaxialData d = ComputeParaxial(lens);
  auto near = [&](double got, double want, const char* name) {
    EXPECT_NEAR(got, want, 1e-9 * std::abs(want)) << what << ": " << name;
  };
  near(d.efl, e.efl, "EFL");
  near(d.bfl, e.bfl, "BFL");
  near(d.ffl, e.ffl, "FFL");
  near(d.entrance_pupil_position, e.ep_position, "entrance pupil position");
  near(d.entrance_pupil_diameter, e.ep_diameter, "entrance pupil diameter");
  near(d.exit_pupil_position, e.xp_position, "exit pupil position");
  near(d.exit_pupil_diameter, e.xp_diameter, "exit pupil diameter");
  near(d.fnumber, e.efl / e.ep_diameter, "f-number");
}

TEST(StopInGlass, PbrtFilesAreReadWithTheHandComputedFirstOrderData) {
  test::LogCapture log;
  LensPrescription a = ParsePbrtLens(kSinglet, "a.dat");
  ASSERT_EQ(a.StopIndex(), 1);
  EXPECT_TRUE(a.surfaces[1].medium) << "the stop lies in glass";
  ExpectParaxial(a, kSingletByHand, "singlet");
  EXPECT_NEAR(ComputeParaxial(a).fnumber, 2.5, 1e-12);
  EXPECT_FALSE(log.Has("a.dat")) << "the same glass on both sides needs no warning: " << log.Text();
  // B's stop parts two media: pbrt-v4 would not refract there; Objektiv does, and says so.
  LensPrescription b = ParsePbrtLens(kDoublet, "b.dat");
  ExpectParaxial(b, DoubletByHand(), "doublet");
  EXPECT_TRUE(log.Has("b.dat:3: the stop row's index 1.7 differs from the medium before it (1.5)")) << log.Text();
  EXPECT_EQ(log.Count("b.dat"), 1);
}

// Real rays close to the axis (heights h from 0.4 down to 0.05 mm) cross the axis ever closer
// to the paraxial focus, as spherical aberration's h^2: the double tracer and the batch tracer
// both refract (or not) at the stop as the paraxial optics does.
TEST(StopInGlass, RealRaysNearTheAxisMeetTheParaxialFocus) {
  for (const char* text : {kSinglet, kDoublet}) {
    LensPrescription lens = ParsePbrtLens(text, "lens.dat");
    const double bfl = ComputeParaxial(lens).bfl;
    LensSystem exact(lens);
    exact.SetBackFocus(bfl);
    BatchLensTracer fast(exact);
    const double last_z = exact.VertexZ(int(lens.surfaces.size()) - 1), focus_z = last_z + bfl;
    const std::vector<double> heights = {0.4, 0.2, 0.1, 0.05};
    RayBatch batch;
    for (double h : heights) batch.Push({0, float(h), -10, 0, 0, 1, 587.5618f});
    fast.TraceFromObject(batch);
    std::vector<double> miss;  // axis crossing minus the paraxial focus, mm
    for (size_t k = 0; k < heights.size(); ++k) {
      TraceResult r = TraceFromObject(exact, {{0, heights[k], -10}, {0, 0, 1}}, 587.5618);
      ASSERT_TRUE(r.ray && batch.alive[k]) << text << " h " << heights[k];
      double crossing = r.ray->o.z - r.ray->o.y / r.ray->d.y * r.ray->d.z;
      miss.push_back(crossing - focus_z);
      // The batch tracer's ray at the film agrees with the double tracer's.
      double s = (exact.FilmZ() - batch.oz[k]) / batch.dz[k];
      double y_fast = batch.oy[k] + s * batch.dy[k];
      double y_exact = r.ray->o.y + (exact.FilmZ() - r.ray->o.z) / r.ray->d.z * r.ray->d.y;
      EXPECT_NEAR(y_fast, y_exact, 1e-4) << text << " h " << heights[k];
    }
    EXPECT_LT(std::abs(miss[0]), 0.05) << text;
    // Quadratic in h: halving h quarters the miss (within 10%), down to the smallest height.
    for (size_t k = 1; k < miss.size(); ++k)
      EXPECT_NEAR(miss[k] / miss[k - 1], 0.25, 0.025) << text << " h " << heights[k] << " miss " << miss[k];
  }
}

// The same doublet written as a native .lens file and as a Zemax file: each reader makes the
// plane stop surface the stop itself, in its medium, with the same first-order data.
TEST(StopInGlass, NativeAndZemaxFilesExpressTheSameLens) {
  LensPrescription native = ParseNativeLens("surface 50 4 n=1.5 12\nstop 4 n=1.7 10\nsurface -60 0 air 12\n", "b.lens");
  ExpectParaxial(native, DoubletByHand(), "native");
  // Zemax model glasses (nd 1.5 and 1.7) at the d line, where the paraxial data are taken.
  LensPrescription zemax = ParseZemaxLens(
      "SURF 0\n DISZ INFINITY\nSURF 1\n CURV 0.02\n DISZ 4\n GLAS ___BLANK 1 0 1.5 50\n DIAM 12\n"
      "SURF 2\n STOP\n DISZ 4\n GLAS ___BLANK 1 0 1.7 50\n DIAM 10\nSURF 3\n CURV -0.016666666666666666\n DISZ 0\n DIAM 12\n"
      "SURF 4\n DISZ 0\n DIAM 12\n",
      "b.zmx");
  ASSERT_EQ(zemax.surfaces.size(), 3u) << "no extra iris for a plane stop surface";
  EXPECT_EQ(zemax.StopIndex(), 1);
  ExpectParaxial(zemax, DoubletByHand(), "zemax");
}

// The layout draws the singlet as one element (the stop inside it is no face of it).
TEST(StopInGlass, LayoutDrawsOneElementAcrossTheStop) {
  LensPrescription lens = ParsePbrtLens(kSinglet, "a.dat");
  LensSystem tracer(lens);
  tracer.SetBackFocus(ComputeParaxial(lens).bfl);
  std::string svg = PlotLensLayout(tracer, {0, 5}).ToString();
  EXPECT_EQ(test::Occurrences(svg, "<polygon"), 1);
  EXPECT_NE(svg.find("<polyline"), std::string::npos) << "ray fans are drawn";
}

// The realistic camera renders through the doublet: under a uniform sky of radiance 1 a film
// point on the axis records 4 sin^2(theta) (LensCameraSettings: 4/pi times the irradiance
// pi sin^2(theta) of a round cone), theta the steepest ray from the film's centre that gets
// through the lens at the camera's focus, found here with the double tracer.
TEST(StopInGlass, RealisticCameraRendersThroughIt) {
  const std::string path = (std::filesystem::temp_directory_path() / "objektiv_stop_in_glass.dat").string();
  std::ofstream(path) << kDoublet;
  auto r = test::RenderXml(fmt::format(R"(<scene version="3.0.0">
  <sensor type="realistic">
    <string name="lens" value="{}"/>
    <boolean name="transmission" value="false"/>
    <float name="sensor_width" value="0.5"/>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/>
      <rfilter type="box"/></film>
  </sensor>
  <emitter type="constant"><float name="radiance" value="1"/></emitter>
</scene>)",
                                       path));
  std::remove(path.c_str());
  LensPrescription lens = ParsePbrtLens(kDoublet, "b.dat");
  LensSystem t(lens);
  t.SetBackFocus(FocusLens(t, INFINITY).back_focus);
  double lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) {
    double s = 0.5 * (lo + hi);
    (TraceFromFilm(t, {{0, 0, t.FilmZ()}, {0, s, -std::sqrt(1 - s * s)}}, 587.5618).ray ? lo : hi) = s;
  }
  const double expected = 4 * lo * lo;  // about 1 / (2.3 f-number)^2
  for (int c = 0; c < 3; ++c) {
    auto m = test::ChannelMean(r.image, c);
    // The film spans 0.3 degrees: cos^4 differs from 1 by 1e-5. 3e-3: the RGB round trip.
    EXPECT_NEAR(m.mean, expected, 4 * m.se + 3e-3 * expected) << "channel " << c;
  }
  EXPECT_GT(r.stats.CameraPassRate(), 0.5);
  EXPECT_EQ(r.stats.nan_count, 0u);
}

}  // namespace
}  // namespace objektiv
