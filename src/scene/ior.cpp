#include "scene/ior.h"

#include "optics/dispersion.h"
#include "optics/glass.h"

#include <cmath>
#include <utility>

namespace objektiv {

IorModel IorModel::Cauchy(double a, double b, double c) {
  IorModel m;
  m.kind_ = Kind::kCauchy;
  m.a_ = {a, b, c};
  return m;
}

IorModel IorModel::Sellmeier(std::array<double, 3> b, std::array<double, 3> c) {
  IorModel m;
  m.kind_ = Kind::kSellmeier;
  m.a_ = b;
  m.b_ = c;
  return m;
}

IorModel IorModel::FromGlass(const Glass* glass) {
  IorModel m;
  m.kind_ = glass->IsDispersive() ? Kind::kGlass : Kind::kConstant;
  m.glass_ = glass;
  m.n_ = glass->Index(kLambdad);
  return m;
}

double IorModel::operator()(double lambda_nm) const {
  double l = lambda_nm * 1e-3, l2 = l * l;
  switch (kind_) {
    case Kind::kConstant:
      return n_;
    case Kind::kCauchy:
      return a_[0] + a_[1] / l2 + a_[2] / (l2 * l2);
    case Kind::kGlass:
      return glass_->Index(lambda_nm);
    case Kind::kSellmeier: {
      double n2 = 1;
      for (int i = 0; i < 3; ++i) n2 += a_[i] * l2 / (l2 - b_[i]);
      return std::sqrt(std::max(n2, 1e-6));
    }
  }
  return 1;
}

std::optional<double> NamedIor(std::string_view name) {
  static const std::pair<const char*, double> table[] = {
      {"vacuum", 1.0},          {"helium", 1.00004},        {"hydrogen", 1.00013},
      {"air", 1.00028},         {"carbon dioxide", 1.00045}, {"water", 1.3330},
      {"acetone", 1.36},        {"ethanol", 1.361},          {"carbon tetrachloride", 1.461},
      {"glycerol", 1.4729},     {"benzene", 1.501},          {"silicone oil", 1.52045},
      {"bromine", 1.661},       {"water ice", 1.31},         {"fused quartz", 1.458},
      {"pyrex", 1.470},         {"acrylic glass", 1.49},     {"polypropylene", 1.49},
      {"bk7", 1.5046},          {"sodium chloride", 1.544},  {"amber", 1.55},
      {"pet", 1.5750},          {"diamond", 2.419},
  };
  for (const auto& [n, v] : table)
    if (name == n) return v;
  return std::nullopt;
}

}  // namespace objektiv
