// The scene's <sensor> as the viewer changes it: properties set over the scene's own (replacing
// a value, or adding one the scene left at its default), kept apart from the scene's node, which
// stays as read. The camera is built from the node with them (io/scene_loader.h: BuildCamera,
// the same code a render uses, so that every value is checked as a scene's is), and the saved
// camera (app/view/scene_with_camera.h) writes them.
//
// Setting a property removes the scene's properties that would contradict it: an f-number
// replaces an aperture diameter or radius, a focus distance a focus point and the reverse, a
// field of view a focal length.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/properties.h"
#include "io/xml_document.h"

namespace objektiv {

class SensorOverrides {
 public:
  // `sensor`: the scene's <sensor> node. The values set are located at the scene file (line
  // 0), so that a relative file name in them (a lens file) resolves from the scene's folder,
  // as in the scene and in the saved camera.
  explicit SensorOverrides(std::shared_ptr<const ObjectNode> sensor) : sensor_(std::move(sensor)) {}

  // `type_name`: the tag the value would be written with (float, integer, boolean, string,
  // point, transform).
  void Set(const std::string& name, PropertyData value, const std::string& type_name);
  void SetFloat(const std::string& name, double v) { Set(name, v, "float"); }
  void SetInteger(const std::string& name, int64_t v) { Set(name, v, "integer"); }
  void SetBoolean(const std::string& name, bool v) { Set(name, v, "boolean"); }
  void SetString(const std::string& name, const std::string& v) { Set(name, v, "string"); }
  // Back to the scene's value (or its default), and the scene's properties it had replaced
  // back too (unless another value set replaces them).
  void Reset(const std::string& name);
  // Left out: the property's default, whatever the scene says (focus at infinity, wide open).
  void Unset(const std::string& name);

  // The node the camera is built from: the scene's with the values set (a copy).
  ObjectNode Node() const;
  // The same over another scene's sensor (the scene read again after it changed on disk).
  void Rebase(std::shared_ptr<const ObjectNode> sensor) { sensor_ = std::move(sensor); }

  // A property as the node has it now (set here, else the scene's); empty where neither gives
  // it or it has another type.
  const Property* Find(const std::string& name) const;
  std::optional<double> Float(const std::string& name) const;
  std::optional<int64_t> Integer(const std::string& name) const;
  std::optional<bool> Boolean(const std::string& name) const;
  std::optional<std::string> String(const std::string& name) const;

  const std::string& type() const { return sensor_->type; }
  const ObjectNode& scene_sensor() const { return *sensor_; }
  // The values set, in the order they were first set.
  const std::vector<Property>& set() const { return set_; }
  // Names of the scene's properties left out: unset, or replaced by a value set that
  // contradicts them.
  std::vector<std::string> removed() const;

 private:
  bool Removed(const std::string& name) const;
  std::shared_ptr<const ObjectNode> sensor_;
  std::vector<Property> set_;
  std::vector<std::string> unset_;
};

// The declaration of a property that a sensor type reads (the scene reader's registry), if it
// reads it; the common ones (to_world, far_clip) included.
std::optional<PropertyDecl> SensorPropertyDecl(const std::string& sensor_type, const std::string& name);
// A property's value from text (a script's or a field's): a number, an integer, true or false,
// one of its choices, or "x, y, z", as the property is declared; the tag it is written with.
// InputError where the sensor type does not read it or the text is not such a value.
struct SensorValue {
  PropertyData data;
  std::string type_name;
};
SensorValue ParseSensorValue(const std::string& sensor_type, const std::string& name, const std::string& text);

}  // namespace objektiv
