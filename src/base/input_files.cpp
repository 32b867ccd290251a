#include "base/input_files.h"

#include <filesystem>
#include <map>
#include <mutex>

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

}  // namespace objektiv
