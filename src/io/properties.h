// Typed, checked access to an object's properties (in the spirit of Mitsuba's Properties):
// a missing required property, a property of the wrong type or a value out of range is an
// error naming the file and line; a property nobody asked for is a warning.
#pragma once
#include <optional>

#include "io/xml_document.h"

namespace objektiv {

class Properties {
 public:
  explicit Properties(const ObjectNode& node) : node_(node) { node.used = true; }

  const Location& loc() const { return node_.loc; }
  const std::string& type() const { return node_.type; }
  const ObjectNode& node() const { return node_; }
  bool Has(const std::string& name) const { return Find(name) != nullptr; }
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
  // One of the given choices.
  std::string Choice(const std::string& name, const std::string& fallback, std::initializer_list<const char*> choices) const;
  Vec3d Point(const std::string& name, const Vec3d& fallback) const;
  Vec3d Vector(const std::string& name, const Vec3d& fallback) const;
  Transform GetTransform(const std::string& name) const;  // identity if absent
  // A float, rgb or spectrum property.
  std::optional<SpectrumValue> SpectrumProp(const std::string& name) const;
  // A named nested object (e.g. a texture given as <texture name="reflectance">).
  std::shared_ptr<ObjectNode> Object(const std::string& name) const;
  // Unnamed nested objects with this tag (marks them used).
  std::vector<std::shared_ptr<ObjectNode>> Children(const std::string& tag) const;

  // Warns (once per object) about properties and nested objects that were never read.
  void WarnUnused() const;

 private:
  const Property* Find(const std::string& name) const;
  [[noreturn]] void WrongType(const Property& p, const char* expected) const;
  const ObjectNode& node_;
};

}  // namespace objektiv
