// Hostile and broken input files (many found by fuzzing, see tests/data/fuzz/README.md): each
// ends in an InputError naming the file (and the line where there is one), never in a crash,
// a hang or a runaway allocation.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "base/text_file.h"
#include "io/mesh_io.h"
#include "io/scene_loader.h"
#include "io/xml_document.h"
#include "optics/glass_catalog.h"
#include "optics/lens_file.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

// A fresh temporary directory for one test.
fs::path TempDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("objektiv_bad_inputs_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs f, which must throw an InputError whose message starts with `prefix` and contains `part`.
template <typename F>
void ExpectInputError(F f, const std::string& prefix, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no error; expected '" << prefix << "...'" << part;
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.rfind(prefix, 0), 0u) << msg;
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
  }
}

const char* kSensor = R"(<sensor type="perspective"><film type="hdrfilm"><integer name="width" value="4"/>
<integer name="height" value="4"/></film></sensor>)";

// A scene file in `dir` holding `body` after a small sensor (on line 3 and on).
std::string WriteScene(const fs::path& dir, const std::string& body) {
  fs::path p = dir / "scene.xml";
  std::ofstream(p) << "<scene version=\"3.0.0\">\n" << kSensor << "\n" << body << "\n</scene>\n";
  return p.string();
}

TEST(BadInputs, OnlyRegularFilesAreRead) {
  fs::path dir = TempDir("regular");
  std::string fifo = (dir / "fifo").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  ExpectInputError([&] { ReadTextFile("/dev/zero", "lens file"); }, "/dev/zero: cannot read lens file", "not a regular file");
  ExpectInputError([&] { ReadTextFile(fifo, "lens file"); }, fifo + ":", "a pipe, not a regular file");
  ExpectInputError([&] { ReadTextFile(dir.string(), "lens file"); }, dir.string() + ":", "a directory");
  ExpectInputError([&] { LoadObj("/dev/zero", {}); }, "/dev/zero:", "not a regular file");
  ExpectInputError([&] { LoadPly(fifo, {}); }, fifo + ":", "not a regular file");
  std::string fifo_lens = (dir / "fifo.lens").string();
  ASSERT_EQ(mkfifo(fifo_lens.c_str(), 0600), 0);
  ExpectInputError([&] { LoadLens(fifo_lens); }, fifo_lens + ":", "not a regular file");
  ExpectInputError([&] { GlassCatalog().LoadAgf(fifo, "TEST"); }, fifo + ":", "not a regular file");
  // A text file beyond the limit is refused before it is read (a sparse file takes no space).
  fs::path big = dir / "big.lens";
  std::ofstream(big).put('#');
  fs::resize_file(big, kMaxTextFileBytes + 1);
  ExpectInputError([&] { ReadTextFile(big.string(), "lens file"); }, big.string() + ":", "more than the limit of 64 MiB");
}

TEST(BadInputs, SpecialFilesInScenesAreErrorsAtTheirLine) {
  fs::path dir = TempDir("special");
  for (const std::string& element :
       {std::string(R"(<include filename="/dev/zero"/>)"),
        std::string(R"(<shape type="obj"><string name="filename" value="/dev/zero"/></shape>)"),
        std::string(R"(<shape type="ply"><string name="filename" value="/dev/zero"/></shape>)"),
        std::string(R"(<emitter type="envmap"><string name="filename" value="/dev/zero"/></emitter>)"),
        std::string(R"(<shape type="rectangle"><bsdf type="diffuse"><texture type="bitmap" name="reflectance">)"
                    R"(<string name="filename" value="/dev/zero"/></texture></bsdf></shape>)")}) {
    std::string scene = WriteScene(dir, element);
    ExpectInputError([&] { LoadScene(scene, {}); }, scene + ":4: /dev/zero:", "not a regular file");
  }
  // An included directory.
  std::string scene = WriteScene(dir, R"(<include filename="."/>)");
  ExpectInputError([&] { LoadScene(scene, {}); }, scene + ":4:", "a directory");
}

TEST(BadInputs, ObjMaterialLibrariesAreNotOpened) {
  // tinyobjloader would read 'mtllib' files, /dev/zero until memory runs out; materials come
  // from the scene, so the mesh loads without opening it.
  fs::path dir = TempDir("mtllib");
  fs::path obj = dir / "tri.obj";
  std::ofstream(obj) << "mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  MeshData m = LoadObj(obj.string(), {});
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.indices.size(), 3u);
}

// `n` nested objects (one per line from line 2), as repro 01-deep-nesting (6000 levels) had.
std::string NestedBsdfs(int n) {
  std::string xml = "<scene version=\"3.0.0\">\n";
  for (int i = 0; i < n; ++i) xml += "<bsdf type=\"twosided\">\n";
  for (int i = 0; i < n; ++i) xml += "</bsdf>";
  return xml + "</scene>\n";
}

TEST(BadInputs, DeepNestingIsAnError) {
  EXPECT_NO_THROW(ParseSceneString(NestedBsdfs(kMaxObjectNesting), "deep.xml", {}));
  // The first object too deep is on line 2 + kMaxObjectNesting. 6000 levels overflowed the stack.
  for (int n : {kMaxObjectNesting + 1, 6000})
    ExpectInputError([&] { ParseSceneString(NestedBsdfs(n), "deep.xml", {}); },
                     "deep.xml:" + std::to_string(2 + kMaxObjectNesting) + ":", "nested more than 100 levels deep");
}

TEST(BadInputs, ReferenceChainsCountAsNesting) {
  // Each texture refers to the one before: no element is nested, but every walk over the
  // objects (building textures, destroying the tree) recursed 20000 deep.
  std::string xml = "<scene version=\"3.0.0\">\n<texture type=\"checkerboard\" id=\"t0\"/>\n";
  for (int i = 1; i < 20000; ++i)
    xml += fmt::format("<texture type=\"checkerboard\" id=\"t{}\"><ref id=\"t{}\" name=\"color0\"/></texture>\n", i, i - 1);
  xml += "</scene>\n";
  // Texture t100 (line 102) is the first with 101 levels.
  ExpectInputError([&] { ParseSceneString(xml, "chain.xml", {}); }, "chain.xml:102:", "counting those <ref>s");
}

TEST(BadInputs, SharedNestedTexturesLoadInLinearTime) {
  // Checkerboards whose two colours are one texture, 60 deep: a recursive mean (for the
  // emitter's power) visited 2^60 leaves.
  std::string body = "<texture type=\"checkerboard\" id=\"t0\"/>\n";
  for (int i = 1; i <= 60; ++i)
    body += fmt::format("<texture type=\"checkerboard\" id=\"t{0}\"><ref id=\"t{1}\" name=\"color0\"/>"
                        "<ref id=\"t{1}\" name=\"color1\"/></texture>\n", i, i - 1);
  body += "<shape type=\"rectangle\"><emitter type=\"area\"><ref id=\"t60\" name=\"radiance\"/></emitter></shape>";
  RenderSetup setup = LoadSceneFromString(std::string("<scene version=\"3.0.0\">") + kSensor + body + "</scene>", "dag.xml", {});
  EXPECT_EQ(setup.scene->lights().size(), 1u);
}

TEST(BadInputs, ParameterExpansionIsBounded) {
  // Each parameter is ten of the one before: $p9 would be 10^10 characters.
  std::string xml = "<scene version=\"3.0.0\">\n<default name=\"p0\" value=\"0123456789\"/>\n";
  for (int i = 1; i < 10; ++i)
    xml += fmt::format("<default name=\"p{}\" value=\"{}\"/>\n", i, [&] {
      std::string v;
      for (int k = 0; k < 10; ++k) v += fmt::format("$p{}", i - 1);
      return v;
    }());
  xml += "</scene>\n";
  ExpectInputError([&] { ParseSceneString(xml, "laughs.xml", {}); }, "laughs.xml:", "more than 64 MiB of text");
}

TEST(BadInputs, IncludesAreBounded) {
  fs::path dir = TempDir("includes");
  // Each level includes the next ten times: 10^6 includes of the last.
  for (int level = 0; level < 6; ++level) {
    std::ofstream f(dir / fmt::format("f{}.xml", level));
    f << "<scene>\n";
    for (int k = 0; k < 10; ++k) f << fmt::format("<include filename=\"f{}.xml\"/>\n", level + 1);
    f << "</scene>\n";
  }
  std::ofstream(dir / "f6.xml") << "<scene/>\n";
  std::string f0 = (dir / "f0.xml").string();
  ExpectInputError([&] { ParseSceneFile(f0, {}); }, dir.string(), "more than 10000 <include>s in all");
  // A large file included twice: more XML in all than a single file may hold.
  {
    std::ofstream big(dir / "big.xml");
    big << "<scene><!--" << std::string(kMaxTextFileBytes / 2 + 1, '.') << "--></scene>\n";
  }
  std::ofstream(dir / "twice.xml") << "<scene>\n<include filename=\"big.xml\"/>\n<include filename=\"big.xml\"/>\n</scene>\n";
  ExpectInputError([&] { ParseSceneFile((dir / "twice.xml").string(), {}); }, (dir / "big.xml").string() + ":",
                   "more than 64 MiB of XML in all");
}

TEST(BadInputs, BlackbodyTemperaturesOutsidePlancksRangeAreErrors) {
  // 1e30 K and 1e-30 K made every sample of the emitter NaN (Planck's law overflowed).
  for (const char* t : {"1e30", "1e-30", "0.5", "2e9"})
    ExpectInputError(
        [&] {
          LoadSceneFromString(std::string("<scene version=\"3.0.0\">") + kSensor +
                                  "\n<shape type=\"rectangle\"><emitter type=\"area\"><spectrum name=\"radiance\" "
                                  "type=\"blackbody\" temperature=\"" + t + "\"/></emitter></shape></scene>",
                              "bb.xml", {});
        },
        "bb.xml:3:", "temperature from 1 to 1e9 K");
}

TEST(BadInputs, GeometryBeyondTheCoordinateLimitIsAnError) {
  // Repro 02 (a mesh vertex at 9.2e18 as an area light) overflowed light sampling to
  // non-finite shadow rays; bounded at load, everywhere a position can come from.
  struct Case {
    std::string element, part;
  };
  const std::vector<Case> cases = {
      {R"(<shape type="rectangle"><transform name="to_world"><scale value="2e8"/></transform></shape>)",
       "vertex 0 lies at (-2e+08, -2e+08, 0), beyond the scene's coordinate limit of 1e+08"},
      {R"(<shape type="sphere"><float name="radius" value="1e9"/></shape>)", "the sphere reaches"},
      {R"(<shape type="sphere"><point name="center" x="1e20" y="0" z="0"/></shape>)", "the sphere reaches"},
      {R"(<shape type="disk"><transform name="to_world"><translate x="-3e8"/></transform></shape>)", "the disk reaches"},
      {R"(<shape type="cylinder"><float name="radius" value="1e9"/></shape>)", "the cylinder reaches"},
      {R"(<shape type="plane"><transform name="to_world"><translate z="1e30"/></transform></shape>)", "the plane's origin"},
      {R"(<shape type="shapegroup" id="g"><shape type="cube"/></shape>)"
       R"(<shape type="instance"><ref id="g"/><transform name="to_world"><translate y="5e8"/></transform></shape>)",
       "the instance reaches"},
      {R"(<emitter type="point"><point name="position" x="0" y="1e10" z="0"/></emitter>)", "the point light at (0, 1e+10, 0)"},
      {R"(<emitter type="spot"><transform name="to_world"><translate x="1e9"/></transform></emitter>)", "the spot light"},
      {R"(<emitter type="directional"><vector name="direction" x="0" y="0" z="0"/></emitter>)", "direction must be finite and not zero"},
      // Each scale is finite; composed, they overflow a double.
      {R"(<shape type="cube"><transform name="to_world"><scale value="1e200"/><scale value="1e200"/></transform></shape>)",
       "the transform overflows"},
  };
  for (const Case& c : cases)
    ExpectInputError([&] { LoadSceneFromString(std::string("<scene version=\"3.0.0\">") + kSensor + "\n" + c.element + "</scene>", "far.xml", {}); },
                     "far.xml:3:", c.part);
  std::string far_sensor = R"(<scene version="3.0.0"><sensor type="perspective">
<transform name="to_world"><translate x="2e8"/></transform></sensor></scene>)";
  ExpectInputError([&] { LoadSceneFromString(far_sensor, "cam.xml", {}); }, "cam.xml:2:", "the sensor at (2e+08, 0, 0)");
  // A direction far from unit length is normalised without overflowing.
  LoadSceneFromString(std::string("<scene version=\"3.0.0\">") + kSensor +
                          R"(<emitter type="directional"><vector name="direction" x="0" y="-1e30" z="0"/></emitter></scene>)",
                      "dir.xml", {});
}

}  // namespace
}  // namespace objektiv
