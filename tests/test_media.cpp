// Homogeneous participating media (scene/medium.h) and their phase functions, in the path
// tracer: the phase functions' normalisation and sampling, the spectral free-flight estimator
// against exp(-sigma_t d) per wavelength, a camera looking at a lamp through a slab of fog, the
// white furnace, next-event estimation against phase sampling alone, a glass of milk against
// the same scene with its boundary made null, and the loader's errors.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "base/rng.h"
#include "chi2.h"
#include "image_estimates.h"
#include "log_capture.h"
#include "render_helpers.h"
#include "sanitizer_build.h"
#include "scene/medium.h"

namespace objektiv {
namespace {

using test::ChannelMean;
using test::RenderXml;

// --- phase functions --------------------------------------------------------------------

// Integral of p(wo, .) over the sphere by the midpoint rule in cos theta (p depends on theta
// alone; the peak of g = 0.9 needs the fine grid).
double PhaseIntegral(float g) {
  constexpr int kSteps = 200000;
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double cos_theta = -1 + (i + 0.5) * 2.0 / kSteps;
    sum += HenyeyGreenstein(float(cos_theta), g) * 2 * M_PI * (2.0 / kSteps);
  }
  return sum;
}

TEST(Media, PhaseFunctionsIntegrateToOne) {
  for (float g : {0.f, 0.3f, -0.5f, 0.7f, 0.9f, -0.9f}) EXPECT_NEAR(PhaseIntegral(g), 1.0, 1e-4) << "g " << g;
  // Isotropic is 1 / (4 pi) everywhere; g > 0 scatters forward (along -wo).
  const HGPhaseFunction iso(0), fwd(0.7f);
  const Vec3f wo = Normalize(Vec3f(0.3f, -0.4f, 0.8f));
  EXPECT_NEAR(iso.p(wo, Vec3f(0, 0, 1)), 1 / (4 * M_PI), 1e-7);
  EXPECT_GT(fwd.p(wo, -wo), 10 * fwd.p(wo, wo));
  // Reciprocal.
  const Vec3f wi = Normalize(Vec3f(-0.2f, 0.9f, 0.1f));
  EXPECT_FLOAT_EQ(fwd.p(wo, wi), fwd.p(wi, wo));
}

TEST(Media, PhaseSamplingMatchesItsDensity) {
  for (float g : {0.f, 0.4f, -0.6f, 0.85f}) {
    const HGPhaseFunction phase(g);
    // wo points back along the arriving ray: here the ray travels toward +x, the chi-square
    // grid's pole, so the forward peak sits in its first bins.
    const Vec3f wo(-1, 0, 0);
    bool consistent = true;
    auto sample = [&](PCG32& rng) -> std::optional<Vec3f> {
      const PhaseSample s = phase.Sample(wo, Vec2f(rng.UniformFloat(), rng.UniformFloat()));
      if (std::abs(s.p - phase.p(wo, s.wi)) > 1e-3f * s.p + 1e-6f) consistent = false;
      return s.wi;
    };
    auto pdf = [&](const Vec3f& wi) { return double(phase.Pdf(wo, wi)); };
    const test::Chi2Result r = test::Chi2TestDirections(sample, pdf, 200000, 16, 16);
    EXPECT_GT(r.p_value, 1e-3) << "g " << g << ": " << r.Describe();
    EXPECT_NEAR(r.pdf_integral, 1.0, 0.02) << "g " << g;
    EXPECT_TRUE(consistent) << "g " << g << ": the sample's p is not p(wo, wi)";
  }
  // The test can fail: a sampler of the isotropic directions against the pdf of g = 0.5.
  const HGPhaseFunction iso(0), hg(0.5f);
  auto wrong = [&](PCG32& rng) -> std::optional<Vec3f> {
    return iso.Sample(Vec3f(-1, 0, 0), Vec2f(rng.UniformFloat(), rng.UniformFloat())).wi;
  };
  auto pdf = [&](const Vec3f& wi) { return double(hg.Pdf(Vec3f(-1, 0, 0), wi)); };
  EXPECT_LT(test::Chi2TestDirections(wrong, pdf, 200000, 16, 16).p_value, 1e-6);
}

// --- free-flight sampling -----------------------------------------------------------------

// With albedo 0 a path through a segment of length d survives or dies, and a survivor's
// estimate is its weight over the mean of its density ratios (the spectral MIS, scene/medium.h),
// the sampling wavelength chosen at random: its mean is the transmittance exp(-sigma_t d), at
// every wavelength of the bundle on its own, also where sigma_t differs by orders of magnitude
// between them or is 0 at some.
TEST(Media, FreeFlightEstimatesTheTransmittanceOfEveryWavelength) {
  // sigma_t: 0 below 450 nm, rising to 6 per unit at 700 nm.
  const Spectrum sigma_t = Spectrum::Tabulated({360, 450, 700, 830}, {0, 0, 6, 6});
  // An albedo above 0, or no distance would be sampled at all (the pure absorber, below).
  const HomogeneousMedium medium = HomogeneousMedium::FromExtinction(sigma_t, Spectrum(0.5f), 1, HGPhaseFunction(0));
  ASSERT_TRUE(medium.Scatters());
  PCG32 rng(7, 3);
  for (float d : {0.1f, 0.5f, 2.f}) {
    for (int trial = 0; trial < 4; ++trial) {
      const SampledWavelengths lambda = SampledWavelengths::SampleUniform(rng.UniformFloat());
      constexpr int kN = 1000000;
      double sum[kSpectrumSamples] = {}, sum2[kSpectrumSamples] = {};
      for (int i = 0; i < kN; ++i) {
        const int channel = std::min(int(rng.UniformFloat() * kSpectrumSamples), kSpectrumSamples - 1);
        const MediumSample ms = medium.SampleDistance(d, lambda, channel, rng.UniformFloat());
        ASSERT_FALSE(ms.weight.HasNaN() || ms.weight.HasInf() || ms.ratio.HasNaN() || ms.ratio.HasInf());
        ASSERT_GT(ms.ratio.Average(), 0.f);
        const SampledSpectrum w = ms.scattered ? SampledSpectrum(0.f) : ms.weight / ms.ratio.Average();
        for (int k = 0; k < kSpectrumSamples; ++k) sum[k] += w[k], sum2[k] += double(w[k]) * w[k];
      }
      const SampledSpectrum st = sigma_t.Sample(lambda);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        const double mean = sum[k] / kN, se = std::sqrt(std::max(0.0, sum2[k] / kN - mean * mean) / kN);
        const double expected = std::exp(-double(st[k]) * d);
        EXPECT_NEAR(mean, expected, 5 * se + 1e-6) << "lambda " << lambda[k] << " sigma_t " << st[k] << " d " << d;
        // Able to tell an error of 1% of the light that enters.
        EXPECT_LT(5 * se, 0.01);
      }
    }
  }
  // The closed form itself.
  const SampledWavelengths lambda = SampledWavelengths::SampleUniform(0.3f);
  const SampledSpectrum tr = medium.Transmittance(1.5f, lambda), st = medium.SigmaT(lambda);
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_FLOAT_EQ(tr[k], std::exp(-st[k] * 1.5f));
  const SampledSpectrum far = medium.Transmittance(std::numeric_limits<float>::infinity(), lambda);
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_EQ(far[k], st[k] > 0 ? 0.f : 1.f);
}

// A medium that only absorbs samples no distance: every segment passes with exactly its
// transmittance, whatever the random number (albedo 0, or sigma_s 0 given as coefficients).
TEST(Media, PureAbsorberPassesEverySegmentWithItsTransmittance) {
  const Spectrum sigma_t = Spectrum::Tabulated({360, 450, 700, 830}, {0, 0, 6, 6});
  const HomogeneousMedium by_albedo = HomogeneousMedium::FromExtinction(sigma_t, Spectrum(0.f), 1, HGPhaseFunction(0));
  const HomogeneousMedium by_coefficients =
      HomogeneousMedium::FromCoefficients(sigma_t, Spectrum(0.f), 2, HGPhaseFunction(0.5f));
  EXPECT_FALSE(by_albedo.Scatters());
  EXPECT_FALSE(by_coefficients.Scatters());
  EXPECT_TRUE(HomogeneousMedium::FromCoefficients(Spectrum(0.f), Spectrum(0.1f), 1, HGPhaseFunction(0)).Scatters());
  const SampledWavelengths lambda = SampledWavelengths::SampleUniform(0.6f);
  for (const HomogeneousMedium* m : {&by_albedo, &by_coefficients}) {
    for (float u : {0.f, 0.5f, 0.999f}) {
      for (int channel = 0; channel < kSpectrumSamples; ++channel) {
        const MediumSample ms = m->SampleDistance(0.7f, lambda, channel, u);
        EXPECT_FALSE(ms.scattered);
        EXPECT_EQ(ms.distance, 0.7f);
        const SampledSpectrum tr = m->Transmittance(0.7f, lambda);
        for (int k = 0; k < kSpectrumSamples; ++k) {
          EXPECT_EQ(ms.weight[k], tr[k]);
          EXPECT_EQ(ms.ratio[k], 1.f);
        }
      }
    }
  }
}

// --- whole renders --------------------------------------------------------------------------

std::string Sensor(int spp, int size = 24, const std::string& extra = "", int seed = 0, float fov = 30) {
  return fmt::format(R"(
  <sensor type="perspective">
    <float name="fov" value="{}"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/>
      <rfilter type="box"/></film>{}
  </sensor>)",
                     fov, spp, seed, size, size, extra);
}

// A camera sees a lamp of radiance 1 through a unit slab of fog (a cube with a null boundary)
// that absorbs only: every pixel reads exp(-sigma_t). A narrow field of view (2 degrees): a ray
// at angle theta crosses 1 / cos(theta) of the slab, at 30 degrees 2.3% more on the average.
TEST(Media, CameraSeesALampThroughFogAttenuatedByItsTransmittance) {
  for (float sigma : {0.4f, 1.5f}) {
    const std::string xml = fmt::format(R"(<scene version="3.0.0">{}
  <shape type="rectangle"><transform name="to_world"><scale value="10"/><translate z="-3"/></transform>
    <emitter type="area"><float name="radiance" value="1"/></emitter></shape>
  <shape type="cube"><transform name="to_world"><scale x="5" y="5" z="0.5"/></transform>
    <bsdf type="null"/>
    <medium type="homogeneous" name="interior"><float name="sigma_t" value="{}"/><float name="albedo" value="0"/></medium>
  </shape>
</scene>)",
                                        Sensor(256, 16, "", 0, 2), sigma);
    const test::RenderResult r = RenderXml(xml);
    for (int c = 0; c < 3; ++c) {
      const test::MeanSe m = ChannelMean(r.image, c);
      // 3e-3: the RGB round trip of the constant illuminant (as the furnace tests).
      EXPECT_NEAR(m.mean, std::exp(-sigma), 4 * m.se + 3e-3) << "sigma_t " << sigma << " channel " << c;
      EXPECT_LT(4 * m.se, 0.05 * std::exp(-sigma));
    }
    EXPECT_EQ(r.stats.nan_count, 0u);
  }
}

// A slab that only absorbs takes no random decision: each pixel of the camera's view of the lamp
// through it is the same pixel without the slab times exp(-sigma_t) (the same wavelengths and
// lens samples; only the spectral sampling's colour noise, common to both, is left). Free-flight
// sampling would let a pixel's 4 samples through all or nothing (ratios 0, 1/4, ...). A field of
// view of 2 degrees: the rays cross at most 1 / cos(1.4 deg) = 1 + 3e-4 of the slab, which moves
// the ratio by at most 1.1e-4.
TEST(Media, PureAbsorberDimsEveryPixelByItsTransmittanceWithoutNoise) {
  const float sigma = 0.8f;
  auto render = [&](const std::string& slab) {
    return RenderXml(fmt::format(R"(<scene version="3.0.0">{}
  <shape type="rectangle"><transform name="to_world"><scale value="10"/><translate z="-3"/></transform>
    <emitter type="area"><rgb name="radiance" value="1, 0.7, 0.4"/></emitter></shape>{}
</scene>)",
                                 Sensor(4, 12, "", 0, 2), slab));
  };
  const test::RenderResult open = render("");
  const test::RenderResult slab = render(fmt::format(R"(
  <shape type="cube"><transform name="to_world"><scale x="5" y="5" z="0.5"/></transform>
    <bsdf type="null"/>
    <medium type="homogeneous" name="interior"><float name="sigma_a" value="{}"/></medium>
  </shape>)",
                                                     sigma));
  double worst = 0;
  for (int y = 0; y < open.image.height; ++y)
    for (int x = 0; x < open.image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float a = open.image.At(x, y, c), b = slab.image.At(x, y, c);
        ASSERT_GT(a, 0.f);
        worst = std::max(worst, std::abs(double(b) / a - std::exp(-double(sigma))));
      }
  EXPECT_LT(worst, 1.5e-4) << "largest deviation of a pixel's ratio from exp(-sigma_t)";
}

// A medium inside a surface that lets no light through is never entered: said, with its line;
// inside glass, a null boundary or a blend holding glass, nothing is said.
TEST(Media, AMediumInsideAnOpaqueSurfaceIsWarnedAbout) {
  auto warnings = [](const std::string& bsdf) {
    test::LogCapture log;
    LoadSceneFromString(fmt::format(R"(<scene version="3.0.0">{}
  <shape type="sphere">{}
    <medium type="homogeneous" name="interior"><float name="sigma_t" value="1"/></medium>
  </shape>
</scene>)",
                                    Sensor(1, 4), bsdf),
                        "opaque.xml", {});
    return log.Text();
  };
  const std::string diffuse = warnings(R"(<bsdf type="diffuse"/>)");
  EXPECT_NE(diffuse.find("opaque.xml:"), std::string::npos) << diffuse;
  EXPECT_NE(diffuse.find("interior medium is never entered"), std::string::npos) << diffuse;
  for (const char* opaque : {R"(<bsdf type="bumpmap"><texture type="checkerboard"/><bsdf type="conductor"/></bsdf>)",
                             R"(<bsdf type="principled"/>)",  // spec_trans 0 by default
                             R"(<bsdf type="dielectric"><rgb name="specular_transmittance" value="0"/></bsdf>)"})
    EXPECT_NE(warnings(opaque).find("never entered"), std::string::npos) << opaque;
  for (const char* passes : {R"(<bsdf type="dielectric"/>)", R"(<bsdf type="null"/>)", R"(<bsdf type="thindielectric"/>)",
                             R"(<bsdf type="roughdielectric"/>)",
                             R"(<bsdf type="principled"><float name="spec_trans" value="0.5"/></bsdf>)",
                             R"(<bsdf type="blendbsdf"><bsdf type="diffuse"/><bsdf type="dielectric"/></bsdf>)"})
    EXPECT_EQ(warnings(passes).find("never entered"), std::string::npos) << passes;
}

// A phase function or sample_emitters on a medium that scatters nowhere changes nothing: said.
TEST(Media, ScatteringSettingsOfAPureAbsorberAreWarnedAbout) {
  auto warnings = [](const std::string& medium) {
    test::LogCapture log;
    LoadSceneFromString(fmt::format(R"(<scene version="3.0.0">{}
  <shape type="cube"><bsdf type="null"/>
    <medium type="homogeneous" name="interior">{}</medium>
  </shape>
</scene>)",
                                    Sensor(1, 4), medium),
                        "absorber.xml", {});
    return log.Text();
  };
  const std::string both = warnings(R"(<float name="sigma_a" value="2"/><phase type="hg"><float name="g" value="0.5"/></phase>
      <boolean name="sample_emitters" value="false"/>)");
  EXPECT_EQ(test::Occurrences(both, "changes nothing"), 2) << both;
  EXPECT_NE(both.find("absorber.xml:"), std::string::npos) << both;
  EXPECT_NE(both.find("only absorbs (it scatters nowhere), so its <phase> changes nothing"), std::string::npos) << both;
  EXPECT_NE(both.find("so its 'sample_emitters' changes nothing"), std::string::npos) << both;
  // Albedo 0 is a pure absorber too.
  EXPECT_NE(warnings(R"(<float name="sigma_t" value="2"/><float name="albedo" value="0"/><phase type="isotropic"/>)")
                .find("so its <phase> changes nothing"),
            std::string::npos);
  // A medium that scatters uses both: nothing said.
  EXPECT_EQ(warnings(R"(<float name="sigma_t" value="2"/><phase type="hg"/><boolean name="sample_emitters" value="false"/>)")
                .find("changes nothing"),
            std::string::npos);
}

// The same slab with a coloured sigma_t, against Beer-Lambert absorption inside a dielectric
// that does not refract (int_ior = ext_ior): the same exp(-sigma_t(lambda) d) per wavelength
// from a different code path (render/direct_lighting.h, SegmentTransmittance).
TEST(Media, ColouredFogSlabIsAnAbsorbingSlabOfTheSameCoefficients) {
  SKIP_UNDER_SANITIZERS("CameraSeesALampThroughFogAttenuatedByItsTransmittance");
  auto scene = [](const std::string& slab) {
    return [slab](int seed) {
      return fmt::format(R"(<scene version="3.0.0">{}
  <shape type="rectangle"><transform name="to_world"><scale value="10"/><translate z="-3"/></transform>
    <emitter type="area"><rgb name="radiance" value="1, 0.8, 0.6"/></emitter></shape>
  <shape type="cube"><transform name="to_world"><scale x="5" y="5" z="0.5"/></transform>{}</shape>
</scene>)",
                         Sensor(32, test::kSize, "", seed), slab);
    };
  };
  const std::string rgb = R"(<rgb name="{}" value="0.3, 1.2, 2.5"/>)";
  const test::Estimate fog = test::Estimated(scene(R"(<bsdf type="null"/><medium type="homogeneous" name="interior">)" +
                                                   fmt::format(fmt::runtime(rgb), "sigma_t") +
                                                   R"(<float name="albedo" value="0"/></medium>)"));
  const test::Estimate glass = test::Estimated(
      scene(R"(<bsdf type="dielectric"><float name="int_ior" value="1.000277"/><float name="ext_ior" value="1.000277"/>)" +
            fmt::format(fmt::runtime(rgb), "absorption") + "</bsdf>"));
  test::ExpectSameImage(glass, fog, 0.02, "fog slab against absorbing dielectric slab");
}

// A white furnace: a sphere of fog that scatters and never absorbs (albedo 1), under an
// environment of radiance 1, seen from outside and from inside, with a coloured sigma_t (the
// spectral free-flight weights), forward and backward scattering, with and without next-event
// estimation: every pixel reads 1.
TEST(Media, WhiteFurnaceOfScatteringFogConservesEnergy) {
  struct Case {
    const char* what;
    std::string sigma, phase;
    bool inside, nee;
  };
  const Case cases[] = {
      {"isotropic, grey", R"(<float name="sigma_t" value="2"/>)", R"(<phase type="isotropic"/>)", false, true},
      {"hg 0.7, coloured", R"(<rgb name="sigma_t" value="0.5, 2, 6"/>)",
       R"(<phase type="hg"><float name="g" value="0.7"/></phase>)", false, true},
      {"hg -0.4, coloured, phase sampling only", R"(<rgb name="sigma_t" value="3, 1, 0.2"/>)",
       R"(<phase type="hg"><float name="g" value="-0.4"/></phase>)", false, false},
      {"camera inside, hg 0.5", R"(<float name="sigma_t" value="1.5"/>)",
       R"(<phase type="hg"><float name="g" value="0.5"/></phase>)", true, true},
  };
  for (const Case& c : cases) {
    const std::string medium = fmt::format(
        R"(<medium type="homogeneous" id="fog">{}<float name="albedo" value="1"/><boolean name="sample_emitters" value="{}"/>{}</medium>)",
        c.sigma, c.nee, c.phase);
    const std::string xml = fmt::format(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="-1"/></integrator>{}
  {}
  <emitter type="constant"><float name="radiance" value="1"/></emitter>
  <shape type="sphere"><float name="radius" value="{}"/><bsdf type="null"/><ref name="interior" id="fog"/></shape>
</scene>)",
                                        medium, Sensor(512, 16, c.inside ? R"(<ref id="fog"/>)" : ""),
                                        c.inside ? 5 : 1);
    const test::RenderResult r = RenderXml(xml);
    for (int ch = 0; ch < 3; ++ch) {
      const test::MeanSe m = ChannelMean(r.image, ch);
      EXPECT_NEAR(m.mean, 1.0, 4 * m.se + 3e-3) << c.what << " channel " << ch << " se " << m.se;
      EXPECT_LT(4 * m.se, 0.03) << c.what;
    }
    EXPECT_EQ(r.stats.nan_count, 0u) << c.what;
    EXPECT_EQ(r.stats.inf_count, 0u) << c.what;
  }
}

// The furnace can fail: fog that absorbs a little (albedo 0.9) is visibly darker than 1.
TEST(Media, FurnaceSeesAbsorption) {
  const std::string xml = fmt::format(R"(<scene version="3.0.0">{}
  <emitter type="constant"><float name="radiance" value="1"/></emitter>
  <shape type="sphere"><float name="radius" value="1"/><bsdf type="null"/>
    <medium type="homogeneous" name="interior"><float name="sigma_t" value="2"/><float name="albedo" value="0.9"/></medium>
  </shape>
</scene>)",
                                      Sensor(64, 16, "", 0, 20));
  const test::MeanSe m = ChannelMean(RenderXml(xml).image, 1);
  EXPECT_LT(m.mean + 4 * m.se, 0.95);
}

// Next-event estimation with MIS and phase sampling alone estimate the same image: a box of
// fog around a lamp and a diffuse floor, lit by an area light, seen from inside the fog.
TEST(Media, NextEventEstimationAgreesWithPhaseSamplingAlone) {
  SKIP_UNDER_SANITIZERS("WhiteFurnaceOfScatteringFogConservesEnergy (with and without NEE)");
  auto scene = [](bool nee) {
    return [nee](int seed) {
      return fmt::format(R"(<scene version="3.0.0">
  <medium type="homogeneous" id="fog"><rgb name="sigma_t" value="0.4, 0.6, 0.9"/><float name="albedo" value="0.85"/>
    <boolean name="sample_emitters" value="{}"/><phase type="hg"><float name="g" value="0.5"/></phase></medium>
  {}
  <shape type="rectangle"><transform name="to_world"><scale value="1.2"/><rotate x="1" angle="90"/><translate y="1.2"/></transform>
    <emitter type="area"><rgb name="radiance" value="2, 1.7, 1.3"/></emitter></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.5, 0.4"/></bsdf></shape>
  <shape type="sphere"><float name="radius" value="5"/><bsdf type="null"/><ref name="interior" id="fog"/></shape>
</scene>)",
                         nee, Sensor(nee ? 48 : 192, test::kSize, R"(<ref id="fog"/>)", seed, 60));
    };
  };
  const test::Estimate with_nee = test::Estimated(scene(true));
  const test::Estimate phase_only = test::Estimated(scene(false));
  test::ExpectSameImage(with_nee, phase_only, 0.03, "fog lit by an area light: NEE+MIS against phase sampling");
}

// --- the loader ---------------------------------------------------------------------------

std::string ErrorOf(const std::string& body, const std::string& integrator = "") {
  const std::string xml = "<scene version=\"3.0.0\">" + integrator + Sensor(1, 4) + "\n" + body + "\n</scene>";
  try {
    LoadSceneFromString(xml, "test.xml", {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kFogShape = R"(<shape type="sphere"><bsdf type="null"/>
  <medium type="homogeneous" name="interior">{}</medium></shape>)";

TEST(Media, BadInputIsAnErrorAtItsLine) {
  // The line of the body's first line: after <scene> and the sensor.
  const std::string sensor = Sensor(1, 4);
  const int body = 2 + int(std::count(sensor.begin(), sensor.end(), '\n'));
  auto fog = [](const std::string& props) { return fmt::format(fmt::runtime(kFogShape), props); };
  struct Case {
    std::string body, integrator, expected;
    int line;
  };
  const Case cases[] = {
      {fog(R"(<float name="sigma_t" value="-1"/>)"), "", "'sigma_t' must be finite and not negative", body + 1},
      {fog(R"(<rgb name="sigma_t" value="1, -0.5, 1"/>)"), "", "'sigma_t' must be finite and not negative", body + 1},
      {fog(R"(<float name="sigma_s" value="1e39"/>)"), "", "'sigma_s' = 1e+39 is too large", body + 1},
      {fog(R"(<float name="albedo" value="1.5"/>)"), "", "albedo must lie in [0, 1]", body + 1},
      {fog(R"(<float name="scale" value="-2"/>)"), "", "scale must be finite and not negative", body + 1},
      {fog(R"(<float name="sigma_t" value="1e30"/><float name="scale" value="1e20"/>)"), "", "is not finite", body + 1},
      {fog(R"(<float name="sigma_t" value="1"/><float name="sigma_a" value="1"/>)"), "", "not both", body + 1},
      {fog(R"(<phase type="hg"><float name="g" value="1"/></phase>)"), "", "g must lie strictly between -1 and 1",
       body + 1},
      {fog(R"(<phase type="hg"><float name="g" value="-1.5"/></phase>)"), "", "g must lie strictly between", body + 1},
      {fog(R"(<phase type="rayleigh"/>)"), "", "unknown phase type 'rayleigh'", body + 1},
      {R"(<medium type="heterogeneous" id="m"/>)", "", "unknown medium type 'heterogeneous'", body},
      {R"(<medium type="homogeneous" id="m"/>)", "", "this <medium> fills nothing", body},
      {R"(<shape type="sphere"><medium type="homogeneous"/></shape>)", "", "needs name=\"interior\"", body},
      {R"(<shape type="sphere"><medium type="homogeneous" name="inside"/></shape>)", "", "not 'inside'", body},
      {R"(<bsdf type="diffuse"><medium type="homogeneous"/></bsdf>)", "", "a <medium> belongs in", body},
      {R"(<shape type="sphere"><phase type="isotropic"/></shape>)", "", "a <phase> belongs in a <medium>", body},
      {R"(<shape type="sphere"><float name="interior" value="1"/></shape>)", "", "must be a <medium>", body},
      {R"(<shape type="sphere"><bsdf type="null"/><emitter type="area"/></shape>)", "", "cannot emit", body},
      {fog(""), R"(<integrator type="whitted"/>)", "'whitted' integrator does not render", 1},
      {fog(""), R"(<integrator type="direct"/>)", "'direct' integrator does not render", 1},
      {fog(""), R"(<integrator type="ptracer"/>)", "'ptracer' integrator does not render", 1},
      {fog(""), R"(<integrator type="path"><boolean name="caustics" value="true"/></integrator>)", "not with caustics",
       1},
      {R"(<shape type="sphere"><bsdf type="null"/></shape>)", R"(<integrator type="whitted"/>)", "null BSDFs", 1},
      {fog(""), R"(<integrator type="path"><boolean name="caustics" value="true"/></integrator>)",
       "'path' integrator with caustics does not render", 1},
      // Rays through a mask's holes would pass its boundary without entering the medium.
      {R"(<shape type="sphere"><bsdf type="mask"><float name="opacity" value="0.5"/><bsdf type="diffuse"/></bsdf>
<medium type="homogeneous" name="interior"/></shape>)",
       "", "cannot have a mask BSDF", body + 1},
      // A null part of a blend or mask: neither a surface nor a boundary.
      {R"(<shape type="sphere"><bsdf type="mask">
<bsdf type="null"/></bsdf></shape>)",
       "", "mask cannot hold a null BSDF", body + 1},
      {R"(<shape type="sphere"><bsdf type="blendbsdf"><bsdf type="diffuse"/>
<bsdf type="null"/></bsdf></shape>)",
       "", "blendbsdf cannot hold a null BSDF", body + 1},
  };
  for (const Case& c : cases) {
    const std::string msg = ErrorOf(c.body, c.integrator);
    EXPECT_EQ(msg.rfind(fmt::format("test.xml:{}:", c.line), 0), 0u) << msg << "\nfor " << c.body;
    EXPECT_NE(msg.find(c.expected), std::string::npos) << msg << "\nfor " << c.body;
  }
  // And what is right loads: both ways of giving the coefficients, a medium the sensor and a
  // shape share, a shape with a medium on either side.
  EXPECT_EQ(ErrorOf(fog(R"(<rgb name="sigma_a" value="0.1, 0.2, 0.3"/><spectrum name="sigma_s" value="400:1, 700:2"/>)")),
            "no error");
  EXPECT_EQ(ErrorOf(R"(<medium type="homogeneous" id="m"/>
    <shape type="sphere"><bsdf type="null"/><ref name="exterior" id="m"/></shape>)"),
            "no error");
}

}  // namespace
}  // namespace objektiv
