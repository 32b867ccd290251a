// Fuzz harness: XML scenes through the whole loader (parsing, <include>s, <default>s, every
// plugin, meshes, textures, lenses, the Embree scene), then a few camera paths: the film's
// central 2 x 2 pixels at one sample each. The scene file lies in a scratch folder beside the
// shipped scenes' small assets (cornell-box.obj, prism.obj, grid-tile.png) and the files in
// fuzz/scene_assets (an include, a PLY, a small sky.exr), so that seeds and mutants find them.
#include <algorithm>
#include <filesystem>

#include "fuzz_support.h"
#include "io/scene_loader.h"
#include "render/renderer.h"

namespace {

namespace fs = std::filesystem;

void CopyAssets() {
  const fs::path source(OBJEKTIV_SOURCE_DIR);
  auto copy = [](const fs::path& from) {
    fs::copy_file(from, fs::path(objektiv::fuzz::ScratchDir()) / from.filename(), fs::copy_options::overwrite_existing);
  };
  for (const auto& folder : fs::directory_iterator(source / "scenes"))
    if (folder.is_directory())
      for (const auto& e : fs::directory_iterator(folder.path()))
        if (e.is_regular_file() && e.path().extension() != ".xml" && e.file_size() <= 64 * 1024) copy(e.path());
  for (const auto& e : fs::directory_iterator(source / "fuzz" / "scene_assets")) copy(e.path());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  static const bool assets = (CopyAssets(), true);
  (void)assets;
  fuzz::Quiet();
  std::string path = fuzz::WriteScratchFile("scene.xml", fuzz::Bytes(data, size));
  fuzz::IgnoringInputErrors([&] {
    RenderSetup setup = LoadScene(path, {}, GlassCatalog::Default());
    const FilmSettings& f = setup.film;
    int x0 = std::max(0, f.width / 2 - 1), y0 = std::max(0, f.height / 2 - 1);
    CropWindow crop{x0, y0, std::min(f.width, x0 + 2), std::min(f.height, y0 + 2)};
    Film film(f.width, f.height, crop, f.filter);
    SamplerSettings one = setup.sampler;
    one.spp = 1;
    RenderOptions options;
    options.spp_end = 1;
    options.threads = 1;
    Render(*setup.camera, *setup.integrator, *MakeSampler(one), film, options);
  });
  return 0;
}
