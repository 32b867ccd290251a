#include "optics/coating.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace objektiv {

namespace {
double IndexOf(const std::shared_ptr<const Glass>& g, double lambda_nm) { return g ? g->Index(lambda_nm) : 1.0; }
}  // namespace

Coating::Coating(std::string name, double design_nm, std::vector<Layer> layers)
    : name_(std::move(name)), design_nm_(design_nm), layers_(std::move(layers)) {
  if (layers_.size() > kMaxLayers) throw std::invalid_argument(fmt::format("more than {} layers", kMaxLayers));
  for (size_t i = 0; i < layers_.size(); ++i) {
    const bool last = i + 1 == layers_.size();
    if (!layers_[i].material && !(last && (i == 0 || layers_[0].material)))
      throw std::invalid_argument("a matched layer is the only layer or the one next to the glass");
  }
}

Coating Coating::Ideal(std::string name, double t) {
  Coating c(std::move(name), 550, {});
  c.ideal_t_ = t;
  return c;
}

std::string Coating::Describe() const {
  if (ideal_t_) return fmt::format("ideal, transmittance {} at every wavelength and angle", *ideal_t_);
  if (layers_.empty()) return "uncoated";
  std::string text;
  for (const Layer& l : layers_) {
    if (!text.empty()) text += " | ";
    text += l.material ? l.material->name() : "matched";
    text += l.waves > 0 ? fmt::format(" {:g} wave", l.waves) : fmt::format(" {:g} nm", l.thickness_nm);
  }
  bool optical = false;
  for (const Layer& l : layers_) optical |= l.waves > 0;
  return optical ? fmt::format("{} (waves at {:g} nm), outermost first", text, design_nm_) : text + ", outermost first";
}

std::string CoatingMismatch(const Coating& coating, const Glass* before, const Glass* after) {
  if (coating.ideal_transmittance()) return {};  // no layers
  const double l0 = coating.design_nm();
  auto bad = [&](const Glass* g) {
    const double n = g ? g->Index(l0) : 1.0;
    return !(std::isfinite(n) && n >= 1);
  };
  auto range = [](const Glass& g) {
    return g.lambda_max_um > 0 ? fmt::format(" (its formula covers {:g} to {:g} nm)", g.lambda_min_um * 1e3,
                                             g.lambda_max_um * 1e3)
                               : std::string();
  };
  for (const Glass* g : {before, after})
    if (bad(g))
      return fmt::format("coating {}: the glass {} has no index at its design wavelength {:g} nm{}", coating.name(),
                         g->name(), l0, range(*g));
  for (const Coating::Layer& layer : coating.layers())
    if (layer.material && bad(layer.material.get()))
      return fmt::format("coating {}: its layer material {} has no index at its design wavelength {:g} nm{}",
                         coating.name(), layer.material->name(), l0, range(*layer.material));
  return {};
}

CoatedInterface::CoatedInterface(std::shared_ptr<const Coating> coating, std::shared_ptr<const Glass> outer,
                                 std::shared_ptr<const Glass> substrate)
    : coating_(std::move(coating)), outer_(std::move(outer)), substrate_(std::move(substrate)) {
  const std::vector<Coating::Layer>& layers = coating_->layers();
  const double l0 = coating_->design_nm();
  const double n_outer = IndexOf(outer_, l0), n_glass = IndexOf(substrate_, l0);
  for (const Coating::Layer& layer : layers) {
    double n0 = layer.material ? layer.material->Index(l0)
                : layers.size() == 1 ? std::sqrt(n_outer * n_glass)
                                     : layers[0].material->Index(l0) * std::sqrt(n_glass / n_outer);
    materials_.push_back(layer.material);
    matched_index_.push_back(n0);
    thickness_nm_.push_back(layer.waves > 0 ? layer.waves * l0 / n0 : layer.thickness_nm);
  }
}

bool CoatedInterface::SameResponse(const CoatedInterface& other, std::span<const double> wavelengths) const {
  if (coating_->ideal_transmittance() != other.coating_->ideal_transmittance() ||
      thickness_nm_ != other.thickness_nm_ || matched_index_ != other.matched_index_)
    return false;
  for (double l : wavelengths) {
    if (IndexOf(outer_, l) != IndexOf(other.outer_, l) || IndexOf(substrate_, l) != IndexOf(other.substrate_, l)) return false;
    for (size_t i = 0; i < materials_.size(); ++i) {
      const Glass *a = materials_[i].get(), *b = other.materials_[i].get();
      if (bool(a) != bool(b) || (a && a != b && a->Index(l) != b->Index(l))) return false;
    }
  }
  return true;
}

ThinFilmResponse CoatedInterface::Response(double lambda_nm, double cos_i, bool from_outer) const {
  const double n_outer = IndexOf(outer_, lambda_nm), n_glass = IndexOf(substrate_, lambda_nm);
  if (const std::optional<double>& t = coating_->ideal_transmittance()) {
    // Total internal reflection stays total.
    const double n_from = from_outer ? n_outer : n_glass, n_to = from_outer ? n_glass : n_outer;
    const double sin2 = (n_from / n_to) * (n_from / n_to) * std::max(0.0, 1 - cos_i * cos_i);
    if (sin2 >= 1) return {1, 1, 0, 0};
    return {1 - *t, 1 - *t, *t, *t};
  }
  const size_t n = materials_.size();
  ThinFilmLayer stack[Coating::kMaxLayers];
  for (size_t i = 0; i < n; ++i) {
    const size_t k = from_outer ? i : n - 1 - i;
    stack[i] = {materials_[k] ? materials_[k]->Index(lambda_nm) : matched_index_[k], thickness_nm_[k]};
  }
  return from_outer ? ThinFilmStack(n_outer, {stack, n}, n_glass, lambda_nm, cos_i)
                    : ThinFilmStack(n_glass, {stack, n}, n_outer, lambda_nm, cos_i);
}

}  // namespace objektiv
