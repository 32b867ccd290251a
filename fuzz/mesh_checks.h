// What the mesh harnesses do with a mesh that a reader accepted: check what the readers
// promise (whole triangles, indices in range, normals and uvs for every vertex or none, every
// number finite), then build the shape and sample points on it, as an area light does. The
// shape may still refuse a vertex beyond the scene's coordinate limit (std::invalid_argument,
// which the scene loader reports at the <shape>'s line): that is a right answer too.
#pragma once
#include "scene/triangle_mesh.h"

namespace objektiv::fuzz {

void ExerciseMesh(MeshData mesh);

}  // namespace objektiv::fuzz
