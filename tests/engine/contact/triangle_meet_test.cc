// triangles_meet (triangle_meet.h) answers most leaf pairs of a collision query in place of
// FCL's separating-axis test, so every answer it gives must be FCL's: on random pairs, on
// pairs built to touch (a vertex on the other triangle, two edges crossing) and nudged by
// amounts from round-off upward, and far from the origin. It may say Unsure, never differ.
#include "engine/contact/triangle_meet.h"

#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#include <gtest/gtest.h>

#include <array>
#include <random>

namespace pcsg {
namespace {

using V = Eigen::Vector3d;
using Tri = std::array<V, 3>;

bool fcl_meets(const Tri& P, const Tri& Q) {
  return fcl::detail::Intersect<double>::intersect_Triangle(P[0], P[1], P[2], Q[0], Q[1], Q[2],
                                                            Eigen::Matrix3d::Identity(), V::Zero());
}

TriangleMeet ours(const Tri& P, const Tri& Q) {
  return triangles_meet(P[0], P[1], P[2], Q[0], Q[1], Q[2]);
}

struct Tally {
  long decided = 0, unsure = 0, intersect = 0;
};

// Checks one pair (and the pair with P and Q exchanged): a decided answer is FCL's.
void check(const Tri& P, const Tri& Q, Tally& t) {
  const bool fcl = fcl_meets(P, Q);
  for (const TriangleMeet m : {ours(P, Q), ours(Q, P)}) {
    if (m == TriangleMeet::Unsure) {
      ++t.unsure;
      continue;
    }
    ++t.decided;
    t.intersect += m == TriangleMeet::Intersect;
    ASSERT_EQ(m == TriangleMeet::Intersect, fcl)
        << "P " << P[0].transpose() << " | " << P[1].transpose() << " | " << P[2].transpose()
        << "\nQ " << Q[0].transpose() << " | " << Q[1].transpose() << " | " << Q[2].transpose();
  }
}

V random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return V(n(rng), n(rng), n(rng)).normalized();
}

Tri random_triangle(const V& centre, double size, std::mt19937& rng) {
  return {centre + size * random_unit(rng), centre + size * random_unit(rng),
          centre + size * random_unit(rng)};
}

TEST(TrianglesMeet, AgreesWithFclOnRandomPairs) {
  std::mt19937 rng(7);
  Tally t;
  for (int k = 0; k < 200000; ++k) {
    const Tri P = random_triangle(V::Zero(), 1.0, rng);
    const Tri Q = random_triangle(0.8 * random_unit(rng), 1.0, rng);
    check(P, Q, t);
    if (HasFatalFailure()) return;
  }
  // Both answers occur, and nearly every pair is decided (else the leaf test saves nothing).
  EXPECT_GT(t.intersect, t.decided / 10);
  EXPECT_LT(t.intersect, t.decided - t.decided / 10);
  EXPECT_LT(t.unsure, (t.decided + t.unsure) / 1000);
}

// Q built to touch P, then moved along P's normal (a vertex on P's face) or along the common
// perpendicular of two edges (edges crossing) by `nudge` of the triangles' size, both ways.
TEST(TrianglesMeet, AgreesWithFclOnTouchingPairsNudged) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  Tally t;
  for (int k = 0; k < 4000; ++k) {
    const Tri P = random_triangle(V::Zero(), 1.0, rng);
    const V n = (P[1] - P[0]).cross(P[2] - P[0]).normalized();
    // a point inside P, and one on its edge P0-P1
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const V inside = P[0] + a * (P[1] - P[0]) + b * (P[2] - P[0]);
    const V on_edge = P[0] + u(rng) * (P[1] - P[0]);
    for (double nudge : {0.0, 1e-15, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1}) {
      for (double side : {-1.0, 1.0}) {
        // a vertex of Q on P's face, Q above it
        const V up = n + 0.3 * random_unit(rng);
        const V top = inside + side * nudge * n;
        const Tri Qv = {top, top + up + 0.5 * random_unit(rng), top + up + 0.5 * random_unit(rng)};
        check(P, Qv, t);
        // an edge of Q crossing P's edge P0-P1, Q on the far side of the edge
        const V e = (P[1] - P[0]).normalized();
        const V perp = n.cross(e);  // in P's plane, across its edge
        const V out = (P[2] - P[0]).dot(perp) > 0 ? V(-perp) : perp;
        const V f = (n + 0.5 * random_unit(rng)).normalized();  // Q's edge, through P's plane
        const V mid = on_edge + side * nudge * n;
        const Tri Qe = {mid - 0.5 * f, mid + 0.5 * f, mid + out + 0.3 * random_unit(rng)};
        check(P, Qe, t);
        if (HasFatalFailure()) return;
      }
    }
  }
  EXPECT_GT(t.decided, 0);
  EXPECT_GT(t.unsure, 0);  // the exact touches are left to FCL
}

// Far from the origin (the stress scenes put B 1e4 sizes away): the same answers.
TEST(TrianglesMeet, AgreesWithFclFarFromTheOrigin) {
  std::mt19937 rng(13);
  Tally t;
  const V far(1.2e5, -5e4, 2e4);
  for (int k = 0; k < 50000; ++k) {
    Tri P = random_triangle(V::Zero(), 1.0, rng);
    Tri Q = random_triangle(0.8 * random_unit(rng), 1.0, rng);
    for (V& v : P) v += far;
    for (V& v : Q) v += far;
    check(P, Q, t);
    if (HasFatalFailure()) return;
  }
  EXPECT_LT(t.unsure, (t.decided + t.unsure) / 100);
}

TEST(TrianglesMeet, DegenerateAndCoplanarPairsAreLeftToFcl) {
  const Tri P = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  EXPECT_EQ(ours(P, {V(0.2, 0.2, 0), V(2, 0.2, 0), V(0.2, 2, 0)}), TriangleMeet::Unsure);
  EXPECT_EQ(ours(P, {V(0.2, 0.2, -1), V(0.2, 0.2, 1), V(0.2, 0.2, 0)}), TriangleMeet::Unsure);
  EXPECT_EQ(ours(P, {V(0.2, 0.2, -1), V(0.3, 0.2, 1), V(0.2, 0.5, 1)}), TriangleMeet::Intersect);
  EXPECT_EQ(ours(P, {V(2, 2, -1), V(2.1, 2, 1), V(2, 2.5, 1)}), TriangleMeet::Apart);
  EXPECT_EQ(ours(P, {V(0, 0, 1), V(1, 0, 1), V(0, 1, 2)}), TriangleMeet::Apart);
}

}  // namespace
}  // namespace pcsg
