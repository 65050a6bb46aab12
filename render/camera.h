#pragma once
// The camera: an orbit around the scene given by azimuth, elevation and zoom, framed
// automatically so that every given point fits a region of the image. Eigen only, no GL: the
// same matrices serve the shaders and the CPU-side projection of label anchors.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace pcsg::render {

struct Camera {
  // The eye's direction from the scene, about B's z axis from +x toward +y (degrees).
  double azimuth_deg = -60;
  // The eye's height above B's xy plane (degrees, clamped to +-89 to keep "up" defined).
  double elevation_deg = 20;
  // Magnification about the framed region's centre: 2 shows the scene twice as large.
  double zoom = 1;
};

// Parses "az el zoom" (degrees, degrees, factor > 0; commas allowed). Throws UsageError naming
// the text when it is malformed.
Camera parse_camera(const std::string& text);

// A rectangle of the image in pixels (x right, y down, origin at the top-left corner).
struct PixelRect {
  double left = 0, top = 0, right = 0, bottom = 0;
  double width() const { return right - left; }
  double height() const { return bottom - top; }
};

// The framed camera of one image.
struct CameraView {
  int width = 0, height = 0;             // image size in pixels
  Eigen::Vector3d eye, right, up, back;  // world (= B's frame); back points from scene to eye
  double near = 0, far = 0;              // clip distances along -back
  double depth_min = 0, depth_max = 0;   // depth range of the framed points
  Eigen::Matrix4f view, projection;      // OpenGL conventions (right-handed, NDC z in [-1, 1])

  // The pixel position (x right, y down) of a world point in front of the eye.
  Eigen::Vector2d project(const Eigen::Vector3d& p_W) const;
  // Distance of a world point from the eye along the viewing direction.
  double depth(const Eigen::Vector3d& p_W) const { return (eye - p_W).dot(back); }
  // Unit direction from a world point toward the eye.
  Eigen::Vector3d to_eye(const Eigen::Vector3d& p_W) const { return (eye - p_W).normalized(); }
};

// The basis (right, up, back) of the camera's orientation, before any framing.
void camera_basis(const Camera& camera, Eigen::Vector3d* right, Eigen::Vector3d* up,
                  Eigen::Vector3d* back);

// Places the eye on the camera's orbit so that all points (world frame, non-empty) fill the
// pixel region `fit` of a width x height image, centred in it, then applies the zoom.
CameraView frame_points(const Camera& camera, const std::vector<Eigen::Vector3d>& points_W,
                        int width, int height, const PixelRect& fit);

}  // namespace pcsg::render
