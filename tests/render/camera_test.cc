// Automatic framing: every point lands inside the requested region, centred, and zoom scales
// about the region's centre.
#include "render/camera.h"

#include <gtest/gtest.h>

#include "engine/core/error.h"

namespace pcsg::render {
namespace {

// Framing is exact up to the centring iterations; a pixel of slack covers float matrices.
constexpr double kPixelSlack = 1.0;

std::vector<Eigen::Vector3d> box_corners(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::vector<Eigen::Vector3d> c;
  for (int i = 0; i < 8; ++i) {
    c.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  }
  return c;
}

TEST(CameraTest, FramesAllPointsInsideTheRegion) {
  const auto points = box_corners({-1, -2, -0.5}, {3, 1, 2});
  const PixelRect fit{100, 150, 700, 550};
  for (double az : {-90.0, -60.0, 0.0, 45.0, 170.0}) {
    for (double el : {-30.0, 0.0, 20.0, 60.0, 89.0}) {
      const CameraView v = frame_points(Camera{az, el, 1}, points, 800, 600, fit);
      double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
      for (const auto& p : points) {
        const Eigen::Vector2d q = v.project(p);
        x0 = std::min(x0, q.x());
        x1 = std::max(x1, q.x());
        y0 = std::min(y0, q.y());
        y1 = std::max(y1, q.y());
      }
      EXPECT_GE(x0, fit.left - kPixelSlack) << az << " " << el;
      EXPECT_LE(x1, fit.right + kPixelSlack) << az << " " << el;
      EXPECT_GE(y0, fit.top - kPixelSlack) << az << " " << el;
      EXPECT_LE(y1, fit.bottom + kPixelSlack) << az << " " << el;
      // the tighter direction fills the region: one pair of sides is touched
      const bool fills_x = x1 - x0 > fit.width() - 2 * kPixelSlack - 1;
      const bool fills_y = y1 - y0 > fit.height() - 2 * kPixelSlack - 1;
      EXPECT_TRUE(fills_x || fills_y) << az << " " << el;
    }
  }
}

TEST(CameraTest, UpIsBsZAxis) {
  const auto points = box_corners({-1, -1, -1}, {1, 1, 1});
  const CameraView v = frame_points(Camera{-60, 20, 1}, points, 640, 480, {0, 0, 640, 480});
  // a point above another in z appears higher (smaller y) in the image
  EXPECT_LT(v.project({0, 0, 1}).y(), v.project({0, 0, -1}).y());
}

TEST(CameraTest, ZoomScalesAboutTheRegionCentre) {
  const auto points = box_corners({-1, -1, -1}, {1, 1, 1});
  const PixelRect fit{0, 100, 640, 480};
  const CameraView v1 = frame_points(Camera{-60, 20, 1}, points, 640, 480, fit);
  const CameraView v2 = frame_points(Camera{-60, 20, 2}, points, 640, 480, fit);
  const Eigen::Vector2d centre(320, 290);
  for (const auto& p : points) {
    EXPECT_NEAR((v2.project(p) - centre).norm(), 2 * (v1.project(p) - centre).norm(), 1e-3 * 640);
  }
}

TEST(CameraTest, ParsesAndRejectsCameraText) {
  const Camera c = parse_camera("30, -10 1.5");
  EXPECT_DOUBLE_EQ(c.azimuth_deg, 30);
  EXPECT_DOUBLE_EQ(c.elevation_deg, -10);
  EXPECT_DOUBLE_EQ(c.zoom, 1.5);
  EXPECT_THROW(parse_camera("30 10"), UsageError);
  EXPECT_THROW(parse_camera("30 10 0"), UsageError);
  EXPECT_THROW(parse_camera("30 10 1 extra"), UsageError);
  EXPECT_THROW(parse_camera("a b c"), UsageError);
}

}  // namespace
}  // namespace pcsg::render
