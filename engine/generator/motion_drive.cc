#include "engine/generator/motion_drive.h"

#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "engine/contact/pair_solver.h"
#include "engine/geometry/surface.h"

namespace pcsg {

Eigen::Vector3d normal_in_A(const Pose& X, const PointContact& c) {
  return -(X.quaternion.conjugate() * c.normal_B);
}

std::optional<PointContact> track_pair(const SceneGeometry& scene, const Pose& X,
                                       ElementId a, ElementId b, PtcType type,
                                       const Eigen::Vector3d& start_A,
                                       const Eigen::Vector3d& start_B) {
  PairSolution sol = solve_pair_problem(scene, X, a, b, type, start_A, start_B);
  if (!sol.converged) return std::nullopt;
  return std::move(sol.contact);
}

std::optional<ContactRates> contact_rates(const SceneGeometry& scene, const Pose& X,
                                          const TwistFrame& frame, const PointContact& c,
                                          long& pair_solves) {
  // One-sided differences: a perturbation that leaves the element is retried on the other side.
  const double eps = scene.tol.rate_step;
  ContactRates r;
  const Eigen::Vector3d nA0 = normal_in_A(X, c);
  for (int i = 0; i < 6; ++i) {
    std::optional<PointContact> moved;
    double h = eps;
    for (double sign : {1.0, -1.0}) {
      Twist s = Twist::Zero();
      s[i] = sign * eps;
      const Pose Xi = frame.apply(X, s);
      ++pair_solves;
      moved = track_pair(scene, Xi, c.a, c.b, c.type, c.p_A, c.p_B);
      if (moved) {
        h = sign * eps;
        r.normal_A.col(i) = (normal_in_A(Xi, *moved) - nA0) / h;
        break;
      }
    }
    if (!moved) return std::nullopt;
    r.point_A.col(i) = (moved->p_A - c.p_A) / h;
    r.point_B.col(i) = (moved->p_B - c.p_B) / h;
    r.normal_B.col(i) = (moved->normal_B - c.normal_B) / h;
  }
  return r;
}

void DriveSystem::add_hard(const Eigen::MatrixXd& rows) {
  for (int i = 0; i < rows.rows(); ++i) hard.push_back(rows.row(i));
}

void DriveSystem::add_drive(const Eigen::MatrixXd& rows, const Eigen::VectorXd& t, double weight) {
  for (int i = 0; i < rows.rows(); ++i) {
    drive.push_back(rows.row(i) * weight);
    target.push_back(t[i] * weight);
  }
}

namespace {

// Orthonormal basis of the null space of the stacked rows (6 x k).
Eigen::MatrixXd null_space(const std::vector<Eigen::Matrix<double, 1, 6>>& rows) {
  if (rows.empty()) return Eigen::MatrixXd::Identity(6, 6);
  Eigen::MatrixXd C(rows.size(), 6);
  for (size_t i = 0; i < rows.size(); ++i) C.row(i) = rows[i];
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  // Rank threshold relative to the largest singular value: rows are contact normals and
  // moments of unit size, so 1e-9 separates true dependence from round-off (~1e-15).
  constexpr double kRankRelative = 1e-9;
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i)
    if (sv[i] > kRankRelative * std::max(sv[0], 1e-300)) ++rank;
  return svd.matrixV().rightCols(6 - rank);
}

}  // namespace

std::optional<Twist> DriveSystem::solve() const {
  // Eigen's JacobiSVD reads out of bounds on non-finite input (pair_touch.cc): a row from a
  // degenerate point (an edge's faces tangent there) gives no drive.
  for (const auto& r : hard)
    if (!r.allFinite()) return std::nullopt;
  for (size_t i = 0; i < drive.size(); ++i)
    if (!drive[i].allFinite() || !std::isfinite(target[i])) return std::nullopt;
  const Eigen::MatrixXd N = null_space(hard);
  if (N.cols() == 0 || drive.empty()) return std::nullopt;
  Eigen::MatrixXd D(drive.size(), 6);
  Eigen::VectorXd t(drive.size());
  for (size_t i = 0; i < drive.size(); ++i) {
    D.row(i) = drive[i];
    t[i] = target[i];
  }
  const Eigen::MatrixXd DN = D * N;
  // Drive rows are finite-difference rates (contact_rates) whose geometric rank deficiencies
  // (a point on a surface moves in its tangent plane, a unit normal turns perpendicular to
  // itself) show as singular values at their noise level, ~solve_residual / rate_step = 1e-5
  // of the largest: inverting those amplifies the noise into an O(1) part of the twist, which
  // differs with the scene's frame (Example 1 rotated: step-0 twists differed by O(1)), and
  // spends the step on a direction no motion gives (three spheres: a contact sliding along an
  // edge toward its vertex moved 3e-4 of a step per step). Singular values below 1e-3 of the
  // largest are dropped (100x above that noise; a drive that weak is no drive).
  constexpr double kDriveRankRelative = 1e-3;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(DN, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(kDriveRankRelative);
  const Eigen::VectorXd z = svd.solve(t);
  const Twist s = N * z;
  // Progress: the drive residual must drop; otherwise the kept contacts forbid this drive.
  const double before = t.norm(), after = (D * s - t).norm();
  constexpr double kMinProgress = 1e-6;  // relative decrease of the drive residual
  if (!(before - after > kMinProgress * before) || !s.allFinite()) return std::nullopt;
  return s;
}

Twist minimum_norm_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  // no step from non-finite rows (read out of bounds by Eigen's pivoting QR otherwise)
  if (!J.allFinite() || !r.allFinite()) return Twist::Zero();
  const Eigen::VectorXd d = J.completeOrthogonalDecomposition().solve(-r);
  return d;
}

namespace {

int nearest_sample(const Edge& e, const Eigen::Vector3d& x) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < e.samples.size(); ++i) {
    const double d = (e.samples[i].point - x).squaredNorm();
    if (d < best_d) best = static_cast<int>(i), best_d = d;
  }
  return best;
}

}  // namespace

Eigen::Vector3d step_toward_on_element(const Solid& S, ElementId el, const Eigen::Vector3d& x,
                                       const Eigen::Vector3d& target, const Eigen::Vector3d& n) {
  const Eigen::Vector3d chord = target - x;
  if (el.kind == ElementKind::Vertex) return Eigen::Vector3d::Zero();
  if (el.kind == ElementKind::Edge) {
    const Edge& e = S.edges[el.index];
    if (e.samples.size() < 2) return chord;
    const int i = nearest_sample(e, x), j = nearest_sample(e, target);
    double ds = e.samples[j].s - e.samples[i].s;
    if (e.closed) {
      // The shorter way round.
      if (ds > 0.5 * e.length) ds -= e.length;
      if (ds < -0.5 * e.length) ds += e.length;
    }
    Eigen::Vector3d t = e.samples[i].tangent;
    return t * ds;
  }
  const Eigen::Vector3d proj = chord - chord.dot(n) * n;
  // Projected chord shorter than this fraction of the chord: the target is nearly opposite.
  constexpr double kOppositeFraction = 0.3;
  if (proj.norm() >= kOppositeFraction * chord.norm()) return proj;
  Eigen::Vector3d side = n.cross(chord);
  if (side.norm() == 0) side = n.unitOrthogonal();
  return proj + side.normalized() * chord.norm();
}

ElementId nearest_boundary(const Solid& S, ElementId face, const Eigen::Vector3d& x) {
  ElementId best = face;
  double best_d = std::numeric_limits<double>::infinity();
  for (int e : S.faces[face.index].edges) {
    const Edge& edge = S.edges[e];
    if (edge.samples.empty()) continue;
    const double d = (edge.samples[nearest_sample(edge, x)].point - x).norm();
    if (d < best_d) best = {ElementKind::Edge, e}, best_d = d;
  }
  return best;
}

int element_dimension(ElementId el) {
  return el.kind == ElementKind::Face ? 2 : el.kind == ElementKind::Edge ? 1 : 0;
}

Eigen::Vector3d face_normal(const Solid& S, int face, const Eigen::Vector3d& x) {
  return S.surfaces[S.faces[face].surface].gradient(x).normalized();
}

namespace {

std::vector<int> surfaces_of(const Solid& S, ElementId el) {
  switch (el.kind) {
    case ElementKind::Face:
      return {S.faces[el.index].surface};
    case ElementKind::Edge:
      return {S.edges[el.index].surface1, S.edges[el.index].surface2};
    case ElementKind::Vertex:
      return S.vertices[el.index].surfaces;
  }
  return {};
}

Eigen::Vector3d tangential(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  return v - v.dot(n) * n;
}

}  // namespace

std::optional<Eigen::Vector3d> nearest_point_on_edge(const Solid& S, int edge,
                                                     const Eigen::Vector3d& x,
                                                     const Tolerances& tol) {
  const Edge& e = S.edges[edge];
  if (e.samples.empty()) return std::nullopt;
  const Polynomial& g1 = S.surfaces[e.surface1];
  const Polynomial& g2 = S.surfaces[e.surface2];
  // Secant iterations on the arc length s for f(s) = (q(s) - x) . t(s), zero at the foot;
  // each new point is the tangent step projected back onto the curve. A plain tangent step
  // shrinks the error only by the factor (distance x curvature), which nears 1 for x far
  // inside a curved rim; the secant slope f' = 1 - (x - q) . k takes that into account.
  const CurveSample& start = e.samples[nearest_sample(e, x)];
  Eigen::Vector3d q = start.point;
  Eigen::Vector3d t = curve_tangent(g1, g2, q);
  double f = (q - x).dot(t);
  double step = -f;  // first step: along the tangent to the perpendicular's foot
  // A few secant steps reach round-off from a sample's spacing away; the cap stops a curve
  // whose tangent flips (a cusp), keeping the best point so far.
  constexpr int kMaxFootIterations = 30;
  for (int it = 0; it < kMaxFootIterations && std::abs(f) > tol.solve_residual; ++it) {
    const Projection p = project_onto_curve(g1, g2, q + step * t, tol);
    if (!p.converged) break;
    const Eigen::Vector3d t_new = curve_tangent(g1, g2, p.point);
    const double f_new = (p.point - x).dot(t_new);
    if (!(std::abs(f_new) < std::abs(f))) break;
    // the arc length actually travelled, to first order
    const double ds = (p.point - q).dot(0.5 * (t + t_new));
    const double slope = ds != 0 ? (f_new - f) / ds : 0;
    q = p.point;
    t = t_new;
    f = f_new;
    step = slope > 0 ? -f / slope : -f;
  }
  return q;
}

std::optional<Eigen::Vector3d> direction_toward(const Solid& S, ElementId el,
                                                const Eigen::Vector3d& x,
                                                const Eigen::Vector3d& n_S,
                                                const Tolerances& tol) {
  Eigen::Vector3d q = x;
  if (el.kind == ElementKind::Vertex) {
    q = S.vertices[el.index].point;
  } else if (el.kind == ElementKind::Edge) {
    const std::optional<Eigen::Vector3d> foot = nearest_point_on_edge(S, el.index, x, tol);
    if (!foot) return std::nullopt;
    q = *foot;
  } else {
    q = S.faces[el.index].interior_point;
  }
  const Eigen::Vector3d d = tangential(q - x, n_S);
  if (d.norm() <= 0) return std::nullopt;
  return d.normalized();
}

Eigen::Vector3d cone_middle(const Solid& S, ElementId el, const Eigen::Vector3d& x) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int s : surfaces_of(S, el)) sum += S.surfaces[s].gradient(x).normalized();
  return sum.normalized();
}

Eigen::Vector3d into_face(const Solid& S, int face, ElementId from, const Eigen::Vector3d& x) {
  const int own = S.faces[face].surface;
  const Eigen::Vector3d n = face_normal(S, face, x);
  // The other surfaces through the boundary element bound the face: their inequality rises
  // outward, so minus their gradient, on the tangent plane, points into the face.
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int s : surfaces_of(S, from))
    if (s != own) d -= tangential(S.surfaces[s].gradient(x).normalized(), n);
  if (d.norm() == 0) d = tangential(S.faces[face].interior_point - x, n);
  return d.normalized();
}

}  // namespace pcsg
