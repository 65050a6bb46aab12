#include "render/framed_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pcsg::render {

namespace {

// Directions sampled on the sphere: with 128, the extreme vertex in any direction is within
// ~10 degrees of a sampled one, far inside the renderer's label room around the objects.
constexpr int kDirections = 128;

}  // namespace

std::vector<Eigen::Vector3d> extent_of_A(const SceneGeometry& scene, const std::vector<Pose>& poses) {
  const auto& pa = scene.mesh_A.positions;
  if (pa.empty()) return {};
  // the extreme vertices in A's own frame: rotating A rotates the sample directions with it,
  // which stay as dense, so one set serves every pose
  std::vector<int> extremes;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));  // the golden angle
  for (int k = 0; k < kDirections; ++k) {
    const double z = 1 - 2 * (k + 0.5) / kDirections, r = std::sqrt(1 - z * z);
    const Eigen::Vector3d d(r * std::cos(golden * k), r * std::sin(golden * k), z);
    int best = 0;
    for (int i = 1; i < static_cast<int>(pa.size()); ++i)
      if (pa[i].dot(d) > pa[best].dot(d)) best = i;
    extremes.push_back(best);
  }
  std::sort(extremes.begin(), extremes.end());
  extremes.erase(std::unique(extremes.begin(), extremes.end()), extremes.end());
  std::vector<Eigen::Vector3d> out;
  out.reserve(extremes.size() * poses.size());
  for (const Pose& X : poses)
    for (int i : extremes) out.push_back(X.apply(pa[i]));
  return out;
}

SceneGeometry framed_scene(const SceneGeometry& scene, const std::vector<Eigen::Vector3d>& points_B) {
  SceneGeometry copy = scene;
  SolidMesh& m = copy.mesh_B;
  for (const Eigen::Vector3d& p : points_B) {
    m.positions.push_back(p);
    m.normals.push_back(Eigen::Vector3d::UnitZ());  // never used: no triangle refers to it
    if (!m.vertex_edge.empty()) m.vertex_edge.push_back(-1);
    if (!m.vertex_vertex.empty()) m.vertex_vertex.push_back(-1);
  }
  return copy;
}

}  // namespace pcsg::render
