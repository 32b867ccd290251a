// RayMemo (render/ray_memo.h): a later wavelength set of the same camera ray gets the recorded
// answers without tracing; a ray it did not record, or a new camera ray, is traced and counted.
#include <gtest/gtest.h>

#include "io/scene_loader.h"
#include "render/ray_memo.h"

namespace objektiv {
namespace {

TEST(RayMemo, RepeatsAnswersOnlyForTheSameRaysOfTheSameCameraRay) {
  const RenderSetup setup = LoadSceneFromString(R"(<scene version="3.0.0"><sensor type="perspective"/>
    <shape type="sphere"><point name="center" x="0" y="0" z="-3"/><float name="radius" value="1"/></shape></scene>)",
                                                "test.xml", {});
  const Scene& scene = setup.integrator->scene();
  const Ray camera{Vec3f(0.f), Vec3f(0, 0, -1)}, other_camera{Vec3f(0.f), Vec3f(0, 0.1f, -1)};
  const Ray to_ball{Vec3f(0, 0, 1), Vec3f(0, 0, -1)}, past_ball{Vec3f(0, 5, 0), Vec3f(0, 0, -1)};
  const Ray shadow{Vec3f(0, 0, 0), Vec3f(0, 0, -1), 10.f}, short_shadow{Vec3f(0, 0, 0), Vec3f(0, 0, -1), 1.f};
  RayMemo memo;
  RayCounts counts;
  memo.Begin(scene, camera, counts);
  const std::optional<SurfaceInteraction> hit = memo.Intersect(to_ball);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->p.z, -2.f, 1e-5f);
  EXPECT_FALSE(memo.Intersect(past_ball));
  EXPECT_TRUE(memo.Occluded(shadow));
  EXPECT_EQ(counts.closest, 2u);
  EXPECT_EQ(counts.shadow, 1u);
  // The next set: the same rays answered from the record (a branch passed over, the order kept).
  memo.Begin(scene, camera, counts);
  const std::optional<SurfaceInteraction> again = memo.Intersect(to_ball);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->p, hit->p);
  EXPECT_TRUE(memo.Occluded(shadow));
  EXPECT_EQ(counts.closest, 2u);
  EXPECT_EQ(counts.shadow, 1u);
  // A ray that differs (here only in tmax) is the scene's to answer.
  EXPECT_FALSE(memo.Occluded(short_shadow));
  EXPECT_EQ(counts.shadow, 2u);
  // A new camera ray starts a new record: everything traced again.
  memo.Begin(scene, other_camera, counts);
  EXPECT_TRUE(memo.Intersect(to_ball));
  EXPECT_TRUE(memo.Occluded(shadow));
  EXPECT_EQ(counts.closest, 3u);
  EXPECT_EQ(counts.shadow, 3u);
  // Not recording (a sample of one set): nothing is kept, a set begun after it replays nothing.
  memo.Begin(scene, camera, counts, /*record=*/false);
  EXPECT_TRUE(memo.Intersect(to_ball));
  memo.Begin(scene, camera, counts);
  EXPECT_TRUE(memo.Intersect(to_ball));
  EXPECT_EQ(counts.closest, 5u);
}

}  // namespace
}  // namespace objektiv
