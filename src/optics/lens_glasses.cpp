#include "optics/lens_glasses.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "base/error.h"
#include "base/log.h"
#include "base/text_file.h"
#include "optics/glass_file.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

// The AGF files in `dir` (any entry NAME.AGF, in any case), by upper-case NAME.
std::map<std::string, std::vector<fs::directory_entry>> AgfEntriesIn(const fs::path& dir) {
  std::map<std::string, std::vector<fs::directory_entry>> entries;
  std::error_code ec;
  for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec))
    if (GlassKey(it->path().extension().string()) == ".AGF")
      entries[GlassKey(it->path().stem().string())].push_back(*it);
  return entries;
}

// The nearest shipped glasses to a stated nd and Vd, for the message about a glass in no catalog.
std::string NearestGlasses(const StatedGlass& stated, const GlassCatalog& shipped) {
  std::vector<std::pair<double, const Glass*>> by_distance;
  for (const Glass* g : shipped.All()) {
    double dn = (g->catalog_nd - stated.nd) / 1e-3, dv = (g->catalog_vd - stated.vd) / 0.5;
    by_distance.emplace_back(dn * dn + dv * dv, g);
  }
  const size_t n = std::min<size_t>(3, by_distance.size());
  std::partial_sort(by_distance.begin(), by_distance.begin() + n, by_distance.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string out;
  for (size_t i = 0; i < n; ++i) {
    const Glass& g = *by_distance[i].second;
    out += fmt::format("{}{}:{} {:.5f}/{:.2f}", i ? ", " : "", g.catalog(), g.name(), g.catalog_nd, g.catalog_vd);
  }
  return out;
}


}  // namespace

LensGlasses::LensGlasses(const std::string& lens_path, const GlassCatalog& shipped,
                         const std::vector<NamedCatalog>& named)
    : lookup_(shipped), lens_path_(lens_path) {
  const fs::path path(lens_path);
  std::error_code ec;
  const fs::path file = fs::path(path).replace_extension(".glass");
  if (fs::symlink_status(file, ec).type() != fs::file_type::not_found) {
    if (!fs::is_regular_file(file, ec))
      throw MakeInputError(file.string(), 0, "the glass file beside the lens is not a regular file");
    auto user = std::make_shared<GlassCatalog>();
    LoadGlassFile(*user, file.string(), file.filename().string());
    spdlog::info("{}: glasses from {} are searched first", lens_path, file.string());
    glass_file_ = file.string();
    lookup_.SetUserGlasses(user, file.filename().string());
  }
  auto beside = std::make_shared<GlassCatalog>();
  std::vector<std::string> names;
  std::set<std::string> seen;
  const auto agf_entries = named.empty() ? std::map<std::string, std::vector<fs::directory_entry>>{}
                                         : AgfEntriesIn(path.parent_path());
  std::string shipped_list;
  for (const std::string& s : shipped.catalogs()) shipped_list += (shipped_list.empty() ? "" : ", ") + s;
  for (const NamedCatalog& c : named) {
    const std::string key = GlassKey(c.name);
    if (!seen.insert(key).second) continue;  // named twice
    if (auto agf = agf_entries.find(key); agf != agf_entries.end()) {
      const std::vector<fs::directory_entry>& files = agf->second;
      if (files.size() > 1)
        throw MakeInputError(lens_path, c.line, "catalog {}: two files beside the lens name it ({} and {})",
                             Printable(c.name), files[0].path().string(), files[1].path().string());
      if (!files[0].is_regular_file(ec))
        throw MakeInputError(files[0].path().string(), 0, "catalog {} named on line {} of {} is not a regular file",
                             Printable(c.name), c.line, lens_path);
      beside->LoadAgf(files[0].path().string(), key);
      names.push_back(key);
      spdlog::info("{}:{}: catalog {} is read from {}{}", lens_path, c.line, key, files[0].path().string(),
                   shipped.HasCatalog(key) ? " (not the shipped one)" : "");
    } else if (shipped.HasCatalog(key)) {
      names.push_back(key);
    } else if (size_t cut = key.find('_'); cut != std::string::npos && shipped.HasCatalog(key.substr(0, cut))) {
      // A dated catalog (SUMITA_AUG2011, OHARA_2017): the maker's catalog as shipped.
      names.push_back(key.substr(0, cut));
      spdlog::warn("{}:{}: glass catalog {} is read as the shipped {} (put {}.AGF beside the lens for that edition)",
                   lens_path, c.line, Printable(c.name), key.substr(0, cut), Printable(c.name));
    } else {
      spdlog::warn("{}:{}: glass catalog {} is not shipped ({}) and no {}.AGF lies beside the lens: its glasses are "
                   "looked up in the shipped catalogs",
                   lens_path, c.line, Printable(c.name), shipped_list, Printable(c.name));
    }
  }
  lookup_.Prefer(names, beside);
}

std::shared_ptr<const Glass> LensGlasses::Resolve(const std::string& name, int line,
                                                  std::optional<StatedGlass> stated) const {
  std::optional<GlassMatch> m = lookup_.Find(name, stated);
  if (!m) {
    const std::string values = stated ? fmt::format(" nd={} vd={}", stated->nd, stated->vd) : " nd=N vd=V";
    const std::string where =
        glass_file_.empty()
            ? fmt::format("give it in {} beside the lens",
                          fs::path(lens_path_).filename().replace_extension(".glass").string())
            : fmt::format("add it to {}", glass_file_);
    throw MakeInputError(
        lens_path_, line,
        "glass {} is in no catalog (searched {}){}; {} (a line 'glass {}{}', or an index table: docs/lens-format.md){}",
        Printable(name), lookup_.SearchedCatalogs(),
        stated ? fmt::format(". The file states nd {} vd {}; the nearest shipped glasses are {}", stated->nd, stated->vd,
                             NearestGlasses(*stated, lookup_.shipped()))
               : "",
        where, Printable(name), values,
        GlassKey(fs::path(lens_path_).extension().string()) == ".ZMX"
            ? ", or put its maker's AGF catalog there and name it on the GCAT line"
            : "; a lens file may also write the medium as n=INDEX or nd=N,vd=V");
  }
  const Glass& g = *m->glass;
  if (noted_.insert(GlassKey(name)).second)
    if (std::string note = SubstitutionNote(name, *m); !note.empty()) spdlog::warn("{}:{}: {}", lens_path_, line, note);
  if (stated && !AgreesWith(g, *stated)) {
    const double nd = g.NominalNd(), vd = g.NominalVd();
    if (std::abs(nd - stated->nd) > 0.01 || std::abs(vd - stated->vd) > 5)
      throw MakeInputError(lens_path_, line,
                           "glass {}: the file states nd {} vd {}, but {}:{} has nd {:.5f} vd {:.2f}: another material "
                           "of that name; give the file's glass in {} beside the lens (a line 'glass {} nd={} vd={}')",
                           Printable(name), stated->nd, stated->vd, g.catalog(), g.name(), nd, vd,
                           fs::path(lens_path_).filename().replace_extension(".glass").string(), Printable(name),
                           stated->nd, stated->vd);
    spdlog::warn("{}:{}: glass {}: the file states nd {} vd {}, but {}:{} has nd {:.5f} vd {:.2f}", lens_path_, line,
                 Printable(name), stated->nd, stated->vd, g.catalog(), g.name(), nd, vd);
  }
  return m->glass;
}

void LensGlasses::WarnUnused() const {
  std::vector<std::string> unused = lookup_.UnusedUserGlasses();
  if (unused.empty()) return;
  std::string list;
  for (size_t i = 0; i < unused.size() && i < 10; ++i) list += (i ? ", " : "") + unused[i];
  if (unused.size() > 10) list += fmt::format(" and {} more", unused.size() - 10);
  spdlog::warn("{}: {} glass(es) that no surface of {} uses: {}", glass_file_, unused.size(), lens_path_, list);
}

}  // namespace objektiv
