// Triangle meshes from OBJ (tinyobjloader) and PLY (Assimp) files.
#pragma once
#include <cstdint>
#include <string>

#include "scene/triangle_mesh.h"

namespace objektiv {

struct MeshLoadOptions {
  std::string group;            // OBJ only: load just this 'o' / 'g' group (empty: all)
  bool flip_tex_coords = true;  // v -> 1 - v (OBJ convention, as Mitsuba)
  bool face_normals = false;    // drop vertex normals: flat shading
};

// Largest mesh file read (OBJ or PLY).
inline constexpr uintmax_t kMaxMeshFileBytes = uintmax_t(4) << 30;

// Throws InputError naming the file on any problem.
MeshData LoadObj(const std::string& path, const MeshLoadOptions& options);
MeshData LoadPly(const std::string& path, const MeshLoadOptions& options);

}  // namespace objektiv
