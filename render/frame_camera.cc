#include "render/frame_camera.h"

#include "render/annotations.h"

namespace pcsg::render {

namespace {

// The renderer's label room (render/scene_renderer.cc, kSideRoom and kBottomRoom): share of the
// image width kept free on each side of the objects, and of the height below them.
constexpr double kSideRoom = 0.12;
constexpr double kBottomRoom = 0.07;

}  // namespace

CameraView frame_camera_view(const SceneGeometry& scene, const FrameRequest& f) {
  const Pose X_WA = display_pose_of_A(scene, f.X_BA, f.camera);
  std::vector<Eigen::Vector3d> points = scene.mesh_B.positions;
  points.reserve(points.size() + scene.mesh_A.positions.size());
  for (const auto& p : scene.mesh_A.positions) points.push_back(X_WA.apply(p));
  const double header = header_height(f);
  const PixelRect fit{kSideRoom * f.width, header + kBottomRoom * f.height,
                      (1 - kSideRoom) * f.width, (1 - kBottomRoom) * f.height};
  return frame_points(f.camera, points, f.width, f.height, fit);
}

}  // namespace pcsg::render
