// triangles_meet (triangle_meet.h) answers most leaf pairs of a collision query in place of
// FCL's separating-axis test, so every answer it gives must be FCL's: on random pairs, on
// pairs built to touch (a vertex on the other triangle, two edges crossing) and nudged by
// amounts from round-off upward, and far from the origin. It may say Unsure, never differ.
#include "engine/contact/triangle_meet.h"

#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
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

Eigen::Vector4d random_unit4(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Eigen::Vector4d(n(rng), n(rng), n(rng), n(rng)).normalized();
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

// The interval test as triangle_meet.cc first wrote it, every slack from computed norms (ten
// square roots a pair): the reference for its bounds, which may spare those roots but must
// change no verdict.
TriangleMeet reference_meet(const V& p1, const V& p2, const V& p3, const V& q1, const V& q2,
                            const V& q3) {
  constexpr double kPlaneRoundOff = 1e-9, kMinPlaneSine = 1e-3;
  struct Sides {
    V n;
    double d[3], slack, reach;
  };
  auto sides = [&](const V& a1, const V& a2, const V& a3, const V& b1, const V& b2, const V& b3) {
    Sides s;
    const V e1 = a2 - a1, e2 = a3 - a1;
    s.n = e1.cross(e2);
    const V r1 = b1 - a1, r2 = b2 - a1, r3 = b3 - a1;
    s.d[0] = s.n.dot(r1);
    s.d[1] = s.n.dot(r2);
    s.d[2] = s.n.dot(r3);
    s.reach = e1.norm() + e2.norm() + std::max({r1.norm(), r2.norm(), r3.norm()});
    s.slack = kPlaneRoundOff * s.n.norm() * s.reach;
    return s;
  };
  auto one_side = [](const Sides& s) {
    return (s.d[0] > s.slack && s.d[1] > s.slack && s.d[2] > s.slack) ||
           (s.d[0] < -s.slack && s.d[1] < -s.slack && s.d[2] < -s.slack);
  };
  auto clear = [](const Sides& s) {
    return std::abs(s.d[0]) > s.slack && std::abs(s.d[1]) > s.slack && std::abs(s.d[2]) > s.slack;
  };
  auto cut = [](const double t[3], const double d[3], double& lo, double& hi) {
    const int k = (d[0] > 0) == (d[1] > 0) ? 2 : (d[0] > 0) == (d[2] > 0) ? 1 : 0;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double a = t[i] + (t[k] - t[i]) * d[i] / (d[i] - d[k]);
    const double b = t[j] + (t[k] - t[j]) * d[j] / (d[j] - d[k]);
    lo = std::min(a, b);
    hi = std::max(a, b);
  };
  const Sides onP = sides(p1, p2, p3, q1, q2, q3);
  if (one_side(onP)) return TriangleMeet::Apart;
  const Sides onQ = sides(q1, q2, q3, p1, p2, p3);
  if (one_side(onQ)) return TriangleMeet::Apart;
  if (!clear(onP) || !clear(onQ)) return TriangleMeet::Unsure;
  const V D = onP.n.cross(onQ.n);
  if (D.norm() <= kMinPlaneSine * onP.n.norm() * onQ.n.norm()) return TriangleMeet::Unsure;
  const double tp[3] = {0.0, D.dot(p2 - p1), D.dot(p3 - p1)};
  const double tq[3] = {D.dot(q1 - p1), D.dot(q2 - p1), D.dot(q3 - p1)};
  double lo_p, hi_p, lo_q, hi_q;
  cut(tp, onQ.d, lo_p, hi_p);
  cut(tq, onP.d, lo_q, hi_q);
  const double overlap = std::min(hi_p, hi_q) - std::max(lo_p, lo_q);
  const double slack = kPlaneRoundOff * D.norm() * (onP.reach + onQ.reach);
  if (overlap > slack) return TriangleMeet::Intersect;
  if (overlap < -slack) return TriangleMeet::Apart;
  return TriangleMeet::Unsure;
}

// Per verdict of the reference, how many pairs gave it.
struct Verdicts {
  long apart = 0, intersect = 0, unsure = 0;
};

// Checks that triangles_meet gives the reference's verdict on P, Q (and Q, P), at scale `s` and
// offset `o` (every vertex x becomes s x + o).
void check_as_reference(const Tri& P0, const Tri& Q0, double s, const V& o, Verdicts& v) {
  Tri P, Q;
  for (int i = 0; i < 3; ++i) {
    P[i] = s * P0[i] + o;
    Q[i] = s * Q0[i] + o;
  }
  for (int swap = 0; swap < 2; ++swap) {
    const Tri& X = swap ? Q : P;
    const Tri& Y = swap ? P : Q;
    const TriangleMeet want = reference_meet(X[0], X[1], X[2], Y[0], Y[1], Y[2]);
    (want == TriangleMeet::Apart       ? v.apart
     : want == TriangleMeet::Intersect ? v.intersect
                                       : v.unsure)++;
    ASSERT_EQ(ours(X, Y), want) << "scale " << s << ", offset " << o.transpose() << "\nP "
                                << X[0].transpose() << " | " << X[1].transpose() << " | "
                                << X[2].transpose() << "\nQ " << Y[0].transpose() << " | "
                                << Y[1].transpose() << " | " << Y[2].transpose();
  }
}

// The bounds that spare triangles_meet its square roots change no verdict: on pairs built to sit
// at each of its thresholds (a vertex at 0.5 to 2 times the plane slack from the other's plane,
// with the other vertices on one side or across, or both triangles across each other's plane; the
// planes' sine at 0.5 to 2 times its least; the two segments' ends at 0.5 to 2 times the interval
// slack apart or overlapping), at scales from 1e-60 to 1e60, far from the origin, 1e160 apart, in
// random frames and in the one where the bounds are tightest, and on random pairs, every verdict is
// the reference's: Apart, Intersect and Unsure each met at every threshold.
TEST(TrianglesMeet, BoundsChangeNoVerdictAtTheThresholds) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  Verdicts v;
  const double ratios[] = {0.0, 0.5, 0.9, 0.99, 0.999, 1.001, 1.01, 1.1, 2.0};
  const double scales[] = {1.0, 1e-4, 1e4, 1e-60, 1e60};
  for (int k = 0; k < 300; ++k) {
    // every fourth frame the identity, where the bounds are tightest (|n|_1 = |n|)
    const Eigen::Matrix3d R =
        k % 4 == 0 ? Eigen::Matrix3d::Identity()
                   : Eigen::Quaterniond(Eigen::Vector4d(random_unit4(rng))).toRotationMatrix();
    const double s = scales[k % 5];
    const V o = (k % 3 == 0 ? 1e4 * s : 0.0) * random_unit(rng);
    // P in the plane z = 0 of a random frame
    const Tri P = {R * V(0, 0, 0), R * V(1, 0, 0), R * V(0, 1, 0)};
    for (const double ratio : ratios) {
      // Q's vertices at heights h, 7h, h above P (tilted, so that its plane cuts P), or at h,
      // -7h, h (across), with h `ratio` times P's plane slack for these triangles
      const double reach = 2 + V(2, 0.5, 0).norm();
      const double h = ratio * 1e-9 * reach;
      for (const double across : {1.0, -1.0}) {
        const Tri Q = {R * V(0.5, -1, h), R * V(2, 0.5, 7 * across * h), R * V(0.5, 2, h)};
        check_as_reference(P, Q, s, o, v);
      }
      // Q across P's plane, tilted by `ratio` times the least sine about a line through P
      // (every vertex of each clearly off the other's plane)
      const double tilt = std::tan(std::asin(ratio * 1e-3));
      auto on_tilt = [&](double x, double y) { return V(x, y, tilt * (y - 0.3)); };
      const Tri Qs = {R * on_tilt(-1, -0.5), R * on_tilt(1.5, -0.5), R * on_tilt(0.3, 2)};
      check_as_reference(P, Qs, s, o, v);
      // Q across P's plane and P across Q's (z = 1e-2 (x - 0.5)), one vertex of Q `ratio` times
      // the plane slack above P
      const double hq = ratio * 1e-9 * (2 + V(2, 0.5, 1.5e-2).norm());
      const Tri Qh = {R * V(0.5 + hq / 1e-2, -1, hq), R * V(2, 0.5, 1.5e-2),
                      R * V(-1, 0.8, -1.5e-2)};
      check_as_reference(P, Qh, s, o, v);
      // Q crossing P's plane along the line y = 0.3 with its segment ending `ratio` times the
      // interval slack beyond (or short of) P's segment end at x = 0.7 (P's edge x + y = 1)
      const double gap = ratio * 1e-9 * 4;
      for (const double side : {1.0, -1.0}) {
        const double x_end = 0.7 + side * gap;
        const Tri Qc = {R * V(x_end, 0.3, -0.5), R * V(x_end, 0.3, 0.5),
                        R * V(x_end + 1.0, 0.3 + 0.2 * u(rng), 0.1)};
        check_as_reference(P, Qc, s, o, v);
      }
      if (HasFatalFailure()) return;
    }
  }
  // Q so far from P (1e160) that the lengths' squares overflow while their bounds do not: the
  // computed slack is infinite, so no plane separates them.
  for (int k = 0; k < 100; ++k) {
    const Tri P = random_triangle(V::Zero(), 1.0, rng);
    const Tri Q = random_triangle(1e160 * random_unit(rng), 1.0, rng);
    check_as_reference(P, Q, 1.0, V::Zero(), v);
    if (HasFatalFailure()) return;
  }
  for (int k = 0; k < 100000; ++k) {
    const Tri P = random_triangle(V::Zero(), 1.0, rng);
    const Tri Q = random_triangle(0.8 * random_unit(rng), 1.0, rng);
    check_as_reference(P, Q, scales[k % 5], V::Zero(), v);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(v.apart, 1000);
  EXPECT_GT(v.intersect, 1000);
  EXPECT_GT(v.unsure, 100);
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
