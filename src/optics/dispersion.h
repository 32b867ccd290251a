// Refractive index formulas of the Zemax AGF glass catalogs (wavelength in micrometres).
#pragma once
#include <array>
#include <optional>
#include <string_view>

namespace objektiv {

// AGF formula numbers, as written on NM lines.
enum class DispersionFormula {
  kSchott = 1,        // n^2 = a0 + a1 l^2 + a2 l^-2 + a3 l^-4 + a4 l^-6 + a5 l^-8
  kSellmeier1 = 2,    // n^2 - 1 = sum_i=1..3 Ki l^2 / (l^2 - Li)           (K1 L1 K2 L2 K3 L3)
  kHerzberger = 3,    // n = A + B L + C L^2 + D l^2 + E l^4 + F l^6, L = 1 / (l^2 - 0.028)
  kSellmeier2 = 4,    // n^2 - 1 = A + B l^2 / (l^2 - l1^2) + C / (l^2 - l2^2)   (A B l1 C l2)
  kConrady = 5,       // n = n0 + A / l + B / l^3.5
  kSellmeier3 = 6,    // n^2 - 1 = sum_i=1..4 Ki l^2 / (l^2 - Li)
  kHandbook1 = 7,     // n^2 = A + B / (l^2 - C) - D l^2
  kHandbook2 = 8,     // n^2 = A + B l^2 / (l^2 - C) - D l^2
  kSellmeier4 = 9,    // n^2 = A + B l^2 / (l^2 - C) + D l^2 / (l^2 - E)
  kExtended = 10,     // Schott + a6 l^-10 + a7 l^-12
  kSellmeier5 = 11,   // n^2 - 1 = sum_i=1..5 Ki l^2 / (l^2 - Li)
  kExtended2 = 12,    // Schott + a6 l^4 + a7 l^6
  kExtended3 = 13,    // n^2 = a0 + a1 l^2 + a2 l^4 + a3 l^-2 + a4 l^-4 + a5 l^-6 + a6 l^-8 + a7 l^-10 + a8 l^-12
};

std::optional<DispersionFormula> DispersionFormulaFromNumber(int n);
std::string_view DispersionFormulaName(DispersionFormula f);

// The index at lambda (um) with the AGF coefficient list (CD line, up to 10 numbers).
// Returns NaN where the formula has no real value (e.g. at a resonance).
double EvaluateDispersion(DispersionFormula f, const std::array<double, 10>& c, double lambda_um);

// Fraunhofer lines used by catalogs (nm): F (hydrogen), d (helium), C (hydrogen).
constexpr double kLambdaF = 486.1327, kLambdad = 587.5618, kLambdaC = 656.2725;

}  // namespace objektiv
