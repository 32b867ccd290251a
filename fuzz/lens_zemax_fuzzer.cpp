// Fuzz harness: Zemax sequential .zmx files (ASCII or UTF-16), then the lens as the lens commands use it.
#include "fuzz_support.h"
#include "lens_checks.h"
#include "optics/zemax_lens.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  fuzz::IgnoringInputErrors([&] { fuzz::ExerciseLens(ParseZemaxLens(std::string(fuzz::Bytes(data, size)), "fuzz.zmx", GlassCatalog::Default())); });
  return 0;
}
