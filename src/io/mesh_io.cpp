#include "io/mesh_io.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_obj_loader.h>

#include <assimp/Importer.hpp>
#include <map>
#include <tuple>

#include "base/error.h"
#include "base/text_file.h"

namespace objektiv {

namespace {
void CheckFinite(const MeshData& m, const std::string& path) {
  for (const Vec3f& p : m.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw MakeInputError(path, 0, "mesh has a non-finite vertex position");
  if (m.indices.empty()) throw MakeInputError(path, 0, "mesh has no triangles");
}
}  // namespace

MeshData LoadObj(const std::string& path, const MeshLoadOptions& options) {
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

MeshData LoadPly(const std::string& path, const MeshLoadOptions& options) {
  CheckInputFile(path, "PLY mesh", kMaxMeshFileBytes);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode) throw MakeInputError(path, 0, "cannot read PLY: {}", importer.GetErrorString());
  MeshData m;
  bool has_normals = !options.face_normals, has_uvs = true;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    has_normals &= mesh->HasNormals();
    has_uvs &= mesh->HasTextureCoords(0);
  }
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
      if (face.mNumIndices != 3) continue;  // points and lines
      for (int k = 0; k < 3; ++k) m.indices.push_back(base + face.mIndices[k]);
    }
  }
  CheckFinite(m, path);
  return m;
}

}  // namespace objektiv
