#include "optics/dispersion.h"

#include <cmath>
#include <limits>

namespace objektiv {

std::optional<DispersionFormula> DispersionFormulaFromNumber(int n) {
  if (n < 1 || n > 13) return std::nullopt;
  return DispersionFormula(n);
}

std::string_view DispersionFormulaName(DispersionFormula f) {
  static const char* names[] = {"Schott",    "Sellmeier 1", "Herzberger", "Sellmeier 2", "Conrady",
                                "Sellmeier 3", "Handbook of Optics 1", "Handbook of Optics 2", "Sellmeier 4",
                                "Extended",  "Sellmeier 5", "Extended 2", "Extended 3"};
  return names[int(f) - 1];
}

namespace {
double SqrtOrNaN(double n2) { return n2 > 0 ? std::sqrt(n2) : std::numeric_limits<double>::quiet_NaN(); }

// 1 + sum of `terms` Sellmeier terms K l^2 / (l^2 - L) from c = K1 L1 K2 L2 ...
double SellmeierSum(const std::array<double, 10>& c, int terms, double l2) {
  double n2 = 1;
  for (int i = 0; i < terms; ++i) n2 += c[2 * i] * l2 / (l2 - c[2 * i + 1]);
  return n2;
}
}  // namespace

double EvaluateDispersion(DispersionFormula f, const std::array<double, 10>& c, double l) {
  const double l2 = l * l, l4 = l2 * l2, li2 = 1 / l2, li4 = li2 * li2, li6 = li4 * li2, li8 = li4 * li4;
  switch (f) {
    case DispersionFormula::kSchott:
      return SqrtOrNaN(c[0] + c[1] * l2 + c[2] * li2 + c[3] * li4 + c[4] * li6 + c[5] * li8);
    case DispersionFormula::kSellmeier1:
      return SqrtOrNaN(SellmeierSum(c, 3, l2));
    case DispersionFormula::kHerzberger: {
      double L = 1 / (l2 - 0.028);
      return c[0] + c[1] * L + c[2] * L * L + c[3] * l2 + c[4] * l4 + c[5] * l4 * l2;
    }
    case DispersionFormula::kSellmeier2:
      return SqrtOrNaN(1 + c[0] + c[1] * l2 / (l2 - c[2] * c[2]) + c[3] / (l2 - c[4] * c[4]));
    case DispersionFormula::kConrady:
      return c[0] + c[1] / l + c[2] / std::pow(l, 3.5);
    case DispersionFormula::kSellmeier3:
      return SqrtOrNaN(SellmeierSum(c, 4, l2));
    case DispersionFormula::kHandbook1:
      return SqrtOrNaN(c[0] + c[1] / (l2 - c[2]) - c[3] * l2);
    case DispersionFormula::kHandbook2:
      return SqrtOrNaN(c[0] + c[1] * l2 / (l2 - c[2]) - c[3] * l2);
    case DispersionFormula::kSellmeier4:
      return SqrtOrNaN(c[0] + c[1] * l2 / (l2 - c[2]) + c[3] * l2 / (l2 - c[4]));
    case DispersionFormula::kExtended:
      return SqrtOrNaN(c[0] + c[1] * l2 + c[2] * li2 + c[3] * li4 + c[4] * li6 + c[5] * li8 + c[6] * li8 * li2 +
                       c[7] * li8 * li4);
    case DispersionFormula::kSellmeier5:
      return SqrtOrNaN(SellmeierSum(c, 5, l2));
    case DispersionFormula::kExtended2:
      return SqrtOrNaN(c[0] + c[1] * l2 + c[2] * li2 + c[3] * li4 + c[4] * li6 + c[5] * li8 + c[6] * l4 + c[7] * l4 * l2);
    case DispersionFormula::kExtended3:
      return SqrtOrNaN(c[0] + c[1] * l2 + c[2] * l4 + c[3] * li2 + c[4] * li4 + c[5] * li6 + c[6] * li8 +
                       c[7] * li8 * li2 + c[8] * li8 * li4);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace objektiv
