#include "io/ply_check.h"

#include <cctype>
#include <climits>
#include <string_view>

#include "base/error.h"
#include "base/text_file.h"

namespace objektiv {
namespace {

// Size in bytes of a PLY scalar type, 0 if it is not one.
int TypeSize(const std::string& t) {
  static const struct {
    const char* name;
    int size;
  } kTypes[] = {{"char", 1},  {"uchar", 1},   {"int8", 1},    {"uint8", 1},    {"short", 2}, {"ushort", 2},
                {"int16", 2}, {"uint16", 2},  {"int", 4},     {"uint", 4},     {"int32", 4}, {"uint32", 4},
                {"float", 4}, {"float32", 4}, {"double", 8},  {"float64", 8}};
  for (const auto& k : kTypes)
    if (t == k.name) return k.size;
  return 0;
}

bool IsIntegral(const std::string& t) { return TypeSize(t) > 0 && t.find("float") == std::string::npos && t != "double"; }
bool IsSigned(const std::string& t) { return t == "char" || t == "short" || t.rfind("int", 0) == 0; }

// A header line for an error message: printable characters only, at most 40.
std::string Shown(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return s.size() > 40 ? out + "..." : out;
}

PlyLayout ReadHeader(const std::string& bytes, const std::string& path, size_t* body, int* body_line) {
  PlyLayout h;
  const std::string_view head = std::string_view(bytes).substr(0, kMaxPlyHeaderBytes);
  size_t pos = 0;
  int line = 0;
  bool have_format = false;
  for (;;) {
    size_t eol = head.find('\n', pos);
    if (eol == std::string::npos)
      throw MakeInputError(path, 0, "no 'end_header' line in the first {} KiB (not a PLY file, or cut short)",
                           kMaxPlyHeaderBytes / 1024);
    ++line;
    const std::string_view text = head.substr(pos, eol - pos);
    std::vector<std::string> f = SplitFields(std::string(text));
    pos = eol + 1;
    if (line == 1) {
      if (f.size() != 1 || f[0] != "ply") throw MakeInputError(path, 1, "not a PLY file (it must begin with 'ply')");
      continue;
    }
    if (f.empty() || f[0] == "comment" || f[0] == "obj_info") continue;
    // Every other header line is printable ASCII (names with other bytes are read differently
    // by different readers: Assimp's took such a header for another layout and ran out of
    // memory), and the format comes first, once.
    for (char c : text)
      if (!std::isprint(static_cast<unsigned char>(c)) && c != '\t' && c != '\r')
        throw MakeInputError(path, line, "a header line with a byte that is not printable ASCII: '{}'", Shown(text));
    if (f[0] != "format" && !have_format) throw MakeInputError(path, line, "the format line must follow 'ply'");
    if (f[0] == "end_header") {
      if (f.size() != 1) throw MakeInputError(path, line, "'end_header' takes nothing after it");
      break;
    }
    if (f[0] == "format") {
      if (have_format) throw MakeInputError(path, line, "a second format line");
      if (f.size() != 3 || f[2] != "1.0") throw MakeInputError(path, line, "the format line is 'format TYPE 1.0'");
      if (f[1] == "ascii") h.format = PlyLayout::Format::kAscii;
      else if (f[1] == "binary_little_endian") h.format = PlyLayout::Format::kBinaryLittleEndian;
      else if (f[1] == "binary_big_endian") h.format = PlyLayout::Format::kBinaryBigEndian;
      else throw MakeInputError(path, line, "unknown PLY format '{}' (ascii, binary_little_endian, binary_big_endian)", Shown(f[1]));
      have_format = true;
    } else if (f[0] == "element") {
      if (f.size() != 3) throw MakeInputError(path, line, "an element line is 'element NAME COUNT'");
      std::optional<int> count = ParseIntegerIn(f[2], 0, INT_MAX);
      if (!count) throw MakeInputError(path, line, "element count '{}' is not an integer from 0 to {}", Shown(f[2]), INT_MAX);
      h.elements.push_back({f[1], *count, line, {}});
    } else if (f[0] == "property") {
      if (h.elements.empty()) throw MakeInputError(path, line, "a property before any element");
      if (f.size() == 5 && f[1] == "list" && IsIntegral(f[2]) && TypeSize(f[3]))
        h.elements.back().properties.push_back({f[4], TypeSize(f[3]), TypeSize(f[2]), IsSigned(f[2])});
      else if (f.size() == 3 && TypeSize(f[1]))
        h.elements.back().properties.push_back({f[2], TypeSize(f[1]), 0, false});
      else
        throw MakeInputError(path, line,
                             "a property line is 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME' "
                             "(an integer count), not '{}'",
                             Shown(text));
    } else {
      throw MakeInputError(path, line, "unknown header line '{}'", Shown(f[0]));
    }
  }
  if (!have_format) throw MakeInputError(path, line, "the header has no format line");
  *body = pos;
  *body_line = line + 1;
  return h;
}

// A face's list of corners: fewer than three make no polygon (Assimp's reader crashed on
// faces of none).
bool IsCornerList(const PlyElement& e, const PlyProperty& p) {
  return e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
}
InputError TooFewCorners(const std::string& path, int line, const PlyElement& e, int64_t r, uint64_t n) {
  return MakeInputError(path, line, "{} {} has {} corners (a face needs at least 3)", e.name, r, n);
}

// The largest list length a count of this type can hold (at most INT_MAX).
int64_t MaxListLength(const PlyProperty& p) {
  const int bits = 8 * p.count_size - (p.count_signed ? 1 : 0);
  return bits >= 31 ? INT_MAX : (int64_t(1) << bits) - 1;
}

// Walks the ASCII body: one token per value, a list's count then its items, each record on a
// line of its own (as Assimp reads them: a record that runs onto the next line, or leaves
// values over, would be read out of step).
void CheckAsciiBody(const std::string& bytes, size_t pos, int line, const PlyLayout& h, const std::string& path) {
  int token_line = line - 1;  // of the last token read (the end_header line at first)
  auto token = [&]() -> std::string_view {
    while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos])))
      if (bytes[pos++] == '\n') ++line;
    size_t start = pos;
    while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    if (pos > start) token_line = line;
    return std::string_view(bytes).substr(start, pos - start);
  };
  int record_line = token_line;
  auto same_line = [&](const PlyElement& e, int64_t r) {
    if (token_line != record_line)
      throw MakeInputError(path, record_line, "{} {} has fewer values on its line than the header declares (line {})", e.name,
                           r, e.line);
  };
  for (const PlyElement& e : h.elements)
    for (int64_t r = 0; r < e.count && !e.properties.empty(); ++r)
      for (size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty& p = e.properties[i];
        const int previous_line = token_line;
        std::string_view t = token();
        if (t.empty())
          throw MakeInputError(path, token_line, "the file ends in {} {} of {} (declared on line {})", e.name, r, e.count, e.line);
        if (i == 0) {
          if (token_line == previous_line)
            throw MakeInputError(path, token_line, "more values on the line than a record holds (the header's line {})", e.line);
          record_line = token_line;
        }
        same_line(e, r);
        if (!p.count_size) continue;
        std::optional<int> items = ParseIntegerIn(std::string(t), 0, int(MaxListLength(p)));
        if (!items)
          throw MakeInputError(path, token_line, "'{}' is not a list length from 0 to {} ({} {})", Shown(t), MaxListLength(p),
                               e.name, r);
        if (*items < 3 && IsCornerList(e, p)) throw TooFewCorners(path, token_line, e, r, uint64_t(*items));
        for (int k = 0; k < *items; ++k) {
          if (token().empty())
            throw MakeInputError(path, token_line, "the file ends in {} {} of {} (declared on line {})", e.name, r, e.count, e.line);
          same_line(e, r);
        }
      }
  if (!token().empty()) throw MakeInputError(path, token_line, "values after the last record the header declares");
}

// Walks the binary body by sizes, reading each list's count.
void CheckBinaryBody(const std::string& bytes, size_t pos, const PlyLayout& h, const std::string& path) {
  const bool big = h.format == PlyLayout::Format::kBinaryBigEndian;
  for (const PlyElement& e : h.elements)
    for (int64_t r = 0; r < e.count && !e.properties.empty(); ++r)
      for (const PlyProperty& p : e.properties) {
        auto ends = [&] {
          return MakeInputError(path, 0, "the file ends in {} {} of {} (declared on line {})", e.name, r, e.count, e.line);
        };
        if (!p.count_size) {
          if (bytes.size() - pos < size_t(p.size)) throw ends();
          pos += size_t(p.size);
          continue;
        }
        if (bytes.size() - pos < size_t(p.count_size)) throw ends();
        uint64_t n = 0;
        for (int b = 0; b < p.count_size; ++b)
          n |= uint64_t(uint8_t(bytes[pos + size_t(big ? p.count_size - 1 - b : b)])) << (8 * b);
        pos += size_t(p.count_size);
        if (p.count_signed && (n >> (8 * p.count_size - 1)))
          throw MakeInputError(path, 0, "a negative list length in {} {}", e.name, r);
        if (n < 3 && IsCornerList(e, p)) throw TooFewCorners(path, 0, e, r, n);
        if ((bytes.size() - pos) / size_t(p.size) < n) throw ends();
        pos += size_t(n) * size_t(p.size);
      }
  if (pos != bytes.size())
    throw MakeInputError(path, 0, "{} bytes after the last record the header declares", bytes.size() - pos);
}

}  // namespace

int64_t PlyLayout::Count(const std::string& name) const {
  for (const PlyElement& e : elements)
    if (e.name == name) return e.count;
  return 0;
}

PlyLayout CheckPlyFile(const std::string& bytes, const std::string& path) {
  size_t body = 0;
  int body_line = 0;
  PlyLayout h = ReadHeader(bytes, path, &body, &body_line);
  if (h.format == PlyLayout::Format::kAscii) CheckAsciiBody(bytes, body, body_line, h, path);
  else CheckBinaryBody(bytes, body, h, path);
  return h;
}

}  // namespace objektiv
