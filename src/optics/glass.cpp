#include "optics/glass.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace objektiv {

Glass::Glass(std::string name, std::string catalog, DispersionFormula formula, const std::array<double, 10>& c)
    : name_(std::move(name)), catalog_(std::move(catalog)), formula_(formula), c_(c) {}

Glass Glass::Model(double nd, double vd) {
  // Solve n = A + B / l^2 through n(d) = nd and nF - nC = (nd - 1) / vd (l in um).
  double lf = kLambdaF * 1e-3, lc = kLambdaC * 1e-3, ld = kLambdad * 1e-3;
  double b = (nd - 1) / vd / (1 / (lf * lf) - 1 / (lc * lc));
  Glass g = Cauchy(nd - b / (ld * ld), b);
  g.name_ = fmt::format("model {:.6f}/{:.2f}", nd, vd);
  g.catalog_ = "MODEL";
  g.catalog_nd = nd;
  g.catalog_vd = vd;
  return g;
}

Glass Glass::Cauchy(double a, double b, double c) {
  Glass g(fmt::format("cauchy {}/{}/{}", a, b, c), "FORMULA", DispersionFormula::kConrady, {a, b, c});
  g.kind_ = Kind::kCauchy;
  return g;
}

Glass Glass::Sellmeier(const std::array<double, 3>& b, const std::array<double, 3>& c) {
  return Glass("sellmeier", "FORMULA", DispersionFormula::kSellmeier1, {b[0], c[0], b[1], c[1], b[2], c[2]});
}

Glass Glass::Constant(double n) {
  Glass g(fmt::format("n={}", n), "CONSTANT", DispersionFormula::kConrady, {});
  g.kind_ = Kind::kConstant;
  g.c_[0] = n;
  g.catalog_nd = n;
  return g;
}

Glass Glass::Undispersed() const {
  Glass g = *this;
  g.c_ = {};
  g.c_[0] = ComputedNd();
  g.kind_ = Kind::kConstant;
  g.catalog_vd = 0;
  return g;
}

Glass Glass::Named(std::string name, std::string catalog) const {
  Glass g = *this;
  g.name_ = std::move(name);
  g.catalog_ = std::move(catalog);
  return g;
}

double Glass::Index(double lambda_nm) const {
  double l = lambda_nm * 1e-3;
  switch (kind_) {
    case Kind::kConstant:
      return c_[0];
    case Kind::kCauchy: {
      double l2 = l * l;
      return c_[0] + c_[1] / l2 + c_[2] / (l2 * l2);
    }
    case Kind::kCatalog:
      return EvaluateDispersion(formula_, c_, l);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

void Glass::AddTransmission(double lambda_um, double tau, double thickness_mm) {
  // tau = exp(-alpha d); a zero transmittance is kept finite (opaque within any lens).
  double alpha = -std::log(std::max(tau, 1e-12)) / thickness_mm;
  auto it = std::lower_bound(absorption_.begin(), absorption_.end(), std::make_pair(lambda_um, 0.0),
                             [](const auto& a, const auto& b) { return a.first < b.first; });
  absorption_.insert(it, {lambda_um, std::max(alpha, 0.0)});
}

double Glass::AbsorptionCoefficient(double lambda_nm) const {
  if (absorption_.empty()) return 0;
  const double l = lambda_nm * 1e-3;
  if (l <= absorption_.front().first) return absorption_.front().second;
  if (l >= absorption_.back().first) return absorption_.back().second;
  auto hi = std::upper_bound(absorption_.begin(), absorption_.end(), l, [](double v, const auto& a) { return v < a.first; });
  auto lo = hi - 1;
  const double t = (l - lo->first) / (hi->first - lo->first);
  return lo->second + t * (hi->second - lo->second);
}

double Glass::InternalTransmittance(double lambda_nm, double thickness_mm) const {
  if (absorption_.empty() || thickness_mm <= 0) return 1;
  return std::exp(-AbsorptionCoefficient(lambda_nm) * thickness_mm);
}

}  // namespace objektiv
