// What every fuzz harness shares. A harness is libFuzzer's entry point
// `LLVMFuzzerTestOneInput(data, size)`: it hands the bytes to one reader of user files, then
// uses what the reader returned a little (so that what a bad file can smuggle through the
// reader is exercised too). An InputError is the right answer to a bad input and is swallowed;
// anything else that escapes (another exception, a crash, a sanitizer report, a hang, a huge
// allocation) is a finding. The same entry point is linked with libFuzzer (fuzz/CMakeLists.txt,
// OBJEKTIV_FUZZ=ON) and with replay_main.cpp, which the test suite runs over the regressions.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "base/error.h"

namespace objektiv::fuzz {

// Warnings off (a mutated file warns a lot, and printing is most of the time).
void Quiet();

// A folder of this process's own (made on first use, removed at exit) for readers that take
// a path: the input is written there under `name`, the same name for every input.
std::string ScratchDir();
std::string WriteScratchFile(const std::string& name, std::string_view bytes);

inline std::string_view Bytes(const uint8_t* data, size_t size) { return {reinterpret_cast<const char*>(data), size}; }

// Runs f; an InputError (the reader refusing a bad file) ends it quietly.
template <typename F>
void IgnoringInputErrors(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

}  // namespace objektiv::fuzz
