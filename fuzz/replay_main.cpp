// Replays inputs through a fuzz harness without libFuzzer, for the ordinary test suite (any
// compiler): `replay HARNESS INPUT...`, HARNESS one of fuzz/CMakeLists.txt's names, every INPUT
// a file or a folder of them (folders in name order, not recursive; a missing folder holds
// nothing). Exits 0 after all of them ran: a finding that comes back crashes, hangs or trips a
// sanitizer instead. Every harness is linked in (its entry point renamed objektiv_fuzz_NAME).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#define OBJEKTIV_HARNESS(name) extern "C" int objektiv_fuzz_##name(const uint8_t* data, size_t size);
#include "replay_harnesses.inc"
#undef OBJEKTIV_HARNESS

namespace {
struct Harness {
  const char* name;
  int (*run)(const uint8_t* data, size_t size);
};
constexpr Harness kHarnesses[] = {
#define OBJEKTIV_HARNESS(name) {#name, objektiv_fuzz_##name},
#include "replay_harnesses.inc"
#undef OBJEKTIV_HARNESS
};
}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const Harness* harness = nullptr;
  for (const Harness& h : kHarnesses)
    if (argc > 1 && std::strcmp(argv[1], h.name) == 0) harness = &h;
  if (!harness) {
    std::fprintf(stderr, "usage: replay HARNESS INPUT...; HARNESS one of:");
    for (const Harness& h : kHarnesses) std::fprintf(stderr, " %s", h.name);
    std::fprintf(stderr, "\n");
    return 2;
  }
  std::vector<fs::path> inputs;
  for (int i = 2; i < argc; ++i) {
    fs::path p(argv[i]);
    if (fs::is_directory(p)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
      std::sort(files.begin(), files.end());
      inputs.insert(inputs.end(), files.begin(), files.end());
    } else if (fs::exists(p)) {
      inputs.push_back(p);
    }
  }
  for (const fs::path& p : inputs) {
    std::printf("%s\n", p.string().c_str());
    std::fflush(stdout);
    std::ifstream in(p, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    harness->run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("replayed %zu inputs\n", inputs.size());
  return 0;
}
