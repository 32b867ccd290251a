#include "io/properties.h"

#include "base/log.h"

#include <cmath>
#include <limits>

namespace objektiv {

const Property* Properties::Find(const std::string& name) const {
  for (const Property& p : node_.props)
    if (p.name == name) {
      p.used = true;
      return &p;
    }
  return nullptr;
}

Location Properties::LocOf(const std::string& name) const {
  for (const Property& p : node_.props)
    if (p.name == name) return p.loc;
  return node_.loc;
}

void Properties::WrongType(const Property& p, const char* expected) const {
  throw ErrorAt(p.loc, "property '{}' of {} '{}' must be {}, not <{}>", p.name, node_.tag, node_.type, expected, p.type_name);
}

double Properties::Float(const std::string& name) const {
  const Property* p = Find(name);
  if (!p) throw ErrorAt(node_.loc, "{} '{}' needs the property '{}'", node_.tag, node_.type, name);
  double v;
  if (auto* d = std::get_if<double>(&p->data)) v = *d;
  else if (auto* i = std::get_if<int64_t>(&p->data)) v = double(*i);
  else WrongType(*p, "a <float>");
  // The renderer computes in single precision: a value beyond its range would become infinite.
  if (std::abs(v) > std::numeric_limits<float>::max())
    throw ErrorAt(p->loc, "{} '{}': '{}' = {} is too large (beyond single precision)", node_.tag, node_.type, name, v);
  return v;
}

double Properties::Float(const std::string& name, double fallback) const { return Has(name) ? Float(name) : fallback; }

double Properties::FloatIn(const std::string& name, double fallback, double lo, double hi) const {
  double v = Float(name, fallback);
  if (v < lo || v > hi) throw ErrorAt(LocOf(name), "{} '{}': '{}' = {} is outside [{}, {}]", node_.tag, node_.type, name, v, lo, hi);
  return v;
}

int64_t Properties::Int(const std::string& name, int64_t fallback) const {
  const Property* p = Find(name);
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
  const Property* p = Find(name);
  if (!p) return fallback;
  if (auto* b = std::get_if<bool>(&p->data)) return *b;
  WrongType(*p, "a <boolean>");
}

std::string Properties::String(const std::string& name) const {
  const Property* p = Find(name);
  if (!p) throw ErrorAt(node_.loc, "{} '{}' needs the property '{}'", node_.tag, node_.type, name);
  if (auto* s = std::get_if<std::string>(&p->data)) return *s;
  WrongType(*p, "a <string>");
}

std::string Properties::String(const std::string& name, const std::string& fallback) const {
  return Has(name) ? String(name) : fallback;
}

std::string Properties::Choice(const std::string& name, const std::string& fallback,
                               std::initializer_list<const char*> choices) const {
  std::string v = String(name, fallback);
  std::string list;
  for (const char* c : choices) {
    if (v == c) return v;
    list += list.empty() ? c : std::string(", ") + c;
  }
  throw ErrorAt(LocOf(name), "{} '{}': '{}' = '{}' is not one of: {}", node_.tag, node_.type, name, v, list);
}

Vec3d Properties::Point(const std::string& name, const Vec3d& fallback) const {
  const Property* p = Find(name);
  if (!p) return fallback;
  if (auto* v = std::get_if<Vec3d>(&p->data)) return *v;
  WrongType(*p, "a <point>");
}

Vec3d Properties::Vector(const std::string& name, const Vec3d& fallback) const { return Point(name, fallback); }

Transform Properties::GetTransform(const std::string& name) const {
  const Property* p = Find(name);
  if (!p) return Transform();
  if (auto* t = std::get_if<Transform>(&p->data)) return *t;
  WrongType(*p, "a <transform>");
}

std::optional<SpectrumValue> Properties::SpectrumProp(const std::string& name) const {
  const Property* p = Find(name);
  if (!p) return std::nullopt;
  SpectrumValue s;
  if (auto* sv = std::get_if<SpectrumValue>(&p->data)) {
    s = *sv;
  } else if (std::holds_alternative<double>(p->data)) {
    s.kind = SpectrumValue::Kind::kConstant;
    s.value = float(Float(name));
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
  const Property* p = Find(name);
  if (!p) return nullptr;
  if (auto* o = std::get_if<std::shared_ptr<ObjectNode>>(&p->data)) return *o;
  return nullptr;
}

std::vector<std::shared_ptr<ObjectNode>> Properties::Children(const std::string& tag) const {
  std::vector<std::shared_ptr<ObjectNode>> out;
  for (const auto& c : node_.children)
    if (c->tag == tag) out.push_back(c);
  return out;
}

void Properties::WarnUnused() const {
  for (const Property& p : node_.props)
    if (!p.used)
      spdlog::warn("{}:{}: {} '{}' does not use the property '{}'", p.loc.file, p.loc.line, node_.tag, node_.type, p.name);
  for (const auto& c : node_.children)
    if (!c->used)
      spdlog::warn("{}:{}: {} '{}' does not use the nested {} '{}'", c->loc.file, c->loc.line, node_.tag, node_.type,
                   c->tag, c->type);
}

}  // namespace objektiv
