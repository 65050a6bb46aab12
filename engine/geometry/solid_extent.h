#pragma once
// A first box around a solid { p : g_i(p) <= 0 for all i }, before its faces are known, and the
// checks that the solid is neither empty nor unbounded (both are scene errors: pcsg needs
// bounded objects with interior).
#include <Eigen/Geometry>

#include "engine/scene/scene.h"

namespace pcsg {

// A box holding the whole solid. Throws SceneError (at the object's place in the file) when the
// solid is unbounded, naming a direction in which it extends, or empty.
//
// Unboundedness is decided scale-invariantly in three steps: (1) the top-degree homogeneous
// parts h_i on the unit sphere: a direction with every h_i < 0 is a ray that ends inside the
// solid; (2) directions where max_i h_i is zero (a paraboloid's axis) are refined and followed
// from points inside the solid: the solid is unbounded when it stays inside for 10^6 times its
// size; (3) a growing-box check: the box from rays cast through the solid is doubled while the
// solid still crosses its boundary.
Eigen::AlignedBox3d solid_box_estimate(const ObjectSpec& object);

// The box and an estimate of the solid's thickness: twice the largest distance to the
// boundary seen from the ray origins inside the solid (its frame's origin and its surfaces'
// centres), each measured as the shortest exit along the sampled directions. A needle of
// radius r gives ~2r; the box alone would give its length. Infinite when no ray origin lies
// inside the solid.
struct SolidExtent {
  Eigen::AlignedBox3d box;
  double thickness = 0;
};
SolidExtent solid_extent(const ObjectSpec& object);

}  // namespace pcsg
