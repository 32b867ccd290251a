// A native lens file's text read as the reader reads "test.lens", and the reader's message for
// a text it refuses (the tests of each surface kind check their options' errors with it).
#pragma once
#include <string>

#include "base/error.h"
#include "optics/lens_file.h"

namespace objektiv::test {

inline LensPrescription ParseLensText(const std::string& text) {
  return ParseNativeLens(text, "test.lens", GlassCatalog::Default());
}

// The message, or "accepted".
inline std::string LensTextError(const std::string& text) {
  try {
    ParseLensText(text);
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::string("accepted");
}

}  // namespace objektiv::test
