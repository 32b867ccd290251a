#include "io/properties.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "base/log.h"

namespace objektiv {

const char* PropTypeName(PropType t) {
  switch (t) {
    case PropType::kFloat:
      return "float";
    case PropType::kInteger:
      return "integer";
    case PropType::kBoolean:
      return "boolean";
    case PropType::kString:
      return "string";
    case PropType::kFloatOrString:
      return "float or string";
    case PropType::kSpectrum:
      return "spectrum";
    case PropType::kSpectrumOrTexture:
      return "spectrum or texture";
    case PropType::kPoint:
      return "point";
    case PropType::kVector:
      return "vector";
    case PropType::kTransform:
      return "transform";
    case PropType::kObject:
      return "object";
    case PropType::kMedium:
      return "medium";
  }
  return "?";
}

const PropertyDecl& Properties::Declared(std::string_view name, std::initializer_list<PropType> types,
                                         bool nested) const {
  for (const auto* decls : {&common_, &own_})
    for (const PropertyDecl& d : *decls) {
      if (d.name != name || (d.type == PropType::kObject) != nested) continue;
      if (types.size() && std::find(types.begin(), types.end(), d.type) == types.end())
        throw std::logic_error(fmt::format("{} '{}' reads '{}', declared a {}, as another type", node_.tag, node_.type,
                                           name, PropTypeName(d.type)));
      return d;
    }
  throw std::logic_error(fmt::format("{} '{}' reads the undeclared {} '{}'", node_.tag, node_.type,
                                     nested ? "nested object" : "property", name));
}

const Property* Properties::Find(const std::string& name, std::initializer_list<PropType> types) const {
  Declared(name, types);
  for (const Property& p : node_.props)
    if (p.name == name) {
      p.used = true;
      return &p;
    }
  return nullptr;
}

std::optional<ValueType> Properties::TypeOf(const std::string& name) const {
  const Property* p = Find(name);
  if (!p) return std::nullopt;
  const PropertyData& d = p->data;
  if (std::holds_alternative<double>(d)) return ValueType::kFloat;
  if (std::holds_alternative<int64_t>(d)) return ValueType::kInteger;
  if (std::holds_alternative<bool>(d)) return ValueType::kBoolean;
  if (std::holds_alternative<std::string>(d)) return ValueType::kString;
  if (std::holds_alternative<SpectrumValue>(d)) return p->type_name == "rgb" ? ValueType::kRgb : ValueType::kSpectrum;
  if (std::holds_alternative<Vec3d>(d)) return p->type_name == "vector" ? ValueType::kVector : ValueType::kPoint;
  if (std::holds_alternative<Transform>(d)) return ValueType::kTransform;
  return ValueType::kObject;
}

Location Properties::LocOf(const std::string& name) const {
  Declared(name, {});
  for (const Property& p : node_.props)
    if (p.name == name) return p.loc;
  return node_.loc;
}

void Properties::WrongType(const Property& p, const char* expected) const {
  throw ErrorAt(p.loc, "property '{}' of {} '{}' must be {}, not <{}>", p.name, node_.tag, node_.type, expected, p.type_name);
}

double Properties::ToFloat(const Property& p) const {
  double v;
  if (auto* d = std::get_if<double>(&p.data))
    v = *d;
  else if (auto* i = std::get_if<int64_t>(&p.data))
    v = double(*i);
  else
    WrongType(p, "a <float>");
  // The renderer computes in single precision: a value beyond its range would become infinite.
  if (std::abs(v) > std::numeric_limits<float>::max())
    throw ErrorAt(p.loc, "{} '{}': '{}' = {} is too large (beyond single precision)", node_.tag, node_.type, p.name, v);
  return v;
}

double Properties::Float(const std::string& name) const {
  const Property* p = Find(name, {PropType::kFloat, PropType::kFloatOrString});
  if (!p) throw ErrorAt(node_.loc, "{} '{}' needs the property '{}'", node_.tag, node_.type, name);
  return ToFloat(*p);
}

double Properties::Float(const std::string& name, double fallback) const { return Has(name) ? Float(name) : fallback; }

double Properties::FloatIn(const std::string& name, double fallback, double lo, double hi) const {
  double v = Float(name, fallback);
  if (v < lo || v > hi) throw ErrorAt(LocOf(name), "{} '{}': '{}' = {} is outside [{}, {}]", node_.tag, node_.type, name, v, lo, hi);
  return v;
}

int64_t Properties::Int(const std::string& name, int64_t fallback) const {
  const Property* p = Find(name, {PropType::kInteger});
  if (!p) return fallback;
  if (auto* i = std::get_if<int64_t>(&p->data)) return *i;
  WrongType(*p, "an <integer>");
}

int64_t Properties::IntIn(const std::string& name, int64_t fallback, int64_t lo, int64_t hi) const {
  int64_t v = Int(name, fallback);
  if (v < lo || v > hi) throw ErrorAt(LocOf(name), "{} '{}': '{}' = {} is outside [{}, {}]", node_.tag, node_.type, name, v, lo, hi);
  return v;
}

bool Properties::Bool(const std::string& name, bool fallback) const {
  const Property* p = Find(name, {PropType::kBoolean});
  if (!p) return fallback;
  if (auto* b = std::get_if<bool>(&p->data)) return *b;
  WrongType(*p, "a <boolean>");
}

std::string Properties::String(const std::string& name) const {
  const Property* p = Find(name, {PropType::kString, PropType::kFloatOrString});
  if (!p) throw ErrorAt(node_.loc, "{} '{}' needs the property '{}'", node_.tag, node_.type, name);
  if (auto* s = std::get_if<std::string>(&p->data)) return *s;
  WrongType(*p, "a <string>");
}

std::string Properties::String(const std::string& name, const std::string& fallback) const {
  return Has(name) ? String(name) : fallback;
}

std::optional<size_t> Properties::ChoiceIndex(const std::string& name, std::span<const char* const> names) const {
  const PropertyDecl& d = Declared(name, {PropType::kString});
  if (!std::equal(d.choices.begin(), d.choices.end(), names.begin(), names.end()))
    throw std::logic_error(
        fmt::format("{} '{}' reads '{}' with other choices than it declares", node_.tag, node_.type, name));
  if (!Has(name)) return std::nullopt;
  // Compared without case ("Emitters" is "emitters"), as sensor formats and glass names are.
  auto lower = [](std::string t) {
    for (char& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
    return t;
  };
  std::string v = String(name), list;
  for (size_t i = 0; i < names.size(); ++i) {
    if (lower(v) == lower(names[i])) return i;
    list += list.empty() ? names[i] : std::string(", ") + names[i];
  }
  throw ErrorAt(LocOf(name), "{} '{}': '{}' = '{}' is not one of: {}", node_.tag, node_.type, name, v, list);
}

Vec3d Properties::Triple(const std::string& name, const Vec3d& fallback, PropType type, const char* expected) const {
  const Property* p = Find(name, {type});
  if (!p) return fallback;
  if (auto* v = std::get_if<Vec3d>(&p->data)) return *v;
  WrongType(*p, expected);
}

Vec3d Properties::Point(const std::string& name, const Vec3d& fallback) const {
  return Triple(name, fallback, PropType::kPoint, "a <point>");
}

Vec3d Properties::Vector(const std::string& name, const Vec3d& fallback) const {
  return Triple(name, fallback, PropType::kVector, "a <vector>");
}

Transform Properties::GetTransform(const std::string& name) const {
  const Property* p = Find(name, {PropType::kTransform});
  if (!p) return Transform();
  if (auto* t = std::get_if<Transform>(&p->data)) return *t;
  WrongType(*p, "a <transform>");
}

std::optional<SpectrumValue> Properties::SpectrumProp(const std::string& name) const {
  const Property* p = Find(name, {PropType::kSpectrum, PropType::kSpectrumOrTexture});
  if (!p) return std::nullopt;
  SpectrumValue s;
  if (auto* sv = std::get_if<SpectrumValue>(&p->data)) {
    s = *sv;
  } else if (std::holds_alternative<double>(p->data)) {
    s.kind = SpectrumValue::Kind::kConstant;
    s.value = float(ToFloat(*p));
  } else {
    WrongType(*p, "a <float>, <rgb> or <spectrum>");
  }
  // Reflectances, radiances, indices and absorption coefficients are never negative, and
  // must stay within single precision.
  bool bad = s.value < 0 || MinComponent(s.rgb) < 0 || !std::isfinite(s.value) || !std::isfinite(MaxComponent(s.rgb));
  for (float v : s.values) bad |= v < 0 || !std::isfinite(v);
  if (bad) throw ErrorAt(p->loc, "{} '{}': '{}' must be finite and not negative", node_.tag, node_.type, name);
  return s;
}

std::shared_ptr<ObjectNode> Properties::Object(const std::string& name) const {
  const Property* p = Find(name, {PropType::kSpectrumOrTexture, PropType::kMedium});
  if (!p) return nullptr;
  if (auto* o = std::get_if<std::shared_ptr<ObjectNode>>(&p->data)) return *o;
  return nullptr;
}

std::vector<std::shared_ptr<ObjectNode>> Properties::Children(const std::string& tag) const {
  Declared(tag, {}, /*nested=*/true);
  std::vector<std::shared_ptr<ObjectNode>> out;
  for (const auto& c : node_.children)
    if (c->tag == tag) {
      out.push_back(c);
      handed_out_.insert(c.get());
    }
  return out;
}

void Properties::WarnUnused() const {
  for (const Property& p : node_.props)
    if (!p.used)
      spdlog::warn("{}:{}: {} '{}' does not use the property '{}'", p.loc.file, p.loc.line, node_.tag, node_.type, p.name);
  for (const auto& c : node_.children)
    if (!c->used || !handed_out_.count(c.get()))
      spdlog::warn("{}:{}: {} '{}' does not use the nested {} '{}'", c->loc.file, c->loc.line, node_.tag, node_.type,
                   c->tag, c->type);
}

}  // namespace objektiv
