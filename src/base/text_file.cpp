#include "base/text_file.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/error.h"
#include "base/input_files.h"

namespace objektiv {

uintmax_t CheckInputFile(const std::string& path, const char* what, uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw MakeInputError(path, 0, "cannot read {}: no such file", what);
  if (!fs::is_regular_file(st)) {
    const char* kind = fs::is_directory(st) ? "a directory" : fs::is_fifo(st) ? "a pipe" : "a device or special file";
    throw MakeInputError(path, 0, "cannot read {}: it is {}, not a regular file", what, kind);
  }
  uintmax_t size = fs::file_size(path, ec);
  if (ec) throw MakeInputError(path, 0, "cannot read {}: {}", what, ec.message());
  if (size > max_bytes)
    throw MakeInputError(path, 0, "cannot read {}: it has {} bytes, more than the limit of {} MiB", what, size,
                         max_bytes >> 20);
  return size;
}

std::string ReadTextFile(const std::string& path, const char* what, uintmax_t max_bytes) {
  uintmax_t size = CheckInputFile(path, what, max_bytes);
  RecordInputFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MakeInputError(path, 0, "cannot open {}", what);
  std::string text(size_t(size), '\0');
  in.read(text.data(), std::streamsize(size));
  if (in.bad()) throw MakeInputError(path, 0, "cannot read {}", what);
  text.resize(size_t(in.gcount()));  // shorter if the file shrank since
  return text;
}

std::string DecodeToAscii(const std::string& raw) {
  auto byte = [&](size_t i) { return uint8_t(raw[i]); };
  if (raw.size() >= 2 && ((byte(0) == 0xff && byte(1) == 0xfe) || (byte(0) == 0xfe && byte(1) == 0xff))) {
    bool le = byte(0) == 0xff;
    std::string out;
    for (size_t i = 2; i + 1 < raw.size(); i += 2) {
      unsigned c = le ? (byte(i) | (byte(i + 1) << 8)) : ((byte(i) << 8) | byte(i + 1));
      out += c < 128 ? char(c) : '?';
    }
    return out;
  }
  if (raw.size() >= 3 && byte(0) == 0xef && byte(1) == 0xbb && byte(2) == 0xbf) return raw.substr(3);
  return raw;
}

std::optional<double> ParseFiniteNumber(const std::string& s) {
  const char* begin = s.c_str();
  while (std::isspace(static_cast<unsigned char>(*begin))) ++begin;
  // Decimal only: strtod would also take hexadecimal (0x2A.F8), which no lens or scene file means.
  const char* digits = begin + (*begin == '+' || *begin == '-');
  if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  while (std::isspace(static_cast<unsigned char>(*end))) ++end;
  // An underflow (1e-320) is the tiny number it is; an overflow is no finite number.
  const bool overflow = errno == ERANGE && std::abs(v) > 1;
  if (*end != '\0' || overflow || !std::isfinite(v)) return std::nullopt;
  return v;
}

double ParseFiniteNumber(const std::string& s, const std::string& path, int line) {
  std::optional<double> v = ParseFiniteNumber(s);
  if (!v) throw MakeInputError(path, line, "'{}' is not a finite number", s);
  return *v;
}

std::optional<int> ParseIntegerIn(const std::string& s, int lo, int hi) {
  std::optional<double> v = ParseFiniteNumber(s);
  if (!v || *v != std::floor(*v) || *v < lo || *v > hi) return std::nullopt;
  return int(*v);
}

std::vector<std::string> SplitFields(const std::string& line) {
  std::istringstream tok(line);
  std::vector<std::string> fields;
  for (std::string t; tok >> t;) fields.push_back(t);
  return fields;
}

std::string Printable(const std::string& token) {
  std::string out;
  for (unsigned char c : token) {
    if (out.size() >= 60) return out + "...";
    if (c >= 0x20 && c < 0x7f)
      out += char(c);
    else
      out += fmt::format("\\x{:02x}", c);
  }
  return out;
}

}  // namespace objektiv
