// Descent on a face toward the other solid's surface (surface_descent.h), on two overlapping
// balls whose deepest points are known in closed form.
#include "engine/contact/surface_descent.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "engine/contact/contact_classification.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

using testkit::sphere_solid;

// The descent as written before it kept its direction across refused steps (session 61's
// code): each iteration re-evaluated the proof, both normals and the direction at the current
// point. The reference the descent must match bit for bit.
namespace reference {
double signed_distance(const Polynomial& g, const Eigen::Vector3d& x, Eigen::Vector3d* unit) {
  double v;
  Eigen::Vector3d grad;
  g.evaluate(x, &v, &grad, nullptr);
  const double n = grad.norm();
  if (!(n > 0)) return INFINITY;
  if (unit) *unit = grad / n;
  return v / n;
}
Eigen::Vector3d onto_surface(const Polynomial& g, Eigen::Vector3d p) {
  for (int k = 0; k < 4; ++k) {
    double v;
    Eigen::Vector3d grad;
    g.evaluate(p, &v, &grad, nullptr);
    const double n2 = grad.squaredNorm();
    if (!(n2 > 0)) break;
    p -= (v / n2) * grad;
  }
  return p;
}
bool within_face(const Solid& solid, int surface, const Eigen::Vector3d& p) {
  for (int i = 0; i < static_cast<int>(solid.surfaces.size()); ++i)
    if (i != surface && solid.surfaces[i].value(p) > 0) return false;
  return true;
}
SurfaceDescent descend_into(const Solid& solid, int face, const Pose& X, const Solid& other,
                            int other_surface, const Eigen::Vector3d& start, double length_scale,
                            double proof_depth, int iterations) {
  const int surface = solid.faces[face].surface;
  const Polynomial& g = solid.surfaces[surface];
  const Polynomial& h = other.surfaces[other_surface];
  const Eigen::Matrix3d R_T = X.rotation().transpose();
  SurfaceDescent cur{start, signed_distance(h, X.apply(start), nullptr)};
  double step = 1e-2 * length_scale;
  for (int it = 0; it < iterations && step > 1e-15 * length_scale; ++it) {
    if (strictly_inside(other, X.apply(cur.point), proof_depth)) break;
    Eigen::Vector3d n_other = Eigen::Vector3d::Zero(), n_face = Eigen::Vector3d::Zero();
    if (!std::isfinite(signed_distance(h, X.apply(cur.point), &n_other)) ||
        !std::isfinite(signed_distance(g, cur.point, &n_face)))
      break;
    Eigen::Vector3d t = R_T * n_other;
    t -= n_face * n_face.dot(t);
    const double tn = t.norm();
    if (!(tn > 0)) break;
    const Eigen::Vector3d q = onto_surface(g, cur.point - (step / tn) * t);
    const double d = signed_distance(h, X.apply(q), nullptr);
    if (d < cur.distance && within_face(solid, surface, q)) {
      cur = {q, d};
      step *= 2;
    } else {
      step *= 0.5;
    }
  }
  return cur;
}
}  // namespace reference

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

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

// The descent keeps its direction across refused steps (only the step length changes there)
// and takes the other surface's normal at an accepted point from the evaluation that accepted
// it: the same points and distances, bit for bit, as re-evaluating everything each iteration.
// Compared from every mesh vertex of each face of A (a sample of them) into each surface of B,
// about contact poses pressed in, at the faces' edges (the lens, the three-ball solid: refused
// steps that would leave the face), with and without a proof depth, and 0 to 200 iterations.
TEST(SurfaceDescent, KeepingTheDirectionAcrossRefusedStepsChangesNoBit) {
  struct Case {
    testkit::MeshedSolid A, B;
    Pose X;
  };
  std::vector<Case> cases;
  cases.push_back({testkit::ellipsoid_solid(1, 1.5, 2.5), testkit::bowl_solid(1),
                   testkit::lying_ellipsoid_pose()});
  {
    Pose X;  // the lens's rim pressed into the three-ball solid's side
    X.position = {1.2, 0.3, 0.1};
    X.quaternion =
        Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 0.5).normalized()));
    cases.push_back({testkit::lens_solid(1.0, 0.6), testkit::three_ball_solid(1.0, 0.5), X});
  }
  {
    Pose X;
    X.position = {0.2, -0.1, 1.6};
    cases.push_back({testkit::three_ball_solid(1.0, 0.5), testkit::double_paraboloid_solid(1), X});
  }
  std::mt19937 rng(29);
  std::normal_distribution<double> n(0, 1);
  long compared = 0, proved = 0, moved = 0;
  for (const Case& c : cases) {
    const double L = 4.0;
    for (int k = 0; k < 6; ++k) {
      // pressed in along a random direction by up to 5% of L, turned a little
      const Eigen::Vector3d v(n(rng), n(rng), n(rng)), w(n(rng), n(rng), n(rng));
      const Pose X =
          c.X.displaced(0.01 * k * L * v.normalized(), 0.02 * k * w.normalized(), c.X.position);
      for (int f = 0; f < static_cast<int>(c.A.solid.faces.size()); ++f)
        for (int s = 0; s < static_cast<int>(c.B.solid.surfaces.size()); ++s)
          for (size_t t = k; t < c.A.mesh.triangles.size(); t += 37) {
            if (c.A.mesh.triangle_face[t] != f) continue;
            const Eigen::Vector3d start = c.A.mesh.positions[c.A.mesh.triangles[t][0]];
            for (const double depth : {static_cast<double>(INFINITY), 1e-3 * L}) {
              const int iterations = (t / 37) % 5 == 0 ? static_cast<int>(t % 200) : 200;
              const SurfaceDescent a = reference::descend_into(c.A.solid, f, X, c.B.solid, s, start,
                                                               L, depth, iterations);
              const SurfaceDescent b =
                  descend_into(c.A.solid, f, X, c.B.solid, s, start, L, depth, iterations);
              ASSERT_TRUE(same_bits(a.distance, b.distance)) << compared;
              for (int i = 0; i < 3; ++i)
                ASSERT_TRUE(same_bits(a.point[i], b.point[i])) << compared;
              ++compared;
              proved += std::isfinite(depth) && strictly_inside(c.B.solid, X.apply(b.point), depth);
              moved += b.point != start;
            }
          }
    }
  }
  // Many descents, most of them moving, some of them proving a penetration.
  EXPECT_GE(compared, 10000);
  EXPECT_GE(moved, compared / 2);
  EXPECT_GE(proved, 1000);
}

}  // namespace
}  // namespace pcsg
