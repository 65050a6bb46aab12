#include "engine/contact/triangle_meet.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace pcsg {
namespace {

// Where triangle Q lies against the plane of triangle P = (p1, p2, p3): `d` holds n . (q_i - p1)
// for P's normal n = (p2 - p1) x (p3 - p1); `slack` is kPlaneRoundOff of the lengths involved,
// far above the round-off of those products, so |d_i| > slack decides q_i's side for certain.
constexpr double kPlaneRoundOff = 1e-9;

// The tests below compare with lengths (norms) that cost a square root each, ten per pair of
// triangles. Each first compares with a bound on the computed length from the coordinates'
// absolute values: |v|_inf <= |v| <= |v|_1, the bound moved by kBoundRoom, far beyond the
// round-off of either computation (a few units of 1e-16). Only where the bound leaves the
// comparison open are the lengths computed, as the test always computed them: every verdict is
// the one the computed lengths give.
constexpr double kBoundRoom = 1e-12;
// Coordinates bounded only below this: their squares, summed, stay finite, so a computed norm
// cannot overflow to infinity past its upper bound.
constexpr double kNoOverflow = 1e150;
// A coordinate above this has a normal square, so a computed norm cannot underflow below its
// lower bound.
constexpr double kNoUnderflow = 1e-140;

double l1(const Eigen::Vector3d& v) { return v.cwiseAbs().sum(); }

struct PlaneSides {
  Eigen::Vector3d e1, e2, r[3];  // P's edges from p1, and q_i - p1
  Eigen::Vector3d n;
  double d[3];
  // |n|_1 and reach_1 = |e1|_1 + |e2|_1 + max |r_i|_1, the bounds of |n| and of the reach;
  // `bounded` where they are below kNoOverflow; slack_bound, an upper bound on the computed
  // slack from them (infinite where they do not hold).
  double n1 = 0, reach1 = 0, slack_bound = INFINITY;
  bool bounded = false;
  // kPlaneRoundOff * |n| * reach, with reach = |e1| + |e2| + max |r_i|, computed only where a
  // verdict needs them (have_slack).
  double slack = 0, reach = 0;
  bool have_slack = false;
  void compute_slack() {
    if (have_slack) return;
    reach = e1.norm() + e2.norm() + std::max({r[0].norm(), r[1].norm(), r[2].norm()});
    slack = kPlaneRoundOff * n.norm() * reach;
    have_slack = true;
  }
  // All three points clearly on one side (every d_i > slack, or every d_i < -slack): the
  // triangles cannot meet.
  bool one_side() {
    const bool above = d[0] > 0 && d[1] > 0 && d[2] > 0;
    const bool below = d[0] < 0 && d[1] < 0 && d[2] < 0;
    if (!above && !below) return false;
    const double least = std::min({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
    if (least > slack_bound) return true;
    compute_slack();
    return least > slack;
  }
  // no point within round-off of the plane
  bool clear() {
    const double b = slack_bound;
    if (std::abs(d[0]) > b && std::abs(d[1]) > b && std::abs(d[2]) > b) return true;
    compute_slack();
    return std::abs(d[0]) > slack && std::abs(d[1]) > slack && std::abs(d[2]) > slack;
  }
};

PlaneSides plane_sides(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                       const Eigen::Vector3d& p3, const Eigen::Vector3d& q1,
                       const Eigen::Vector3d& q2, const Eigen::Vector3d& q3) {
  PlaneSides s;
  s.e1 = p2 - p1;
  s.e2 = p3 - p1;
  s.n = s.e1.cross(s.e2);
  s.r[0] = q1 - p1;
  s.r[1] = q2 - p1;
  s.r[2] = q3 - p1;
  for (int i = 0; i < 3; ++i) s.d[i] = s.n.dot(s.r[i]);
  s.n1 = l1(s.n);
  s.reach1 = l1(s.e1) + l1(s.e2) + std::max({l1(s.r[0]), l1(s.r[1]), l1(s.r[2])});
  s.bounded = s.n1 < kNoOverflow && s.reach1 < kNoOverflow;
  if (s.bounded) s.slack_bound = kPlaneRoundOff * s.n1 * s.reach1 * (1 + kBoundRoom);
  return s;
}

// The segment a triangle (x1, x2, x3) cuts from the other triangle's plane, as an interval of
// the planes' common line (coordinates t_i = D . x_i), given the vertices' signed distances
// `d` from that plane, none zero and not all of one sign.
void plane_cut(const double t[3], const double d[3], double& lo, double& hi) {
  // the vertex alone on its side of the plane
  const int k = (d[0] > 0) == (d[1] > 0) ? 2 : (d[0] > 0) == (d[2] > 0) ? 1 : 0;
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double a = t[i] + (t[k] - t[i]) * d[i] / (d[i] - d[k]);
  const double b = t[j] + (t[k] - t[j]) * d[j] / (d[j] - d[k]);
  lo = std::min(a, b);
  hi = std::max(a, b);
}

// Planes this close to parallel (sine of their angle) leave the interval test to FCL's: the
// common line's direction is then ill-conditioned.
constexpr double kMinPlaneSine = 1e-3;

}  // namespace

// Whether triangles P and Q (both in one frame) meet: the interval test (Moller 1997) where
// round-off cannot change its answer. Each triangle crossing the other's plane cuts a
// segment of the planes' common line; two triangles in general position meet exactly when
// these segments overlap. Apart across a plane: with the margins of `one_side`; the segments
// overlapping or apart by more than kPlaneRoundOff of the lengths along the line: decided;
// otherwise (a vertex within round-off of a plane, nearly parallel planes, segments ending
// within round-off of each other) Unsure, and FCL's own test decides.
TriangleMeet triangles_meet(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Eigen::Vector3d& p3, const Eigen::Vector3d& q1,
                            const Eigen::Vector3d& q2, const Eigen::Vector3d& q3) {
  PlaneSides onP = plane_sides(p1, p2, p3, q1, q2, q3);
  if (onP.one_side()) return TriangleMeet::Apart;
  PlaneSides onQ = plane_sides(q1, q2, q3, p1, p2, p3);
  if (onQ.one_side()) return TriangleMeet::Apart;
  if (!onP.clear() || !onQ.clear()) return TriangleMeet::Unsure;
  const Eigen::Vector3d D = onP.n.cross(onQ.n);
  const double D1 = l1(D);
  const bool bounded = onP.bounded && onQ.bounded && D1 < kNoOverflow;
  // |D| > kMinPlaneSine |n_P| |n_Q| for certain where |D|_inf exceeds the bound of the right side
  const double D_inf = D.cwiseAbs().maxCoeff();
  if (!bounded ||
      !(D_inf > kNoUnderflow && D_inf > kMinPlaneSine * onP.n1 * onQ.n1 * (1 + kBoundRoom))) {
    const double nn = onP.n.norm() * onQ.n.norm();
    if (D.norm() <= kMinPlaneSine * nn) return TriangleMeet::Unsure;
  }
  // coordinates along D from p1, so that they scale with the triangles, not with the frame
  const double tp[3] = {0.0, D.dot(p2 - p1), D.dot(p3 - p1)};
  const double tq[3] = {D.dot(q1 - p1), D.dot(q2 - p1), D.dot(q3 - p1)};
  double lo_p, hi_p, lo_q, hi_q;
  plane_cut(tp, onQ.d, lo_p, hi_p);
  plane_cut(tq, onP.d, lo_q, hi_q);
  const double overlap = std::min(hi_p, hi_q) - std::max(lo_p, lo_q);
  if (bounded) {
    const double bound = kPlaneRoundOff * D1 * (onP.reach1 + onQ.reach1) * (1 + kBoundRoom);
    if (overlap > bound) return TriangleMeet::Intersect;
    if (overlap < -bound) return TriangleMeet::Apart;
  }
  onP.compute_slack();
  onQ.compute_slack();
  const double slack = kPlaneRoundOff * D.norm() * (onP.reach + onQ.reach);
  if (overlap > slack) return TriangleMeet::Intersect;
  if (overlap < -slack) return TriangleMeet::Apart;
  return TriangleMeet::Unsure;
}

}  // namespace pcsg
