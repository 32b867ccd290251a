// Fuzz harness: pbrt's .dat lens files, then the lens as the lens commands use it.
#include "fuzz_support.h"
#include "lens_checks.h"
#include "optics/pbrt_lens.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  fuzz::IgnoringInputErrors([&] { fuzz::ExerciseLens(ParsePbrtLens(std::string(fuzz::Bytes(data, size)), "fuzz.dat")); });
  return 0;
}
