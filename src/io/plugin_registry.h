// The scene loader makes every object through a registry of plugins, one registry per kind
// of object (<sensor>, <film>, <rfilter>, <sampler>, <integrator>, <shape>, <bsdf>,
// <texture>, <emitter>), as Mitsuba 3 does. A plugin is a type name (type="..."), the
// properties it reads (their names and types) and a factory that reads them from Properties
// and makes the object; Properties allow only the declared reads, and what the file gives
// that the plugin did not read is warned about. The declarations are also what the test of
// docs/scene-format.md checks the reference against.
//
// Adding a plugin: write its factory (in its kind's file, or a file of its own) with its
// declarations next to it, add it to the kind's registry (one line), document it in
// docs/scene-format.md (the test says what is missing).
#pragma once
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/properties.h"

namespace objektiv {

template <typename Product, typename... Context>
struct Plugin {
  std::string type;
  std::vector<PropertyDecl> properties;  // what `make` reads, besides its kind's common ones
  std::function<Product(const Properties&, Context...)> make;
  std::vector<std::string> aliases = {};  // other type names for the same plugin
};

// A registry's description: what the scene-format reference documents.
struct PluginInfo {
  std::string type;
  std::vector<std::string> aliases;
  std::vector<PropertyDecl> properties;
};
struct PluginKind {
  std::string tag;                   // the element: "sensor", "bsdf", ...
  std::vector<PropertyDecl> common;  // read for every plugin of the kind (by its loader)
  std::vector<PluginInfo> plugins;
};

// Declarations `a` followed by `b` (a plugin that reads what another does, and more).
std::vector<PropertyDecl> Join(const std::vector<PropertyDecl>& a, const std::vector<PropertyDecl>& b);

// "unknown <tag> type 'x' (known: a, b, c)"
[[noreturn]] void ThrowUnknownType(const ObjectNode& node, const std::vector<std::string>& known);
// Throws std::logic_error if a type or a declaration (with the common ones) is given twice.
void CheckPluginKind(const PluginKind& kind);

template <typename Product, typename... Context>
class PluginRegistry {
 public:
  using PluginType = Plugin<Product, Context...>;

  PluginRegistry(std::string tag, std::vector<PropertyDecl> common, std::vector<PluginType> plugins)
      : tag_(std::move(tag)), common_(std::move(common)), plugins_(std::move(plugins)) {
    for (size_t i = 0; i < plugins_.size(); ++i) {
      by_type_[plugins_[i].type] = i;
      for (const std::string& alias : plugins_[i].aliases) by_type_[alias] = i;
    }
    CheckPluginKind(Describe());
  }

  // The plugin of `node`'s type; an error listing the known types if there is none.
  const PluginType& Find(const ObjectNode& node) const {
    auto it = by_type_.find(node.type);
    if (it == by_type_.end()) {
      std::vector<std::string> known;
      for (const auto& [type, i] : by_type_) known.push_back(type);
      ThrowUnknownType(node, known);
    }
    return plugins_[it->second];
  }
  // `node`'s properties as `plugin` and its kind declare them.
  Properties Open(const ObjectNode& node, const PluginType& plugin) const {
    return Properties(node, common_, plugin.properties);
  }
  // Makes `node` with its plugin, then warns about what the plugin did not read.
  Product Build(const ObjectNode& node, Context... context) const {
    const PluginType& plugin = Find(node);
    Properties props = Open(node, plugin);
    Product made = plugin.make(props, context...);
    props.WarnUnused();
    return made;
  }

  PluginKind Describe() const {
    PluginKind kind{tag_, common_, {}};
    for (const PluginType& p : plugins_) kind.plugins.push_back({p.type, p.aliases, p.properties});
    return kind;
  }

 private:
  std::string tag_;
  std::vector<PropertyDecl> common_;
  std::vector<PluginType> plugins_;
  std::map<std::string, size_t> by_type_;  // types and aliases, sorted (for the list of known types)
};

}  // namespace objektiv
