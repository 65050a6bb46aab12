// Descent on a face toward the other solid's surface (surface_descent.h), on two overlapping
// balls whose deepest points are known in closed form.
#include "engine/contact/surface_descent.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/contact/contact_classification.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

using testkit::sphere_solid;

// Unit balls, B's centre 1.9 from A's: they overlap by 0.2, and the point of A's sphere
// deepest in B is the one nearest B's centre, (1, 0, 0) in A's frame, 0.9 from it.
TEST(SurfaceDescent, ReachesTheDeepestPointOfOverlappingBalls) {
  const Solid A = sphere_solid(1.0, "fA").solid;
  const Solid B = sphere_solid(1.0, "fB").solid;
  Pose X;  // A's frame in B's: A's centre at (-1.9, 0, 0) in B
  X.position = {-1.9, 0, 0};
  // start 40 degrees around A's sphere from the deepest point, outside B
  const double a = 40 * M_PI / 180;
  const Eigen::Vector3d start(std::cos(a), std::sin(a), 0);
  // Without a proof depth to stop at, the descent runs to the bottom.
  const SurfaceDescent d = descend_into(A, 0, X, B, 0, start, 4.0, INFINITY, 200);
  // Converges to the sphere's deepest point to a small fraction of its radius (gradient
  // descent along a smooth bowl: linear convergence, 200 steps leave < 1e-6).
  EXPECT_NEAR((d.point - Eigen::Vector3d(1, 0, 0)).norm(), 0, 1e-6);
  EXPECT_NEAR(d.point.norm(), 1.0, 1e-12);  // on A's surface to round-off
  // g_B = |x|^2 - 1 at |x| = 0.9: value -0.19, gradient 1.8: first-order distance -0.19/1.8
  EXPECT_NEAR(d.distance, -0.19 / 1.8, 1e-9);
  // With a proof depth it stops as soon as the point is that deep inside B.
  const SurfaceDescent p = descend_into(A, 0, X, B, 0, start, 4.0, 1e-3, 200);
  EXPECT_TRUE(strictly_inside(B, X.apply(p.point), 1e-3));
  // Apart by 0.1: no point of A's sphere gets inside B.
  X.position = {-2.1, 0, 0};
  const SurfaceDescent q = descend_into(A, 0, X, B, 0, start, 4.0, 0.0, 200);
  EXPECT_FALSE(strictly_inside(B, X.apply(q.point), 0.0));
  EXPECT_NEAR(q.distance, (1.1 * 1.1 - 1) / 2.2, 1e-9);
}

}  // namespace
}  // namespace pcsg
