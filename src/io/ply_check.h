// A PLY file read and checked before Assimp sees it. Assimp's reader hangs on a header cut
// short, reserves memory for whatever element counts a header claims, and takes a cut-off
// ASCII body for faces of fewer corners. Here the header must end (`end_header`) within its
// first kMaxPlyHeaderBytes, begin with its one format line, hold only printable ASCII outside
// comments (so that Assimp reads the same layout), and the body must hold every record the
// header declares: for
// ASCII, one value per property and the declared number of items per list; for binary, the
// bytes of every property and list (their counts read as the header types them), and nothing
// after; a face has at least three corners.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace objektiv {

inline constexpr size_t kMaxPlyHeaderBytes = 64 * 1024;

struct PlyProperty {
  std::string name;
  int size = 0;        // bytes of the value (of each item, for a list)
  int count_size = 0;  // bytes of a list's count; 0 for a single value
  bool count_signed = false;
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  int line = 0;  // where it is declared
  std::vector<PlyProperty> properties;
};

struct PlyLayout {
  enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian } format = Format::kAscii;
  std::vector<PlyElement> elements;
  // The declared count of the element named `name` (0 if absent).
  int64_t Count(const std::string& name) const;
};

// The header of `bytes` (the whole file), after checking that the body holds what it
// declares; throws InputError "PATH:LINE: ..." otherwise.
PlyLayout CheckPlyFile(const std::string& bytes, const std::string& path);

}  // namespace objektiv
