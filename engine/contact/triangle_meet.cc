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
struct PlaneSides {
  Eigen::Vector3d n;
  double d[3];
  double slack;
  // all three points clearly on one side: the triangles cannot meet
  bool one_side() const {
    return (d[0] > slack && d[1] > slack && d[2] > slack) ||
           (d[0] < -slack && d[1] < -slack && d[2] < -slack);
  }
  // no point within round-off of the plane
  bool clear() const {
    return std::abs(d[0]) > slack && std::abs(d[1]) > slack && std::abs(d[2]) > slack;
  }
};

PlaneSides plane_sides(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                       const Eigen::Vector3d& p3, const Eigen::Vector3d& q1,
                       const Eigen::Vector3d& q2, const Eigen::Vector3d& q3, double& reach) {
  const Eigen::Vector3d e1 = p2 - p1, e2 = p3 - p1;
  PlaneSides s;
  s.n = e1.cross(e2);
  const Eigen::Vector3d r1 = q1 - p1, r2 = q2 - p1, r3 = q3 - p1;
  s.d[0] = s.n.dot(r1);
  s.d[1] = s.n.dot(r2);
  s.d[2] = s.n.dot(r3);
  reach = e1.norm() + e2.norm() + std::max({r1.norm(), r2.norm(), r3.norm()});
  s.slack = kPlaneRoundOff * s.n.norm() * reach;
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
  double reach_p, reach_q;
  const PlaneSides onP = plane_sides(p1, p2, p3, q1, q2, q3, reach_p);
  if (onP.one_side()) return TriangleMeet::Apart;
  const PlaneSides onQ = plane_sides(q1, q2, q3, p1, p2, p3, reach_q);
  if (onQ.one_side()) return TriangleMeet::Apart;
  if (!onP.clear() || !onQ.clear()) return TriangleMeet::Unsure;
  const Eigen::Vector3d D = onP.n.cross(onQ.n);
  const double nn = onP.n.norm() * onQ.n.norm();
  if (D.norm() <= kMinPlaneSine * nn) return TriangleMeet::Unsure;
  // coordinates along D from p1, so that they scale with the triangles, not with the frame
  const double tp[3] = {0.0, D.dot(p2 - p1), D.dot(p3 - p1)};
  const double tq[3] = {D.dot(q1 - p1), D.dot(q2 - p1), D.dot(q3 - p1)};
  double lo_p, hi_p, lo_q, hi_q;
  plane_cut(tp, onQ.d, lo_p, hi_p);
  plane_cut(tq, onP.d, lo_q, hi_q);
  const double overlap = std::min(hi_p, hi_q) - std::max(lo_p, lo_q);
  const double slack = kPlaneRoundOff * D.norm() * (reach_p + reach_q);
  if (overlap > slack) return TriangleMeet::Intersect;
  if (overlap < -slack) return TriangleMeet::Apart;
  return TriangleMeet::Unsure;
}

}  // namespace pcsg
