// PLY meshes: ASCII and both binary byte orders read alike, polygons split into triangles
// inside them, and broken files (many found by fuzzing, tests/data/fuzz/README.md) are errors
// naming the file: never a crash inside Assimp, an assertion, a hang or a runaway allocation.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "base/error.h"
#include "io/mesh_io.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

fs::path WritePly(const std::string& name, const std::string& bytes) {
  fs::path dir = fs::temp_directory_path() / "objektiv_ply_test";
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
  return dir / name;
}

// Bytes of a value in the given byte order.
template <typename T>
std::string Bytes(T v, bool big_endian) {
  std::string b(sizeof(T), '\0');
  std::memcpy(b.data(), &v, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b.begin(), b.end());
  return b;
}

// A unit square (a quad) beside a triangle, with uvs, in the given format.
std::string SquareAndTriangle(const std::string& format) {
  const float v[6][5] = {{0, 0, 0, 0, 0}, {1, 0, 0, 1, 0}, {1, 1, 0, 1, 1}, {0, 1, 0, 0, 1}, {2, 0, 0, 0, 0}, {3, 0, 0, 0, 0}};
  std::string s = "ply\nformat " + format +
                  " 1.0\ncomment test\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                  "property float u\nproperty float v\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const std::vector<std::vector<int>> faces = {{0, 1, 2, 3}, {1, 4, 2}};
  const bool ascii = format == "ascii", big = format == "binary_big_endian";
  for (const auto& row : v)
    for (int c = 0; c < 5; ++c) s += ascii ? fmt::format("{}{}", row[c], c == 4 ? "\n" : " ") : Bytes(row[c], big);
  for (const auto& f : faces) {
    if (ascii) s += std::to_string(f.size());
    else s.push_back(char(f.size()));
    for (int i : f) s += ascii ? fmt::format(" {}", i) : Bytes(int32_t(i), big);
    if (ascii) s += "\n";
  }
  return s;
}

float TotalArea(const MeshData& m) {
  float area = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    Vec3f a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    area += 0.5f * Length(Cross(b - a, c - a));
  }
  return area;
}

TEST(Ply, AsciiAndBinaryReadAlike) {
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    MeshData m = LoadPly(WritePly(std::string(format) + ".ply", SquareAndTriangle(format)).string(), {});
    EXPECT_EQ(m.indices.size(), 9u) << format;  // the square as two triangles, and the triangle
    EXPECT_FLOAT_EQ(TotalArea(m), 1 + 0.5f) << format;
    ASSERT_EQ(m.uvs.size(), m.positions.size()) << format;
  }
}

TEST(Ply, ConcaveQuadrilateralsAreSplitInside) {
  // An arrowhead whose reflex corner is corner 1: split along the diagonal from corner 0 (as a
  // fan from the first corner would), two of its triangles lie outside, and the area is 12.
  std::string s = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                  "4 0 0\n1 1 0\n0 4 0\n0 0 0\n4 0 1 2 3\n";
  MeshData m = LoadPly(WritePly("arrow.ply", s).string(), {});
  EXPECT_EQ(m.indices.size(), 6u);
  EXPECT_FLOAT_EQ(TotalArea(m), 4);
}

struct Bad {
  std::string name, bytes, part;
};

TEST(Ply, BrokenFilesAreErrors) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
  std::string binary = SquareAndTriangle("binary_little_endian");
  // The first face's first index (after the header, 6 vertices of 20 bytes and a count byte).
  const size_t first_index = binary.find("end_header\n") + 11 + 6 * 20 + 1;
  std::string far_index = binary, negative_count = binary;
  far_index.replace(first_index, 4, Bytes(int32_t(1000000), false));
  negative_count[first_index - 1] = char(0xff);
  negative_count.replace(negative_count.find("list uchar"), 10, "list  char");
  std::vector<Bad> cases = {
      // Repro 09 (its header cut inside 'end_header') hung Assimp's reader.
      {"no_end.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_head" + std::string(100000, 'x'),
       ": no 'end_header' line in the first 64 KiB"},
      {"not_ply.ply", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nend_header\n", ":1: not a PLY file"},
      {"format.ply", "ply\nformat binary 1.0\nend_header\n", ":2: unknown PLY format 'binary'"},
      {"count.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999\nend_header\n", ":3: element count '99999999999' is not"},
      {"minus.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", ":3: element count '-3'"},
      {"property.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n", ":4: a property line"},
      // Two billion vertices claimed by a file of a few bytes: Assimp reserved memory for them.
      {"claims.ply", "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nend_header\n1\n2\n",
       ":7: the file ends in vertex 2 of 2000000000"},
      {"cut_ascii.ply", head + verts + "3 0 1\n", ":13: the file ends in face 0 of 1"},
      {"list_len.ply", head + verts + "1e10 0 1 2\n", "'1e10' is not a list length"},
      {"cut_binary.ply", binary.substr(0, binary.size() - 3), ": the file ends in face 1 of 2 (declared on line 10)"},
      {"negative.ply", negative_count, ": a negative list length in face 0"},
      // Out-of-range corners crashed Assimp's post-processing (a segmentation fault).
      {"far.ply", far_index, "out of range"},
      {"far_ascii.ply", head + verts + "3 0 1 7\n", "out of range"},
      {"nan.ply", head + "nan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "non-finite vertex position"},
      {"nan_uv.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty float u\n"
       "property float v\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
       "0 0 0 0 0\n1 0 0 inf 0\n0 1 0 0 0\n3 0 1 2\n",
       "non-finite texture coordinate"},
      // Faces of fewer than three corners: a face of none crashed Assimp's reader (found by the
      // fuzzer: fuzz/regressions/mesh_ply/crash-b09c9da49bdc).
      {"lines.ply", head + verts + "2 0 1\n", ":13: face 0 has 2 corners (a face needs at least 3)"},
      {"trailing_binary.ply", binary + "xyz", ": 3 bytes after the last record"},
      // Each record on its own line, as Assimp reads them: a short or a long row (the fuzzer's
      // "-1 1-1" row put a 57-digit list length where Assimp read it: 3.8 GB allocated).
      {"short_row.ply", head + "0 0\n0 1 0 0\n0 1 0\n3 0 1 2\n", ":10: vertex 0 has fewer values on its line"},
      {"long_row.ply", head + "0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n", ":10: more values on the line than a record holds"},
      {"uchar_count.ply", head + verts + "300 0 1 2\n", "'300' is not a list length from 0 to 255"},
      {"trailing.ply", head + verts + "3 0 1 2\n5 5\n", ":14: values after the last record"},
      // Found by the fuzzer (fuzz/regressions/mesh_ply/crash-*, oom-68ac55b4a8e4): a second format
      // line, or names with bytes outside printable ASCII, and Assimp read another layout than
      // the check had passed (one took 6 GB).
      {"two_formats.ply", "ply\nformat ascii 1.0\nformat binary_big_endian 1.0\nend_header\n", ":3: a second format line"},
      {"late_format.ply", "ply\nelement vertex 1\nformat ascii 1.0\nend_header\n", ":2: the format line must follow 'ply'"},
      {"odd_name.ply", "ply\nformat ascii 1.0\nelement ve\xdf\xdfrtex 1\nproperty float x\nend_header\n1\n",
       ":3: a header line with a byte that is not printable ASCII"},
  };
  for (const Bad& b : cases) {
    fs::path p = WritePly(b.name, b.bytes);
    try {
      LoadPly(p.string(), {});
      ADD_FAILURE() << b.name << ": no error";
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind(p.string() + ":", 0), 0u) << msg;
      EXPECT_NE(msg.find(b.part), std::string::npos) << b.name << ": " << msg;
    }
  }
}

}  // namespace
}  // namespace objektiv
