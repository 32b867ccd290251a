#include "io/obj_check.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include "base/error.h"

namespace objektiv {
namespace {

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool IsFiniteNumber(std::string_view t) {
  double v = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc() && end == t.data() + t.size() && std::isfinite(v);
}

bool IsIndex(std::string_view t) {
  long v = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc() && end == t.data() + t.size() && v != 0;
}

// i, i/t, i//n, i/t/n
bool IsCorner(std::string_view t) {
  size_t a = t.find('/');
  if (a == std::string_view::npos) return IsIndex(t);
  if (!IsIndex(t.substr(0, a))) return false;
  std::string_view rest = t.substr(a + 1);
  size_t b = rest.find('/');
  if (b == std::string_view::npos) return IsIndex(rest);
  return (b == 0 || IsIndex(rest.substr(0, b))) && IsIndex(rest.substr(b + 1));
}

}  // namespace

void CheckObjText(const std::string& text, const std::string& path) {
  std::string_view all(text);
  int line_no = 0;
  size_t pos = 0;
  while (pos <= all.size()) {
    size_t end = all.find('\n', pos);
    if (end == std::string_view::npos) end = all.size();
    std::string_view line = all.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::vector<std::string_view> t = Tokens(line);
    if (t.empty()) continue;
    const std::string_view key = t[0];
    const size_t values = t.size() - 1;
    auto numbers = [&](size_t lo, size_t hi, const char* what) {
      if (values < lo || values > hi)
        throw MakeInputError(path, line_no, "{} takes {} to {} numbers, got {}", what, lo, hi, values);
      for (size_t i = 1; i < t.size(); ++i)
        if (!IsFiniteNumber(t[i])) throw MakeInputError(path, line_no, "'{}' in a {} is not a finite number", t[i], what);
    };
    if (key == "v") numbers(3, 7, "vertex (v)");  // x y z [w] or x y z r g b
    else if (key == "vn") numbers(3, 3, "normal (vn)");
    else if (key == "vt") numbers(1, 3, "texture coordinate (vt)");
    else if (key == "f" || key == "l" || key == "p") {
      if (values < (key == "f" ? 3u : 1u))
        throw MakeInputError(path, line_no, "'{}' with {} corners", key, values);
      for (size_t i = 1; i < t.size(); ++i)
        if (!IsCorner(t[i]))
          throw MakeInputError(path, line_no, "'{}' is not a corner (i, i/t, i//n or i/t/n with non-zero integers)", t[i]);
    }
    if (end == all.size()) break;
  }
}

}  // namespace objektiv
