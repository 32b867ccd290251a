#include "mesh_checks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace objektiv::fuzz {

namespace {
void Require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "accepted mesh: %s\n", what);
  std::abort();
}
}  // namespace

void ExerciseMesh(MeshData mesh) {
  const size_t n = mesh.positions.size();
  Require(!mesh.indices.empty() && mesh.indices.size() % 3 == 0, "no whole triangles");
  for (uint32_t i : mesh.indices) Require(i < n, "index out of range");
  Require(mesh.normals.empty() || mesh.normals.size() == n, "normals for some vertices only");
  Require(mesh.uvs.empty() || mesh.uvs.size() == n, "uvs for some vertices only");
  for (const Vec3f& p : mesh.positions)
    Require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "non-finite position");
  TriangleMesh shape(std::move(mesh), Transform(), false);
  for (float u : {0.1f, 0.5f, 0.9f}) shape.SampleArea({u, 1 - u});
}

}  // namespace objektiv::fuzz
