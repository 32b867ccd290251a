// Fuzz harness: Zemax AGF glass catalogs (ASCII or UTF-16), then every glass's index and
// internal transmittance across the visible, as lenses and dielectrics use them.
#include "fuzz_support.h"
#include "optics/glass_catalog.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  fuzz::IgnoringInputErrors([&] {
    GlassCatalog catalog;
    catalog.LoadAgfText(std::string(fuzz::Bytes(data, size)), "fuzz.agf", "FUZZ");
    for (const Glass* g : catalog.All())
      for (double lambda : {380.0, 587.5618, 830.0}) {
        g->Index(lambda);
        g->InternalTransmittance(lambda, 10);
      }
    catalog.Find("FUZZ:N-BK7");
  });
  return 0;
}
