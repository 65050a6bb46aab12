#include "render/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

// Vertical field of view: narrow enough that the objects keep their proportions (little
// perspective distortion), wide enough that depth still reads.
constexpr double kFieldOfViewYDeg = 30;
// Elevation limit: at +-90 degrees the orbit's "up" (B's z axis) would be the view direction.
constexpr double kMaxElevationDeg = 89;
// Centring iterations: each re-centres the projected points; the error shrinks by roughly the
// ratio of the scene's depth to the eye distance (< 1/3) per step, so 6 steps reach < 0.1%.
constexpr int kCentringIterations = 6;
// The clip range is the points' depth range widened by this share on each side, so that the
// edges drawn slightly toward the eye (depth bias) and the markers are never clipped.
constexpr double kClipMargin = 0.25;
// A flat scene (all points at one depth) still gets a depth range, relative to the distance.
constexpr double kMinDepthRange = 1e-3;
// The near plane never comes closer than this share of the nearest point's distance (depth
// precision drops with near / far).
constexpr double kMinNearShare = 0.05;

constexpr double kPi = 3.14159265358979323846;

}  // namespace

Camera parse_camera(const std::string& text) {
  std::string cleaned = text;
  std::replace(cleaned.begin(), cleaned.end(), ',', ' ');
  std::istringstream in(cleaned);
  Camera c;
  std::string rest;
  if (!(in >> c.azimuth_deg >> c.elevation_deg >> c.zoom) || (in >> rest) ||
      !std::isfinite(c.azimuth_deg) || !std::isfinite(c.elevation_deg) || !std::isfinite(c.zoom) ||
      c.zoom <= 0) {
    throw UsageError("--camera \"" + text +
                     "\": expected \"azimuth elevation zoom\" (degrees, degrees, factor > 0), "
                     "e.g. \"-60 20 1\"");
  }
  return c;
}

void camera_basis(const Camera& camera, Eigen::Vector3d* right, Eigen::Vector3d* up,
                  Eigen::Vector3d* back) {
  const double az = camera.azimuth_deg * kPi / 180;
  const double el =
      std::clamp(camera.elevation_deg, -kMaxElevationDeg, kMaxElevationDeg) * kPi / 180;
  *back = Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  // B's z axis is "up" in every view (the scenes are modelled z-up).
  *right = (-*back).cross(Eigen::Vector3d::UnitZ()).normalized();
  *up = right->cross(-*back);
}

Eigen::Vector2d CameraView::project(const Eigen::Vector3d& p_W) const {
  const Eigen::Vector4f clip =
      projection * view * Eigen::Vector4f(float(p_W.x()), float(p_W.y()), float(p_W.z()), 1.f);
  const double w = clip.w() != 0 ? clip.w() : 1e-30;
  const double x_ndc = clip.x() / w, y_ndc = clip.y() / w;
  return {(x_ndc + 1) * 0.5 * width, (1 - y_ndc) * 0.5 * height};
}

CameraView frame_points(const Camera& camera, const std::vector<Eigen::Vector3d>& points_W,
                        int width, int height, const PixelRect& fit) {
  if (points_W.empty()) throw Error("frame_points: nothing to frame (no mesh vertices)");
  CameraView v;
  v.width = width;
  v.height = height;
  camera_basis(camera, &v.right, &v.up, &v.back);

  // the fit region in NDC: half sizes and centre (the centre becomes a lens shift)
  const double x0 = 2 * fit.left / width - 1, x1 = 2 * fit.right / width - 1;
  const double y0 = 1 - 2 * fit.bottom / height, y1 = 1 - 2 * fit.top / height;
  const double hx = 0.5 * (x1 - x0), hy = 0.5 * (y1 - y0);
  const double shift_x = 0.5 * (x0 + x1), shift_y = 0.5 * (y0 + y1);
  const double ty = std::tan(0.5 * kFieldOfViewYDeg * kPi / 180);
  const double tx = ty * width / height;

  // start at the points' bounding-box centre, then re-centre on the projected extent
  Eigen::Vector3d lo = points_W.front(), hi = points_W.front();
  for (const auto& p : points_W) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Eigen::Vector3d target = 0.5 * (lo + hi);
  double dist = 0;
  const double inf = std::numeric_limits<double>::infinity();
  for (int iter = 0; iter <= kCentringIterations; ++iter) {
    // distance at which every point's |x| / depth and |y| / depth fit the region
    dist = 0;
    for (const auto& p : points_W) {
      const Eigen::Vector3d q = p - target;
      const double toward_eye = q.dot(v.back);
      dist = std::max(dist, toward_eye + std::abs(q.dot(v.right)) / (hx * tx));
      dist = std::max(dist, toward_eye + std::abs(q.dot(v.up)) / (hy * ty));
    }
    if (iter == kCentringIterations) break;
    double umin = inf, umax = -inf, vmin = inf, vmax = -inf;
    for (const auto& p : points_W) {
      const Eigen::Vector3d q = p - target;
      const double d = dist - q.dot(v.back);
      umin = std::min(umin, q.dot(v.right) / d);
      umax = std::max(umax, q.dot(v.right) / d);
      vmin = std::min(vmin, q.dot(v.up) / d);
      vmax = std::max(vmax, q.dot(v.up) / d);
    }
    target += v.right * (0.5 * (umin + umax) * dist) + v.up * (0.5 * (vmin + vmax) * dist);
  }
  v.eye = target + v.back * dist;

  double dmin = inf, dmax = 0;
  for (const auto& p : points_W) {
    const double d = v.depth(p);
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
  }
  v.depth_min = dmin;
  v.depth_max = dmax;
  const double range = std::max(dmax - dmin, kMinDepthRange * dist);
  v.near = std::max(dmin - kClipMargin * range, kMinNearShare * dmin);
  v.far = dmax + kClipMargin * range;

  // view: rows are the camera axes; projection: perspective with the lens shift and the zoom
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = v.right.transpose();
  view.block<1, 3>(1, 0) = v.up.transpose();
  view.block<1, 3>(2, 0) = v.back.transpose();
  view.block<3, 1>(0, 3) = -view.block<3, 3>(0, 0) * v.eye;
  const double zoom = camera.zoom > 0 ? camera.zoom : 1;
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj(0, 0) = zoom / tx;
  proj(1, 1) = zoom / ty;
  proj(0, 2) = -shift_x;  // x_ndc = x / (-z tx) + shift_x, since w = -z
  proj(1, 2) = -shift_y;
  proj(2, 2) = -(v.far + v.near) / (v.far - v.near);
  proj(2, 3) = -2 * v.far * v.near / (v.far - v.near);
  proj(3, 2) = -1;
  v.view = view.cast<float>();
  v.projection = proj.cast<float>();
  return v;
}

}  // namespace pcsg::render
