// What users write: lenses found by every name they may use, messages that say what is wrong
// once, and nothing accepted without a word (every ignored input is warned about).
#include <gtest/gtest.h>

#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "base/error.h"
#include "io/scene_loader.h"
#include "io/xml_document.h"
#include "log_capture.h"
#include "render_helpers.h"
#include "optics/lens_file.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The message of the InputError `f` throws ("" if none).
template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LensNames, ByNameNamePlusExtensionOrPath) {
  EXPECT_TRUE(EndsWith(ResolveLens("tessar.brendel.100mm"), "tessar.brendel.100mm.lens"));  // .lens first
  EXPECT_TRUE(EndsWith(ResolveLens("tessar.brendel.100mm.dat"), "tessar.brendel.100mm.dat"));
  EXPECT_TRUE(EndsWith(ResolveLens("tessar.brendel.100mm.lens"), "tessar.brendel.100mm.lens"));
  EXPECT_NO_THROW(LoadLens("dgauss.50mm.dat", GlassCatalog::Default()));
  // A path: absolute, or relative to the base directory (a scene's folder).
  fs::path dir = fs::temp_directory_path() / "objektiv_lens_names";
  fs::create_directories(dir / "lenses");
  fs::copy_file(ResolveLens("dgauss.50mm"), dir / "lenses" / "mine.dat", fs::copy_options::overwrite_existing);
  EXPECT_EQ(ResolveLens((dir / "lenses" / "mine.dat").string()), (dir / "lenses" / "mine.dat").string());
  EXPECT_EQ(ResolveLens("lenses/mine.dat", dir.string()), (dir / "lenses" / "mine.dat").string());
  std::string msg = ErrorOf([] { ResolveLens("no.such.lens"); });
  EXPECT_NE(msg.find("no lens file 'no.such.lens'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("dgauss.50mm"), std::string::npos) << "lists the shipped lenses: " << msg;
  // A file type nobody reads is named with the ones that are.
  msg = ErrorOf([&] { ReadLensFile((dir / "lenses" / "x.txt").string(), GlassCatalog::Default()); });
  EXPECT_NE(msg.find(".lens, .dat or .zmx"), std::string::npos) << msg;
}

std::string RealisticScene(const std::string& props) {
  return "<scene version=\"3.0.0\">\n<sensor type=\"realistic\">\n" + props +
         "\n<film type=\"hdrfilm\"><integer name=\"width\" value=\"6\"/><integer name=\"height\" value=\"4\"/></film>\n"
         "</sensor>\n</scene>\n";
}

TEST(LensNames, ScenesFindLensesTheSameWayAndSayWhereOnce) {
  EXPECT_NO_THROW(LoadSceneFromString(RealisticScene("<string name=\"lens\" value=\"tessar.brendel.100mm.dat\"/>"), "s.xml", {}));
  std::string msg = ErrorOf([] {
    LoadSceneFromString(RealisticScene("<string name=\"lens\" value=\"no.such.lens\"/>"), "s.xml", {});
  });
  EXPECT_EQ(msg.rfind("s.xml:3: ", 0), 0u) << msg;
  EXPECT_EQ(test::Occurrences(msg, "s.xml:"), 1) << msg;
  // A broken lens file beside the scene: the scene's line, then the lens file's.
  fs::path dir = fs::temp_directory_path() / "objektiv_scene_lens";
  fs::create_directories(dir);
  std::ofstream(dir / "broken.dat") << "# a lens\n50 5 1.5\n";
  std::ofstream(dir / "scene.xml") << RealisticScene("<string name=\"lens\" value=\"broken.dat\"/>");
  msg = ErrorOf([&] { LoadScene((dir / "scene.xml").string(), {}); });
  EXPECT_EQ(test::Occurrences(msg, "scene.xml:3:"), 1) << msg;
  EXPECT_NE(msg.find("broken.dat:2: a lens row needs 4 numbers"), std::string::npos) << msg;
}

const char* kDeclares = R"(<scene version="3.0.0">
  <default name="res" value="4"/>
  <sensor type="perspective"><float name="fov" value="$fov"/><film type="hdrfilm"><integer name="width" value="$res"/>
  <integer name="height" value="$res"/></film></sensor>
</scene>)";

TEST(Defines, AnUndeclaredNameIsWarnedAbout) {
  test::LogCapture log;
  LoadSceneFromString(kDeclares, "d.xml", {{"fov", "30"}, {"res", "8"}, {"spp", "64"}});
  EXPECT_TRUE(log.Has("d.xml: -D spp: the scene declares no parameter 'spp'")) << log.Text();
  EXPECT_EQ(log.Count("-D "), 1) << "res (a <default>) and fov (used as $fov) are declared: " << log.Text();
}

TEST(PbrtScenes, AreNamedForWhatTheyAre) {
  const char* pbrt = "# a pbrt-v4 scene\nLookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n";
  for (auto [text, name] : {std::pair{pbrt, "scene.xml"}, std::pair{pbrt, "scene.pbrt"},
                            std::pair{"<scene version=\"3.0.0\"/>", "scene.pbrt"}}) {
    std::string msg = ErrorOf([&, text = text, name = name] { ParseSceneString(text, name, {}); });  // clang 14 captures no bindings
    EXPECT_EQ(msg.rfind(std::string(name) + ": a pbrt scene", 0), 0u) << msg;
    EXPECT_EQ(msg.find("XML syntax"), std::string::npos) << msg;
  }
}

TEST(KnownTypes, ErrorsListEveryRegisteredType) {
  auto unknown = [](const std::string& object) {
    return ErrorOf([&] {
      LoadSceneFromString("<scene>\n<sensor type=\"perspective\"/>\n" + object + "\n</scene>", "k.xml", {});
    });
  };
  EXPECT_NE(unknown("<bsdf type=\"velvet\"/>").find("phong, plastic"), std::string::npos);
  EXPECT_NE(unknown("<bsdf type=\"velvet\"/>").find("twosided"), std::string::npos);
  for (const char* type : {"blendbsdf, bumpmap", "mask, normalmap", "roughdielectric, roughplastic"})
    EXPECT_NE(unknown("<bsdf type=\"velvet\"/>").find(type), std::string::npos) << type;
  EXPECT_NE(unknown("<integrator type=\"bdpt\"/>").find("(known: aov, direct, path, ptracer, sppm, whitted)"), std::string::npos);
  std::string msg = ErrorOf([] { LoadSceneFromString("<scene>\n<sensor type=\"fisheye\"/>\n</scene>", "k.xml", {}); });
  EXPECT_NE(msg.find("(known: orthographic, perspective, realistic, stereo, thinlens)"), std::string::npos) << msg;
  msg = ErrorOf([] {
    LoadSceneFromString("<scene>\n<sensor type=\"perspective\"><film type=\"hdrfilm\"><rfilter type=\"sinc\"/></film>"
                        "</sensor>\n</scene>",
                        "k.xml", {});
  });
  EXPECT_NE(msg.find("blackman-harris"), std::string::npos) << msg;
}

// The scene's coating property: a built-in coating on every air-glass surface, checked names,
// and a warning where it can do nothing.
TEST(Coatings, SceneChoosesTheLensCoating) {
  const std::string lens = "<string name=\"lens\" value=\"dgauss.50mm\"/>\n";
  {
    test::LogCapture log;
    LoadSceneFromString(RealisticScene(lens + "<string name=\"coating\" value=\"multi@520\"/>"), "s.xml", {});
    EXPECT_FALSE(log.Has("coating")) << log.Text();
  }
  std::string msg = ErrorOf([&] {
    LoadSceneFromString(RealisticScene(lens + "<string name=\"coating\" value=\"Zap\"/>"), "s.xml", {});
  });
  EXPECT_NE(msg.find("s.xml:4: unknown coating 'Zap' (built in: none, MgF2[@NM], multi[@NM], I.xx"), std::string::npos) << msg;
  for (const char* other : {"<string name=\"lens_model\" value=\"thin\"/>", "<boolean name=\"transmission\" value=\"false\"/>"}) {
    test::LogCapture log;
    LoadSceneFromString(RealisticScene(lens + "<string name=\"coating\" value=\"MgF2\"/>\n" + other), "s.xml", {});
    EXPECT_TRUE(log.Has("s.xml:4: coating does nothing with")) << log.Text();
  }
}

std::string ShiftedScene(double shift) {
  return RealisticScene(
      fmt::format("<string name=\"lens\" value=\"dgauss.50mm\"/>\n<float name=\"shift_x\" value=\"{}\"/>", shift));
}

TEST(LensShift, BeyondTheImageCircleIsWarnedAbout) {
  auto scene = ShiftedScene;
  {
    test::LogCapture log;
    LoadSceneFromString(scene(2), "s.xml", {});
    EXPECT_FALSE(log.Has("image circle")) << log.Text();
  }
  test::LogCapture log;
  LoadSceneFromString(scene(40), "s.xml", {});
  EXPECT_TRUE(log.Has("s.xml:4: the lens shift (40, 0) mm puts the film's corners")) << log.Text();
  EXPECT_TRUE(log.Has("beyond its image circle")) << log.Text();
}

// A circular fisheye leaves the frame's corners dark with or without a shift: a small shift is
// not blamed for them.
TEST(LensShift, CornersDarkWithoutTheShiftAreNotBlamedOnIt) {
  test::LogCapture log;
  LoadSceneFromString(RealisticScene("<string name=\"lens\" value=\"fisheye.10mm\"/>\n<float name=\"shift_x\" value=\"1\"/>"),
                      "f.xml", {});
  EXPECT_FALSE(log.Has("image circle")) << log.Text();
}

// A film shifted wholly off the lens traces no camera ray: no pass rate (it read 100%).
TEST(LensShift, AFilmThatSeesNoLensHasNoPassRate) {
  test::RenderResult r = test::RenderXml(ShiftedScene(200));
  EXPECT_EQ(r.stats.camera_rays_traced, 0u);
  EXPECT_FALSE(r.stats.CameraPassRate().has_value());
  EXPECT_TRUE(test::RenderXml(ShiftedScene(0)).stats.CameraPassRate().has_value());
}

// Properties that are read but do nothing here are said to do nothing.
TEST(IgnoredInput, IsWarnedAbout) {
  test::LogCapture log;
  LoadSceneFromString(R"(<scene version="3.0.0">
<sensor type="realistic"><string name="lens" value="dgauss.50mm"/>
<float name="near_clip" value="0.5"/>
<sampler type="stratified"><boolean name="jitter" value="false"/></sampler>
<film type="hdrfilm"><integer name="width" value="6"/><integer name="height" value="4"/>
<string name="pixel_format" value="rgba"/></film></sensor>
</scene>)",
                      "i.xml", {});
  EXPECT_TRUE(log.Has("i.xml:3: sensor 'realistic' does not use the property 'near_clip'")) << log.Text();
  EXPECT_TRUE(log.Has("i.xml:4: sampler: jitter = false is not supported")) << log.Text();
  EXPECT_TRUE(log.Has("i.xml:6: film: the EXR is written as rgb float32, not rgba float32")) << log.Text();
}

// What only the real lens has (glass losses, rims) is said to do nothing in the ideal models.
TEST(IgnoredInput, RealLensOnlySettingsAreWarnedAboutInTheIdealModels) {
  for (const char* model : {"thick", "thin"}) {
    test::LogCapture log;
    LoadSceneFromString(RealisticScene(fmt::format("<string name=\"lens\" value=\"dgauss.50mm\"/>\n"
                                                   "<string name=\"lens_model\" value=\"{}\"/>\n"
                                                   "<boolean name=\"transmission\" value=\"false\"/>\n"
                                                   "<string name=\"vignetting\" value=\"aperture\"/>",
                                                   model)),
                        "m.xml", {});
    EXPECT_TRUE(log.Has(fmt::format("m.xml:5: transmission (the real lens's Fresnel and glass losses) does nothing with "
                                    "lens_model '{}'",
                                    model)))
        << log.Text();
    EXPECT_TRUE(log.Has(fmt::format("m.xml:6: lens_model '{}' has no rims", model))) << log.Text();
  }
  test::LogCapture log;
  LoadSceneFromString(RealisticScene("<string name=\"lens\" value=\"dgauss.50mm\"/>\n"
                                     "<boolean name=\"transmission\" value=\"false\"/>"),
                      "r.xml", {});
  EXPECT_FALSE(log.Has("does nothing")) << log.Text();
}

// A <ref> to an object of a kind the plugin does not take is warned about, even when the
// object is used elsewhere (it was ignored silently: the defaults rendered).
TEST(IgnoredInput, ReferencesToTheWrongKindAreWarnedAbout) {
  test::LogCapture log;
  LoadSceneFromString(R"(<scene version="3.0.0">
<sensor type="perspective"><film type="hdrfilm"><integer name="width" value="6"/><integer name="height" value="4"/></film></sensor>
<texture type="checkerboard" id="t"/>
<bsdf type="diffuse" id="d"/>
<shape type="sphere">
<ref id="t"/></shape>
<shape type="sphere"><bsdf type="diffuse">
<ref name="reflectance" id="d"/></bsdf>
<emitter type="area">
<ref name="radiance" id="d"/></emitter></shape>
</scene>)",
                      "w.xml", {});
  EXPECT_TRUE(log.Has("w.xml:3: shape 'sphere' does not use the nested texture 'checkerboard'")) << log.Text();
  EXPECT_TRUE(log.Has("w.xml:4: bsdf 'diffuse' does not use the nested bsdf 'diffuse'")) << log.Text();
  EXPECT_TRUE(log.Has("w.xml:4: emitter 'area' does not use the nested bsdf 'diffuse'")) << log.Text();
}

// Text between tags and elements beside the root mean nothing in the language: said so.
TEST(IgnoredInput, TextAndElementsOutsideTheLanguageAreWarnedAbout) {
  test::LogCapture log;
  LoadSceneFromString(R"(<scene version="3.0.0">
<sensor type="perspective"><float name="fov" value="40">wide</float>
<film type="hdrfilm"><integer name="width" value="6"/><integer name="height" value="4"/></film></sensor>
stray words <![CDATA[more]]>
</scene>
<scene/>)",
                      "t.xml", {});
  EXPECT_TRUE(log.Has("t.xml:2: text inside <float> is ignored: \"wide\"")) << log.Text();
  EXPECT_TRUE(log.Has("t.xml:4: text inside <scene> is ignored: \"stray words\"")) << log.Text();
  EXPECT_TRUE(log.Has("inside <scene> is ignored: \"more\"")) << log.Text();
  EXPECT_TRUE(log.Has("t.xml:6: <scene> beside the root <scene> is ignored")) << log.Text();
}

}  // namespace
}  // namespace objektiv
