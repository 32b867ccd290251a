// Strict readers of command-line values: a number is digits and nothing else (no sign, no
// blanks, no trailing text), so that a job script's empty or mangled variable is an error, not
// a different render.
#pragma once
#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace objektiv {

// `count` unsigned decimal integers (each below 2^31) separated by `separator`, or nothing.
inline std::optional<std::vector<int>> ParseCounts(const std::string& text, char separator, size_t count) {
  std::vector<int> out;
  const char* p = text.data();
  const char* end = text.data() + text.size();
  while (out.size() < count) {
    if (p == end || *p < '0' || *p > '9') return std::nullopt;
    int v = 0;
    auto [next, ec] = std::from_chars(p, end, v);
    if (ec != std::errc()) return std::nullopt;
    out.push_back(v);
    p = next;
    if (out.size() < count) {
      if (p == end || *p != separator) return std::nullopt;
      ++p;
    }
  }
  if (p != end) return std::nullopt;
  return out;
}

// An unsigned 64-bit decimal integer (0 to 2^64 - 1), or nothing.
inline std::optional<uint64_t> ParseUint64(const std::string& text) {
  uint64_t v = 0;
  if (text.empty() || text[0] < '0' || text[0] > '9') return std::nullopt;
  auto [next, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || next != text.data() + text.size()) return std::nullopt;
  return v;
}

// A finite number above 0 (NaN and infinity are refused) and at most `max`.
inline CLI::Validator FinitePositive(double max = 1e300) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        double v = 0;
        try {
          size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) return "'" + text + "' is not a number";
        } catch (const std::exception&) {
          return "'" + text + "' is not a number";
        }
        if (!std::isfinite(v) || v <= 0 || v > max)
          return max < 1e300 ? "'" + text + "' is not a number above 0 and at most " + CLI::detail::to_string(max)
                             : "'" + text + "' is not a finite number above 0";
        return "";
      },
      max < 1e300 ? "in (0, " + CLI::detail::to_string(max) + "]" : "> 0");
}

}  // namespace objektiv
