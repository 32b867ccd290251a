#include "app/view/scene_with_camera.h"

#include <filesystem>
#include <sstream>

#include <fmt/format.h>
#include <pugixml.hpp>

#include "base/error.h"
#include "base/output_file.h"
#include "base/text_file.h"

namespace objektiv {

namespace {

// Shortest text that reads back to the same double.
std::string Number(double v) { return fmt::format("{}", v); }

// Removes the elements directly under `parent` whose name attribute is `name`.
void RemoveNamed(pugi::xml_node parent, const std::string& name) {
  for (pugi::xml_node c = parent.first_child(); c;) {
    pugi::xml_node next = c.next_sibling();
    if (c.type() == pugi::node_element && name == c.attribute("name").value()) parent.remove_child(c);
    c = next;
  }
}

// A property element in `parent`, before its nested objects (film, sampler), else last.
pugi::xml_node AddProperty(pugi::xml_node parent, const char* tag, const std::string& name) {
  RemoveNamed(parent, name);
  pugi::xml_node before;
  for (pugi::xml_node c : parent.children())
    if (c.type() == pugi::node_element && !c.attribute("name") && std::string(c.name()) != "ref") {
      before = c;
      break;
    }
  pugi::xml_node e = before ? parent.insert_child_before(tag, before) : parent.append_child(tag);
  e.append_attribute("name") = name.c_str();
  return e;
}

void WriteProperty(pugi::xml_node sensor, const Property& p) {
  const std::string& type = p.type_name;
  if (const double* v = std::get_if<double>(&p.data)) {
    AddProperty(sensor, "float", p.name).append_attribute("value") = Number(*v).c_str();
  } else if (const int64_t* i = std::get_if<int64_t>(&p.data)) {
    AddProperty(sensor, "integer", p.name).append_attribute("value") = std::to_string(*i).c_str();
  } else if (const bool* b = std::get_if<bool>(&p.data)) {
    AddProperty(sensor, "boolean", p.name).append_attribute("value") = *b ? "true" : "false";
  } else if (const std::string* s = std::get_if<std::string>(&p.data)) {
    AddProperty(sensor, "string", p.name).append_attribute("value") = s->c_str();
  } else if (const Vec3d* v3 = std::get_if<Vec3d>(&p.data)) {
    pugi::xml_node e = AddProperty(sensor, type == "vector" ? "vector" : "point", p.name);
    e.append_attribute("x") = Number(v3->x).c_str();
    e.append_attribute("y") = Number(v3->y).c_str();
    e.append_attribute("z") = Number(v3->z).c_str();
  } else if (const Transform* t = std::get_if<Transform>(&p.data)) {
    std::string values;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) values += (values.empty() ? "" : " ") + Number(t->Matrix().m[r][c]);
    AddProperty(sensor, "transform", p.name).append_child("matrix").append_attribute("value") = values.c_str();
  } else {
    throw InputError(fmt::format("the viewer cannot write the sensor's {} (a {})", p.name, type));
  }
}

}  // namespace

void WriteSceneWithCamera(const SceneWithCamera& what, const std::string& xml_path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path scene_dir = fs::weakly_canonical(fs::absolute(what.scene_path, ec).parent_path(), ec);
  const fs::path out_dir = fs::weakly_canonical(fs::absolute(xml_path, ec).parent_path(), ec);
  if (scene_dir != out_dir)
    throw InputError(fmt::format("{}: save the camera beside the scene, in {} (the scene's relative file names "
                                 "resolve from its folder)", xml_path, scene_dir.string()));
  const std::string text = ReadTextFile(what.scene_path, "scene");
  pugi::xml_document doc;
  const pugi::xml_parse_result r =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_comments | pugi::parse_declaration);
  if (!r) throw InputError(fmt::format("{}: {}", what.scene_path, r.description()));
  pugi::xml_node sensor = doc.child("scene").child("sensor");
  if (!sensor)
    throw InputError(fmt::format("{}: its <sensor> is in an included file; the viewer saves the camera of a scene "
                                 "whose own file holds the <sensor>", what.scene_path));
  // The -D values: the file's <default>s take them (a name it has none for gets one).
  pugi::xml_node scene = doc.child("scene");
  for (auto it = what.defines.rbegin(); it != what.defines.rend(); ++it) {
    pugi::xml_node d = scene.find_child_by_attribute("default", "name", it->first.c_str());
    if (!d) {
      d = scene.prepend_child("default");
      d.append_attribute("name") = it->first.c_str();
      d.append_attribute("value");
    }
    d.attribute("value").set_value(it->second.c_str());
  }
  for (const std::string& name : what.sensor->removed()) RemoveNamed(sensor, name);
  for (const Property& p : what.sensor->set()) WriteProperty(sensor, p);
  if (what.sample_count) {
    pugi::xml_node sampler = sensor.child("sampler");
    if (!sampler) {
      sampler = sensor.append_child("sampler");
      sampler.append_attribute("type") = "independent";
    }
    AddProperty(sampler, "integer", "sample_count").append_attribute("value") = *what.sample_count;
  }
  if (what.whole_film)
    for (const char* crop : {"crop_offset_x", "crop_offset_y", "crop_width", "crop_height"})
      RemoveNamed(sensor.child("film"), crop);
  if (what.film_size || what.exposure) {
    pugi::xml_node film = sensor.child("film");
    if (!film) {
      film = sensor.append_child("film");
      film.append_attribute("type") = "hdrfilm";
    }
    if (what.film_size) {
      AddProperty(film, "integer", "width").append_attribute("value") = what.film_size->x;
      AddProperty(film, "integer", "height").append_attribute("value") = what.film_size->y;
    }
    if (what.exposure) AddProperty(film, "float", "exposure").append_attribute("value") = Number(*what.exposure).c_str();
  }
  sensor.prepend_child(pugi::node_comment).set_value(" the camera as set in objektiv view ");
  std::ostringstream out;
  doc.save(out, "  ");
  WriteTextFileAtomically(xml_path, out.str());
}

}  // namespace objektiv
