#include "engine/geometry/surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/poly/parser.h"

namespace pcsg {
namespace {

// Closed-form values are computed in double precision from exact formulas; the kernel's are
// from the Hessian and gradient, exact up to round-off (~1e-15 relative): 1e-12 leaves margin.
constexpr double kRoundOff = 1e-12;

Polynomial g_of(const std::string& inequality) { return parse_inequality(inequality).g; }

TEST(Surface, SphereNormalAndCurvaturesAreOneOverR) {
  const Polynomial g = g_of("x^2 + y^2 + z^2 <= 16");
  const Eigen::Vector3d p = Eigen::Vector3d(1, 2, 3).normalized() * 4;
  EXPECT_TRUE(unit_normal(g, p).isApprox(p / 4, kRoundOff));
  const auto pc = principal_curvatures(g, p);
  ASSERT_TRUE(pc);
  EXPECT_NEAR(pc->k1, 0.25, kRoundOff);
  EXPECT_NEAR(pc->k2, 0.25, kRoundOff);
  EXPECT_NEAR(pc->d1.dot(pc->normal), 0, kRoundOff);
  EXPECT_TRUE(pc->d1.cross(pc->d2).isApprox(pc->normal, kRoundOff));
}

TEST(Surface, EllipsoidPoleIsAnOrdinaryPoint) {
  // x^2 + y^2/1.5^2 + z^2/2.5^2 <= 1: at the pole (0, 0, c) the curvatures are c/a^2, c/b^2
  const Polynomial g = g_of("225x^2 + 100y^2 + 36z^2 <= 225");
  const Eigen::Vector3d pole(0, 0, 2.5);
  const auto pc = principal_curvatures(g, pole);
  ASSERT_TRUE(pc);
  EXPECT_NEAR(pc->k1, 2.5 / 2.25, kRoundOff);
  EXPECT_NEAR(pc->k2, 2.5, kRoundOff);
  EXPECT_NEAR(std::abs(pc->d1.y()), 1, kRoundOff);  // the flatter direction is along b
  EXPECT_NEAR(std::abs(pc->d2.x()), 1, kRoundOff);
  // the other poles too
  const auto px = principal_curvatures(g, Eigen::Vector3d(1, 0, 0));
  ASSERT_TRUE(px);
  EXPECT_NEAR(px->k1, 1 / 6.25, kRoundOff);  // a / c^2
  EXPECT_NEAR(px->k2, 1 / 2.25, kRoundOff);  // a / b^2
}

TEST(Surface, ParaboloidTipsConvexAndConcave) {
  // z = a r^2 + c has curvature 2a at its tip: the convex bottom (a = 1/4) seen from its solid
  // side is +0.5; the dish (a = 4/10.07047), whose solid lies above it, is concave: -2a.
  const auto bottom = principal_curvatures(g_of("x^2 + y^2 - 4z <= 16"), {0, 0, -4});
  ASSERT_TRUE(bottom);
  EXPECT_NEAR(bottom->k1, 0.5, kRoundOff);
  EXPECT_NEAR(bottom->k2, 0.5, kRoundOff);
  EXPECT_TRUE(bottom->normal.isApprox(Eigen::Vector3d(0, 0, -1), kRoundOff));
  const auto dish =
      principal_curvatures(g_of("4x^2 + 4y^2 - 10.07047z >= 15.75982"), {0, 0, -15.75982 / 10.07047});
  ASSERT_TRUE(dish);
  EXPECT_NEAR(dish->k1, -8 / 10.07047, kRoundOff);
  EXPECT_NEAR(dish->k2, -8 / 10.07047, kRoundOff);
}

TEST(Surface, TangentFrameHasNoPole) {
  for (const Eigen::Vector3d& n :
       {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, 0),
        Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(1, 1, 1).normalized(),
        Eigen::Vector3d(1e-12, 0, 1).normalized()}) {
    const TangentFrame f = tangent_frame(n);
    EXPECT_NEAR(f.u.norm(), 1, kRoundOff);
    EXPECT_NEAR(f.u.dot(n), 0, kRoundOff);
    EXPECT_TRUE(f.u.cross(f.v).isApprox(n, kRoundOff));
  }
}

TEST(Surface, ProjectionsLandOnTheSurfacesWithinTheResidual) {
  const Tolerances tol = Tolerances::for_length_scale(10);
  const Polynomial sphere = g_of("x^2 + y^2 + z^2 <= 16");
  // minimum-norm steps along the gradient move radially on a sphere
  const Projection p = project_onto_surface(sphere, {3, 4, 5}, tol);
  ASSERT_TRUE(p.converged);
  EXPECT_TRUE(p.point.isApprox(Eigen::Vector3d(3, 4, 5).normalized() * 4, 1e-12));
  EXPECT_LE(surface_distance(sphere, p.point), tol.solve_residual);
  // onto the circle r = 4, z = 0 where the sphere meets the bottom paraboloid
  const Polynomial bottom = g_of("x^2 + y^2 - 4z <= 16");
  const Projection c = project_onto_curve(sphere, bottom, {3, 1, 0.5}, tol);
  ASSERT_TRUE(c.converged);
  EXPECT_NEAR(c.point.z(), 0, tol.solve_residual);
  EXPECT_NEAR(c.point.head<2>().norm(), 4, tol.solve_residual);
  EXPECT_NEAR(std::abs(curve_tangent(sphere, bottom, c.point).z()), 0, kRoundOff);
  // the vertex of three unit spheres centred on a triangle of side 1
  const Projection v = solve_three_surfaces(
      g_of("x^2 + y^2 + z^2 <= 1"), g_of("(x - 1)^2 + y^2 + z^2 <= 1"),
      g_of("(x - 0.5)^2 + (y - 0.8660254037844386)^2 + z^2 <= 1"), {0.4, 0.3, 0.7}, tol);
  ASSERT_TRUE(v.converged);
  EXPECT_TRUE(v.point.isApprox(Eigen::Vector3d(0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3)), 1e-12));
}

// Multiplying an inequality through by a positive constant changes neither its surface nor
// the projections: the solves divide each row by its gradient's norm. Before they did,
// project_onto_curve failed for the sphere x 1e8 against the paraboloid x 1e-8 (J J^T's
// eigenvalues 1e32 apart, the small one cut by the pseudo-inverse).
TEST(Surface, ProjectionsDoNotDependOnTheInequalitiesScales) {
  const Tolerances tol = Tolerances::for_length_scale(10);
  const Polynomial sphere = g_of("x^2 + y^2 + z^2 <= 16"), bottom = g_of("x^2 + y^2 - 4z <= 16");
  const Polynomial third = g_of("(x - 4)^2 + y^2 + z^2 <= 16");
  const Projection c = project_onto_curve(sphere, bottom, {3, 1, 0.5}, tol);
  const Projection v = solve_three_surfaces(sphere, bottom, third, {2, 3, 0.3}, tol);
  ASSERT_TRUE(c.converged);
  ASSERT_TRUE(v.converged);
  for (const auto& [k1, k2] : {std::pair{1e8, 1e-8}, std::pair{1e-8, 1e8}, std::pair{1e16, 1.0}}) {
    SCOPED_TRACE(k1);
    const Projection cs = project_onto_curve(sphere * k1, bottom * k2, {3, 1, 0.5}, tol);
    ASSERT_TRUE(cs.converged);
    EXPECT_LE((cs.point - c.point).norm(), 2 * tol.solve_residual);
    const Projection vs = solve_three_surfaces(sphere * k1, bottom * k2, third, {2, 3, 0.3}, tol);
    ASSERT_TRUE(vs.converged);
    EXPECT_LE((vs.point - v.point).norm(), 2 * tol.solve_residual);
  }
}

}  // namespace
}  // namespace pcsg
