#include "optics/lens_glasses.h"

#include <filesystem>
#include <map>
#include <set>

#include "base/log.h"
#include "optics/glass_file.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

// The AGF files in `dir`, by upper-case name without the extension (NAME.AGF in any case).
std::map<std::string, std::string> AgfFilesIn(const fs::path& dir) {
  std::map<std::string, std::string> files;
  std::error_code ec;
  for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    if (GlassKey(p.extension().string()) == ".AGF" && it->is_regular_file(ec))
      files.emplace(GlassKey(p.stem().string()), p.string());
  }
  return files;
}

}  // namespace

LensGlasses::LensGlasses(const std::string& lens_path, const GlassCatalog& shipped,
                         const std::vector<NamedCatalog>& named)
    : lookup_(shipped), lens_path_(lens_path) {
  const fs::path path(lens_path);
  std::error_code ec;
  if (fs::path file = fs::path(path).replace_extension(".glass"); fs::is_regular_file(file, ec)) {
    auto user = std::make_shared<GlassCatalog>();
    LoadGlassFile(*user, file.string(), file.filename().string());
    spdlog::info("{}: glasses from {} are searched first", lens_path, file.string());
    glass_file_ = file.string();
    lookup_.SetUserGlasses(user);
  }
  auto beside = std::make_shared<GlassCatalog>();
  std::vector<std::string> names;
  std::set<std::string> seen;
  const std::map<std::string, std::string> agf_files = named.empty() ? std::map<std::string, std::string>{}
                                                                      : AgfFilesIn(path.parent_path());
  for (const NamedCatalog& c : named) {
    if (!seen.insert(GlassKey(c.name)).second) continue;  // named twice
    names.push_back(GlassKey(c.name));
    if (auto agf = agf_files.find(GlassKey(c.name)); agf != agf_files.end()) {
      beside->LoadAgf(agf->second, GlassKey(c.name));
      if (shipped.HasCatalog(c.name))
        spdlog::info("{}:{}: catalog {} is read from {} (not the shipped one)", lens_path, c.line, c.name, agf->second);
    } else if (!shipped.HasCatalog(c.name)) {
      std::string list;
      for (const std::string& s : shipped.catalogs()) list += (list.empty() ? "" : ", ") + s;
      spdlog::warn("{}:{}: glass catalog {} is not shipped ({}) and no {}.AGF lies beside the lens: its glasses are "
                   "looked up in the shipped catalogs",
                   lens_path, c.line, c.name, list, c.name);
    }
  }
  lookup_.Prefer(names, beside);
}

std::optional<GlassMatch> LensGlasses::Find(std::string_view name, int line, std::optional<StatedGlass> stated) const {
  std::optional<GlassMatch> m = lookup_.Find(name, stated);
  if (m && noted_.insert(GlassKey(name)).second)
    if (std::string note = SubstitutionNote(name, *m); !note.empty()) spdlog::warn("{}:{}: {}", lens_path_, line, note);
  return m;
}

void LensGlasses::WarnUnused() const {
  std::vector<std::string> unused = lookup_.UnusedUserGlasses();
  if (unused.empty()) return;
  std::string list;
  for (const std::string& n : unused) list += (list.empty() ? "" : ", ") + n;
  spdlog::warn("{}: glass(es) no surface of the lens uses: {}", glass_file_, list);
}

}  // namespace objektiv
