#pragma once
// One framing for many pictures. SceneRenderer frames each image on B and on A where it is
// drawn, so A's pose changes the framing: thumbnails of different states would differ in
// scale, and an animation of a motion would jitter. A FramedScene is a copy of the scene whose
// B mesh carries extra vertices that no triangle uses: the renderer's framing includes every
// mesh position (and frame_camera_view with it), its drawing only triangles, so these points
// widen the framing without being drawn. Given A's extremal points at every pose of a set,
// each picture of the set is framed alike.
//
// (A FrameRequest field with points to frame would say this directly; it would be a change to
// the renderer's API.)
#include <vector>

#include "engine/core/pose.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg::render {

// A's extremal mesh vertices in many directions, at each pose (B's frame): what the framing
// needs of A, far fewer points than its mesh.
std::vector<Eigen::Vector3d> extent_of_A(const SceneGeometry& scene, const std::vector<Pose>& poses);

// A copy of `scene` whose B mesh also holds `points_B` as unused vertices.
SceneGeometry framed_scene(const SceneGeometry& scene, const std::vector<Eigen::Vector3d>& points_B);

}  // namespace pcsg::render
