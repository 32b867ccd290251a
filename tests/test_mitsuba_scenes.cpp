// Plain Mitsuba 3 scenes load as Mitsuba 3 reads them (its documented scene grammar:
// docs/src/key_topics/scene_format.rst): names on objects as keys, named nested objects,
// every value type, references and aliases.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "io/scene_loader.h"
#include "io/xml_document.h"
#include "log_capture.h"

namespace objektiv {
namespace {

// As Mitsuba 3's exporters write them: every object named, the film and sampler named inside
// the sensor, a top-level BSDF with id and name referenced by a named <ref>, the twosided
// BSDF's inner BSDF named.
const char* kNamedObjects = R"(<scene version="3.0.0">
  <integrator type="path" name="integrator"><integer name="max_depth" value="3"/></integrator>
  <sensor type="perspective" name="sensor">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent" name="sampler"><integer name="sample_count" value="3"/></sampler>
    <film type="hdrfilm" name="film"><integer name="width" value="10"/><integer name="height" value="6"/>
      <rfilter type="box" name="rfilter"/></film>
  </sensor>
  <bsdf type="twosided" id="mat-white" name="mat-white">
    <bsdf type="diffuse" name="bsdf"><rgb name="reflectance" value="0.8"/></bsdf>
  </bsdf>
  <emitter type="constant" name="emitter"><rgb name="radiance" value="1"/></emitter>
  <shape type="sphere" name="ball"><ref id="mat-white" name="bsdf"/></shape>
  <shape type="rectangle" name="light">
    <emitter type="area" name="emitter"><rgb name="radiance" value="4"/></emitter>
  </shape>
</scene>)";

TEST(MitsubaScenes, NamesOnObjectsAreKeys) {
  test::LogCapture log;
  RenderSetup s = LoadSceneFromString(kNamedObjects, "named.xml", {});
  EXPECT_EQ(s.film.width, 10);
  EXPECT_EQ(s.film.height, 6);
  EXPECT_EQ(s.sampler.spp, 3);
  EXPECT_EQ(s.scene->ShapeCount(), 2u);
  EXPECT_EQ(s.scene->lights().size(), 2u);  // the constant and the area emitter
  EXPECT_EQ(log.Text(), "") << "nothing was left unused";
}

// Every property type in the forms Mitsuba 3 accepts.
TEST(MitsubaScenes, ValueTypesInEveryDocumentedForm) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "objektiv_mitsuba_values";
  fs::create_directories(dir);
  std::ofstream(dir / "grey.spd") << "# a measured reflectance\n400 0.4\n550.5 0.5\n\n700 0.6 # red end\n";
  std::ofstream(dir / "scene.xml") << R"(<scene version="3.0.0">
  <default name="r" value="0.5"/>
  <sensor type="perspective">
    <float name="fov" value="45"/>
    <boolean name="unused_check" value="True"/>
    <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/></film>
  </sensor>
  <shape type="sphere">
    <integer name="radius" value="2"/>
    <point name="center" value="1, 2, 3"/>
    <boolean name="flip_normals" value="FALSE"/>
    <bsdf type="diffuse"><spectrum name="reflectance" filename="grey.spd"/></bsdf>
  </shape>
  <shape type="sphere"><point name="center" x="4" z="1"/><float name="radius" value="$r"/>
    <bsdf type="plastic"><rgb name="diffuse_reflectance" value="0.1 0.2 0.3"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="-4"/>
    <bsdf type="diffuse" id="tex-mat"><texture type="checkerboard" name="reflectance">
      <rgb name="color0" value="0.5"/><spectrum name="color1" value="400:0.1 550:0.3, 700:0.9"/></texture></bsdf></shape>
  <alias id="tex-mat" as="also-tex-mat"/>
  <shape type="cube"><ref id="also-tex-mat"/>
    <transform name="to_world"><translate value="0, -3, 0"/><rotate value="0, 1, 0" angle="30"/><scale value="2, 1, 1"/>
      <matrix value="1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1"/><matrix value="1 0 0 0 1 0 0 0 1"/></transform></shape>
  <emitter type="directional"><vector name="direction" value="0, -1, 0"/><spectrum name="irradiance" value="2"/></emitter>
</scene>)";
  test::LogCapture log;
  RenderSetup s = LoadScene((dir / "scene.xml").string(), {});
  EXPECT_EQ(s.scene->ShapeCount(), 4u);
  // The one property the sensor does not take is named (nothing else is left over).
  EXPECT_TRUE(log.Has("does not use the property 'unused_check'")) << log.Text();
  EXPECT_EQ(log.Count("[warning]"), 1) << log.Text();
}

TEST(MitsubaScenes, WhatMitsubaRefusesIsAnErrorWithItsLine) {
  struct Case {
    const char* xml;
    const char* message;
  };
  const Case cases[] = {
      {"<scene version=\"3.0.0\" colour=\"red\">\n</scene>", "does not take the attribute 'colour'"},
      {"<scene>\n<shape type=\"sphere\"><point name=\"center\" value=\"1,2,3\" x=\"1\"/></shape></scene>",
       "either value or x, y, z"},
      {"<scene>\n<emitter type=\"constant\"><spectrum name=\"radiance\" type=\"d65\" value=\"2\"/></emitter></scene>",
       "does not take the attribute 'value'"},
      {"<scene>\n<emitter type=\"constant\"><spectrum name=\"radiance\" type=\"d65\">"
       "<float name=\"temperature\" value=\"3000\"/></spectrum></emitter></scene>",
       "does not take <float name=\"temperature\">"},
      {"<scene>\n<alias id=\"nothing\" as=\"x\"/></scene>", "alias of unknown id 'nothing'"},
      {"<scene>\n<shape type=\"sphere\"><boolean name=\"flip_normals\" value=\"yes\"/></shape></scene>",
       "not a boolean"},
  };
  for (const Case& c : cases) {
    try {
      ParseSceneString(c.xml, "m.xml", {});
      ADD_FAILURE() << "accepted: " << c.xml;
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find(c.message), std::string::npos) << msg;
      EXPECT_EQ(msg.rfind("m.xml:", 0), 0u) << msg;
    }
  }
}

}  // namespace
}  // namespace objektiv
