#include "io/render_part.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <map>

#include <fmt/format.h>

#include "base/error.h"
#include "base/output_file.h"
#include "base/text_file.h"
#include "io/image_file_checks.h"
#include "io/image_io.h"

namespace objektiv {

namespace {
constexpr int kFormat = 1;  // objektiv:part_format: the layout of the channels above
constexpr int kStrip = 64;  // rows written or read at a time

std::string CropText(const CropWindow& c) { return fmt::format("{},{},{},{}", c.x0, c.y0, c.x1, c.y1); }

bool ParseCropText(const std::string& text, CropWindow& c) {
  return std::sscanf(text.c_str(), "%d,%d,%d,%d", &c.x0, &c.y0, &c.x1, &c.y1) == 4 && c.x0 < c.x1 && c.y0 < c.y1;
}

void PutDouble(uint32_t* w, double v) { std::memcpy(w, &v, sizeof v); }
double GetDouble(const uint32_t* w) {
  double v;
  std::memcpy(&v, w, sizeof v);
  return v;
}
}  // namespace

std::string RenderPartInfo::Mismatch(const RenderPartInfo& o) const {
  auto differ = [](const char* what, const auto& a, const auto& b) {
    return a == b ? std::string() : fmt::format("{} {} against {}", what, a, b);
  };
  for (const std::string& m :
       {differ("objektiv version", version, o.version), differ("scene contents (hash)", scene_hash, o.scene_hash),
        differ("-D values", defines, o.defines), differ("samples per pixel", spp, o.spp), differ("seed", seed, o.seed),
        differ("sampling", sampling.empty() ? std::string("plain") : sampling, o.sampling.empty() ? std::string("plain") : o.sampling),
        differ("film", fmt::format("{}x{}", width, height), fmt::format("{}x{}", o.width, o.height)),
        differ("render crop", CropText(render_crop), CropText(o.render_crop))})
    if (!m.empty()) return m;
  return "";
}

std::string RenderPartInfo::ChangedInputs(const RenderPartInfo& o) const {
  auto parse = [](const std::string& text) {
    std::map<std::string, std::string> files;  // name -> hash
    for (size_t p = 0; p < text.size();) {
      size_t q = text.find('\n', p);
      if (q == std::string::npos) q = text.size();
      if (q > p + 17) files[text.substr(p + 17, q - p - 17)] = text.substr(p, 16);
      p = q + 1;
    }
    return files;
  };
  const auto a = parse(inputs), b = parse(o.inputs);
  std::vector<std::string> changed;
  for (const auto& [name, hash] : a) {
    auto it = b.find(name);
    changed.push_back(it == b.end() ? name + " (read only now)" : it->second != hash ? name : "");
  }
  for (const auto& [name, hash] : b)
    if (!a.count(name)) changed.push_back(name + " (read only then)");
  std::erase(changed, "");
  return fmt::format("{}", fmt::join(changed, ", "));
}

void WriteRenderPart(const std::string& path, const Image& rgb, const Film& film, const RenderPartInfo& info) {
  const CropWindow& crop = film.crop();
  const int w = crop.Width(), h = crop.Height();
  const std::vector<std::string> plane_names = film.PlaneNames();
  const size_t planes = plane_names.size();
  std::vector<std::string> names = {"R", "G", "B", "state.count"};
  for (const std::string& p : plane_names)
    for (int k = 0; k < 4; ++k) names.push_back(fmt::format("state.{}.{}", p, k));
  const size_t nch = names.size();
  OIIO::ImageSpec spec(w, h, int(nch), OIIO::TypeDesc::UINT32);
  spec.channelnames = names;
  spec.channelformats.assign(nch, OIIO::TypeDesc::UINT32);
  for (int c = 0; c < 3; ++c) spec.channelformats[c] = OIIO::TypeDesc::FLOAT;
  spec.x = crop.x0, spec.y = crop.y0;
  spec.full_x = 0, spec.full_y = 0, spec.full_width = info.width, spec.full_height = info.height;
  spec.attribute("compression", "rle");  // 3x smaller than none at no cost; zip: 20% smaller, 0.9 s more per 1024^2
  spec.attribute("objektiv:part_format", kFormat);
  spec.attribute("objektiv:version", info.version);
  spec.attribute("objektiv:scene", info.scene);
  spec.attribute("objektiv:scene_hash", info.scene_hash);
  spec.attribute("objektiv:inputs", info.inputs);
  spec.attribute("objektiv:film", fmt::format("{}x{}", info.width, info.height));
  spec.attribute("objektiv:defines", info.defines);
  if (!info.sampling.empty()) spec.attribute("objektiv:sampling", info.sampling);
  spec.attribute("objektiv:spp", info.spp);
  spec.attribute("objektiv:seed", std::to_string(info.seed));
  spec.attribute("objektiv:render_crop", CropText(info.render_crop));
  spec.attribute("objektiv:crop", CropText(crop));
  spec.attribute("objektiv:spp_begin", info.spp_begin);
  spec.attribute("objektiv:spp_end", info.spp_end);
  spec.attribute("objektiv:first_sample", film.first_sample());
  spec.attribute("objektiv:checkpoint", int(info.checkpoint));
  spec.attribute("objektiv:seconds", OIIO::TypeDesc::DOUBLE, &info.seconds);
  spec.attribute("objektiv:pixels_completed", int(info.pixels_completed));  // (a crop beyond 2^31 pixels is far over any budget)
  spec.attribute("objektiv:partial", int(!info.Complete()));
  spec.attribute("objektiv:planes", fmt::format("{}", fmt::join(plane_names, " ")));
  auto out = OIIO::ImageOutput::create("exr");
  if (!out) throw InputError(fmt::format("{}: cannot create image file: {}", path, OIIO::geterror()));
  WriteFileAtomically(path, [&](const std::string& temp) {
    if (!out->open(temp, spec)) throw InputError(fmt::format("{}: cannot write render part: {}", path, out->geterror()));
    // All channels are 4 bytes: a strip of rows in words, the image's floats by their bits.
    std::vector<uint32_t> words;
    for (int y0 = crop.y0; y0 < crop.y1; y0 += kStrip) {
      const int y1 = std::min(y0 + kStrip, crop.y1);
      const FilmAccumulators acc = film.Accumulators({crop.x0, y0, crop.x1, y1});
      const size_t pixels = size_t(w) * (y1 - y0);
      words.resize(pixels * nch);
      for (size_t i = 0; i < pixels; ++i) {
        uint32_t* px = &words[i * nch];
        std::memcpy(px, &rgb.pixels[3 * (size_t(y0 - crop.y0) * w + i)], 3 * sizeof(float));
        px[3] = acc.counts[i];
        for (size_t p = 0; p < planes; ++p) {
          PutDouble(&px[4 + 4 * p], acc.sums[i * planes + p].hi);
          PutDouble(&px[6 + 4 * p], acc.sums[i * planes + p].lo);
        }
      }
      if (!out->write_scanlines(y0, y1, 0, OIIO::TypeDesc::UNKNOWN, words.data()))
        throw InputError(fmt::format("{}: cannot write render part: {}", path, out->geterror()));
    }
    if (!out->close()) throw InputError(fmt::format("{}: cannot write render part: {}", path, out->geterror()));
  });
}

namespace {
// Opens a part and reads its header; `in` stays open for the pixels.
RenderPartInfo OpenPart(const std::string& path, std::unique_ptr<OIIO::ImageInput>& in, std::vector<std::string>& planes,
                        int& first_sample) {
  const uintmax_t size = CheckInputFile(path, "render part", UINTMAX_MAX);
  CheckExrHeaders(path, size);
  in = OIIO::ImageInput::create("exr");
  OIIO::ImageSpec opened;
  if (!in || !in->open(path, opened)) throw MakeInputError(path, 0, "cannot read as EXR: {}", in ? in->geterror() : "");
  const OIIO::ImageSpec& s = in->spec();
  if (s.get_int_attribute("objektiv:part_format", 0) != kFormat)
    throw MakeInputError(path, 0, "not a render part or checkpoint of objektiv (no objektiv:part_format {} in its header)",
                         kFormat);
  RenderPartInfo i;
  auto text = [&](const char* name) {
    const std::string v = s.get_string_attribute(name, "\x01");
    if (v == "\x01") throw MakeInputError(path, 0, "its header lacks {}", name);
    return v;
  };
  auto integer = [&](const char* name) {
    int v = 0;
    if (!s.getattribute(name, OIIO::TypeDesc::INT, &v)) throw MakeInputError(path, 0, "its header lacks {}", name);
    return v;
  };
  i.version = text("objektiv:version");
  i.scene = text("objektiv:scene");
  i.scene_hash = text("objektiv:scene_hash");
  i.inputs = s.get_string_attribute("objektiv:inputs", "");  // (an empty list is not written)
  i.defines = text("objektiv:defines");
  i.sampling = s.get_string_attribute("objektiv:sampling", "");  // (a plain sampler's is not written)
  i.spp = integer("objektiv:spp");
  i.spp_begin = integer("objektiv:spp_begin");
  i.spp_end = integer("objektiv:spp_end");
  first_sample = integer("objektiv:first_sample");
  i.checkpoint = integer("objektiv:checkpoint") != 0;
  i.width = s.full_width, i.height = s.full_height;
  if (!s.getattribute("objektiv:seconds", OIIO::TypeDesc::DOUBLE, &i.seconds))
    throw MakeInputError(path, 0, "its header lacks objektiv:seconds");
  char* end = nullptr;
  const std::string seed = text("objektiv:seed");
  const int completed = integer("objektiv:pixels_completed");
  i.seed = std::strtoull(seed.c_str(), &end, 10);
  if (seed.empty() || *end) throw MakeInputError(path, 0, "objektiv:seed '{}' is not a number", seed);
  if (completed < 0) throw MakeInputError(path, 0, "objektiv:pixels_completed {} is negative", completed);
  i.pixels_completed = uint64_t(completed);
  if (!ParseCropText(text("objektiv:render_crop"), i.render_crop) || !ParseCropText(text("objektiv:crop"), i.crop))
    throw MakeInputError(path, 0, "its crop windows are not x0,y0,x1,y1");
  if (i.crop.x0 != s.x || i.crop.y0 != s.y || i.crop.Width() != s.width || i.crop.Height() != s.height ||
      !i.render_crop.Contains(i.crop) || i.render_crop.x0 < 0 || i.render_crop.y0 < 0 || i.render_crop.x1 > i.width ||
      i.render_crop.y1 > i.height)
    throw MakeInputError(path, 0, "its crop {} does not match its pixels or the {}x{} film", CropText(i.crop), i.width,
                         i.height);
  if (!(0 <= i.spp_begin && i.spp_begin < i.spp_end && i.spp_end <= i.spp) || first_sample != i.spp_begin ||
      i.pixels_completed > uint64_t(i.crop.Width()) * i.crop.Height())
    throw MakeInputError(path, 0, "its sample range {}:{} of {} (or its counts) is not valid", i.spp_begin, i.spp_end, i.spp);
  std::string list = text("objektiv:planes");
  planes.clear();
  for (size_t p = 0; p < list.size();) {
    size_t q = list.find(' ', p);
    if (q == std::string::npos) q = list.size();
    if (q > p) planes.push_back(list.substr(p, q - p));
    p = q + 1;
  }
  return i;
}
}  // namespace

RenderPartInfo ReadRenderPartInfo(const std::string& path) {
  std::unique_ptr<OIIO::ImageInput> in;
  std::vector<std::string> planes;
  int first = 0;
  return OpenPart(path, in, planes, first);
}

namespace {
// Reads a part's sums a strip of rows at a time, each strip handed to `strip` as accumulators of
// its rows (the sums growing with what the file holds: a short file that claims many pixels
// fails having taken memory only for what it had). Returns the header.
template <typename StripFn>
RenderPartInfo ReadStrips(const std::string& path, StripFn&& strip) {
  std::unique_ptr<OIIO::ImageInput> in;
  FilmAccumulators acc;
  const RenderPartInfo info = OpenPart(path, in, acc.names, acc.first_sample);
  const OIIO::ImageSpec& s = in->spec();
  const size_t nch = size_t(s.nchannels), pixels = size_t(s.width) * s.height, planes = acc.names.size();
  if (int64_t(pixels) > kMaxImagePixels || int64_t(pixels) * int64_t(nch) * 4 > kMaxImageBytes)
    throw MakeInputError(path, 0, "{}x{} pixels of {} channels: beyond the limits of an image read", s.width, s.height, nch);
  if (s.tile_width > 0 || s.depth != 1) throw MakeInputError(path, 0, "a tiled or deep EXR: not a render part");
  // Where each word of a pixel comes from.
  std::map<std::string, int> index;
  for (int c = 0; c < s.nchannels; ++c) {
    if (s.channelformat(c).size() != 4) throw MakeInputError(path, 0, "channel {} is not 32 bits", s.channel_name(c));
    index[s.channel_name(c)] = c;
  }
  auto channel = [&](const std::string& name) {
    auto it = index.find(name);
    if (it == index.end()) throw MakeInputError(path, 0, "channel {} is missing", name);
    if (s.channelformat(it->second) != OIIO::TypeDesc::UINT32)
      throw MakeInputError(path, 0, "channel {} is not 32-bit unsigned", name);
    return it->second;
  };
  const int count = channel("state.count");
  std::vector<int> words;
  for (const std::string& p : acc.names)
    for (int k = 0; k < 4; ++k) words.push_back(channel(fmt::format("state.{}.{}", p, k)));
  std::vector<uint32_t> data;
  for (int y0 = s.y; y0 < s.y + s.height; y0 += kStrip) {
    const int y1 = std::min(y0 + kStrip, s.y + s.height);
    const size_t n = size_t(y1 - y0) * s.width;
    data.resize(n * nch);
    if (!in->read_scanlines(0, 0, y0, y1, 0, 0, s.nchannels, OIIO::TypeDesc::UNKNOWN, data.data()))
      throw MakeInputError(path, 0, "cannot read its pixels: {}", in->geterror());
    acc.crop = {s.x, y0, s.x + s.width, y1};
    acc.counts.resize(n);
    acc.sums.resize(n * planes);
    for (size_t i = 0; i < n; ++i) {
      const uint32_t* px = &data[i * nch];
      if (px[count] > uint32_t(info.spp_end - info.spp_begin))
        throw MakeInputError(path, 0, "pixel ({}, {}) counts {} samples, more than its range {}:{}",
                             s.x + int(i % s.width), y0 + int(i / s.width), px[count], info.spp_begin, info.spp_end);
      acc.counts[i] = px[count];
      for (size_t p = 0; p < planes; ++p) {
        const uint32_t hi[2] = {px[words[4 * p]], px[words[4 * p + 1]]}, lo[2] = {px[words[4 * p + 2]], px[words[4 * p + 3]]};
        acc.sums[i * planes + p] = {GetDouble(hi), GetDouble(lo)};
      }
    }
    strip(acc);
  }
  return info;
}
}  // namespace

RenderPart ReadRenderPart(const std::string& path) {
  RenderPart part;
  part.info = ReadStrips(path, [&](const FilmAccumulators& strip) {
    if (part.acc.names.empty()) part.acc = strip;
    else {
      part.acc.counts.insert(part.acc.counts.end(), strip.counts.begin(), strip.counts.end());
      part.acc.sums.insert(part.acc.sums.end(), strip.sums.begin(), strip.sums.end());
    }
  });
  part.acc.crop = part.info.crop;
  return part;
}

RenderPartInfo AddRenderPart(const std::string& path, Film& film) {
  return ReadStrips(path, [&](const FilmAccumulators& strip) {
    try {
      film.AddAccumulators(strip);
    } catch (const std::invalid_argument& e) {
      throw MakeInputError(path, 0, "{}", e.what());
    }
  });
}

}  // namespace objektiv
