// Fuzz harness: OBJ meshes (tinyobjloader) through Objektiv's mesh loader, then the mesh as a shape.
#include "fuzz_support.h"
#include "io/mesh_io.h"
#include "mesh_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  std::string path = fuzz::WriteScratchFile("input.obj", fuzz::Bytes(data, size));
  fuzz::IgnoringInputErrors([&] { fuzz::ExerciseMesh(LoadObj(path, MeshLoadOptions{})); });
  return 0;
}
