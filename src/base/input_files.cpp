#include "base/input_files.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include <fmt/format.h>

#include "base/error.h"

namespace objektiv {

namespace {
namespace fs = std::filesystem;

struct InputLog {
  std::mutex mutex;
  std::map<fs::path, std::string> files;  // canonical path -> path as given
};

InputLog& Log() {
  static InputLog log;
  return log;
}

// Absolute, symlinks followed as far as the path exists, "." and ".." removed.
fs::path Canonical(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(path, ec);
  return ec ? fs::absolute(path, ec).lexically_normal() : p;
}
}  // namespace

void RecordInputFile(const std::string& path) {
  fs::path key = Canonical(path);
  std::lock_guard lock(Log().mutex);
  Log().files.emplace(key, path);
}

std::optional<std::string> InputFileAt(const std::string& path) {
  fs::path key = Canonical(path);
  std::lock_guard lock(Log().mutex);
  auto it = Log().files.find(key);
  if (it != Log().files.end()) return it->second;
  // Hard links and bind mounts: another path to the same file.
  std::error_code ec;
  if (!fs::exists(key, ec)) return std::nullopt;
  for (const auto& [input, given] : Log().files)
    if (fs::equivalent(key, input, ec)) return given;
  return std::nullopt;
}

std::vector<std::string> InputFiles() {
  std::lock_guard lock(Log().mutex);
  std::vector<std::string> out;
  for (const auto& [canonical, given] : Log().files) out.push_back(canonical.string());
  return out;
}

namespace {
constexpr uint64_t kFnvOffset = 0xcbf29ce484222325ull, kFnvPrime = 0x100000001b3ull;

uint64_t Fnv1a(const char* data, size_t n, uint64_t h) {
  for (size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * kFnvPrime;
  return h;
}
}  // namespace

std::vector<std::pair<std::string, uint64_t>> InputFilesContentHashes() {
  std::vector<std::pair<std::string, uint64_t>> out;
  std::vector<char> buffer(1 << 16);
  for (const std::string& path : InputFiles()) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("{}: cannot be read again (to hash the scene's files)", path));
    uint64_t h = kFnvOffset;
    while (in) {
      in.read(buffer.data(), std::streamsize(buffer.size()));
      h = Fnv1a(buffer.data(), size_t(in.gcount()), h);
    }
    out.emplace_back(path, h);
  }
  return out;
}

uint64_t InputFilesContentHash() { return CombinedContentHash(InputFilesContentHashes()); }

uint64_t CombinedContentHash(const std::vector<std::pair<std::string, uint64_t>>& files) {
  std::vector<uint64_t> hashes;
  for (const auto& [path, h] : files) hashes.push_back(h);
  std::sort(hashes.begin(), hashes.end());
  return Fnv1a(reinterpret_cast<const char*>(hashes.data()), hashes.size() * sizeof(uint64_t), kFnvOffset);
}

}  // namespace objektiv
