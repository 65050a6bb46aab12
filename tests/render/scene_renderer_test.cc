// The scene renderer on hand-built solids (tests/render/test_meshes.h): it draws, it is
// deterministic, and it keeps its context across frames and sizes.
#include "render/scene_renderer.h"

#include <gtest/gtest.h>

#include <thread>

#include "engine/core/error.h"
#include "tests/render/golden.h"
#include "tests/render/test_meshes.h"

namespace pcsg::render {
namespace {

// Share of non-background pixels: the objects must fill a good part of an automatic framing.
double covered_share(const Image& image) {
  std::size_t covered = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] < 250 || p[1] < 250 || p[2] < 250) ++covered;
    }
  }
  return static_cast<double>(covered) / (static_cast<double>(image.width) * image.height);
}

TEST(SceneRendererTest, RendersAndIsDeterministic) {
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.width = 640;
  f.height = 480;
  f.title = scene.spec.name;
  f.subtitle = "objects apart";
  const Image a = renderer.render(f);
  const Image b = renderer.render(f);
  ASSERT_EQ(a.width, 640);
  ASSERT_EQ(a.height, 480);
  EXPECT_GT(covered_share(a), 0.10);
  EXPECT_TRUE(a == b) << "the same request must give the same pixels";
  // a second renderer (a new context) gives the same pixels too
  SceneRenderer other(scene);
  EXPECT_TRUE(other.render(f) == a);
}

// Dark (text) pixels in a rectangle of the image.
int dark_pixels(const Image& image, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) n += image.pixel(x, y)[0] < 100 ? 1 : 0;
  }
  return n;
}

TEST(SceneRendererTest, RowsAreTopFirst) {
  // the header is drawn at the image's top-left corner: it must be in the first rows
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.width = 400;
  f.height = 300;
  f.show_labels = false;
  f.title = "TITLE TITLE TITLE";
  const Image image = renderer.render(f);
  EXPECT_GT(dark_pixels(image, 0, 0, 200, 30), 20);
  EXPECT_EQ(dark_pixels(image, 0, 270, 40, 300), 0);  // left of the objects (side room)
}

TEST(SceneRendererTest, ChangesSizeBetweenFrames) {
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.width = 320;
  f.height = 240;
  EXPECT_EQ(renderer.render(f).width, 320);
  f.width = 500;
  f.height = 260;
  const Image i = renderer.render(f);
  EXPECT_EQ(i.width, 500);
  EXPECT_EQ(i.height, 260);
}

TEST(SceneRendererTest, RenderersInTwoThreadsGiveTheSerialImages) {
  const SceneGeometry scene = testing::synthetic_scene();
  FrameRequest f;
  f.width = 320;
  f.height = 240;
  f.title = scene.spec.name;
  const Image expected = SceneRenderer(scene).render(f);
  Image images[2];
  std::thread threads[2];
  for (int t = 0; t < 2; ++t) {
    threads[t] = std::thread([&, t] {
      SceneRenderer renderer(scene);
      for (int i = 0; i < 3; ++i) images[t] = renderer.render(f);
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_TRUE(images[0] == expected);
  EXPECT_TRUE(images[1] == expected);
}

TEST(SceneRendererTest, RejectsEmptySize) {
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.width = 0;
  EXPECT_THROW(renderer.render(f), Error);
}

TEST(SceneRendererTest, ApartViewPutsABesideB) {
  const SceneGeometry scene = testing::synthetic_scene();
  const Camera camera;
  const Pose X = display_pose_of_A(scene, std::nullopt, camera);
  Eigen::Vector3d right, up, back;
  camera_basis(camera, &right, &up, &back);
  double a_min = 1e9, b_max = -1e9;
  for (const auto& p : scene.mesh_A.positions) a_min = std::min(a_min, X.apply(p).dot(right));
  for (const auto& p : scene.mesh_B.positions) b_max = std::max(b_max, p.dot(right));
  EXPECT_GT(a_min, b_max);  // A entirely to the right of B, as seen by the camera
  // a given pose is used as is
  const Pose given = testing::synthetic_resting_pose();
  EXPECT_EQ(display_pose_of_A(scene, given, camera).str(), given.str());
}

TEST(SceneRendererTest, SyntheticApartMatchesGolden) {
  PCSG_SKIP_WITHOUT_LABEL_FONT();
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.width = 800;
  f.height = 600;
  f.title = scene.spec.name;
  f.subtitle = "objects apart";
  testing::expect_matches_golden(renderer.render(f), "synthetic_apart");
}

TEST(SceneRendererTest, SyntheticContactMatchesGolden) {
  PCSG_SKIP_WITHOUT_LABEL_FONT();
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.width = 800;
  f.height = 600;
  f.camera = Camera{-30, 25, 1};
  f.X_BA = testing::synthetic_resting_pose();
  PointContact c;
  c.point_B = Eigen::Vector3d(0, 0, 1.4);
  c.normal_B = Eigen::Vector3d::UnitZ();
  f.contacts = {c};
  f.show_normals = true;
  f.highlighted = {{Object::B, {ElementKind::Edge, 0}}};  // the warning colour
  f.title = scene.spec.name;
  f.subtitle = "{(fA-f1, 1)}, edge e1 highlighted";
  testing::expect_matches_golden(renderer.render(f), "synthetic_contact");
}

}  // namespace
}  // namespace pcsg::render
