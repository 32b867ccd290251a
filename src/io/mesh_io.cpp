#include "io/mesh_io.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_obj_loader.h>

#include <assimp/Importer.hpp>
#include <map>
#include <tuple>

#include "base/error.h"
#include "base/input_files.h"
#include "base/log.h"
#include "base/text_file.h"
#include "io/ply_check.h"

namespace objektiv {

namespace {
// Every position, normal and texture coordinate finite (NaN or infinite ones would reach the
// renderer's arithmetic, and Embree), and at least one triangle.
void CheckFinite(const MeshData& m, const std::string& path) {
  auto finite = [](const auto& v) {
    if constexpr (requires { v.z; }) return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    else return std::isfinite(v.x) && std::isfinite(v.y);
  };
  auto check = [&](const auto& values, const char* what) {
    for (size_t i = 0; i < values.size(); ++i)
      if (!finite(values[i])) throw MakeInputError(path, 0, "mesh has a non-finite {} (vertex {})", what, i);
  };
  check(m.positions, "vertex position");
  check(m.normals, "normal");
  check(m.uvs, "texture coordinate");
  if (m.indices.empty()) throw MakeInputError(path, 0, "mesh has no triangles");
}
}  // namespace

MeshData LoadObj(const std::string& path, const MeshLoadOptions& options) {
  RecordInputFile(path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From memory, with no material library: tinyobjloader would otherwise open any file an
  // 'mtllib' line names (materials come from the scene, not from .mtl files).
  if (!reader.ParseFromString(ReadTextFile(path, "OBJ mesh", kMaxMeshFileBytes), "", config)) {
    std::string err = reader.Error();
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw MakeInputError(path, 0, "cannot read OBJ: {}", err.empty() ? "unknown error" : err);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  MeshData m;
  std::map<std::tuple<int, int, int>, uint32_t> vertex_ids;
  bool found = options.group.empty();
  std::string available;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    available += (available.empty() ? "" : ", ") + shape.name;
    if (!options.group.empty() && shape.name != options.group) continue;
    found = true;
    for (const tinyobj::index_t& idx : shape.mesh.indices) {
      int vn = options.face_normals ? -1 : idx.normal_index;
      auto key = std::make_tuple(idx.vertex_index, vn, idx.texcoord_index);
      auto it = vertex_ids.find(key);
      if (it == vertex_ids.end()) {
        uint32_t id = uint32_t(m.positions.size());
        it = vertex_ids.emplace(key, id).first;
        size_t v = size_t(idx.vertex_index);
        if (idx.vertex_index < 0 || 3 * v + 2 >= attrib.vertices.size())
          throw MakeInputError(path, 0, "face refers to a missing vertex");
        m.positions.push_back({attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]});
        if (vn >= 0) {
          size_t n = size_t(vn);
          if (3 * n + 2 >= attrib.normals.size()) throw MakeInputError(path, 0, "face refers to a missing normal");
          m.normals.push_back({attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]});
        } else {
          m.normals.push_back({0, 0, 0});
        }
        if (idx.texcoord_index >= 0) {
          size_t t = size_t(idx.texcoord_index);
          if (2 * t + 1 >= attrib.texcoords.size()) throw MakeInputError(path, 0, "face refers to a missing uv");
          float v_coord = attrib.texcoords[2 * t + 1];
          m.uvs.push_back({attrib.texcoords[2 * t], options.flip_tex_coords ? 1 - v_coord : v_coord});
        } else {
          m.uvs.push_back({0, 0});
        }
      }
      m.indices.push_back(it->second);
    }
  }
  if (!found) throw MakeInputError(path, 0, "no group named '{}' (groups: {})", options.group, available);
  // Keep normals / uvs only when every vertex has them.
  bool all_normals = true, any_uv = false;
  for (const auto& [key, id] : vertex_ids) {
    all_normals &= std::get<1>(key) >= 0;
    any_uv |= std::get<2>(key) >= 0;
  }
  if (!all_normals) m.normals.clear();
  if (!any_uv) m.uvs.clear();
  CheckFinite(m, path);
  return m;
}

namespace {

// Appends a polygon's triangles: a fan around one corner, the reflex corner of a concave
// quadrilateral (the one corner whose fan stays inside it) or else the first (exact for
// convex polygons).
void AppendPolygon(const uint32_t* corners, unsigned n, MeshData& m) {
  unsigned start = 0;
  if (n == 4) {
    auto p = [&](unsigned i) { return m.positions[corners[i % 4]]; };
    Vec3f normal(0.f);  // Newell's normal
    for (unsigned i = 0; i < 4; ++i) normal += Cross(p(i), p(i + 1));
    for (unsigned i = 0; i < 4; ++i)
      if (Dot(Cross(p(i) - p(i + 3), p(i + 1) - p(i)), normal) < 0) start = i;
  }
  for (unsigned k = 1; k + 1 < n; ++k)
    for (unsigned c : {start, (start + k) % n, (start + k + 1) % n}) m.indices.push_back(corners[c]);
}

}  // namespace

MeshData LoadPly(const std::string& path, const MeshLoadOptions& options) {
  const std::string bytes = ReadTextFile(path, "PLY mesh", kMaxMeshFileBytes);
  const PlyLayout layout = CheckPlyFile(bytes, path);
  // Only Assimp's PLY reader (the hint), on the bytes checked above. Its data is validated
  // before any post-processing (out-of-range indices crashed it), and polygons are
  // triangulated here (its triangulation asserts on some broken faces).
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(),
                                                     aiProcess_ValidateDataStructure | aiProcess_JoinIdenticalVertices, "ply");
  if (!scene || !scene->mRootNode) throw MakeInputError(path, 0, "cannot read PLY: {}", importer.GetErrorString());
  MeshData m;
  bool has_normals = !options.face_normals, has_uvs = true;
  int64_t faces = 0, not_polygons = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    has_normals &= mesh->HasNormals();
    has_uvs &= mesh->HasTextureCoords(0);
    faces += mesh->mNumFaces;
  }
  if (faces != layout.Count("face"))
    throw MakeInputError(path, 0, "{} faces were read of the {} the header declares (the file is malformed)", faces,
                         layout.Count("face"));
  std::vector<uint32_t> corners;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    uint32_t base = uint32_t(m.positions.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      m.positions.push_back({mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z});
      if (has_normals) m.normals.push_back({mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z});
      if (has_uvs) m.uvs.push_back({mesh->mTextureCoords[0][v].x, mesh->mTextureCoords[0][v].y});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices < 3) {
        ++not_polygons;
        continue;
      }
      corners.clear();
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= mesh->mNumVertices)
          throw MakeInputError(path, 0, "face {} refers to vertex {}, of {}", f, face.mIndices[k], mesh->mNumVertices);
        corners.push_back(base + face.mIndices[k]);
      }
      AppendPolygon(corners.data(), face.mNumIndices, m);
    }
  }
  if (not_polygons) spdlog::warn("{}: {} faces of fewer than 3 vertices (points or lines) are ignored", path, not_polygons);
  CheckFinite(m, path);
  return m;
}

}  // namespace objektiv
