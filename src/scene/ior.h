// Refractive index as a function of wavelength: constant, Cauchy, Sellmeier, or named.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace objektiv {

class Glass;

class IorModel {
 public:
  IorModel() = default;
  explicit IorModel(double n) : kind_(Kind::kConstant), n_(n) {}
  // n = A + B / l^2 + C / l^4, l in micrometres.
  static IorModel Cauchy(double a, double b, double c = 0);
  // n^2 = 1 + sum B_i l^2 / (l^2 - C_i), l in micrometres, C_i in um^2 (Schott's form).
  static IorModel Sellmeier(std::array<double, 3> b, std::array<double, 3> c);
  // A glass of the lens library's catalogs (it must outlive the model).
  static IorModel FromGlass(const Glass* glass);

  double operator()(double lambda_nm) const;
  bool IsDispersive() const { return kind_ != Kind::kConstant; }

 private:
  enum class Kind { kConstant, kCauchy, kSellmeier, kGlass } kind_ = Kind::kConstant;
  const Glass* glass_ = nullptr;
  double n_ = 1;
  std::array<double, 3> a_{}, b_{};
};

// Mitsuba's table of named indices ("bk7", "water", "air", "diamond", ...).
std::optional<double> NamedIor(std::string_view name);

}  // namespace objektiv
