#include "io/image_file_checks.h"

#include <cstdint>
#include <fstream>

#include "base/error.h"

namespace objektiv {

bool JpegIsComplete(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::streambuf& in = *file.rdbuf();
  constexpr int kEof = std::char_traits<char>::eof();
  if (in.sbumpc() != 0xFF || in.sbumpc() != 0xD8) return false;
  for (;;) {
    int b = in.sbumpc();
    if (b == kEof) return false;
    if (b != 0xFF) continue;  // entropy-coded data
    int marker;
    do marker = in.sbumpc();
    while (marker == 0xFF);  // fill bytes
    if (marker == kEof) return false;
    if (marker == 0xD9) return true;  // end of image
    if (marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) continue;  // no length
    int hi = in.sbumpc(), lo = in.sbumpc();
    if (lo == kEof || hi == kEof || (hi << 8 | lo) < 2) return false;
    if (in.pubseekoff((hi << 8 | lo) - 2, std::ios::cur) == std::streampos(-1)) return false;
  }
}

void CheckExrHeaders(const std::string& path, uintmax_t file_size) {
  std::ifstream file(path, std::ios::binary);
  auto bad = [&](const char* what) { return MakeInputError(path, 0, "cannot read image: {} in the OpenEXR header", what); };
  // Magic number and version field; bit 12 of the version marks a multi-part file.
  uint8_t start[8];
  if (!file.read(reinterpret_cast<char*>(start), 8) || start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 ||
      start[3] != 0x01)
    throw bad("no OpenEXR magic number");
  const bool multipart = (start[5] & 0x10) != 0;
  // A NUL-terminated name of at most 255 characters (empty: the end of a header).
  auto name = [&] {
    std::string s;
    for (int c; (c = file.get()) != 0;) {
      if (c == std::char_traits<char>::eof() || s.size() == 255) throw bad("a name that does not end");
      s += char(c);
    }
    return s;
  };
  for (;;) {
    std::string attribute = name();
    if (attribute.empty()) {  // the end of a header; in a multi-part file an empty one ends the list
      if (!multipart || file.peek() == 0) return;
      continue;
    }
    name();  // its type
    uint8_t b[4];
    if (!file.read(reinterpret_cast<char*>(b), 4)) throw bad("a cut attribute");
    const int32_t bytes = int32_t(uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24);
    const std::streamoff at = file.tellg();
    if (bytes < 0 || uintmax_t(at) + uintmax_t(bytes) > file_size) throw bad(("attribute '" + attribute + "' larger than the file").c_str());
    file.seekg(bytes, std::ios::cur);
  }
}

std::optional<ImageSize> BmpClaimedSize(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  uint8_t b[26];  // the 14-byte file header, then the information header's size and dimensions
  if (!file.read(reinterpret_cast<char*>(b), sizeof b)) return std::nullopt;
  auto u16 = [&](int at) { return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8; };
  auto u32 = [&](int at) { return u16(at) | u16(at + 2) << 16; };
  const uint32_t header_size = u32(14);
  if (header_size == 12) return ImageSize{u16(18), u16(20)};  // OS/2 1.x: unsigned 16-bit fields
  if (header_size != 40 && header_size != 52 && header_size != 56 && header_size != 108 && header_size != 124)
    return std::nullopt;
  const int64_t width = int32_t(u32(18)), height = int32_t(u32(22));
  return ImageSize{width, height < 0 ? -height : height};
}

}  // namespace objektiv
