// frame_camera_view repeats SceneRenderer's framing: a contact the renderer marks must be
// where the view projects it (the marker's colour at that pixel), with and without a header.
#include "render/frame_camera.h"

#include <gtest/gtest.h>

#include "render/palette.h"
#include "tests/render/test_meshes.h"

namespace pcsg::render {
namespace {

TEST(FrameCameraTest, ProjectsWhereTheRendererMarksContacts) {
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  for (bool header : {false, true}) {
    FrameRequest f;
    f.width = 480;
    f.height = 360;
    f.X_BA = Pose::identity();
    f.show_labels = false;
    if (header) f.title = "title", f.subtitle = "subtitle";
    PointContact c;
    c.point_B = scene.mesh_B.positions.front();
    f.contacts = {c};
    const Image image = renderer.render(f);
    const Eigen::Vector2d p = frame_camera_view(scene, f).project(c.point_B);
    const std::uint8_t* px = image.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
    // the marker's fill (palette::kContact, 0.85 0.10 0.35)
    EXPECT_NEAR(px[0], 217, 12) << "header " << header << " at " << p.transpose();
    EXPECT_NEAR(px[1], 26, 12);
    EXPECT_NEAR(px[2], 89, 12);
  }
}

}  // namespace
}  // namespace pcsg::render
