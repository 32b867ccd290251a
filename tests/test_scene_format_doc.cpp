// The scene-format reference (docs/scene-format.md) against the loader's plugin registries:
// every plugin and every property a plugin reads is documented, with its type and (for an
// enumerated string) its allowed values, and the reference names no plugin or property that
// does not exist.
//
// What the test reads in the reference: a "## " heading naming an element (`<shape>`) starts
// that kind; a "### " heading in it starts a plugin, named by the heading's `types` (the
// first, then its aliases); a line "As `other`, plus:" makes the plugin read what `other`
// reads; tables headed "| property | type | meaning |" list properties (one or more `names`
// a row, `<tag>` for a nested object), before the first plugin those of every plugin of
// the kind (or, as the text says, of most of them).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "io/scene_loader.h"

namespace objektiv {
namespace {

struct DocProperty {
  std::string type;                    // the type column
  std::vector<std::string> mentioned;  // `words` of the meaning column
  int line;
};
using DocProperties = std::map<std::pair<std::string, bool>, DocProperty>;  // (name, nested) -> row

struct DocPlugin {
  std::vector<std::string> types;  // the type, then its aliases
  DocProperties properties;        // its own (and what it inherits)
  int line;
};

struct DocKind {
  DocProperties common;
  std::vector<DocPlugin> plugins;
};

std::vector<std::string> Backticked(const std::string& text) {
  std::vector<std::string> out;
  static const std::regex word("`([^`]+)`");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

std::vector<std::string> Cells(const std::string& row) {
  std::vector<std::string> cells;
  std::stringstream in(row.substr(1));
  std::string cell;
  while (std::getline(in, cell, '|')) {
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    cells.push_back(cell);
  }
  return cells;
}

std::map<std::string, DocKind> ReadReference(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::map<std::string, DocKind> kinds;
  DocKind* kind = nullptr;
  DocPlugin* plugin = nullptr;
  bool in_table = false;
  std::string line;
  static const std::regex tag_heading("^## .*`<([a-z]+)>`");
  for (int n = 1; std::getline(in, line); ++n) {
    std::smatch m;
    if (line.rfind("## ", 0) == 0) {
      kind = std::regex_search(line, m, tag_heading) ? &kinds[m[1]] : nullptr;
      plugin = nullptr;
    } else if (line.rfind("### ", 0) == 0 && kind) {
      kind->plugins.push_back({Backticked(line), {}, n});
      plugin = &kind->plugins.back();
      EXPECT_FALSE(plugin->types.empty()) << path << ":" << n << ": a plugin heading without a `type`";
    } else if (line.rfind("As `", 0) == 0 && plugin) {
      const std::string base = Backticked(line)[0];
      bool found = false;
      for (const DocPlugin& p : kind->plugins)
        if (&p != plugin && p.types[0] == base) plugin->properties = p.properties, found = true;
      EXPECT_TRUE(found) << path << ":" << n << ": '" << base << "' is not documented before";
    } else if (line == "| property | type | meaning |") {
      in_table = true;
    } else if (in_table && line.rfind("|", 0) == 0) {
      if (line.rfind("|---", 0) == 0 || !kind) continue;
      std::vector<std::string> cells = Cells(line);
      EXPECT_EQ(cells.size(), 3u) << path << ":" << n;
      if (cells.size() != 3) continue;
      DocProperties& props = plugin ? plugin->properties : kind->common;
      for (std::string name : Backticked(cells[0])) {
        const bool nested = name.front() == '<';
        if (nested) name = name.substr(1, name.size() - 2);
        props[{name, nested}] = {cells[1], Backticked(cells[2]), n};
      }
    } else {
      in_table = false;
    }
  }
  return kinds;
}

std::string Describe(const std::string& tag, const std::string& type, const std::string& name, bool nested) {
  return "<" + tag + " type=\"" + type + "\">: " + (nested ? "nested <" + name + ">" : "property '" + name + "'");
}

TEST(SceneFormatDoc, DocumentsEveryPluginAndPropertyAndNothingElse) {
  const std::string path = OBJEKTIV_DOCS_DIR "/scene-format.md";
  std::map<std::string, DocKind> doc = ReadReference(path);
  std::vector<PluginKind> kinds = ScenePluginKinds();
  std::set<std::string> tags;
  for (const PluginKind& kind : kinds) {
    EXPECT_TRUE(tags.insert(kind.tag).second) << "two registries for <" << kind.tag << ">";
    auto dk = doc.find(kind.tag);
    if (dk == doc.end()) {
      ADD_FAILURE() << path << " has no section for <" << kind.tag << "> (a '## ' heading naming `<" << kind.tag
                    << ">`)";
      continue;
    }
    const DocKind& dkind = dk->second;
    // Types and aliases.
    std::map<std::string, const DocPlugin*> documented;
    for (const DocPlugin& p : dkind.plugins) {
      for (const std::string& type : p.types) documented[type] = &p;
    }
    std::set<std::string> registered;
    // What some plugin of the kind reads: the kind's common table must name nothing else.
    std::map<std::pair<std::string, bool>, std::set<std::string>> read_by_some;
    for (const PluginInfo& plugin : kind.plugins) {
      registered.insert(plugin.type);
      registered.insert(plugin.aliases.begin(), plugin.aliases.end());
      auto dp = documented.find(plugin.type);
      if (dp == documented.end()) {
        ADD_FAILURE() << path << " does not document <" << kind.tag << " type=\"" << plugin.type << "\">";
        continue;
      }
      const DocPlugin& dplugin = *dp->second;
      EXPECT_EQ(dplugin.types[0], plugin.type) << path << ":" << dplugin.line << ": the plugin's type comes first";
      std::set<std::string> doc_aliases(dplugin.types.begin() + 1, dplugin.types.end());
      EXPECT_EQ(doc_aliases, std::set<std::string>(plugin.aliases.begin(), plugin.aliases.end()))
          << path << ":" << dplugin.line << ": the aliases of <" << kind.tag << " type=\"" << plugin.type << "\">";
      // Every property the plugin reads is documented for it (or for its kind), as its type.
      std::set<std::pair<std::string, bool>> declared;
      for (const auto* decls : {&kind.common, &plugin.properties})
        for (const PropertyDecl& d : *decls) {
          const bool nested = d.type == PropType::kObject;
          declared.insert({d.name, nested});
          read_by_some[{d.name, nested}].insert(PropTypeName(d.type));
          const std::string what = Describe(kind.tag, plugin.type, d.name, nested);
          const DocProperty* row = nullptr;
          if (auto it = dplugin.properties.find({d.name, nested}); it != dplugin.properties.end())
            row = &it->second;
          else if (auto c = dkind.common.find({d.name, nested}); c != dkind.common.end())
            row = &c->second;
          if (!row) {
            ADD_FAILURE() << path << ":" << dplugin.line << ": " << what << " (" << PropTypeName(d.type)
                          << ") is not documented";
            continue;
          }
          EXPECT_EQ(row->type, PropTypeName(d.type)) << path << ":" << row->line << ": the type of " << what;
          for (const std::string& choice : d.choices)
            if (std::find(row->mentioned.begin(), row->mentioned.end(), choice) == row->mentioned.end())
              ADD_FAILURE() << path << ":" << row->line << ": " << what << " does not list its value `" << choice
                            << "`";
        }
      // Nothing documented for the plugin that it does not read.
      for (const auto& [key, row] : dplugin.properties)
        EXPECT_TRUE(declared.count(key)) << path << ":" << row.line << ": "
                                         << Describe(kind.tag, plugin.type, key.first, key.second)
                                         << " is documented but not read";
    }
    for (const auto& [type, p] : documented)
      EXPECT_TRUE(registered.count(type)) << path << ":" << p->line << ": <" << kind.tag << " type=\"" << type
                                          << "\"> is documented but does not exist";
    for (const auto& [key, row] : dkind.common) {
      auto it = read_by_some.find(key);
      EXPECT_TRUE(it != read_by_some.end() && it->second == std::set<std::string>{row.type})
          << path << ":" << row.line << ": no <" << kind.tag << "> reads " << (key.second ? "nested <" : "'")
          << key.first << (key.second ? ">" : "'") << " as a " << row.type;
    }
  }
  for (const auto& [tag, kind] : doc)
    EXPECT_TRUE(tags.count(tag)) << path << ": documents <" << tag << ">, which the loader does not make";
}

}  // namespace
}  // namespace objektiv
