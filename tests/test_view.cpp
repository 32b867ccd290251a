// The interactive viewer without its window (app/view/): the camera's pose under the
// controls, the sensor's values, the session's frames, focusing by a click, the saved camera
// (which must render the viewer's very image), live reload and scripts.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "app/view/camera_pose.h"
#include "app/view/scene_with_camera.h"
#include "app/view/sensor_overrides.h"
#include "app/view/view_script.h"
#include "app/view/view_session.h"
#include "app/view/view_worker.h"
#include "base/error.h"
#include "camera/realistic_camera.h"
#include "io/lens_plot.h"
#include "render/renderer.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

fs::path TempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("objektiv-view-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void WriteFile(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A small scene through the double Gauss: a ball on a floor before a wall, under an area light.
std::string LensScene(const std::string& light = "10, 10, 10") {
  return R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="3"/></integrator>
  <sensor type="realistic">
    <string name="lens" value="dgauss.50mm"/>
    <string name="sensor" value="full-frame"/>
    <float name="aperture_diameter" value="10"/>
    <float name="focus_distance" value="3"/>
    <float name="exposure_scale" value="20"/>
    <transform name="to_world"><lookat origin="0, 1, 4" target="0, 0.5, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="3"/></sampler>
    <film type="hdrfilm"><integer name="width" value="36"/><integer name="height" value="24"/></film>
  </sensor>
  <shape type="sphere"><point name="center" x="0.3" y="0.5" z="0"/><float name="radius" value="0.5"/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.3, 0.2"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/><translate z="-2"/></transform>
    <bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="90"/><translate y="3"/></transform>
    <emitter type="area"><rgb name="radiance" value=")" + light + R"("/></emitter></shape>
</scene>
)";
}

void ExpectSameMatrix(const Transform& a, const Transform& b, double tol) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a.Matrix().m[r][c], b.Matrix().m[r][c], tol) << r << "," << c;
}

TEST(CameraPose, KeepsTheScenesTransformAndItsMirror) {
  const Transform scene =
      Transform::LookAt(Vec3d(1, 2, 3), Vec3d(0, 1, 0), Vec3d(0, 1, 0)) * Transform::Scale(Vec3d(-1, 1, 1));
  const CameraPose pose = CameraPose::FromToWorld(scene, 2);
  ExpectSameMatrix(pose.ToWorld(), scene, 1e-12);
  EXPECT_NEAR(Length(pose.Centre() - Vec3d(1, 2, 3)), 2, 1e-12);
}

TEST(CameraPose, OrbitsAboutItsCentreAndStopsShortOfTheVertical) {
  CameraPose pose = CameraPose::FromToWorld(Transform::LookAt(Vec3d(0, 1, 5), Vec3d(0, 1, 0), Vec3d(0, 1, 0)), 5);
  const Vec3d centre = pose.Centre(), start = pose.position();
  pose.Orbit(90, 0);
  EXPECT_NEAR(Length(pose.position() - Vec3d(5, 1, 0)), 0, 1e-9);  // turned left: from +z round to +x
  for (int i = 0; i < 3; ++i) pose.Orbit(90, 0);
  EXPECT_NEAR(Length(pose.position() - start), 0, 1e-9);
  pose.Orbit(0, 300);  // looking up, far past the vertical: stops 1 degree short of it, from below
  EXPECT_NEAR(Length(pose.Centre() - centre), 0, 1e-9);
  EXPECT_NEAR(std::acos(pose.forward().y) * 180 / M_PI, 1, 1e-6);
  EXPECT_LT(pose.position().y, centre.y);
  pose.Dolly(0.5);
  EXPECT_NEAR(Length(pose.position() - centre), 2.5, 1e-9);
  const Vec3d before = pose.position();
  pose.Move(0, 0, 1);
  EXPECT_NEAR(Length(pose.position() - before), 1, 1e-12);
}

TEST(SensorOverrides, ValuesReplaceTheScenesAndWhatContradictsThem) {
  SceneDocument doc = ParseSceneString(LensScene(), "scene.xml", {});
  std::shared_ptr<const ObjectNode> sensor = doc.root->children[1];
  ASSERT_EQ(sensor->tag, "sensor");
  SensorOverrides o(sensor);
  EXPECT_EQ(o.Float("aperture_diameter"), 10);
  o.SetFloat("fnumber", 4);
  EXPECT_FALSE(o.Float("aperture_diameter"));
  EXPECT_EQ(o.Float("fnumber"), 4);
  const ObjectNode node = o.Node();
  int fnumbers = 0, diameters = 0;
  for (const Property& p : node.props) fnumbers += p.name == "fnumber", diameters += p.name == "aperture_diameter";
  EXPECT_EQ(fnumbers, 1);
  EXPECT_EQ(diameters, 0);
  o.Unset("focus_distance");
  EXPECT_FALSE(o.Float("focus_distance"));
  o.Reset("focus_distance");
  EXPECT_EQ(o.Float("focus_distance"), 3);
  // A focus point replaces the scene's focus distance; reset, the scene's comes back.
  o.Set("focus_point", Vec3d(0, 1, 0), "point");
  EXPECT_FALSE(o.Float("focus_distance"));
  o.Reset("focus_distance");  // (the point still replaces it)
  EXPECT_FALSE(o.Float("focus_distance"));
  o.Reset("focus_point");
  EXPECT_EQ(o.Float("focus_distance"), 3);
  EXPECT_FALSE(o.Find("focus_point"));
}

TEST(SensorOverrides, TextIsReadAsThePropertyIsDeclared) {
  EXPECT_EQ(std::get<double>(ParseSensorValue("realistic", "fnumber", "2.8").data), 2.8);
  EXPECT_EQ(std::get<int64_t>(ParseSensorValue("realistic", "blades", "6").data), 6);
  EXPECT_EQ(std::get<bool>(ParseSensorValue("realistic", "dispersion", "false").data), false);
  EXPECT_EQ(std::get<std::string>(ParseSensorValue("realistic", "vignetting", "cos4").data), "cos4");
  const Vec3d p = std::get<Vec3d>(ParseSensorValue("realistic", "focus_point", "1, 2.5, -3").data);
  EXPECT_EQ(p.y, 2.5);
  EXPECT_THROW(ParseSensorValue("realistic", "vignetting", "some"), InputError);
  EXPECT_THROW(ParseSensorValue("realistic", "blades", "6.5"), InputError);
  EXPECT_THROW(ParseSensorValue("perspective", "fnumber", "2"), InputError);  // a pinhole has none
}

TEST(ViewSession, PreviewFirstThenPassesUpToTheSampleCount) {
  const fs::path dir = TempDir("passes");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  ASSERT_TRUE(s.Step());
  EXPECT_TRUE(s.progress().preview);
  EXPECT_EQ(s.display().width, 36);
  EXPECT_EQ(s.display().rgba.size(), size_t(4 * 36 * 24));
  while (s.Step()) EXPECT_FALSE(s.progress().preview);
  EXPECT_EQ(s.progress().spp, 3);
  // Moving: previews at reduced resolution at most, never more than the film.
  CameraPose p = s.pose();
  p.Orbit(5, 0);
  s.SetPose(p, true);
  ASSERT_TRUE(s.Step());
  EXPECT_TRUE(s.progress().preview);
  EXPECT_LE(s.display().width, 36);
  EXPECT_EQ(s.display().width, s.progress().width);
  s.SetMoving(false);
  ASSERT_TRUE(s.Step());
  EXPECT_EQ(s.display().width, 36);  // the preview at rest is at full resolution
}

// Camera rays never meet a point light: the preview shows its own image and its ghosts as the
// lens traces them (FlareSettings::Preview), moving and at rest, and only where the lens's
// effects are on (as the passes' lens layers).
TEST(ViewSession, PreviewShowsTheLampsImagesAndGhosts) {
  const fs::path dir = TempDir("preview-flare");
  auto scene = [](const std::string& effects) {
    std::string xml = LensScene("0, 0, 0");
    const std::string lamp = R"(<emitter type="point"><point name="position" x="-0.4" y="0.9" z="0"/><rgb name="intensity" value="50"/></emitter>
</scene>)";
    xml.replace(xml.rfind("</scene>"), 8, lamp);
    xml.replace(xml.find("<transform name=\"to_world\"><lookat"), 0, effects);
    return xml;
  };
  auto total = [](const ViewSession& s) {
    double sum = 0;
    for (size_t i = 0; i < s.display().rgba.size(); i += 4) sum += s.display().rgba[i + 1];
    return sum;
  };
  WriteFile(dir / "plain.xml", scene(""));
  WriteFile(dir / "ghosts.xml", scene(R"(<boolean name="ghosts" value="true"/>)"));
  ViewSession plain((dir / "plain.xml").string(), {}), ghosts((dir / "ghosts.xml").string(), {});
  for (ViewSession* s : {&plain, &ghosts}) {
    CameraPose p = s->pose();
    p.Orbit(2, 0);
    s->SetPose(p, true);
    ASSERT_TRUE(s->Step());
    ASSERT_TRUE(s->progress().preview);
  }
  EXPECT_GT(total(ghosts), 1.2 * total(plain) + 1);
  for (ViewSession* s : {&plain, &ghosts}) {
    s->SetMoving(false);
    ASSERT_TRUE(s->Step());
    EXPECT_EQ(s->display().width, 36);
  }
  EXPECT_GT(total(ghosts), 1.2 * total(plain) + 1);
  // The layer chosen: the ghosts alone (dark where the picture is lit), the primary image
  // without them, no diffraction in a preview; shown at once (the preview frame shown is
  // composed again), and by the preview frames after.
  const double sum = total(ghosts);
  auto show = [&](ViewLayer layer) {
    ghosts.SetLayer(layer);
    const double at_once = total(ghosts);
    ghosts.SetMoving(true);
    EXPECT_TRUE(ghosts.Step());
    ghosts.SetMoving(false);
    EXPECT_TRUE(ghosts.Step());
    EXPECT_NEAR(total(ghosts), at_once, 1e-9 * sum) << ViewLayerName(layer);
    return at_once;
  };
  const double alone = show(ViewLayer::kGhosts);
  EXPECT_GT(alone, 1);
  EXPECT_LT(alone, sum);
  EXPECT_LT(show(ViewLayer::kPrimary), sum);
  EXPECT_EQ(show(ViewLayer::kDiffraction), 0);
  EXPECT_NEAR(show(ViewLayer::kSum), sum, 1e-9 * sum);
}

TEST(ViewSession, ClickFocusesOnThePointUnderThePixel) {
  const fs::path dir = TempDir("focus");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  std::optional<Vec3f> ball = s.PointAt(18 + 3, 12);  // right of centre: the ball (its centre at x = 0.3)
  ASSERT_TRUE(ball);
  EXPECT_NEAR(Length(Vec3d(*ball) - Vec3d(0.3, 0.5, 0)), 0.5, 1e-3);  // on the ball's surface
  ASSERT_TRUE(s.FocusAt(18 + 3, 12));
  const Property* f = s.sensor().Find("focus_point");
  ASSERT_TRUE(f);
  EXPECT_EQ(std::get<Vec3d>(f->data), Vec3d(*ball));
  EXPECT_FALSE(s.sensor().Find("focus_distance"));  // replaced
  EXPECT_FALSE(s.FocusAt(18, -50));                 // off the film: nothing there
}

// The panel's lens section draws the fans from the plane the lens is focused on: focused at
// half a metre, the axial fan meets on the film (from infinity it would not).
TEST(ViewSession, LensSectionFansComeFromThePlaneInFocus) {
  const fs::path dir = TempDir("section");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  s.SetSensorProperty("focus_distance", 0.5, "float");
  s.SetSensorProperty("fnumber", 4.0, "float");
  const auto* real = dynamic_cast<const RealisticCamera*>(&s.camera());
  ASSERT_TRUE(real);
  // The axial fan's (the first colour's) ends on the film, in the drawing's pixels.
  auto spread = [](const Svg& plot) {
    double lo = INFINITY, hi = -INFINITY;
    int rays = 0;
    for (const SvgShape& shape : plot.shapes())
      if (shape.kind == SvgShape::kPolyline && shape.stroke == "#1f5fd1" && shape.points.size() > 2) {
        lo = std::min(lo, shape.points.back().y), hi = std::max(hi, shape.points.back().y);
        ++rays;
      }
    EXPECT_EQ(rays, 5);
    return hi - lo;
  };
  EXPECT_LT(spread(PlotLensLayoutAsFocused(real->lens(), {0, 5})), 1.0);
  EXPECT_GT(spread(PlotLensLayout(real->lens(), {0, 5})), 5.0);
}

// Another lens that does not open as far as the f-number set: taken wide open. A lens file
// beside the scene is found by its name, as the scene would name it.
TEST(ViewSession, LensesChangeAsAPhotographerChangesThem) {
  const fs::path dir = TempDir("lenses");
  WriteFile(dir / "scene.xml", LensScene());
  fs::copy_file(fs::path(OBJEKTIV_SCENES_DIR) / "cornell-box" / "tessar-yellow-filter.lens", dir / "mine.lens");
  fs::copy_file(fs::path(OBJEKTIV_SCENES_DIR) / "cornell-box" / "tessar-yellow-filter.glass", dir / "mine.glass");
  ViewSession s((dir / "scene.xml").string(), {});
  s.SetSensorProperty("fnumber", 2.8, "float");
  s.SetSensorProperty("lens", std::string("telephoto.250mm"), "string");  // opens to f/5.6 only
  EXPECT_FALSE(s.sensor().Find("fnumber"));
  EXPECT_EQ(s.sensor().String("lens"), "telephoto.250mm");
  EXPECT_NE(s.TakeNotice().find("wide open"), std::string::npos);
  s.SetSensorProperty("lens", std::string("dgauss.50mm"), "string");  // opens to f/2: f/2.8 again
  EXPECT_EQ(s.sensor().Float("fnumber"), 2.8);
  s.SetSensorProperty("lens", std::string("mine.lens"), "string");
  const auto* real = dynamic_cast<const RealisticCamera*>(&s.camera());
  ASSERT_TRUE(real);
  EXPECT_NE(real->lens().prescription().name.find("Tessar"), std::string::npos) << real->lens().prescription().name;
}

// Saving over a file the scene reads is refused with the viewer's error, not a crash.
TEST(ViewSession, SavesNeverReplaceTheScenesFiles) {
  const fs::path dir = TempDir("inputs");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  while (s.Step()) {
  }
  EXPECT_THROW(s.SaveScene((dir / "scene.xml").string()), InputError);
  EXPECT_THROW(s.SaveImage((dir / "picture.jpg").string()), InputError);  // an .exr (and its PNG)
  EXPECT_THROW(s.SaveImage((dir / "no-such-folder" / "x.exr").string()), InputError);
}

// A click right after a move looks through the camera where it stands now; an exposure
// change shows the picture already shown (a preview's) again.
TEST(ViewSession, ClicksAndExposureFollowTheLatestChange) {
  const fs::path dir = TempDir("latest");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  const std::optional<Vec3f> before = s.PointAt(18, 12);
  CameraPose p = s.pose();
  p.Move(0.6, 0, 0);
  s.SetPose(p, false);
  const std::optional<Vec3f> moved = s.PointAt(18, 12);  // no frame rendered since the move
  ASSERT_TRUE(before && moved);
  EXPECT_GT(moved->x - before->x, 0.3);  // the camera moved right: so did what it sees ahead
  ASSERT_TRUE(s.Step());
  ASSERT_TRUE(s.progress().preview);
  const std::vector<uint8_t> shown = s.display().rgba;
  s.SetExposure(s.exposure() + 2);
  EXPECT_NE(s.display().rgba, shown);
}

TEST(ViewSession, RefusedValuesLeaveTheCameraAsItWas) {
  const fs::path dir = TempDir("refused");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  s.SetSensorProperty("fnumber", 4.0, "float");
  const Camera* camera = &s.camera();
  EXPECT_THROW(s.SetSensorProperty("fnumber", 0.3, "float"), InputError);  // faster than the lens
  EXPECT_EQ(s.sensor().Float("fnumber"), 4);
  EXPECT_EQ(&s.camera(), camera);
}

// The dispersion toggle: the lens's glasses at their d-line index, so that every wavelength
// of a camera ray takes one path (the sensor's `dispersion false`).
TEST(ViewSession, DispersionOffMakesTheLensUndispersed) {
  const fs::path dir = TempDir("dispersion");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  s.SetSensorProperty("lens", std::string("tessar.brendel.100mm"), "string");  // catalog glasses
  const auto* real = dynamic_cast<const RealisticCamera*>(&s.camera());
  ASSERT_TRUE(real);
  EXPECT_TRUE(real->dispersive());
  const double nd = real->lens().prescription().surfaces[0].IndexAfter(kLambdad);
  s.SetSensorProperty("dispersion", false, "boolean");
  real = dynamic_cast<const RealisticCamera*>(&s.camera());
  ASSERT_TRUE(real);
  EXPECT_FALSE(real->dispersive());
  const LensSurface& front = real->lens().prescription().surfaces[0];
  EXPECT_NEAR(front.IndexAfter(450), nd, 1e-12);
  EXPECT_NEAR(front.IndexAfter(650), nd, 1e-12);
  while (s.Step()) {
  }
  EXPECT_EQ(s.progress().spp, 3);
}

// The saved camera renders, with `objektiv render`'s code, the very image the viewer made:
// the same samples of the same camera (moved, refocused, stopped down).
TEST(ViewSession, SavedCameraRendersTheViewersImage) {
  const fs::path dir = TempDir("saved");
  WriteFile(dir / "scene.xml", LensScene());
  ViewSession s((dir / "scene.xml").string(), {});
  s.SetSensorProperty("fnumber", 4.0, "float");
  s.SetSensorProperty("blades", int64_t(6), "integer");
  ASSERT_TRUE(s.FocusAt(21, 12));
  CameraPose p = s.pose();
  p.Orbit(12, 4);
  p.Dolly(0.9);
  s.SetPose(p, true);
  s.Step();
  s.SetMoving(false);
  while (s.Step()) {
  }
  ASSERT_EQ(s.progress().spp, 3);
  s.SaveScene((dir / "saved.xml").string());
  s.SaveImage((dir / "saved.exr").string());
  EXPECT_TRUE(fs::exists(dir / "saved.png"));

  RenderSetup r = LoadScene((dir / "saved.xml").string(), {});
  Film film(r.film.width, r.film.height, r.film.crop, r.film.filter);
  std::unique_ptr<Sampler> sampler = MakeSampler(r.sampler);
  RenderOptions o;
  o.spp_end = sampler->spp();
  Render(*r.camera, *r.integrator, *sampler, film, o);
  ASSERT_TRUE(s.film());
  EXPECT_EQ(film.Xyz(), s.film()->Xyz());
  // Elsewhere than beside the scene, its relative file names would not resolve: refused.
  const fs::path other = TempDir("saved-elsewhere");
  EXPECT_THROW(s.SaveScene((other / "saved.xml").string()), InputError);
}

TEST(ViewSession, ReadsTheSceneAgainWhenItChangesKeepingTheCamera) {
  const fs::path dir = TempDir("reload");
  const fs::path scene = dir / "scene.xml";
  WriteFile(scene, LensScene());
  ViewSession s(scene.string(), {});
  s.SetSensorProperty("fnumber", 5.6, "float");
  CameraPose p = s.pose();
  p.Orbit(20, 0);
  s.SetPose(p, false);
  EXPECT_FALSE(s.ReloadIfChanged());  // nothing changed
  auto touch = [&] { fs::last_write_time(scene, fs::last_write_time(scene) + std::chrono::seconds(2)); };
  WriteFile(scene, LensScene("20, 20, 20"));
  touch();
  std::optional<std::string> reloaded = s.ReloadIfChanged();
  ASSERT_TRUE(reloaded);
  EXPECT_EQ(*reloaded, "");
  EXPECT_EQ(s.sensor().Float("fnumber"), 5.6);
  EXPECT_NEAR(Length(s.pose().position() - p.position()), 0, 1e-12);
  // A broken file: the message, and the last good scene stays.
  WriteFile(scene, "<scene version=\"3.0.0\"><shape type=\"nonsense\"/></scene>");
  touch();
  reloaded = s.ReloadIfChanged();
  ASSERT_TRUE(reloaded);
  EXPECT_NE(reloaded->find("nonsense"), std::string::npos) << *reloaded;
  EXPECT_TRUE(s.Step());
}

TEST(ViewScript, CommandsRunAndErrorsNameTheLine) {
  const fs::path dir = TempDir("script");
  WriteFile(dir / "scene.xml", LensScene());
  WriteFile(dir / "ok.txt", "# a comment\nset fnumber 4\nset focus_point 0.3, 0.5, 0.5\norbit 5 0\nsamples 2\n"
                            "screenshot " + (dir / "shot.png").string() + "\nquit\nset fnumber 8\n");
  ViewSession s((dir / "scene.xml").string(), {});
  ViewScript script((dir / "ok.txt").string(), ReadViewScript((dir / "ok.txt").string()));
  std::string shot;
  for (;;) {
    const ViewScript::Action a = script.Step(s);
    if (a.kind == ViewScript::Action::kScreenshot) shot = a.path;
    if (a.kind == ViewScript::Action::kDone) break;
  }
  EXPECT_EQ(shot, (dir / "shot.png").string());
  EXPECT_EQ(s.progress().spp, 2);
  // After a change, samples start again from none (they were reached before the change).
  WriteFile(dir / "again.txt", "samples 2\norbit 30 10  # around\nsamples 2\nsave " + (dir / "again.exr").string() + "\n");
  ViewScript again((dir / "again.txt").string(), ReadViewScript((dir / "again.txt").string()));
  while (again.Step(s).kind != ViewScript::Action::kDone) {
  }
  EXPECT_EQ(s.progress().spp, 2);
  EXPECT_TRUE(fs::exists(dir / "again.exr"));
  EXPECT_EQ(s.sensor().Float("fnumber"), 4);  // the line after quit did not run
  EXPECT_TRUE(s.sensor().Find("focus_point"));

  WriteFile(dir / "unknown.txt", "set fnumber 4\nzoom 2\n");
  try {
    ReadViewScript((dir / "unknown.txt").string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown.txt:2: unknown command 'zoom'"), std::string::npos) << e.what();
  }
  // Refused values name the line and the value as written.
  for (const auto& [line, message] : {std::pair{"set fnumber 0.2", "bad.txt:1: set:"},
                                      {"samples -7", "bad.txt:1: samples: -7 is not between 1 and"},
                                      {"exposure 1e40", "bad.txt:1: exposure: 1e40 is not between -64 and 64 stops"}}) {
    WriteFile(dir / "bad.txt", std::string(line) + "\n");
    ViewScript bad((dir / "bad.txt").string(), ReadViewScript((dir / "bad.txt").string()));
    try {
      bad.Step(s);
      ADD_FAILURE() << "no error: " << line;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace objektiv

namespace objektiv {
namespace {

// The window's side of the session: changes posted from another thread, snapshots taken.
TEST(ViewWorker, RunsPostedChangesAndReportsTheirErrors) {
  const fs::path dir = TempDir("worker");
  WriteFile(dir / "scene.xml", LensScene());
  ViewWorker worker(std::make_unique<ViewSession>((dir / "scene.xml").string(), ViewOptions{}));
  ViewSnapshot s;
  // Waits (at most a minute) for a snapshot that satisfies `done`.
  auto wait = [&](const std::function<bool(const ViewSnapshot&)>& done) {
    for (int i = 0; i < 6000; ++i) {
      worker.Latest(s);
      if (done(s)) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  };
  ASSERT_TRUE(wait([](const ViewSnapshot& v) { return !v.progress.preview && v.progress.spp == 3; }));
  EXPECT_EQ(s.display.width, 36);
  EXPECT_EQ(s.lens_name, "dgauss.50mm");
  ASSERT_TRUE(s.lens_plot);
  worker.Post([](ViewSession& v) { v.SetSensorProperty("fnumber", 0.3, "float"); });
  ASSERT_TRUE(wait([](const ViewSnapshot& v) { return !v.error.empty(); }));
  EXPECT_NE(s.error.find("f/0.3 is faster than dgauss.50mm opens"), std::string::npos) << s.error;
  worker.Post([](ViewSession& v) { v.SetSensorProperty("fnumber", 8.0, "float"); }, "stopped down");
  ASSERT_TRUE(wait([](const ViewSnapshot& v) {
    return v.error.empty() && v.sensor->Float("fnumber") == 8.0 && v.progress.spp == 3;
  }));
  EXPECT_EQ(s.notice, "stopped down");
}

}  // namespace
}  // namespace objektiv
