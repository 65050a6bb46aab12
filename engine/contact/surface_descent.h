#pragma once
// The deepest point of one solid's face inside the other solid's surface, by descent on the
// face: detection's fallback where the common-normal solves of an overlap region fail
// (contact_detection.cc). Minimising the other surface's signed distance over a face is
// well posed even where the common-normal system is nearly singular (a nearly conformal ring
// contact: the minima form a shallow valley along the ring, and any point of the valley below
// zero proves the penetration), and every iterate is an exact surface point.
#include <Eigen/Core>

#include "engine/core/pose.h"
#include "engine/geometry/solid.h"

namespace pcsg {

struct SurfaceDescent {
  Eigen::Vector3d point;  // on the face's surface, in its solid's frame
  double distance = 0;    // first-order signed distance of the point to the other surface
};

// Descends from `start` (a point of `solid`'s face `face`, in its frame) along the face's
// surface toward smaller signed distance g / |grad g| of its image X start to `other`'s
// surface `other_surface`. Steps that leave the face (another of the solid's surfaces turns
// positive) are refused. Stops after `iterations`, at a stationary point, or as soon as the
// image lies inside `other` deeper than `proof_depth` (a penetration proved).
SurfaceDescent descend_into(const Solid& solid, int face, const Pose& X, const Solid& other,
                            int other_surface, const Eigen::Vector3d& start, double length_scale,
                            double proof_depth, int iterations);

}  // namespace pcsg
