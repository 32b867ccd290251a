// Colour science: the CIE tables, D65, colour spaces, RGB-to-spectrum round trips,
// wavelength sampling and the film's XYZ estimator.
#include <gtest/gtest.h>

#include <cmath>

#include "base/cie.h"
#include "base/color_space.h"
#include "base/rng.h"
#include "base/spectrum.h"
#include "render/film.h"

namespace objektiv {
namespace {

TEST(Cie, EqualEnergyWhiteHasEqualTristimulus) {
  // The CIE 1931 functions are normalised so that an equal-energy spectrum has X = Y = Z.
  double x = 0, y = 0, z = 0;
  for (int l = 360; l <= 830; ++l) {
    Vec3f c = CieXyz(float(l));
    x += c.x;
    y += c.y;
    z += c.z;
  }
  EXPECT_NEAR(x / y, 1, 2e-3);
  EXPECT_NEAR(z / y, 1, 2e-3);
  EXPECT_NEAR(CieYIntegral(), 106.857, 0.05);  // 10 nm table sum of y-bar times 10
}

TEST(Cie, D65WhitePointChromaticity) {
  // CIE 15's method for 10 nm tables: sum at the tabulated wavelengths. The standard white
  // point (0.3127, 0.3290) is rounded to 4 decimals and was computed from 1 nm data, so
  // 10 nm summation agrees to about 1e-4; a wrong table entry would show far beyond that.
  Vec3d sum(0.0);
  for (int l = 360; l <= 830; l += 10) sum += Vec3d(CieXyz(float(l))) * double(D65Raw(float(l)));
  double s = sum.x + sum.y + sum.z;
  EXPECT_NEAR(sum.x / s, 0.3127, 1.5e-4);
  EXPECT_NEAR(sum.y / s, 0.3290, 1.5e-4);
  // The renderer integrates the continuous (linearly interpolated) tables instead; its
  // white is what the colour spaces are built on (see ColorSpace.WhiteMapsToOne).
  Vec3d w = D65WhiteXYZ();
  EXPECT_NEAR(w.y, 1, 1e-12);
}

TEST(ColorSpace, WhiteMapsToOne) {
  Vec3f rgb = ColorSpace::Rec709().ToRGB(Vec3f(D65WhiteXYZ()));
  EXPECT_NEAR(rgb.x, 1, 1e-5);
  EXPECT_NEAR(rgb.y, 1, 1e-5);
  EXPECT_NEAR(rgb.z, 1, 1e-5);
  // Standard sRGB matrix entries, to the precision of the CIE tables used.
  const Mat3& m = ColorSpace::Rec709().rgb_to_xyz;
  EXPECT_NEAR(m[0][0], 0.4124, 2e-3);
  EXPECT_NEAR(m[1][1], 0.7152, 2e-3);
  EXPECT_NEAR(m[2][2], 0.9505, 3e-3);
  // ACEScg sees D65 white as (1, 1, 1) after the Bradford adaptation.
  Vec3f aces = ColorSpace::ACEScg().ToRGB(Vec3f(D65WhiteXYZ()));
  EXPECT_NEAR(aces.x, 1, 1e-4);
  EXPECT_NEAR(aces.y, 1, 1e-4);
  EXPECT_NEAR(aces.z, 1, 1e-4);
}

TEST(RgbToSpectrum, RoundTripsEveryColour) {
  PCG32 rng(1, 2);
  float worst = 0;
  for (int i = 0; i < 3000; ++i) {
    Vec3f c(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat());
    Vec3f back = SpectrumToRgb(Spectrum::RgbIlluminant(c));
    worst = std::max(worst, MaxComponent(Abs(back - c)));
  }
  EXPECT_LT(worst, 3e-3);
}

TEST(RgbToSpectrum, ReflectancesStayInUnitInterval) {
  PCG32 rng(3, 4);
  for (int i = 0; i < 2000; ++i) {
    Vec3f c(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat());
    Spectrum s = Spectrum::RgbAlbedo(c);
    for (float l = 360; l <= 830; l += 10) {
      EXPECT_GE(s(l), 0);
      EXPECT_LE(s(l), 1);
    }
  }
  // Grey is exactly flat.
  Spectrum g = Spectrum::RgbAlbedo(Vec3f(0.3f));
  EXPECT_NEAR(g(400), 0.3f, 1e-6);
  EXPECT_NEAR(g(700), 0.3f, 1e-6);
}

TEST(RgbToSpectrum, EmissionRecordsItsRgb) {
  Vec3f back = SpectrumToRgb(Spectrum::RgbIlluminant({17, 12, 4}));
  EXPECT_NEAR(back.x, 17, 0.02);
  EXPECT_NEAR(back.y, 12, 0.02);
  EXPECT_NEAR(back.z, 4, 0.02);
}

// A NaN colour (a texture looked up at a NaN coordinate) is NaN at every wavelength; it
// indexed the table with a NaN cast to int (undefined behaviour, found by fuzz_image).
TEST(RgbToSpectrum, NanColourGivesNanSamples) {
  SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
  for (Vec3f c : {Vec3f(NAN, 0.2f, 0.5f), Vec3f(0.1f, NAN, 0.f), Vec3f(NAN)}) {
    SampledSpectrum s = RgbToSigmoid(c).Sample(lambda);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_TRUE(std::isnan(s[i])) << i;
  }
  EXPECT_TRUE(std::isnan(Spectrum::RgbIlluminant(Vec3f(INFINITY, 1.f, 0.f))(550)));
}

TEST(Illuminants, BlackbodyPeaksAtOneAndFollowsWien) {
  Spectrum b = Spectrum::Blackbody(5000);
  float peak_l = 0, peak = 0;
  for (float l = 360; l <= 830; l += 1)
    if (b(l) > peak) {
      peak = b(l);
      peak_l = l;
    }
  EXPECT_NEAR(peak, 1, 1e-3);
  EXPECT_NEAR(peak_l, 2.8977721e6 / 5000, 1.5);
  // Planck's law at one point (lambda = 500 nm, T = 6000 K), W / (m^2 sr nm).
  EXPECT_NEAR(Blackbody(500, 6000) / 3.17569e4, 1, 1e-4);
}

TEST(Wavelengths, VisibleSamplingPdfIsNormalisedAndInverted) {
  double integral = 0;
  for (int l = 360; l < 830; ++l) integral += VisibleWavelengthsPdf(l + 0.5f);
  EXPECT_NEAR(integral, 1, 1e-4);
  // The inverse CDF: the fraction of the pdf below the sample equals u.
  for (float u : {0.1f, 0.37f, 0.5f, 0.9f}) {
    float l = SampleVisibleWavelength(u);
    double cdf = 0;
    for (double x = 360; x < l; x += 0.01) cdf += VisibleWavelengthsPdf(float(x)) * 0.01;
    EXPECT_NEAR(cdf, u, 1e-3);
  }
}

TEST(Film, XyzEstimatorIsUnbiased) {
  // Averaging the film's estimator over stratified hero samples converges to the XYZ of the spectrum.
  Spectrum s = Spectrum::RgbIlluminant({0.2f, 0.7f, 0.4f});
  const int n = 20000;
  Vec3d sum(0.0);
  for (int i = 0; i < n; ++i) {
    SampledWavelengths w = SampledWavelengths::SampleVisible((i + 0.5f) / n);
    sum += Vec3d(SampledToXYZ(s.Sample(w), w));
  }
  Vec3f rgb = ColorSpace::Rec709().ToRGB(Vec3f(sum / double(n)));
  EXPECT_NEAR(rgb.x, 0.2, 3e-3);
  EXPECT_NEAR(rgb.y, 0.7, 3e-3);
  EXPECT_NEAR(rgb.z, 0.4, 3e-3);
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(Spectrum, TabulatedInterpolatesAndClampsAtTheEnds) {
  Spectrum s = Spectrum::Tabulated({400, 500, 600}, {1, 3, 2});
  EXPECT_FLOAT_EQ(s(450), 2);
  EXPECT_FLOAT_EQ(s(300), 1);
  EXPECT_FLOAT_EQ(s(700), 2);
  EXPECT_FLOAT_EQ(s.Scaled(2)(550), 5);
}
}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {
TEST(Wavelengths, BundleMatchesTheScalarFormulas) {
  // A fine grid over u covers the whole range of the vectorised logarithm, and the ends.
  std::vector<float> us = {0.f, kOneMinusEpsilon};
  for (int k = 0; k < 4000; ++k) us.push_back((k + 0.37f) / 4000);
  for (float u : us) {
    SampledWavelengths w = SampledWavelengths::SampleVisible(u);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      float up = u + float(i) / kSpectrumSamples;
      if (up > 1) up -= 1;
      EXPECT_NEAR(w[i], SampleVisibleWavelength(up), 2e-3f);
      EXPECT_NEAR(w.Pdf(i), VisibleWavelengthsPdf(w[i]), 1e-5f * w.Pdf(i) + 1e-9f);
    }
  }
}
}  // namespace
}  // namespace objektiv

#include "scene/texture.h"

namespace objektiv {
namespace {
TEST(ConstantTexture, DenseTableFollowsTheSpectrum) {
  for (const Spectrum& s : {Spectrum::RgbAlbedo({0.7f, 0.2f, 0.1f}), Spectrum::RgbIlluminant({17, 12, 4}), Spectrum::D65(2)}) {
    ConstantTexture t(s);
    for (float u : {0.f, 0.21f, 0.5f, 0.83f}) {
      SampledWavelengths w = SampledWavelengths::SampleVisible(u);
      SampledSpectrum v = t.Evaluate({0, 0}, w);
      // Linear interpolation at 1 nm of smooth spectra (and the 10 nm D65 table).
      for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(v[i], s(w[i]), 2e-4f * s.MaxValue()) << w[i];
    }
  }
  EXPECT_EQ(ConstantTexture(Spectrum(0.25f)).Evaluate({0, 0}, SampledWavelengths::SampleVisible(0.4f))[2], 0.25f);
}
}  // namespace
}  // namespace objektiv
