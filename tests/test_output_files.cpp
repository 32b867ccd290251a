// Output files: atomic replacement, checks before writing, no input overwritten; images written
// with header attributes; a render stopped early keeps whole pixels only.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "base/input_files.h"
#include "base/output_file.h"
#include "io/image_io.h"
#include "render_helpers.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

// A fresh, empty directory for one test.
fs::path TestDir(const char* name) {
  fs::path dir = fs::temp_directory_path() / fmt::format("objektiv-output-{}-{}", name, getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string Contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void Put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

size_t EntriesIn(const fs::path& dir) { return size_t(std::distance(fs::directory_iterator(dir), {})); }

TEST(OutputFiles, ReplaceAtomicallyAndLeaveNoTemporary) {
  fs::path dir = TestDir("replace");
  Put(dir / "a.txt", "old");
  chmod((dir / "a.txt").c_str(), 0640);
  WriteTextFileAtomically((dir / "a.txt").string(), "new contents");
  EXPECT_EQ(Contents(dir / "a.txt"), "new contents");
  EXPECT_EQ(EntriesIn(dir), 1u);
  EXPECT_EQ(fs::status(dir / "a.txt").permissions(), fs::perms(0640));  // the replaced file's mode is kept
  fs::remove_all(dir);
}

TEST(OutputFiles, FailedWriteKeepsTheOldFile) {
  fs::path dir = TestDir("failed");
  Put(dir / "a.txt", "old");
  EXPECT_THROW(WriteFileAtomically((dir / "a.txt").string(),
                                   [](const std::string& temp) {
                                     Put(temp, "half");
                                     throw InputError("disk full");
                                   }),
               InputError);
  EXPECT_EQ(Contents(dir / "a.txt"), "old");
  EXPECT_EQ(EntriesIn(dir), 1u);
  fs::remove_all(dir);
}

TEST(OutputFiles, SymlinkIsWrittenWhereItPoints) {
  fs::path dir = TestDir("symlink");
  fs::create_directory(dir / "real");
  Put(dir / "real" / "a.txt", "old");
  fs::create_symlink(dir / "real" / "a.txt", dir / "link.txt");
  WriteTextFileAtomically((dir / "link.txt").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(Contents(dir / "real" / "a.txt"), "new");
  fs::remove_all(dir);
}

TEST(OutputFiles, InputFilesAreNeverReplaced) {
  fs::path dir = TestDir("inputs");
  fs::create_directory(dir / "sub");
  Put(dir / "texture.png", "pixels");
  RecordInputFile((dir / "sub" / ".." / "texture.png").string());
  fs::create_symlink(dir / "texture.png", dir / "link.png");
  fs::create_hard_link(dir / "texture.png", dir / "hard.png");
  // The same file by another spelling, through a symlink, through a hard link.
  for (const fs::path& p : {dir / "texture.png", dir / "." / "texture.png", dir / "link.png", dir / "hard.png"}) {
    EXPECT_TRUE(InputFileAt(p.string())) << p;
    EXPECT_THROW(CheckOutputFile(p.string()), InputError) << p;
    EXPECT_THROW(WriteTextFileAtomically(p.string(), "overwritten"), InputError) << p;
  }
  EXPECT_EQ(Contents(dir / "texture.png"), "pixels");
  EXPECT_FALSE(InputFileAt((dir / "other.png").string()));
  try {
    CheckOutputFile((dir / "link.png").string());
  } catch (const InputError& e) {  // the message names both files
    EXPECT_NE(std::string(e.what()).find("link.png: refusing to overwrite"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("texture.png"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(OutputFiles, CheckFindsUnwritableTargets) {
  fs::path dir = TestDir("check");
  Put(dir / "file", "x");
  fs::create_directory(dir / "adir");
  EXPECT_NO_THROW(CheckOutputFile((dir / "new.exr").string()));
  EXPECT_EQ(EntriesIn(dir), 2u);  // the probe leaves nothing behind
  EXPECT_THROW(CheckOutputFile((dir / "missing" / "x.exr").string()), InputError);  // directories are not created
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_THROW(CheckOutputFile((dir / "file" / "x.exr").string()), InputError);
  EXPECT_THROW(CheckOutputFile((dir / "adir").string()), InputError);
  if (geteuid() != 0) {  // root may write anywhere
    chmod((dir / "file").c_str(), 0444);
    EXPECT_THROW(CheckOutputFile((dir / "file").string()), InputError);
    EXPECT_THROW(WriteTextFileAtomically((dir / "file").string(), "y"), InputError);
    chmod((dir / "adir").c_str(), 0555);
    EXPECT_THROW(CheckOutputFile((dir / "adir" / "x.exr").string()), InputError);
    chmod((dir / "adir").c_str(), 0755);
  }
  fs::remove_all(dir);
}

TEST(OutputFiles, ExrCarriesHeaderAttributes) {
  fs::path dir = TestDir("exr");
  Image img(3, 2, {"R", "G", "B"});
  img.At(2, 1, 1) = 0.5f;
  std::string path = (dir / "a.exr").string();
  WriteExr(path, img, {{"objektiv:partial", 1}, {"objektiv:pixels_completed", 5.0}});
  EXPECT_EQ(EntriesIn(dir), 1u);
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_int_attribute("objektiv:partial", -1), 1);
  EXPECT_EQ(in->spec().get_float_attribute("objektiv:pixels_completed", -1), 5.0f);
  in->close();
  EXPECT_EQ(ReadImageAny(path).pixels, img.pixels);
  fs::remove_all(dir);
}

// The Cornell-like test box, 16x16 at 8 spp, rendered once whole and once stopped early.
std::string Box() {
  return R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 3.5" target="0, 1, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film></sensor>
  <emitter type="constant"><rgb name="radiance" value="0.5, 0.6, 0.7"/></emitter>
  <shape type="sphere"><point name="center" value="0, 1, 0"/><float name="radius" value="0.5"/></shape>
</scene>)";
}

// Stops the render (the flag the renderer polls) after `calls` radiance estimates.
class StoppingIntegrator final : public CameraPathIntegrator {
 public:
  StoppingIntegrator(const CameraPathIntegrator& inner, std::atomic<bool>& stop, int calls)
      : CameraPathIntegrator(inner.scene()), inner_(inner), stop_(stop), left_(calls) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& hit, SampledWavelengths& lambda,
                     Sampler& sampler, BlockContext& ctx) const override {
    if (--left_ <= 0) stop_ = true;
    return inner_.Li(ray, hit, lambda, sampler, ctx);
  }

 private:
  const CameraPathIntegrator& inner_;
  std::atomic<bool>& stop_;
  mutable std::atomic<int> left_;
};

test::RenderResult RenderBox(int stop_after_calls, int threads) {
  RenderSetup setup = LoadSceneFromString(Box(), "box.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  std::atomic<bool> stop{false};
  StoppingIntegrator integrator(dynamic_cast<const CameraPathIntegrator&>(*setup.integrator), stop, stop_after_calls);
  RenderOptions opt;
  opt.spp_end = sampler->spp();
  opt.threads = threads;
  opt.tile_size = 4;
  opt.stop = &stop;
  RenderStats stats = Render(*setup.camera, integrator, *sampler, film, opt);
  return {film.ToImage(*setup.film.color_space), stats};
}

TEST(Interrupt, StoppedRenderKeepsWholePixelsOnly) {
  const test::RenderResult whole = RenderBox(1 << 30, 1);
  EXPECT_FALSE(whole.stats.Partial());
  EXPECT_EQ(whole.stats.pixels_completed, 256u);
  for (int threads : {1, 2}) {
    // Stopped in the middle of the 41st pixel (8 samples each): the batch of camera samples
    // it is in is finished (64 samples: pixels 41 to 48, as pixels of fewer samples than a
    // batch holds share one), and each other thread's batch.
    const test::RenderResult part = RenderBox(8 * 40 + 3, threads);
    EXPECT_TRUE(part.stats.Partial());
    EXPECT_EQ(part.stats.pixels, 256u);
    EXPECT_GE(part.stats.pixels_completed, 48u);
    EXPECT_LE(part.stats.pixels_completed, 48u + 8u * (threads - 1));
    EXPECT_EQ(part.stats.samples, 8 * part.stats.pixels_completed);
    // Every pixel is the whole render's (all its samples) or black (none).
    size_t same = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        bool black = true, equal = true;
        for (int c = 0; c < 3; ++c) {
          black &= part.image.At(x, y, c) == 0;
          equal &= part.image.At(x, y, c) == whole.image.At(x, y, c);
        }
        EXPECT_TRUE(black || equal) << x << "," << y << " threads " << threads;
        same += !black && equal;
      }
    EXPECT_EQ(same, part.stats.pixels_completed) << "threads " << threads;
  }
}

}  // namespace
}  // namespace objektiv
