// Fuzz harness: the glass readers. The bytes as a Zemax AGF catalog (ASCII or UTF-16), then as
// a glass file beside a lens (glass_file.h); every glass read, its index and internal
// transmittance across the visible, as lenses and dielectrics use them.
#include "fuzz_support.h"
#include "optics/glass_catalog.h"
#include "optics/glass_file.h"

namespace {

void Exercise(const objektiv::GlassCatalog& catalog) {
  for (const objektiv::Glass* g : catalog.All())
    for (double lambda : {380.0, 587.5618, 830.0}) {
      g->Index(lambda);
      g->InternalTransmittance(lambda, 10);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  const std::string bytes(fuzz::Bytes(data, size));
  fuzz::IgnoringInputErrors([&] {
    GlassCatalog catalog;
    catalog.LoadAgfText(bytes, "fuzz.agf", "FUZZ");
    Exercise(catalog);
    catalog.Find("FUZZ:N-BK7");
  });
  fuzz::IgnoringInputErrors([&] {
    GlassCatalog glasses;
    ParseGlassFile(glasses, bytes, "fuzz.glass", "fuzz.glass");
    Exercise(glasses);
  });
  return 0;
}
