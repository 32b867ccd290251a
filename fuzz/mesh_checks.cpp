#include "mesh_checks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace objektiv::fuzz {

namespace {
void Require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "accepted mesh: %s\n", what);
  std::abort();
}
bool Finite(Vec3f v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

void ExerciseMesh(MeshData mesh) {
  const size_t n = mesh.positions.size();
  Require(!mesh.indices.empty() && mesh.indices.size() % 3 == 0, "no whole triangles");
  for (uint32_t i : mesh.indices) Require(i < n, "index out of range");
  Require(mesh.normals.empty() || mesh.normals.size() == n, "normals for some vertices only");
  Require(mesh.uvs.empty() || mesh.uvs.size() == n, "uvs for some vertices only");
  for (const Vec3f& p : mesh.positions) Require(Finite(p), "non-finite position");
  for (const Vec3f& v : mesh.normals) Require(Finite(v), "non-finite normal");
  for (const Vec2f& uv : mesh.uvs) Require(std::isfinite(uv.x) && std::isfinite(uv.y), "non-finite uv");
  try {
    TriangleMesh shape(std::move(mesh), Transform(), false);
    for (float u : {0.1f, 0.5f, 0.9f}) shape.SampleArea({u, 1 - u});
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace objektiv::fuzz
