#include "io/plugin_registry.h"

#include <set>

namespace objektiv {

std::vector<PropertyDecl> Join(const std::vector<PropertyDecl>& a, const std::vector<PropertyDecl>& b) {
  std::vector<PropertyDecl> out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

void ThrowUnknownType(const ObjectNode& node, const std::vector<std::string>& known) {
  std::string list;
  for (const std::string& type : known) list += (list.empty() ? "" : ", ") + type;
  throw ErrorAt(node.loc, "unknown {} type '{}' (known: {})", node.tag, node.type, list);
}

void CheckPluginKind(const PluginKind& kind) {
  std::set<std::string> types;
  for (const PluginInfo& plugin : kind.plugins) {
    std::vector<std::string> names = plugin.aliases;
    names.push_back(plugin.type);
    for (const std::string& type : names)
      if (!types.insert(type).second)
        throw std::logic_error(fmt::format("{} type '{}' registered twice", kind.tag, type));
    std::set<std::pair<std::string, bool>> declared;
    for (const auto* decls : {&kind.common, &plugin.properties})
      for (const PropertyDecl& d : *decls) {
        if (!declared.insert({d.name, d.type == PropType::kObject}).second)
          throw std::logic_error(fmt::format("{} '{}' declares '{}' twice", kind.tag, plugin.type, d.name));
      }
  }
}

}  // namespace objektiv
