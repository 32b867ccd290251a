#include "io/render_part_set.h"

#include <algorithm>

#include <fmt/format.h>

#include "base/error.h"

namespace objektiv {

namespace {
std::string Text(const CropWindow& c) { return fmt::format("{},{},{},{}", c.x0, c.y0, c.x1, c.y1); }

// " (it has samples A:B from FILE, ...)" for the parts that hold a pixel, or "".
std::string Holders(const std::vector<std::string>& paths, const std::vector<RenderPartInfo>& parts,
                    const std::vector<size_t>& members) {
  std::vector<std::string> held;
  for (size_t m : members) held.push_back(fmt::format("{}:{} from {}", parts[m].spp_begin, parts[m].spp_end, paths[m]));
  return held.empty() ? "" : fmt::format(" (it has samples {})", fmt::join(held, ", "));
}

}  // namespace

void CheckPartsMakeOneRender(const std::vector<std::string>& paths, const std::vector<RenderPartInfo>& parts) {
  if (parts.empty()) throw InputError("no render parts to merge");
  const RenderPartInfo& first = parts[0];
  for (size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].checkpoint)
      throw MakeInputError(paths[i], 0, "is a checkpoint, not a finished part (render it to the end with --resume)");
    if (!parts[i].Complete())
      throw MakeInputError(paths[i], 0, "is not finished: {} of its {}x{} pixels have all their samples (render it again "
                           "with --resume, or anew)", parts[i].pixels_completed, parts[i].crop.Width(), parts[i].crop.Height());
    const std::string m = first.Mismatch(parts[i]);
    if (!m.empty())
      throw InputError(fmt::format("{} and {} are parts of different renders: {}", paths[0], paths[i], m));
  }
  const CropWindow& whole = first.render_crop;
  std::vector<int> xs = {whole.x0, whole.x1}, ys = {whole.y0, whole.y1};
  for (const RenderPartInfo& p : parts) xs.insert(xs.end(), {p.crop.x0, p.crop.x1}), ys.insert(ys.end(), {p.crop.y0, p.crop.y1});
  for (std::vector<int>* v : {&xs, &ys}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  std::vector<size_t> members;
  for (size_t j = 0; j + 1 < ys.size(); ++j)
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      const int x = xs[i], y = ys[j];  // the cell's first pixel stands for all of its pixels
      members.clear();
      for (size_t k = 0; k < parts.size(); ++k) {
        const CropWindow& c = parts[k].crop;
        if (x >= c.x0 && x < c.x1 && y >= c.y0 && y < c.y1) members.push_back(k);
      }
      std::sort(members.begin(), members.end(),
                [&](size_t a, size_t b) { return parts[a].spp_begin < parts[b].spp_begin; });
      int next = 0;
      for (size_t m = 0; m < members.size(); ++m) {
        const RenderPartInfo& p = parts[members[m]];
        if (p.spp_begin < next) {
          const RenderPartInfo& q = parts[members[m - 1]];
          throw InputError(fmt::format("{} (samples {}:{} of pixels {}) and {} (samples {}:{} of pixels {}) both hold "
                                       "samples of pixel ({}, {})", paths[members[m - 1]], q.spp_begin, q.spp_end,
                                       Text(q.crop), paths[members[m]], p.spp_begin, p.spp_end, Text(p.crop), x, y));
        }
        if (p.spp_begin > next)
          throw InputError(fmt::format("samples {}:{} of pixel ({}, {}) are in none of the parts{}", next, p.spp_begin, x, y,
                                       Holders(paths, parts, members)));
        next = p.spp_end;
      }
      if (next < first.spp)
        throw InputError(fmt::format("samples {}:{} of pixel ({}, {}) are in none of the parts{}", next, first.spp, x, y,
                                     Holders(paths, parts, members)));
    }
}

}  // namespace objektiv
