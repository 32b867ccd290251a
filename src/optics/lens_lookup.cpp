// Lens files by name: their types by extension, the reader for each, and the shipped lenses
// (data/lenses) that a bare name finds (optics/lens_file.h). The native format's own reader is
// optics/lens_file.cpp.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "base/error.h"
#include "base/text_file.h"
#include "optics/glass_catalog.h"
#include "optics/lens_file.h"
#include "optics/pbrt_lens.h"
#include "optics/zemax_lens.h"

namespace objektiv {

namespace fs = std::filesystem;

std::string LensFileExtensionList() {
  std::string list;
  const size_t n = std::size(kLensFileExtensions);
  for (size_t i = 0; i < n; ++i) list += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + kLensFileExtensions[i];
  return list;
}

namespace {
std::string LowerExtension(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}
bool IsLensExtension(const std::string& ext) {
  return std::find(std::begin(kLensFileExtensions), std::end(kLensFileExtensions), ext) != std::end(kLensFileExtensions);
}
}  // namespace

LensPrescription ReadLensFile(const std::string& path, const GlassCatalog& glasses) {
  std::string ext = LowerExtension(path);
  if (ext == ".dat") return ReadPbrtLens(path);
  if (ext == ".zmx") return ReadZemaxLens(path, glasses);
  if (ext != ".lens")
    throw MakeInputError(path, 0, "unknown lens file type '{}' ({})", fs::path(path).extension().string(), LensFileExtensionList());
  return ParseNativeLens(ReadTextFile(path, "lens file"), path, glasses);
}

std::string ResolveLens(const std::string& name, const std::string& base_dir) {
  fs::path p(name);
  if (p.is_relative() && !base_dir.empty()) p = fs::path(base_dir) / p;
  // Anything that exists at the path is the lens file (the reader refuses directories, pipes
  // and devices with its own message).
  if (fs::exists(p)) return p.string();
  const fs::path shipped = fs::path(DataDirectory()) / "lenses";
  if (IsLensExtension(LowerExtension(name)) && fs::is_regular_file(shipped / name)) return (shipped / name).string();
  for (const char* ext : kLensFileExtensions)
    if (fs::is_regular_file(shipped / (name + ext))) return (shipped / (name + ext)).string();
  std::string known;
  for (const std::string& n : ShippedLensNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError(fmt::format("no lens file '{}'{} and no shipped lens of that name (shipped: {})", name,
                               fs::path(name).is_relative() && !base_dir.empty() ? " in " + base_dir : "", known));
}

LensPrescription LoadLens(const std::string& name, const GlassCatalog& glasses, const std::string& base_dir) {
  return ReadLensFile(ResolveLens(name, base_dir), glasses);
}

std::vector<std::string> ShippedLensNames() {
  std::vector<std::string> names;
  fs::path dir = fs::path(DataDirectory()) / "lenses";
  if (!fs::exists(dir)) return names;
  for (const auto& e : fs::directory_iterator(dir))
    if (IsLensExtension(LowerExtension(e.path()))) names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace objektiv
