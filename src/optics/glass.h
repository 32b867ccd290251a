// Optical glasses: refractive index by wavelength and internal transmittance, from a catalog
// formula, a "model glass" (nd, Vd), Cauchy or Sellmeier coefficients, or a constant index.
// The one index-of-refraction model of the renderer: lens media and the scene's dielectrics.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "optics/dispersion.h"

namespace objektiv {

class Glass {
 public:
  // A catalog glass with its AGF formula and coefficients.
  Glass(std::string name, std::string catalog, DispersionFormula formula, const std::array<double, 10>& coefficients);
  // A model glass through nd and Vd: n = A + B / l^2 (two-term Cauchy), so that n(d) = nd and
  // (nd - 1) / (nF - nC) = Vd exactly. Used when a prescription gives only nd and Vd.
  static Glass Model(double nd, double vd);
  // n = a + b / l^2 + c / l^4, l in micrometres.
  static Glass Cauchy(double a, double b, double c = 0);
  // n^2 = 1 + sum_i b_i l^2 / (l^2 - c_i), l in micrometres, c_i in um^2 (Schott's form, AGF
  // formula 2).
  static Glass Sellmeier(const std::array<double, 3>& b, const std::array<double, 3>& c);
  static Glass Constant(double n);
  // The same glass without dispersion: its index at the d line (587.56 nm) at every wavelength,
  // its name and its transmittance kept (a lens drawn without its colour errors).
  Glass Undispersed() const;
  // The same index model under another name (coating materials: "MgF2" in catalog "COATING").
  Glass Named(std::string name, std::string catalog) const;

  double Index(double lambda_nm) const;
  // Internal transmittance through `thickness_mm` of glass (1 where the catalog has no data):
  // Beer-Lambert with the absorption coefficient interpolated between the catalog's IT rows.
  double InternalTransmittance(double lambda_nm, double thickness_mm) const;
  // That absorption coefficient, 1/mm (0 where the catalog has no data).
  double AbsorptionCoefficient(double lambda_nm) const;
  double ComputedNd() const { return Index(kLambdad); }
  double ComputedVd() const { return (Index(kLambdad) - 1) / (Index(kLambdaF) - Index(kLambdaC)); }
  // nd and Vd as the glass's source states them (the catalog's NM line), else as computed.
  double NominalNd() const { return catalog_nd > 0 ? catalog_nd : ComputedNd(); }
  double NominalVd() const { return catalog_vd > 0 ? catalog_vd : ComputedVd(); }
  bool IsDispersive() const { return kind_ != Kind::kConstant; }
  // Whether the glass has transmittance data (InternalTransmittance is not 1 everywhere).
  bool Absorbs() const { return !absorption_.empty(); }

  const std::string& name() const { return name_; }
  const std::string& catalog() const { return catalog_; }
  DispersionFormula formula() const { return formula_; }  // meaningful for catalog glasses
  // Nominal catalog values from the NM line (0 when not given).
  double catalog_nd = 0, catalog_vd = 0;
  // Wavelength range (um) in which the formula is valid (0, 0 when unknown).
  double lambda_min_um = 0, lambda_max_um = 0;

  void SetCoefficients(const std::array<double, 10>& c) { c_ = c; }
  // IT row: internal transmittance `tau` over `thickness_mm` at `lambda_um`.
  void AddTransmission(double lambda_um, double tau, double thickness_mm);

 private:
  enum class Kind { kCatalog, kCauchy, kConstant } kind_ = Kind::kCatalog;
  std::string name_, catalog_;
  DispersionFormula formula_ = DispersionFormula::kSchott;
  std::array<double, 10> c_{};
  // Absorption coefficient (per mm) at increasing wavelengths (um).
  std::vector<std::pair<double, double>> absorption_;
};

}  // namespace objektiv
