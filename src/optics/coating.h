// Anti-reflection coatings of lens surfaces. A coating is a named stack of thin layers laid on
// a surface's glass (the substrate), listed from the outermost layer (the air side) to the
// glass; each layer has a material (an index model: a coating material, a catalog glass or a
// constant) and a thickness, physical (nm) or optical (waves of n d at the design wavelength,
// 0.25: a quarter-wave layer). A layer may instead be `matched`: its index is chosen for the
// surface it coats, so that the quarter-wave designs reflect nothing on the axis at the design
// wavelength: sqrt(n_outer n_glass) for a single layer, n_1 sqrt(n_glass / n_outer) for the
// layer next to the glass under an outermost layer of index n_1 (the quarter-quarter and
// quarter-half-quarter designs); indices at the design wavelength, then constant. Zemax's ideal
// coating `I.xx` (the same transmittance xx, and reflectance 1 - xx, at every wavelength and
// angle) is the other kind.
//
// A CoatedInterface is a coating as it lies on one surface: the media on its two sides known,
// matched indices and optical thicknesses resolved; its reflectance per wavelength, angle and
// direction comes from the thin-film stack (optics/thin_film.h), unpolarised.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "optics/glass.h"
#include "optics/thin_film.h"

namespace objektiv {

class Coating {
 public:
  static constexpr size_t kMaxLayers = 64;
  struct Layer {
    std::shared_ptr<const Glass> material;  // null: matched to the surface
    double thickness_nm = 0;                // physical thickness, or (when 0)
    double waves = 0;                       // optical thickness n d in waves at the design wavelength
  };
  // A stack of layers, outermost first. Throws std::invalid_argument where a matched layer is
  // anywhere but the only layer or the layer next to the glass under an unmatched one, or
  // where there are more than kMaxLayers.
  Coating(std::string name, double design_nm, std::vector<Layer> layers);
  // Zemax's ideal coating: transmittance `t` in (0, 1] everywhere.
  static Coating Ideal(std::string name, double t);

  const std::string& name() const { return name_; }
  double design_nm() const { return design_nm_; }
  const std::vector<Layer>& layers() const { return layers_; }
  const std::optional<double>& ideal_transmittance() const { return ideal_t_; }
  // "MgF2 0.25 wave at 550 nm" and so on, for the log and `lens info`.
  std::string Describe() const;

 private:
  std::string name_;
  double design_nm_ = 550;
  std::vector<Layer> layers_;
  std::optional<double> ideal_t_;
};

// A coating lies on the glass: facing the object unless only the object side of the surface is
// glass (`glass_before`, `glass_after`: whether the media before and after it are glass).
inline bool CoatingOuterFacesObject(bool glass_before, bool glass_after) { return !(glass_before && !glass_after); }

// Why `coating` cannot lie on a surface between `before` and `after` (null: air): a medium or a
// layer material without an index at the coating's design wavelength (a formula undefined
// there, as N-SF6's at 240 nm; the layers' thicknesses and a matched layer's index come from
// it). Empty where it can.
std::string CoatingMismatch(const Coating& coating, const Glass* before, const Glass* after);

class CoatedInterface {
 public:
  // `outer` and `substrate`: the media on the coating's two sides (null: air).
  CoatedInterface(std::shared_ptr<const Coating> coating, std::shared_ptr<const Glass> outer,
                  std::shared_ptr<const Glass> substrate);
  const Coating& coating() const { return *coating_; }
  // Whether `other` answers as this one does at each of `wavelengths`: the same layers (their
  // thicknesses, and their indices and the media's there), or the same ideal transmittance.
  // (Another loading of a lens makes other objects of the same glasses and coatings.)
  bool SameResponse(const CoatedInterface& other, std::span<const double> wavelengths) const;
  // Reflectance and transmittance (s, p) for light meeting the surface at cos_i (in the medium
  // it comes from), from the outer side or from the glass.
  ThinFilmResponse Response(double lambda_nm, double cos_i, bool from_outer) const;
  double Reflectance(double lambda_nm, double cos_i, bool from_outer) const {
    return Response(lambda_nm, cos_i, from_outer).Reflectance();
  }

 private:
  std::shared_ptr<const Coating> coating_;
  std::shared_ptr<const Glass> outer_, substrate_;
  // Per layer, outermost first: the material (null: the constant matched index) and the
  // physical thickness.
  std::vector<std::shared_ptr<const Glass>> materials_;
  std::vector<double> matched_index_, thickness_nm_;
};

}  // namespace objektiv
