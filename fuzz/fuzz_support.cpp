#include "fuzz_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "base/log.h"

namespace objektiv::fuzz {

namespace fs = std::filesystem;

void Quiet() { spdlog::set_level(spdlog::level::off); }

namespace {
struct Scratch {
  fs::path dir;
  Scratch() {
    std::string tmpl = (fs::temp_directory_path() / "objektiv-fuzz-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    dir = tmpl;
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};
}  // namespace

std::string ScratchDir() {
  static const Scratch scratch;
  return scratch.dir.string();
}

std::string WriteScratchFile(const std::string& name, std::string_view bytes) {
  std::string path = ScratchDir() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) std::abort();
  return path;
}

}  // namespace objektiv::fuzz
