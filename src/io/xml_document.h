// Reads a scene file into a tree of object nodes with typed properties, resolving
// <include>, <default>, $name substitution (overridable from the command line) and <ref>.
// Every node and property remembers its file and line for error messages.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "base/error.h"
#include "base/spectrum.h"
#include "base/transform.h"

namespace objektiv {

// Limits on a scene, far beyond any real one, so that a hostile file ends in an error rather
// than a stack overflow or an exponential blow-up: objects nested in objects (counting those
// a <ref> brings in), includes nested in includes, <include>s in all. The XML read in all (the
// scene and each include, as often as included) and the text made by $parameter substitution
// are each bounded by kMaxTextFileBytes.
inline constexpr int kMaxObjectNesting = 100;
inline constexpr int kMaxIncludeDepth = 16;
inline constexpr int kMaxIncludes = 10000;

struct Location {
  std::string file;
  int line = 0;
};

template <typename... Args>
InputError ErrorAt(const Location& loc, fmt::format_string<Args...> f, Args&&... args) {
  return MakeInputError(loc.file, loc.line, f, std::forward<Args>(args)...);
}

struct ObjectNode;

// A spectrum as written in the file; turned into a Spectrum once its use is known
// (reflectance, unbounded or illuminant), as Mitsuba does.
struct SpectrumValue {
  enum class Kind { kRgb, kConstant, kSampled, kBlackbody, kD65, kIlluminantA } kind = Kind::kConstant;
  Vec3f rgb;
  float value = 0;
  std::vector<float> lambdas, values;
  float temperature = 0;
};

using PropertyData = std::variant<double, int64_t, bool, std::string, SpectrumValue, Vec3d /*point or vector*/,
                                  Transform, std::shared_ptr<ObjectNode>>;

struct Property {
  std::string name;
  PropertyData data;
  std::string type_name;  // the tag it was written with: float, integer, rgb, ...
  Location loc;
  mutable bool used = false;
};

struct ObjectNode {
  std::string tag;   // bsdf, shape, emitter, sensor, film, sampler, rfilter, integrator, texture
  std::string type;  // plugin type, e.g. "diffuse"
  std::string id;
  Location loc;
  std::vector<Property> props;                        // typed values and named nested objects
  std::vector<std::shared_ptr<ObjectNode>> children;  // unnamed nested objects (in order)
  int height = 0;  // levels of objects below this one (at most kMaxObjectNesting)
  mutable bool used = false;
};

struct SceneDocument {
  std::shared_ptr<ObjectNode> root;  // tag "scene"
};

// Parses `path`. `defines` override <default> values (from -D name=value).
SceneDocument ParseSceneFile(const std::string& path, const std::map<std::string, std::string>& defines);
// The same from a string (for tests); `name` stands for the file name in messages.
SceneDocument ParseSceneString(const std::string& xml, const std::string& name,
                               const std::map<std::string, std::string>& defines);

}  // namespace objektiv
