#include "app/view/sensor_overrides.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "base/error.h"
#include "io/scene_loader.h"

namespace objektiv {

namespace {

// The properties a value replaces (they would contradict it).
const std::map<std::string, std::vector<std::string>>& Contradicted() {
  static const std::map<std::string, std::vector<std::string>> kContradicted = {
      {"fnumber", {"aperture_diameter", "aperture_radius"}},
      {"aperture_diameter", {"fnumber"}},
      {"aperture_radius", {"fnumber"}},
      {"focus_distance", {"focus_point"}},
      {"focus_point", {"focus_distance"}},
      {"fov", {"focal_length"}},
      {"focal_length", {"fov"}},
  };
  return kContradicted;
}

template <typename T>
std::optional<T> As(const Property* p) {
  if (!p) return std::nullopt;
  if (const T* v = std::get_if<T>(&p->data)) return *v;
  return std::nullopt;
}

}  // namespace

void SensorOverrides::Set(const std::string& name, PropertyData value, const std::string& type_name) {
  Property p{name, std::move(value), type_name, Location{sensor_->loc.file, 0}};
  auto it = std::find_if(set_.begin(), set_.end(), [&name](const Property& q) { return q.name == name; });
  if (it != set_.end()) *it = std::move(p);
  else set_.push_back(std::move(p));
  std::erase(unset_, name);
  // A value set drops the values set that contradict it (the scene's are left out by removed()).
  if (auto c = Contradicted().find(name); c != Contradicted().end())
    for (const std::string& other : c->second) std::erase_if(set_, [&other](const Property& q) { return q.name == other; });
}

void SensorOverrides::Reset(const std::string& name) {
  std::erase_if(set_, [&name](const Property& p) { return p.name == name; });
  std::erase(unset_, name);
}

void SensorOverrides::Unset(const std::string& name) {
  Reset(name);
  unset_.push_back(name);
}

bool SensorOverrides::Removed(const std::string& name) const {
  if (std::find(unset_.begin(), unset_.end(), name) != unset_.end()) return true;
  for (const Property& p : set_)
    if (auto c = Contradicted().find(p.name); c != Contradicted().end())
      if (std::find(c->second.begin(), c->second.end(), name) != c->second.end()) return true;
  return false;
}

std::vector<std::string> SensorOverrides::removed() const {
  std::vector<std::string> names;
  for (const Property& p : sensor_->props)
    if (Removed(p.name) && std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
  return names;
}

ObjectNode SensorOverrides::Node() const {
  ObjectNode node = *sensor_;
  for (Property& p : node.props) p.used = false;
  std::erase_if(node.props, [this](const Property& p) {
    return Removed(p.name) || std::any_of(set_.begin(), set_.end(), [&p](const Property& q) { return q.name == p.name; });
  });
  for (const Property& p : set_) node.props.push_back(p);
  return node;
}

const Property* SensorOverrides::Find(const std::string& name) const {
  for (const Property& p : set_)
    if (p.name == name) return &p;
  if (Removed(name)) return nullptr;
  for (const Property& p : sensor_->props)
    if (p.name == name) return &p;
  return nullptr;
}

std::optional<double> SensorOverrides::Float(const std::string& name) const {
  const Property* p = Find(name);
  if (auto i = As<int64_t>(p)) return double(*i);
  return As<double>(p);
}
std::optional<int64_t> SensorOverrides::Integer(const std::string& name) const { return As<int64_t>(Find(name)); }
std::optional<bool> SensorOverrides::Boolean(const std::string& name) const { return As<bool>(Find(name)); }
std::optional<std::string> SensorOverrides::String(const std::string& name) const { return As<std::string>(Find(name)); }

std::optional<PropertyDecl> SensorPropertyDecl(const std::string& sensor_type, const std::string& name) {
  for (const PluginKind& kind : ScenePluginKinds()) {
    if (kind.tag != "sensor") continue;
    for (const PropertyDecl& d : kind.common)
      if (d.name == name) return d;
    for (const PluginInfo& plugin : kind.plugins)
      if (plugin.type == sensor_type)
        for (const PropertyDecl& d : plugin.properties)
          if (d.name == name) return d;
  }
  return std::nullopt;
}

namespace {

std::optional<double> Number(const std::string& text) {
  double v = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

SensorValue ParseSensorValue(const std::string& sensor_type, const std::string& name, const std::string& text) {
  const std::optional<PropertyDecl> decl = SensorPropertyDecl(sensor_type, name);
  if (!decl) throw InputError(fmt::format("a '{}' sensor has no property '{}'", sensor_type, name));
  auto bad = [&](const char* what) {
    return InputError(fmt::format("{}: '{}' is not {}", name, text, what));
  };
  switch (decl->type) {
    case PropType::kFloat:
      if (auto v = Number(text)) return {*v, "float"};
      throw bad("a number");
    case PropType::kInteger: {
      int64_t v = 0;
      auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec == std::errc() && ptr == text.data() + text.size()) return {v, "integer"};
      throw bad("an integer");
    }
    case PropType::kBoolean:
      if (text == "true") return {true, "boolean"};
      if (text == "false") return {false, "boolean"};
      throw bad("true or false");
    case PropType::kString:
      if (!decl->choices.empty() && std::find(decl->choices.begin(), decl->choices.end(), text) == decl->choices.end())
        throw bad(fmt::format("one of {}", fmt::join(decl->choices, ", ")).c_str());
      return {text, "string"};
    case PropType::kFloatOrString:
      if (auto v = Number(text)) return {*v, "float"};
      return {text, "string"};
    case PropType::kPoint:
    case PropType::kVector: {
      std::string t = text;
      std::replace(t.begin(), t.end(), ',', ' ');
      std::istringstream in(t);
      std::string a, b, c, rest;
      in >> a >> b >> c;
      auto x = Number(a), y = Number(b), z = Number(c);
      if (!x || !y || !z || (in >> rest)) throw bad("three numbers x, y, z");
      return {Vec3d(*x, *y, *z), decl->type == PropType::kPoint ? "point" : "vector"};
    }
    default:
      throw InputError(fmt::format("{} cannot be set from text (the viewer's controls set it)", name));
  }
}

}  // namespace objektiv
