// A lens that looks into a medium other than air (an underwater port, an immersion objective):
// first-order optics against the single-surface closed forms, real rays, the camera's
// radiance (n^2 L is unchanged along a ray), and the readers.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "base/rng.h"
#include "camera/lens_camera_setup.h"
#include "camera/realistic_camera.h"
#include "optics/lens_file.h"
#include "optics/lens_tracer.h"
#include "optics/paraxial.h"
#include "optics/zemax_lens.h"

namespace objektiv {
namespace {

LensPrescription Parse(const std::string& text) { return ParseNativeLens(text, "test.lens", GlassCatalog::Default()); }

constexpr double kWater = 1.333, kGlass = 1.5;

// A sphere of radius 50 from water into glass, the stop 5 mm inside the glass, a flat face
// into air: the only power is the sphere's, phi = (1.5 - 1.333) / 50.
const char* kDome =
    "object_medium: n=1.333\n"
    "surface 50 5 n=1.5 20\n"
    "stop 5 n=1.5 10\n"
    "surface inf 100 air 20\n";

TEST(ObjectMedium, FirstOrderDataAreTheSingleSurfaces) {
  const LensSystem lens(Parse(kDome));
  const ParaxialData p = lens.paraxial();
  const double phi = (kGlass - kWater) / 50;
  EXPECT_NEAR(p.object_index, kWater, 1e-12);
  EXPECT_NEAR(p.efl, 1 / phi, 1e-9);                   // image side, in air
  EXPECT_NEAR(p.ffl, -kWater / phi, 1e-9);             // the front focus, n0 / phi in front
  EXPECT_NEAR(p.front_principal_plane, 0, 1e-9);       // at the sphere's vertex
  // The entrance pupil: the stop, 5 mm inside the glass, seen through the sphere from the
  // water: n0 / s' = n / s + (n0 - n) / R seen backward, s' = 4.4933 mm behind the vertex,
  // magnified by (n s') / (n0 s).
  const double s_prime = kWater / ((kWater - kGlass) / -50 + kGlass / -5);
  EXPECT_NEAR(p.entrance_pupil_position, -s_prime, 1e-9);
  EXPECT_NEAR(p.entrance_pupil_diameter, 20 * (kGlass * s_prime) / (kWater * -5), 1e-9);
  // Real rays: from the front focus, in the water, a ray near the axis leaves parallel to it.
  TraceResult t = TraceFromObject(lens, {{0, 0, p.ffl}, Normalize(Vec3d(0, 1e-4, 1))}, 587.6);
  ASSERT_TRUE(t.ray);
  EXPECT_NEAR(t.ray->d.y / t.ray->d.z, 0, 1e-10);
  // A beam parallel to the axis in the water meets at the paraxial back focus.
  TraceResult b = TraceFromObject(lens, {{0, 1e-4, -5}, {0, 0, 1}}, 587.6);
  ASSERT_TRUE(b.ray);
  const double z = b.ray->o.z - b.ray->o.y * b.ray->d.z / b.ray->d.y;
  EXPECT_NEAR(z - lens.VertexZ(2), p.bfl, 1e-6);
}

TEST(ObjectMedium, TheCameraSeesTheScenesRadianceOverNSquared) {
  // A flat port (water to air) in front of a lens: from the film the two cameras trace the
  // same rays up to the port; beyond it, in the water, radiance L there is n0^2 times the
  // L / n0^2 it becomes in the air (n^2 L is unchanged through lossless refraction). Under a
  // uniform sky the film irradiance is the air lens's over n0^2, sample by sample.
  const std::string lens =
      "surface inf 2 air 30\n"
      "surface 60 6 n=1.5168 12\n"
      "surface -60 2 air 12\n"
      "stop 50 air 8\n";
  LensCameraSettings settings;
  settings.sensor_width = settings.sensor_height = 24;
  settings.transmission = false;  // no Fresnel loss at the port: the radiance alone
  LensSystem air(Parse(lens)), water(Parse("object_medium: n=1.333\n" + lens));
  air.SetBackFocus(air.paraxial().bfl);
  water.SetBackFocus(air.paraxial().bfl);
  const RealisticCamera in_air(Transform(), 64, 64, air, settings), in_water(Transform(), 64, 64, water, settings);
  PCG32 rng(7, 1);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const CameraSample s{Vec2f(32 + 20 * rng.UniformFloat() - 10, 32), Vec2f(rng.UniformFloat(), rng.UniformFloat())};
    SampledWavelengths l1 = SampledWavelengths::Single(550), l2 = l1;
    const std::optional<CameraRay> a = in_air.GenerateRay(s, l1), w = in_water.GenerateRay(s, l2);
    ASSERT_EQ(a.has_value(), w.has_value()) << i;
    if (!a) continue;
    ++compared;
    EXPECT_NEAR(w->weight[0], a->weight[0] / (kWater * kWater), 1e-5 * a->weight[0]) << i;
    // Beyond the port the ray is bent toward the axis: sin in water = sin in air / n0.
    const double sin_air = std::hypot(a->ray.d.x, a->ray.d.y), sin_water = std::hypot(w->ray.d.x, w->ray.d.y);
    EXPECT_NEAR(sin_water, sin_air / kWater, 1e-5) << i;
  }
  EXPECT_GT(compared, 1000);
}

TEST(ObjectMedium, ReadersAndModels) {
  // Zemax: the object surface's glass.
  const std::string zmx =
      "SURF 0\n  TYPE STANDARD\n  GLAS ___BLANK 1 0 1.333 55.8\n  DISZ INFINITY\n"
      "SURF 1\n  STOP\n  TYPE STANDARD\n  CURV 0.02\n  GLAS N-BK7\n  DISZ 5\n  DIAM 10\n"
      "SURF 2\n  TYPE STANDARD\n  CURV 0\n  DISZ 80\n  DIAM 10\n"
      "SURF 3\n  TYPE STANDARD\n  DISZ 0\n  DIAM 10\n";
  const LensPrescription z = ParseZemaxLens(zmx, "port.zmx", GlassCatalog::Default());
  ASSERT_TRUE(z.object_medium);
  EXPECT_NEAR(z.object_medium->Index(587.5618), 1.333, 1e-6);
  EXPECT_NEAR(ComputeParaxial(z).object_index, 1.333, 1e-6);
  // A plane without a semi-diameter right after the water is no dummy: it parts water from
  // air (it was dropped as one, as a plane in air would be).
  const std::string port = "SURF 0\n  GLAS ___BLANK 1 0 1.333 55.8\n  DISZ INFINITY\n"
                           "SURF 1\n  TYPE STANDARD\n  CURV 0\n  DISZ 2\n  DIAM 0\n" + zmx.substr(zmx.find("SURF 1\n  STOP"));
  try {
    ParseZemaxLens(port, "port.zmx", GlassCatalog::Default());
    ADD_FAILURE() << "a water-air plane without a semi-diameter was dropped";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("port.zmx:4: surface 1 has no semi-diameter"), std::string::npos) << e.what();
  }
  // Native: once only; the paraxial camera models refuse it (their nodal points would be
  // wrong).
  EXPECT_THROW(Parse(std::string("object_medium: n=1.333\n") + kDome), InputError);
  LensCameraSpec spec;
  spec.lens = Parse(kDome);
  spec.model = LensModel::kThin;
  try {
    MakeLensCamera(Transform(), 32, 32, spec);
    ADD_FAILURE() << "thin model accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("use lens_model real"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace objektiv
