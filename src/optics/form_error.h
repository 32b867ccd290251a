// A surface's form error: its figure departs from the prescription by a smooth random shape
// (an optician's irregularity), given by its peak-to-valley height over the clear aperture and
// a seed. The shape is a polynomial in u = x / R, v = y / R (R the clear semi-diameter) of total
// degree 2 to 6,
//
//   e(u, v) = s * sum_{2 <= i + j <= 6} a_ij u^i v^j,
//
// whose coefficients a_ij are drawn (PCG32 with the seed, Box-Muller) from a normal
// distribution of standard deviation 1 / (i + j)^2, so that the low orders (power,
// astigmatism, then coma and trefoil) dominate, as in polished glass; the scale s makes its
// peak-to-valley over the disc u^2 + v^2 <= 1 (a 201 x 201 grid) the given one. No piston and
// no tilt: a constant would move the vertex and a tilt is a wedge (decenter=, tilt= give those).
// The same seed gives the same shape at any size (Scaled).
#pragma once
#include <cstdint>
#include <vector>

namespace objektiv {

class FormError {
 public:
  static constexpr int kDegree = 6;
  // `peak_to_valley` and `radius` in mm (both > 0).
  FormError(double peak_to_valley, uint64_t seed, double radius);

  double peak_to_valley() const { return peak_to_valley_; }
  uint64_t seed() const { return seed_; }
  double radius() const { return radius_; }
  // The height e(x, y) (mm, along the surface's axis) and, where asked, its gradient.
  double Height(double x, double y, double* gx = nullptr, double* gy = nullptr) const;
  FormError Scaled(double factor) const { return FormError(peak_to_valley_ * factor, seed_, radius_ * factor); }

 private:
  double peak_to_valley_, radius_;
  uint64_t seed_;
  std::vector<double> coef_;  // a_ij s for i + j <= kDegree, [i * (kDegree + 1) + j]
};

}  // namespace objektiv
