#pragma once
// Detects straight segments on a face's surface. The paper (Section I) handles strictly curved
// objects only, "those that have no line segment on their boundary surfaces": planes,
// cylinders, cones, one-sheet hyperboloids and hyperbolic paraboloids must be rejected, while
// spheres, ellipsoids, paraboloids of revolution and tori are fine.
//
// Test used: a line through a surface point p lies in the tangent plane and along an
// asymptotic direction (d^T H d = 0: the normal curvature vanishes), so only those few
// directions need the exact check that t -> g(p + t d) vanishes identically.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "engine/core/tolerances.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

// A straight line found on the surface g = 0.
struct StraightLineWitness {
  Eigen::Vector3d point;      // the surface point it passes through
  Eigen::Vector3d direction;  // unit
  // max_k |c_k| L^k / (|grad g| L + |Hess g| L^2) of g(point + t direction) = sum c_k t^k,
  // k = 1..4: how far from straight it is, relative to how g varies over the length L.
  double residual = 0;
};

// Looks for a straight line through each of `surface_points` (points on g = 0, e.g. from
// sample_surface) and returns the first found, or nullopt when every point's surface is curved
// along every tangent direction. `length_scale` L (> 0) is the scene's length unit: the test is
// invariant under scaling the scene and multiplying g by a constant. Singular points
// (grad g ~ 0) are skipped.
std::optional<StraightLineWitness> find_straight_line(
    const Polynomial& g, const std::vector<Eigen::Vector3d>& surface_points, double length_scale,
    double relative_tolerance = Tolerances{}.straight_line_relative);

// Up to n points on g = 0 inside `box`: pseudo-random starts in the box (a fixed generator
// seeded with `seed`, so the result is the same on every run and platform), each projected
// onto the surface by Newton steps along the gradient; points that leave the box are dropped.
// Returns fewer than n points (possibly none) when the surface barely meets the box.
std::vector<Eigen::Vector3d> sample_surface(const Polynomial& g, const Eigen::AlignedBox3d& box,
                                            int n, unsigned seed);

}  // namespace pcsg
