// The index of refraction of a scene's dielectric: a constant, or a glass of the optics library
// (a catalog glass, or Cauchy or Sellmeier coefficients: optics/glass.h, the one dispersion
// model the lens and the scene share).
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string_view>

#include "optics/glass.h"

namespace objektiv {

class IorModel {
 public:
  IorModel() = default;
  explicit IorModel(double n) : n_(n) {}
  // Dispersive: n(lambda) from the glass (a constant glass gives a constant model).
  explicit IorModel(std::shared_ptr<const Glass> glass);
  static IorModel Cauchy(double a, double b, double c = 0) { return IorModel(std::make_shared<const Glass>(Glass::Cauchy(a, b, c))); }
  static IorModel Sellmeier(const std::array<double, 3>& b, const std::array<double, 3>& c) {
    return IorModel(std::make_shared<const Glass>(Glass::Sellmeier(b, c)));
  }
  // A glass of the lens library's catalogs (not owned: it must outlive the model).
  static IorModel FromGlass(const Glass* glass) { return IorModel(std::shared_ptr<const Glass>(std::shared_ptr<const Glass>(), glass)); }

  double operator()(double lambda_nm) const { return glass_ ? glass_->Index(lambda_nm) : n_; }
  bool IsDispersive() const { return glass_ != nullptr; }

 private:
  std::shared_ptr<const Glass> glass_;  // null: the constant n_
  double n_ = 1;
};

// Mitsuba's table of named indices ("bk7", "water", "air", "diamond", ...).
std::optional<double> NamedIor(std::string_view name);

}  // namespace objektiv
