// One step of Dormand and Prince's embedded Runge-Kutta pair RK5(4) (J. R. Dormand, P. J.
// Prince, "A family of embedded Runge-Kutta formulae", J. Comp. Appl. Math. 6, 1980): for
// y' = f(y) (autonomous), the fifth-order solution after a step h and an estimate of its local
// error (the difference from the embedded fourth-order one), from seven evaluations of f (the
// seventh at the new point, which the next step may reuse: "first same as last").
//
// A caller controls the step by the estimate: accept where max |err| <= tol, and scale h by
// 0.9 (tol / err)^(1/5) (clamped), which holds every accepted step's local error under tol.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>

namespace objektiv {

template <size_t N>
using OdeState = std::array<double, N>;

// y1 = y0 + h sum b_i k_i; err = h sum (b_i - b*_i) k_i. `k1` is f(y0) (from the last step's
// seventh evaluation, or computed by the caller); `k7` receives f(y1).
template <size_t N, typename F>
void DormandPrinceStep(const F& f, const OdeState<N>& y0, const OdeState<N>& k1, double h, OdeState<N>& y1,
                       OdeState<N>& err, OdeState<N>& k7) {
  // The tableau (c_i implied: the system is autonomous).
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  // b - b*: the fifth-order weights less the embedded fourth-order ones.
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                   e7 = -1.0 / 40;
  OdeState<N> y, k2, k3, k4, k5, k6;
  for (size_t i = 0; i < N; ++i) y[i] = y0[i] + h * a21 * k1[i];
  k2 = f(y);
  for (size_t i = 0; i < N; ++i) y[i] = y0[i] + h * (a31 * k1[i] + a32 * k2[i]);
  k3 = f(y);
  for (size_t i = 0; i < N; ++i) y[i] = y0[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
  k4 = f(y);
  for (size_t i = 0; i < N; ++i) y[i] = y0[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
  k5 = f(y);
  for (size_t i = 0; i < N; ++i)
    y[i] = y0[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
  k6 = f(y);
  for (size_t i = 0; i < N; ++i) y1[i] = y0[i] + h * (b1 * k1[i] + b3 * k3[i] + b4 * k4[i] + b5 * k5[i] + b6 * k6[i]);
  k7 = f(y1);
  for (size_t i = 0; i < N; ++i)
    err[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
}

// The step after one whose largest error component was `err_max` against `tol`: Dormand and
// Prince's controller, the change held within a factor 0.2 to 5.
inline double NextDormandPrinceStep(double h, double err_max, double tol) {
  double scale = err_max > 0 ? 0.9 * std::pow(tol / err_max, 0.2) : 5.0;
  scale = scale < 0.2 ? 0.2 : (scale > 5.0 ? 5.0 : scale);
  return h * scale;
}

}  // namespace objektiv
