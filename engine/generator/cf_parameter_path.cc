#include "engine/generator/cf_parameter_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/contact/element_geometry.h"
#include "engine/generator/motion_drive.h"
#include "engine/generator/state_identity.h"

namespace pcsg {
namespace {

// Largest change of the twist or of a normal's place in its cone between two waypoints:
// small enough that the straight travel between them (connected_within_cf) stays near the
// planned path.
constexpr double kMaxPieceTurn = M_PI / 12;
// Largest shift of a contact point along its element between two waypoints, in A's sizes
// (half its bounding-box diagonal, as for motions).
constexpr double kMaxPieceShiftSizes = 0.25;
// Near e-e-touch each turn is at most this factor - 1 times the crossing angle's distance
// from it; the walk proper starts at a crossing angle at least kSafeCrossing from it.
constexpr double kTouchGrowth = 1.5;
constexpr double kSafeCrossing = M_PI / 6;
// An edge's normal on the walk stays kOffBoundary of its cone's angle inside the cone at the
// walk's ends (a normal on the boundary is as much the neighbouring face's: the waypoints
// there were detected as that face's contact, Example 2's lens rim on the dish rim) and
// kSafeCone inside it midway (the cone's counterpart of kSafeCrossing).
constexpr double kOffBoundary = 1e-2;
constexpr double kSafeCone = 1.0 / 6;
// More pieces than this: the path is too long to be worth its motions.
constexpr int kMaxPieces = 48;
// Newton iterations that put a point back on its element's surfaces after a piece.
constexpr int kSnapIterations = 20;
// A vector whose part normal to n is below this fraction of its length is taken as along n
// (its tangent direction is then numerically meaningless).
constexpr double kAlongNormalFraction = 1e-3;

bool plane_type(PtcType t) {
  return t == PtcType::FF || t == PtcType::FE || t == PtcType::EF || t == PtcType::EECross;
}

double signed_angle(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                    const Eigen::Vector3d& axis) {
  return std::atan2(axis.dot(from.cross(to)), from.dot(to));
}

// `v` made a unit vector normal to the unit `n`; another such vector when v is along n.
Eigen::Vector3d tangent_part(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  const Eigen::Vector3d t = v - v.dot(n) * n;
  return t.norm() > kAlongNormalFraction * v.norm() ? Eigen::Vector3d(t.normalized())
                                                    : n.unitOrthogonal();
}

// p moved onto the surfaces of element `el` (least-norm Newton steps).
Eigen::Vector3d snapped(const Solid& S, ElementId el, Eigen::Vector3d p, double residual) {
  const SurfaceSet set = element_surfaces(S, el);
  for (int it = 0; it < kSnapIterations; ++it) {
    Eigen::MatrixXd J(set.size, 3);
    Eigen::VectorXd g(set.size);
    for (int i = 0; i < set.size; ++i) {
      const SurfaceJet j = SurfaceJet::at(S.surfaces[set.index[i]], p);
      J.row(i) = j.gradient.transpose() / j.gradient_norm;
      g(i) = j.distance_estimate();
    }
    if (g.cwiseAbs().maxCoeff() <= residual) break;
    p -= J.transpose() * (J * J.transpose()).ldlt().solve(g);
  }
  return p;
}

// The normal cone of edge `el` at p: the outward normals of its two surfaces and the unit
// axis about which the first turns into the second (along the tangent or against it).
struct EdgeCone {
  Eigen::Vector3d n1, axis;
  double angle = 0;
};
EdgeCone edge_cone(const Solid& S, int edge, const Eigen::Vector3d& p) {
  const Edge& e = S.edges[edge];
  EdgeCone c;
  c.n1 = SurfaceJet::at(S.surfaces[e.surface1], p).normal;
  const Eigen::Vector3d n2 = SurfaceJet::at(S.surfaces[e.surface2], p).normal;
  const Eigen::Vector3d x = c.n1.cross(n2);
  c.angle = std::atan2(x.norm(), c.n1.dot(n2));
  c.axis = x.norm() > 0 ? Eigen::Vector3d(x.normalized()) : edge_jet(S, edge, p).tangent;
  return c;
}
// Where the normal m lies in the cone: 0 at the first surface's normal, 1 at the second's.
double cone_fraction(const EdgeCone& c, const Eigen::Vector3d& m) {
  return c.angle > 0 ? signed_angle(c.n1, m, c.axis) / c.angle : 0.0;
}

// Arc length of p along edge e (its nearest sample's, moved along the tangent there).
double arc_length(const Edge& e, const Eigen::Vector3d& p) {
  size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < e.samples.size(); ++i) {
    const double d = (e.samples[i].point - p).squaredNorm();
    if (d < best_d) best = i, best_d = d;
  }
  return e.samples[best].s + e.samples[best].tangent.dot(p - e.samples[best].point);
}
// The point of edge e at arc length s (between samples, then onto the edge).
Eigen::Vector3d edge_point(const Solid& S, int edge, double s, double residual) {
  const Edge& e = S.edges[edge];
  if (e.closed) s -= e.length * std::floor(s / e.length);
  s = std::clamp(s, e.samples.front().s, e.samples.back().s);
  const auto it = std::lower_bound(e.samples.begin(), e.samples.end(), s,
                                   [](const CurveSample& c, double v) { return c.s < v; });
  const size_t j = std::clamp<size_t>(it - e.samples.begin(), 1, e.samples.size() - 1);
  const CurveSample &lo = e.samples[j - 1], &hi = e.samples[j];
  const double f = hi.s > lo.s ? (s - lo.s) / (hi.s - lo.s) : 0.0;
  return snapped(S, {ElementKind::Edge, edge}, (1 - f) * lo.point + f * hi.point, residual);
}

// One side's path: points on its element, its outward normals and reference tangents, from
// the chart of witness a (index 0) to the target's (index n).
struct SidePath {
  std::vector<Eigen::Vector3d> point, normal, ref;
};

// How many pieces one side needs (point shift and cone turn), at least 1.
int side_pieces(const Solid& S, ElementId el, const Eigen::Vector3d& p0, const Eigen::Vector3d& m0,
                const Eigen::Vector3d& p1, const Eigen::Vector3d& m1, double max_shift) {
  double shift = (p1 - p0).norm(), turn = 0;
  if (el.kind == ElementKind::Edge) {
    const Edge& e = S.edges[el.index];
    double ds = arc_length(e, p1) - arc_length(e, p0);
    if (e.closed) ds -= e.length * std::round(ds / e.length);
    shift = std::abs(ds);
    const EdgeCone c0 = edge_cone(S, el.index, p0), c1 = edge_cone(S, el.index, p1);
    turn = std::abs(cone_fraction(c1, m1) * c1.angle - cone_fraction(c0, m0) * c0.angle);
  } else {
    turn = std::acos(std::clamp(m0.dot(m1), -1.0, 1.0));
  }
  return std::max(1,
                  static_cast<int>(std::ceil(std::max(shift / max_shift, turn / kMaxPieceTurn))));
}

SidePath side_path(const Solid& S, ElementId el, const Eigen::Vector3d& p0,
                   const Eigen::Vector3d& m0, const Eigen::Vector3d& r0, const Eigen::Vector3d& p1,
                   const Eigen::Vector3d& m1, int n, double residual) {
  SidePath path;
  path.point.push_back(p0);
  path.normal.push_back(m0);
  path.ref.push_back(r0);
  if (el.kind == ElementKind::Edge) {
    const Edge& e = S.edges[el.index];
    const double s0 = arc_length(e, p0);
    double ds = arc_length(e, p1) - s0;
    if (e.closed) ds -= e.length * std::round(ds / e.length);  // the shorter way round
    // The normal's place in the cone: kOffBoundary inside it at both ends (index 0 and n
    // too: a witness whose normal lies on the cone's boundary, where a transition from a face
    // contact left it, is reached from there by a motion) and up to kSafeCone inside it
    // midway.
    auto inside = [](double f) { return std::clamp(f, kOffBoundary, 1 - kOffBoundary); };
    const double f0 = inside(cone_fraction(edge_cone(S, el.index, p0), m0));
    const double f1 = inside(cone_fraction(edge_cone(S, el.index, p1), m1));
    auto fraction = [&](double t) {
      const double margin = kSafeCone * std::sin(M_PI * t);
      return std::clamp((1 - t) * f0 + t * f1, margin, 1 - margin);
    };
    const EdgeCone c0 = edge_cone(S, el.index, p0);
    path.normal[0] = Eigen::AngleAxisd(f0 * c0.angle, c0.axis) * c0.n1;
    path.ref[0] = tangent_part(edge_jet(S, el.index, p0).tangent, path.normal[0]);
    for (int k = 1; k <= n; ++k) {
      const double t = static_cast<double>(k) / n;
      const Eigen::Vector3d p = k == n ? p1 : edge_point(S, el.index, s0 + t * ds, residual);
      const EdgeCone c = edge_cone(S, el.index, p);
      const Eigen::Vector3d m = Eigen::AngleAxisd(fraction(t) * c.angle, c.axis) * c.n1;
      path.point.push_back(p);
      path.normal.push_back(m);
      path.ref.push_back(tangent_part(edge_jet(S, el.index, p).tangent, m));
    }
    return path;
  }
  // A face: the point walks toward p1 over the surface; the reference tangent is carried
  // along by the least turn of the normal (so the twist measured against it is continuous).
  for (int k = 1; k <= n; ++k) {
    const Eigen::Vector3d& p = path.point.back();
    const Eigen::Vector3d& m = path.normal.back();
    const Eigen::Vector3d q =
        k == n
            ? p1
            : snapped(S, el, p + step_toward_on_element(S, el, p, p1, m) / (n - k + 1), residual);
    const Eigen::Vector3d mq = k == n ? m1 : face_normal(S, el.index, q);
    const Eigen::Vector3d r = Eigen::Quaterniond::FromTwoVectors(m, mq) * path.ref.back();
    path.point.push_back(q);
    path.normal.push_back(mq);
    path.ref.push_back(tangent_part(r, mq));
  }
  return path;
}

// A face's initial reference tangent: the coordinate axis farthest from its normal, made
// tangent (any tangent serves; it is carried along the path).
Eigen::Vector3d face_reference(const Eigen::Vector3d& n) {
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  return tangent_part(Eigen::Vector3d::Unit(axis), n);
}

bool moved_either_way(const SceneGeometry& scene, const Pose& a, const Pose& b,
                      const ContactFormation& cf, MotionCounters& counters) {
  return connected_within_cf(scene, a, b, cf, counters) ||
         connected_within_cf(scene, b, a, cf, counters);
}

// The contact of `contacts` of the pair and type of `c` whose point on A is nearest c's.
const PointContact* matching(const std::vector<PointContact>& contacts, const PointContact& c) {
  const PointContact* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (const PointContact& d : contacts) {
    if (!(d.a == c.a && d.b == c.b && d.type == c.type)) continue;
    const double dist = (d.p_A - c.p_A).norm();
    if (dist < best_d) best = &d, best_d = dist;
  }
  return best;
}

// An e-e-cross's distance from e-e-touch: its crossing angle's distance to 0 or pi.
double from_touch(double twist) { return std::min(std::abs(twist), M_PI - std::abs(twist)); }

// Twists from `from` toward `to` (one crossing sign, `to` farther from e-e-touch), each piece
// at most kMaxPieceTurn and at most kTouchGrowth - 1 times the distance from e-e-touch: near
// it a turn moves the crossing point along the nearly parallel edges by the turn over the
// angle, so the pieces there are that much shorter. Ends with `to`.
std::vector<double> away_from_touch(double from, double to) {
  std::vector<double> twists;
  const double sign = from < 0 ? -1 : 1;
  double d = from_touch(from);
  if (d <= 0) return {to};  // at e-e-touch: not an e-e-cross (no walk leaves it this way)
  const double d_to = from_touch(to);
  // which way |twist| grows away from the touch at 0 (up) or at pi (down)
  const double dir = std::abs(from) < M_PI / 2 ? 1 : -1;
  const double base = dir > 0 ? 0 : M_PI;
  while (d < d_to) {
    d = std::min({d * kTouchGrowth, d + kMaxPieceTurn, d_to});
    twists.push_back(sign * (base + dir * d));
  }
  if (twists.empty() || twists.back() != to) twists.push_back(to);
  return twists;
}

// The walk along one contact's parameters from a (contact ca) to the target (contact cb).
// An e-e-cross first turns about its normal away from e-e-touch (to a crossing angle of at
// least kSafeCrossing), then moves all parameters together, then turns to the target's angle.
bool walk(const SceneGeometry& scene, const Pose& a, const PointContact& ca, const Pose& target,
          const PointContact& cb, const ContactFormation& cf, const RegionSignature& signature,
          MotionCounters& counters) {
  // the size motions measure with (twist_frame.h)
  const double size = ReferenceBody(scene).size;
  const double residual = scene.tol.solve_residual;
  const ContactChart c0 =
      chart_of(scene, a, ca, face_reference(normal_in_A(a, ca)), face_reference(ca.normal_B));
  const ContactChart c1 = chart_of(scene, target, cb, face_reference(normal_in_A(target, cb)),
                                   face_reference(cb.normal_B));
  const double max_shift = kMaxPieceShiftSizes * size;
  const bool cross = ca.type == PtcType::EECross;
  // A twist moved away from e-e-touch to the safe crossing angle (its sign kept).
  auto safe = [&](double twist) {
    if (!cross) return twist;
    return std::copysign(std::clamp(std::abs(twist), kSafeCrossing, M_PI - kSafeCrossing), twist);
  };
  const double t0 = safe(c0.twist);
  int n = std::max(side_pieces(scene.A, ca.a, c0.p_A, c0.normal_A, c1.p_A, c1.normal_A, max_shift),
                   side_pieces(scene.B, ca.b, c0.p_B, c0.normal_B, c1.p_B, c1.normal_B, max_shift));
  // (a second pass when the twist asks for more pieces than the points and normals)
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (n > kMaxPieces) return false;
    // Every other point of the side paths is a waypoint; those between serve as half-way
    // waypoints where a whole piece fails.
    const int sub = 2 * n;
    const SidePath A =
        side_path(scene.A, ca.a, c0.p_A, c0.normal_A, c0.ref_A, c1.p_A, c1.normal_A, sub, residual);
    const SidePath B =
        side_path(scene.B, ca.b, c0.p_B, c0.normal_B, c0.ref_B, c1.p_B, c1.normal_B, sub, residual);
    // The target's twist against the references carried to it.
    const double t_end = signed_angle(B.ref.back(), target.rotate(A.ref.back()), c1.normal_B);
    const double t1 = safe(t_end);
    double turn = t1 - t0;
    // An e-e-cross keeps its crossing sign: both twists lie in one open half turn, and the
    // straight interpolation stays in it (never at 0 or pi, e-e-touch). Otherwise the
    // shorter way round.
    if (!cross) turn -= 2 * M_PI * std::round(turn / (2 * M_PI));
    const int need = static_cast<int>(std::ceil(std::abs(turn) / kMaxPieceTurn));
    if (need > n && attempt == 0) {
      n = need;
      continue;
    }
    // The waypoints: (side path index, twist), each with its half-way one.
    struct Step {
      int index;
      double twist;
      int half_index;
      double half_twist;
    };
    std::vector<Step> steps;
    double prev = c0.twist;
    for (double t : away_from_touch(c0.twist, t0)) {
      if (t == c0.twist) continue;
      steps.push_back({0, t, 0, 0.5 * (prev + t)});
      prev = t;
    }
    for (int j = 2; j <= sub; j += 2)
      steps.push_back({j, t0 + turn * j / sub, j - 1, t0 + turn * (j - 1) / sub});
    std::vector<double> back = away_from_touch(t_end, t1);
    std::reverse(back.begin(), back.end());
    prev = t1;
    for (size_t k = 1; k < back.size(); ++k) {
      steps.push_back({sub, back[k], sub, 0.5 * (prev + back[k])});
      prev = back[k];
    }
    auto waypoint = [&](int j, double twist) -> std::optional<Pose> {
      ContactChart w;
      w.p_A = A.point[j];
      w.p_B = B.point[j];
      w.normal_A = A.normal[j];
      w.normal_B = B.normal[j];
      w.ref_A = A.ref[j];
      w.ref_B = B.ref[j];
      w.twist = twist;
      ++counters.detections;
      const ProjectionResult proj = project_onto_cf(scene, pose_of_chart(w), cf);
      if (!proj.ok || region_signature(proj.contacts) != signature) return std::nullopt;
      return proj.pose;
    };
    Pose at = a;
    for (size_t k = 0; k < steps.size(); ++k) {
      const Step& st = steps[k];
      const bool last = k + 1 == steps.size();
      // the last waypoint is the target itself
      const std::optional<Pose> next =
          last ? std::optional<Pose>(target) : waypoint(st.index, st.twist);
      if (next && moved_either_way(scene, at, *next, cf, counters)) {
        at = *next;
        continue;
      }
      // The piece in two halves; a waypoint that is not on the CF is passed over.
      const std::optional<Pose> half = waypoint(st.half_index, st.half_twist);
      if (half && moved_either_way(scene, at, *half, cf, counters)) {
        at = *half;
        if (next && moved_either_way(scene, at, *next, cf, counters)) {
          at = *next;
          continue;
        }
      }
      if (!next && !last) continue;  // the next piece starts from `at`
      return false;
    }
    return true;
  }
  return false;
}

}  // namespace

Pose pose_of_chart(const ContactChart& chart) {
  const Eigen::Vector3d m = chart.normal_A.normalized();
  const Eigen::Vector3d r = tangent_part(chart.ref_A, m);
  const Eigen::Vector3d nB = -chart.normal_B.normalized();
  const Eigen::Vector3d rB =
      Eigen::AngleAxisd(chart.twist, chart.normal_B.normalized()) * tangent_part(chart.ref_B, nB);
  Eigen::Matrix3d FA, FB;
  FA << m, r, m.cross(r);
  FB << nB, rB, nB.cross(rB);
  Pose X;
  X.quaternion = Eigen::Quaterniond(Eigen::Matrix3d(FB * FA.transpose())).normalized();
  X.position = chart.p_B - X.rotate(chart.p_A);
  return X;
}

ContactChart chart_of(const SceneGeometry& scene, const Pose& X, const PointContact& c,
                      const Eigen::Vector3d& face_ref_A, const Eigen::Vector3d& face_ref_B) {
  ContactChart chart;
  chart.p_A = c.p_A;
  chart.p_B = c.p_B;
  chart.normal_B = c.normal_B;
  chart.normal_A = normal_in_A(X, c);
  chart.ref_A = tangent_part(
      c.a.kind == ElementKind::Edge ? edge_jet(scene.A, c.a.index, c.p_A).tangent : face_ref_A,
      chart.normal_A);
  chart.ref_B = tangent_part(
      c.b.kind == ElementKind::Edge ? edge_jet(scene.B, c.b.index, c.p_B).tangent : face_ref_B,
      chart.normal_B);
  chart.twist = signed_angle(chart.ref_B, X.rotate(chart.ref_A), chart.normal_B);
  return chart;
}

bool joined_by_parameter_path(const SceneGeometry& scene, const Pose& a, const Pose& b,
                              const ContactFormation& cf, MotionCounters& counters,
                              const SceneSymmetry& symmetry) {
  ++counters.detections;
  const ContactReport ra = detect_contacts(scene, a);
  if (ra.penetrating() || !(ContactFormation::of(ra.contacts) == cf)) return false;
  const RegionSignature signature = region_signature(ra.contacts);
  for (const Pose& target : symmetric_images(b, symmetry)) {
    ++counters.detections;
    const ContactReport rb = detect_contacts(scene, target);
    if (rb.penetrating() || !(ContactFormation::of(rb.contacts) == cf) ||
        region_signature(rb.contacts) != signature)
      continue;
    // From a, and from a turned by the solids' symmetries toward the target (the turns keep
    // every contact: a point of a's region).
    std::vector<std::pair<Pose, std::vector<PointContact>>> starts = {{a, ra.contacts}};
    if (symmetry.A || symmetry.B) {
      const Pose t = aligned_by_symmetry(scene, a, target, symmetry);
      ++counters.detections;
      const ContactReport rt = detect_contacts(scene, t);
      if (!rt.penetrating() && ContactFormation::of(rt.contacts) == cf &&
          region_signature(rt.contacts) == signature)
        starts.push_back({t, rt.contacts});
    }
    for (const auto& [start, contacts] : starts)
      for (const PointContact& ca : contacts) {
        if (!plane_type(ca.type)) continue;
        const PointContact* cb = matching(rb.contacts, ca);
        if (cb && walk(scene, start, ca, target, *cb, cf, signature, counters)) return true;
      }
  }
  return false;
}

}  // namespace pcsg
