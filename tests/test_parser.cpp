// The scene language: valid scenes load, and every kind of bad input is an InputError that
// names the file and the line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "io/scene_loader.h"
#include "io/xml_document.h"

namespace objektiv {
namespace {

const char* kSensor = R"(<sensor type="perspective"><film type="hdrfilm"><integer name="width" value="8"/>
<integer name="height" value="8"/></film></sensor>)";

std::string Wrap(const std::string& body) { return std::string("<scene version=\"3.0.0\">\n") + kSensor + "\n" + body + "\n</scene>\n"; }

struct BadCase {
  std::string xml;
  int line;
  std::string message_part;
};

// Each case fails to load with an error at its line that says what is wrong.
void ExpectErrors(const std::vector<BadCase>& cases) {
  for (const BadCase& c : cases) {
    try {
      LoadSceneFromString(c.xml, "bad.xml", {});
      ADD_FAILURE() << "no error for:\n" << c.xml;
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind("bad.xml:" + std::to_string(c.line) + ":", 0), 0u) << msg;
      EXPECT_NE(msg.find(c.message_part), std::string::npos) << msg;
    }
  }
}

TEST(Parser, BadInputNamesFileAndLine) {
  // The sensor occupies lines 2-3; bodies start at line 4.
  std::vector<BadCase> cases = {
      {Wrap("<shape type=\"sphere\">\n<bsdf type=\"velvet\"/></shape>"), 5, "unknown bsdf type 'velvet'"},
      {Wrap("<frobnicate/>"), 4, "unknown element <frobnicate>"},
      {Wrap("<shape type=\"obj\"/>"), 4, "needs the property 'filename'"},
      {Wrap("<shape type=\"sphere\">\n<float name=\"radius\" value=\"abc\"/></shape>"), 5, "not a finite number"},
      {Wrap("<shape type=\"sphere\">\n<ref id=\"nothing\"/></shape>"), 5, "unknown id 'nothing'"},
      {Wrap("<shape type=\"obj\">\n<string name=\"filename\" value=\"missing.obj\"/></shape>"), 5, "file not found"},
      {Wrap("<bsdf type=\"diffuse\" id=\"a\"/>\n<bsdf type=\"diffuse\" id=\"a\"/>"), 5, "id 'a' is used twice"},
      {Wrap("<integrator type=\"bdpt\"/>"), 4, "unknown integrator type 'bdpt'"},
      {Wrap("<shape type=\"sphere\">\n<rgb name=\"radius\" value=\"1,2,3\"/></shape>"), 5, "must be a <float>"},
      {Wrap("<shape type=\"sphere\">\n<float name=\"radius\" value=\"$r\"/></shape>"), 5, "undefined parameter $r"},
      {Wrap("<shape type=\"sphere\">\n<float name=\"radius\" value=\"-1\"/></shape>"), 5, "radius must be positive"},
      {Wrap("<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<rgb name=\"reflectance\" value=\"1.5, 0, 0\"/></bsdf></shape>"),
       5, "must lie in [0, 1]"},
      // As a number and as a tabulated spectrum as well.
      {Wrap("<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<float name=\"reflectance\" value=\"1.2\"/></bsdf></shape>"),
       5, "reflectance 'reflectance' must lie in [0, 1]"},
      {Wrap("<shape type=\"sphere\"><bsdf type=\"roughplastic\">\n<spectrum name=\"diffuse_reflectance\" "
            "value=\"400:0.5, 700:1.3\"/></bsdf></shape>"),
       5, "reflectance 'diffuse_reflectance' must lie in [0, 1]"},
      {Wrap("<shape type=\"sphere\"><bsdf type=\"dielectric\">\n<string name=\"int_ior\" value=\"unobtainium\"/></bsdf></shape>"),
       5, "unknown index of refraction"},
      {Wrap("<shape type=\"sphere\"><bsdf type=\"dielectric\">\n<string name=\"int_ior\" value=\"SCHOTT:N-NOPE\"/></bsdf></shape>"),
       5, "catalog glass"},
      {Wrap("<shape type=\"sphere\"><bsdf type=\"conductor\">\n<string name=\"material\" value=\"Zz\"/></bsdf></shape>"), 5,
       "unknown conductor"},
      // A Sellmeier pole at 500 nm (c1 = 0.25 um^2) and a Cauchy index that turns negative.
      {Wrap("<shape type=\"sphere\"><bsdf type=\"dielectric\">\n<float name=\"sellmeier_b1\" value=\"1\"/>"
            "<float name=\"sellmeier_c1\" value=\"0.25\"/></bsdf></shape>"),
       5, "Sellmeier coefficients give no real positive index of refraction at"},
      {Wrap("<shape type=\"sphere\"><bsdf type=\"dielectric\">\n<float name=\"cauchy_a\" value=\"1.5\"/>"
            "<float name=\"cauchy_b\" value=\"-1\"/></bsdf></shape>"),
       5, "Cauchy coefficients give no real positive index of refraction at 360 nm"},
      {Wrap("<shape type=\"sphere\">\n<transform name=\"to_world\"><scale x=\"0\"/></transform></shape>"), 5,
       "scale factor of zero"},
      {Wrap("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1\"/>\n<float name=\"radius\" value=\"2\"/></shape>"), 6,
       "given twice"},
      {Wrap("<emitter type=\"area\"/>"), 4, "must be nested inside a <shape>"},
      {Wrap("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1\" extra=\"2\"/></shape>"), 5,
       "does not take the attribute 'extra'"},
      {"<scene version=\"3.0.0\">\n<shape type=\"sphere\">\n</scene>\n", 3, "XML syntax error"},
      {"<scene version=\"3.0.0\">\n</scene>\n", 1, "no <sensor>"},
      {"<scene>\n<sensor type=\"perspective\"><sampler type=\"independent\">\n<integer name=\"sample_count\" value=\"0\"/>"
       "</sampler></sensor></scene>",
       3, "outside"},
      {"<scene>\n<sensor type=\"fisheye\"/></scene>", 2, "unknown sensor type"},
      {"<scene>\n<sensor type=\"thinlens\"><float name=\"fov\" value=\"40\"/></sensor></scene>", 2,
       "thinlens needs the property 'focus_distance'"},
      {Wrap("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1e39\"/></shape>"), 5, "too large"},
      {Wrap("<emitter type=\"point\">\n<rgb name=\"intensity\" value=\"-5\"/></emitter>"), 5, "not negative"},
      {Wrap("<emitter type=\"constant\">\n<spectrum name=\"radiance\" value=\"400:1, 500:-2\"/></emitter>"), 5,
       "not negative"},
  };
  ExpectErrors(cases);
}

TEST(Parser, RealisticSensorErrorsNameFileAndLine) {
  auto scene = [](const std::string& props) {
    return "<scene version=\"3.0.0\">\n<sensor type=\"realistic\">\n" + props + "\n</sensor>\n</scene>\n";
  };
  std::vector<BadCase> cases = {
      {scene("<string name=\"lens\" value=\"no.such.lens\"/>"), 3, "no lens file 'no.such.lens'"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"fnumber\" value=\"1.2\"/>"), 2,
       "faster than"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"aperture_diameter\" value=\"90\"/>"), 2,
       "larger than"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<string name=\"sensor\" value=\"imax\"/>"), 4,
       "unknown sensor 'imax'"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<string name=\"vignetting\" value=\"some\"/>"), 4,
       "vignetting"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<integer name=\"blades\" value=\"2\"/>"), 4,
       "blades"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"focus_distance\" value=\"-1\"/>"), 4,
       "focus_distance"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"focus_distance\" value=\"1\"/>\n"
             "<point name=\"focus_point\" x=\"0\" y=\"0\" z=\"1\"/>"),
       5, "either focus_distance or focus_point"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<point name=\"focus_point\" x=\"0\" y=\"0\" z=\"-1\"/>"), 2,
       "behind the camera"},
      {scene("<float name=\"fnumber\" value=\"4\"/>"), 2, "needs the property 'lens'"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"hood_diameter\" value=\"60\"/>"), 4,
       "hood_diameter without hood_length"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"hood_length\" value=\"30\"/>"), 4,
       "hood_diameter (round) or hood_width and hood_height"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"hood_length\" value=\"30\"/>\n"
             "<float name=\"hood_width\" value=\"60\"/>"),
       5, "takes both hood_width and hood_height"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"hood_length\" value=\"30\"/>\n"
             "<float name=\"hood_diameter\" value=\"20\"/>"),
       5, "narrower than the front element (25.2 mm across as placed)"},
      {scene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"hood_length\" value=\"-3\"/>\n"
             "<float name=\"hood_diameter\" value=\"60\"/>"),
       4, "hood_length"},
  };
  ExpectErrors(cases);
}

TEST(Parser, DefaultsSubstitutionAndOverrides) {
  std::string xml = R"(<scene version="3.0.0">
  <default name="res" value="12"/>
  <sensor type="perspective"><film type="hdrfilm"><integer name="width" value="$res"/>
  <integer name="height" value="$res"/></film></sensor>
</scene>)";
  EXPECT_EQ(LoadSceneFromString(xml, "d.xml", {}).film.width, 12);
  EXPECT_EQ(LoadSceneFromString(xml, "d.xml", {{"res", "20"}}).film.width, 20);
}

TEST(Parser, TransformsComposeInOrder) {
  std::string xml = R"(<scene><shape type="sphere"><transform name="to_world">
    <translate x="1"/><scale value="2"/><rotate y="1" angle="90"/><lookat origin="0,0,0" target="0,0,1"/>
    <matrix value="1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1"/></transform></shape></scene>)";
  SceneDocument doc = ParseSceneString(xml, "t.xml", {});
  const Property& p = doc.root->children[0]->props[0];
  const Transform& t = std::get<Transform>(p.data);
  // translate first, then scale by 2, then rotate 90 degrees about y: x=1 -> (2,0,0) -> (0,0,-2).
  Vec3f q = t.Point(Vec3f(0.f));
  EXPECT_NEAR(q.x, 0, 1e-6);
  EXPECT_NEAR(q.z, -2, 1e-6);
}

TEST(Parser, IncludesResolveRelativeToTheIncludingFile) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "objektiv_include_test";
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "part.xml") << "<scene>\n<shape type=\"obj\"><string name=\"filename\" value=\"none.obj\"/>"
                                             "</shape></scene>";
  std::ofstream(dir / "main.xml") << "<scene>\n<include filename=\"sub/part.xml\"/>\n</scene>";
  try {
    LoadScene((dir / "main.xml").string(), {});
    ADD_FAILURE() << "expected a missing-file error";
  } catch (const InputError& e) {
    std::string msg = e.what();
    // The error points into the included file, where the missing file is named.
    EXPECT_NE(msg.find("part.xml:2:"), std::string::npos) << msg;
    EXPECT_NE(msg.find((dir / "sub" / "none.obj").string()), std::string::npos) << msg;
  }
}

TEST(Parser, ShippedScenesLoad) {
  namespace fs = std::filesystem;
  int n = 0;
  for (const auto& entry : fs::recursive_directory_iterator(OBJEKTIV_SCENES_DIR)) {
    if (entry.path().extension() != ".xml") continue;
    EXPECT_NO_THROW(LoadScene(entry.path().string(), {})) << entry.path();
    ++n;
  }
  EXPECT_GE(n, 1);
}

}  // namespace
}  // namespace objektiv
