#include "optics/glass_lookup.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/glass_aliases.h"

namespace objektiv {

bool AgreesWith(const Glass& g, const StatedGlass& stated) {
  return std::abs(g.NominalNd() - stated.nd) <= 1e-3 && std::abs(g.NominalVd() - stated.vd) <= 0.5;
}

std::string SubstitutionNote(std::string_view written, const GlassMatch& m) {
  switch (m.how) {
    case GlassMatch::How::kSuccessor:
      return fmt::format("glass {} is withdrawn; its successor {}:{} is used", written, m.glass->catalog(),
                         m.glass->name());
    case GlassMatch::How::kSameMaterial:
      return fmt::format("glass {} is read as {}:{} (the same material)", written, m.glass->catalog(), m.glass->name());
    case GlassMatch::How::kAgreesWithStated:
      return fmt::format("glass {} is read as {}:{}, whose nd and Vd agree with the file's (the catalogs searched first "
                         "hold another glass of that name)", written, m.glass->catalog(), m.glass->name());
    default:
      return {};
  }
}

void GlassLookup::SetUserGlasses(std::shared_ptr<const GlassCatalog> user, std::string label) {
  user_.clear();
  user_label_ = std::move(label);
  if (!user) return;
  for (const std::string& name : user->catalogs()) user_.push_back({user.get(), name, user});
}

void GlassLookup::Prefer(const std::vector<std::string>& catalogs, std::shared_ptr<const GlassCatalog> beside) {
  preferred_.clear();
  for (const std::string& c : catalogs) {
    const std::string key = GlassKey(c);
    if (std::any_of(preferred_.begin(), preferred_.end(), [&](const Source& s) { return s.name == key; })) continue;
    if (beside && beside->HasCatalog(key))
      preferred_.push_back({beside.get(), key, beside});
    else if (shipped_.HasCatalog(key))
      preferred_.push_back({&shipped_, key, nullptr});
  }
}

std::vector<std::vector<GlassLookup::Source>> GlassLookup::Groups() const {
  std::vector<Source> rest;
  for (const std::string& name : shipped_.catalogs())
    if (std::none_of(preferred_.begin(), preferred_.end(), [&](const Source& s) { return s.name == name; }))
      rest.push_back({&shipped_, name, nullptr});
  return {user_, preferred_, rest};
}

std::optional<GlassMatch> GlassLookup::FindInGroup(const std::vector<Source>& group, const std::string& name,
                                                   const std::optional<StatedGlass>& stated) const {
  using How = GlassMatch::How;
  auto match = [](const Source& s, const Glass* g, How how) {
    // Shipped glasses are not owned; others share their catalog's ownership.
    return GlassMatch{std::shared_ptr<const Glass>(s.owner, g), how};
  };
  const Source* first_source = nullptr;
  const Glass* first = nullptr;
  for (const Source& s : group) {
    const Glass* g = s.catalogs->FindIn(s.name, name);
    if (!g) continue;
    if (!stated || AgreesWith(*g, *stated)) return match(s, g, How::kExactName);
    if (!first) first = g, first_source = &s;
  }
  if (first) return match(*first_source, first, How::kExactName);
  for (const Source& s : group)
    for (const std::string& candidate : SuccessorCandidates(s.name, name))
      if (const Glass* g = s.catalogs->FindIn(s.name, candidate)) return match(s, g, How::kSuccessor);
  if (std::optional<CatalogGlassName> same = SameMaterial(name))
    for (const Source& s : group)
      if (s.name == same->catalog)
        if (const Glass* g = s.catalogs->FindIn(s.name, same->glass)) return match(s, g, How::kSameMaterial);
  return std::nullopt;
}

std::optional<GlassMatch> GlassLookup::Find(std::string_view written, std::optional<StatedGlass> stated) const {
  std::vector<std::vector<Source>> groups = Groups();
  std::string name = GlassKey(written);
  if (size_t colon = name.find(':'); colon != std::string::npos) {
    const std::string catalog = name.substr(0, colon);
    name.erase(0, colon + 1);
    for (auto& group : groups)
      std::erase_if(group, [&](const Source& s) { return s.name != catalog; });
  }
  for (size_t i = 0; i < groups.size(); ++i)
    if (std::optional<GlassMatch> m = FindInGroup(groups[i], name, stated)) {
      if (stated && m->how == GlassMatch::How::kExactName && !AgreesWith(*m->glass, *stated))
        for (size_t later = i + 1; later < groups.size(); ++later)
          for (const Source& s : groups[later])
            if (const Glass* g = s.catalogs->FindIn(s.name, name); g && AgreesWith(*g, *stated))
              return GlassMatch{std::shared_ptr<const Glass>(s.owner, g), GlassMatch::How::kAgreesWithStated};
      if (i == 0) used_.insert(m->glass.get());
      return m;
    }
  return std::nullopt;
}

std::vector<std::string> GlassLookup::UnusedUserGlasses() const {
  std::vector<std::string> unused;
  for (const Source& s : user_)
    for (const Glass* g : s.catalogs->All())
      if (!used_.count(g)) unused.push_back(g->name());
  return unused;
}

std::string GlassLookup::SearchedCatalogs() const {
  std::string out = user_label_;  // the user's glass file, then the catalogs
  const std::vector<std::vector<Source>> groups = Groups();
  for (size_t i = 1; i < groups.size(); ++i)
    for (const Source& s : groups[i]) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

}  // namespace objektiv
