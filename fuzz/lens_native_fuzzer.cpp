// Fuzz harness: the native .lens format (docs/lens-format.md), then the lens as the lens commands use it.
#include "fuzz_support.h"
#include "lens_checks.h"
#include "optics/lens_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  fuzz::IgnoringInputErrors([&] { fuzz::ExerciseLens(ParseNativeLens(std::string(fuzz::Bytes(data, size)), "fuzz.lens", GlassCatalog::Default())); });
  return 0;
}
