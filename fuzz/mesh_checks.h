// What the mesh harnesses do with a mesh that a reader accepted: check that the renderer can
// take it (indices in range, per-vertex normals and uvs for every vertex or none, finite
// positions), then build the shape and sample points on it, as an area light does.
#pragma once
#include "scene/triangle_mesh.h"

namespace objektiv::fuzz {

void ExerciseMesh(MeshData mesh);

}  // namespace objektiv::fuzz
