// Typed, checked access to an object's properties (in the spirit of Mitsuba's Properties):
// a missing required property, a property of the wrong type or a value out of range is an
// error naming the file and line; a property nobody asked for is a warning.
//
// A plugin declares what it reads (name and type, see PropertyDecl) and its Properties allow
// only those reads: reading a name it did not declare, or as another type, is a programming
// error (std::logic_error), so the declarations, which the scene-format reference is checked
// against, are what the plugins read.
#pragma once
#include <array>
#include <optional>
#include <set>
#include <span>
#include <string_view>

#include "io/xml_document.h"

namespace objektiv {

// What a plugin reads a property as (the scene-format reference's "type" column).
enum class PropType {
  kFloat,              // <float> (or <integer>)
  kInteger,            // <integer>
  kBoolean,            // <boolean>
  kString,             // <string>; with choices: one of them
  kFloatOrString,      // a number or a name (an index of refraction, "50mm")
  kSpectrum,           // <float>, <rgb> or <spectrum>
  kSpectrumOrTexture,  // a spectrum, or a nested or referenced <texture> bound by name
  kPoint,              // <point>
  kVector,             // <vector>
  kTransform,          // <transform>
  kObject,             // an unnamed nested object, declared by its tag (<film>, <bsdf>, ...)
  kMedium,             // a nested or referenced <medium> bound by name (interior, exterior)
};
// The word the scene-format reference uses for it ("float", "spectrum or texture", ...).
const char* PropTypeName(PropType t);

// What a property was written as.
enum class ValueType { kFloat, kInteger, kBoolean, kString, kRgb, kSpectrum, kPoint, kVector, kTransform, kObject };

// An entry of an enumerated string property's table: the name a user writes, the value meant.
template <typename E>
struct Named {
  const char* name;
  E value;
};

struct PropertyDecl {
  PropertyDecl(std::string name, PropType type) : name(std::move(name)), type(type) {}
  // An enumerated string: its allowed values are the names of `table` (read with Choice).
  template <typename E, size_t N>
  PropertyDecl(std::string name, const Named<E> (&table)[N]) : name(std::move(name)), type(PropType::kString) {
    for (const Named<E>& n : table) choices.emplace_back(n.name);
  }

  std::string name;  // the property's name, or the nested object's tag (kObject)
  PropType type;
  std::vector<std::string> choices;  // allowed values of an enumerated string
};

class Properties {
 public:
  // `common` (the plugin's kind's) and `own` declare what may be read; both must outlive this.
  Properties(const ObjectNode& node, const std::vector<PropertyDecl>& common, const std::vector<PropertyDecl>& own)
      : node_(node), common_(common), own_(own) {
    node.used = true;
  }
  // Not from temporary declarations: Properties keeps references.
  Properties(const ObjectNode&, std::vector<PropertyDecl>&&, const std::vector<PropertyDecl>&) = delete;
  Properties(const ObjectNode&, const std::vector<PropertyDecl>&, std::vector<PropertyDecl>&&) = delete;
  Properties(const ObjectNode&, std::vector<PropertyDecl>&&, std::vector<PropertyDecl>&&) = delete;

  const Location& loc() const { return node_.loc; }
  const std::string& type() const { return node_.type; }
  bool Has(const std::string& name) const { return Find(name) != nullptr; }
  // What the property was written as (nullopt if absent).
  std::optional<ValueType> TypeOf(const std::string& name) const;
  // Location of a property (or of the object when absent), for range errors.
  Location LocOf(const std::string& name) const;

  double Float(const std::string& name) const;
  double Float(const std::string& name, double fallback) const;
  // A float that must lie in [lo, hi].
  double FloatIn(const std::string& name, double fallback, double lo, double hi) const;
  int64_t Int(const std::string& name, int64_t fallback) const;
  int64_t IntIn(const std::string& name, int64_t fallback, int64_t lo, int64_t hi) const;
  bool Bool(const std::string& name, bool fallback) const;
  std::string String(const std::string& name) const;
  std::string String(const std::string& name, const std::string& fallback) const;
  // An enumerated string: the value `table` names for it, `fallback` if absent; any other
  // string is an error listing the table's names.
  template <typename E, size_t N>
  E Choice(const std::string& name, E fallback, const Named<E> (&table)[N]) const {
    std::array<const char*, N> names;
    for (size_t i = 0; i < N; ++i) names[i] = table[i].name;
    std::optional<size_t> i = ChoiceIndex(name, names);
    return i ? table[*i].value : fallback;
  }
  Vec3d Point(const std::string& name, const Vec3d& fallback) const;
  Vec3d Vector(const std::string& name, const Vec3d& fallback) const;
  Transform GetTransform(const std::string& name) const;  // identity if absent
  // A float, rgb or spectrum property.
  std::optional<SpectrumValue> SpectrumProp(const std::string& name) const;
  // A named nested object (a texture given as <texture name="reflectance">, a medium as
  // <medium name="interior">).
  std::shared_ptr<ObjectNode> Object(const std::string& name) const;
  // Unnamed nested objects with this tag (marks them used).
  std::vector<std::shared_ptr<ObjectNode>> Children(const std::string& tag) const;

  // Warns (once per object) about properties and nested objects that were never read.
  void WarnUnused() const;

 private:
  // The declaration of `name` (a nested object's tag if `nested`); throws std::logic_error
  // unless it is declared as one of `types` (any type if empty).
  const PropertyDecl& Declared(std::string_view name, std::initializer_list<PropType> types, bool nested = false) const;
  // The property, marked used (nullptr if absent), after checking the read against its declaration.
  const Property* Find(const std::string& name, std::initializer_list<PropType> types = {}) const;
  std::optional<size_t> ChoiceIndex(const std::string& name, std::span<const char* const> names) const;
  double ToFloat(const Property& p) const;  // a <float> or <integer> within single precision
  Vec3d Triple(const std::string& name, const Vec3d& fallback, PropType type, const char* expected) const;
  [[noreturn]] void WrongType(const Property& p, const char* expected) const;
  const ObjectNode& node_;
  const std::vector<PropertyDecl>& common_;
  const std::vector<PropertyDecl>& own_;
  // The nested objects Children() handed to the plugin: a <ref> can bring in an object that is
  // used elsewhere (so marked used) but is of a kind this plugin never asks for.
  mutable std::set<const ObjectNode*> handed_out_;
};

}  // namespace objektiv
