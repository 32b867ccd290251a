// Whether these tests were built with the sanitizers (scripts/test.sh's second suite, build-fuzz/).
//
// Under AddressSanitizer a statistical test at its full sample count runs 5 to 10 times slower.
// The sanitizers look for memory and undefined-behaviour errors, which one run through a code
// path finds; the statistics of a long render add nothing there. So the longest statistical
// tests, each of whose code paths a cheaper test also runs under the sanitizers (named at the
// skip), run in the Release suite only: SKIP_UNDER_SANITIZERS("cheaper test that covers it").
#pragma once
#include <gtest/gtest.h>

namespace objektiv {

// GCC says so with __SANITIZE_ADDRESS__, clang before 17 only through __has_feature.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
constexpr bool kAddressSanitizer = __has_feature(address_sanitizer);
#else
constexpr bool kAddressSanitizer = false;
#endif

}  // namespace objektiv

#define SKIP_UNDER_SANITIZERS(covered_by)                                                            \
  do {                                                                                               \
    if (::objektiv::kAddressSanitizer)                                                               \
      GTEST_SKIP() << "statistics at full sample counts: Release suite only (under the sanitizers " \
                      "its code runs in "                                                            \
                   << (covered_by) << ")";                                                           \
  } while (false)
