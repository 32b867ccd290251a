#include "base/cie.h"

#include <cmath>

namespace objektiv {
namespace {

// CIE 1931 standard colorimetric observer, 360..830 nm in 10 nm steps.
constexpr int kCieCount = 48;
constexpr float kCie[kCieCount][3] = {
    {0.000130f, 0.000004f, 0.000606f}, {0.000415f, 0.000012f, 0.001946f},  // 360, 370
    {0.001368f, 0.000039f, 0.006450f}, {0.004243f, 0.000120f, 0.020050f},  // 380, 390
    {0.014310f, 0.000396f, 0.067850f}, {0.043510f, 0.001210f, 0.207400f},  // 400, 410
    {0.134380f, 0.004000f, 0.645600f}, {0.283900f, 0.011600f, 1.385600f},  // 420, 430
    {0.348280f, 0.023000f, 1.747060f}, {0.336200f, 0.038000f, 1.772110f},  // 440, 450
    {0.290800f, 0.060000f, 1.669200f}, {0.195360f, 0.090980f, 1.287640f},  // 460, 470
    {0.095640f, 0.139020f, 0.812950f}, {0.032010f, 0.208020f, 0.465180f},  // 480, 490
    {0.004900f, 0.323000f, 0.272000f}, {0.009300f, 0.503000f, 0.158200f},  // 500, 510
    {0.063270f, 0.710000f, 0.078250f}, {0.165500f, 0.862000f, 0.042160f},  // 520, 530
    {0.290400f, 0.954000f, 0.020300f}, {0.433450f, 0.994950f, 0.008750f},  // 540, 550
    {0.594500f, 0.995000f, 0.003900f}, {0.762100f, 0.952000f, 0.002100f},  // 560, 570
    {0.916300f, 0.870000f, 0.001650f}, {1.026300f, 0.757000f, 0.001100f},  // 580, 590
    {1.062200f, 0.631000f, 0.000800f}, {1.002600f, 0.503000f, 0.000340f},  // 600, 610
    {0.854450f, 0.381000f, 0.000190f}, {0.642400f, 0.265000f, 0.000050f},  // 620, 630
    {0.447900f, 0.175000f, 0.000020f}, {0.283500f, 0.107000f, 0.000000f},  // 640, 650
    {0.164900f, 0.061000f, 0.000000f}, {0.087400f, 0.032000f, 0.000000f},  // 660, 670
    {0.046770f, 0.017000f, 0.000000f}, {0.022700f, 0.008210f, 0.000000f},  // 680, 690
    {0.011359f, 0.004102f, 0.000000f}, {0.005790f, 0.002091f, 0.000000f},  // 700, 710
    {0.002899f, 0.001047f, 0.000000f}, {0.001440f, 0.000520f, 0.000000f},  // 720, 730
    {0.000690f, 0.000249f, 0.000000f}, {0.000332f, 0.000120f, 0.000000f},  // 740, 750
    {0.000166f, 0.000060f, 0.000000f}, {0.000083f, 0.000030f, 0.000000f},  // 760, 770
    {0.000042f, 0.000015f, 0.000000f}, {0.000021f, 0.000007f, 0.000000f},  // 780, 790
    {0.000010f, 0.000004f, 0.000000f}, {0.000005f, 0.000002f, 0.000000f},  // 800, 810
    {0.000003f, 0.000001f, 0.000000f}, {0.000001f, 0.000000f, 0.000000f},  // 820, 830
};

// CIE standard illuminant D65, 360..830 nm in 10 nm steps.
constexpr float kD65[kCieCount] = {
    46.6383f, 52.0891f, 49.9755f, 54.6482f, 82.7549f, 91.4860f, 93.4318f, 86.6823f,
    104.865f, 117.008f, 117.812f, 114.861f, 115.923f, 108.811f, 109.354f, 107.802f,
    104.790f, 107.689f, 104.405f, 104.046f, 100.000f, 96.3342f, 95.7880f, 88.6856f,
    90.0062f, 89.5991f, 87.6987f, 83.2886f, 83.6992f, 80.0268f, 80.2146f, 82.2778f,
    78.2842f, 69.7213f, 71.6091f, 74.3490f, 61.6040f, 69.8856f, 75.0870f, 63.5927f,
    46.4182f, 66.8054f, 63.3828f, 64.3040f, 59.4519f, 51.9590f, 57.4406f, 60.3125f,
};

// Position of lambda in the 10 nm tables: index and fraction, or false outside.
bool Locate(float lambda, int* i, float* t) {
  if (!(lambda >= kLambdaMin && lambda <= kLambdaMax)) return false;
  float x = (lambda - kLambdaMin) * 0.1f;
  *i = std::min(int(x), kCieCount - 2);
  *t = x - *i;
  return true;
}

}  // namespace

Vec3f CieXyz(float lambda) {
  int i;
  float t;
  if (!Locate(lambda, &i, &t)) return {0, 0, 0};
  return {Lerp(t, kCie[i][0], kCie[i + 1][0]), Lerp(t, kCie[i][1], kCie[i + 1][1]),
          Lerp(t, kCie[i][2], kCie[i + 1][2])};
}

float CieYIntegral() {
  // Exact integral of the piecewise-linear interpolant (trapezoid rule on the table).
  static const float integral = [] {
    double s = 0;
    for (int i = 0; i + 1 < kCieCount; ++i) s += 5.0 * (kCie[i][1] + kCie[i + 1][1]);
    return float(s);
  }();
  return integral;
}

float D65Raw(float lambda) {
  int i;
  float t;
  if (!Locate(lambda, &i, &t)) return 0;
  return Lerp(t, kD65[i], kD65[i + 1]);
}

double Blackbody(double lambda_nm, double temperature_k) {
  if (temperature_k <= 0) return 0;
  constexpr double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
  double l = lambda_nm * 1e-9;
  double le = (2 * h * c * c) / (std::pow(l, 5) * (std::exp((h * c) / (l * kb * temperature_k)) - 1));
  return le * 1e-9;  // per nm
}

}  // namespace objektiv
