#include "engine/contact/pair_solver.h"

#include <Eigen/Dense>
#include <algorithm>

#include "engine/contact/pair_touch.h"

namespace pcsg {
namespace {

// For a pair solved at coordinates of size `coordinate_size` (B's frame).
NewtonOptions newton_options(const Tolerances& tol, double coordinate_size, int max_iterations) {
  NewtonOptions o;
  o.length_scale = tol.length_scale;
  o.residual = tol.residual_at(coordinate_size);
  o.max_iterations = max_iterations;
  return o;
}

// Row [e^T, (x x e)^T]: the rate of the separation along the fixed direction e when A moves
// with the twist (v, w) about B's origin (A's point x moves with v + w x x).
Eigen::Matrix<double, 1, 6> separation_row(const Eigen::Vector3d& e, const Eigen::Vector3d& x) {
  Eigen::Matrix<double, 1, 6> row;
  row << e.transpose(), x.cross(e).transpose();
  return row;
}

// Sine of the angle between two edges' tangents at their points (A's in A's frame).
double tangents_sine(const SceneGeometry& scene, const Pose& X_BA, ElementId a, ElementId b,
                      const Eigen::Vector3d& p_A, const Eigen::Vector3d& p_B) {
  const Eigen::Vector3d t_a = X_BA.rotation() * edge_jet(scene.A, a.index, p_A).tangent;
  return t_a.cross(edge_jet(scene.B, b.index, p_B).tangent).norm();
}

}  // namespace

PairSolution solve_pair_problem(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                ElementId b, PtcType type, const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B) {
  return solve_pair_problem(scene, X_BA, a, b, type, start_A, start_B,
                            scene.tol.solve_max_iterations);
}

PairSolution solve_pair_problem(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                ElementId b, PtcType type, const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B, int max_iterations) {
  const PairSetup setup = PairSetup::make(scene, X_BA, a, b);
  // A's points enter B's frame at |t| + |p_A| at most.
  const NewtonOptions options = newton_options(
      scene.tol, std::max(setup.t.norm() + start_A.norm(), start_B.norm()), max_iterations);
  PairSolution out;
  PointContact& c = out.contact;
  c.a = a;
  c.b = b;
  c.type = type;
  if (type == PtcType::EETouch) {
    const TouchSolution t = solve_touch(setup, start_A, start_B, options);
    if (!t.converged) return out;
    c.p_A = t.p_A;
    c.p_B = t.p_B;
    const Eigen::Vector3d D = setup.R * c.p_A + setup.t - c.p_B;
    const Eigen::Vector3d t_b = edge_jet(scene.B, b.index, c.p_B).tangent;
    c.normal_B = outward_bisector(scene.B, element_surfaces(scene.B, b), c.p_B, t_b);
    c.gap = D.dot(c.normal_B) < 0 ? -D.norm() : D.norm();
  } else {
    const PairSystem system(setup, type);
    SmallVector z = system.initial(start_A, start_B);
    if (system.size() > 0) {
      const NewtonResult r = solve_square_system(system, z, options);
      out.iterations = r.iterations;
      if (!r.converged) {
        // nearly parallel rims off their touch: a descent on |D|^2 (pair_crossing.cc)
        if (type != PtcType::EECross) return out;
        z = system.initial(start_A, start_B);
        if (!system.descend_crossing(z, options)) return out;
      }
    }
    PairPoints p = system.points(z);
    // nearly parallel rims: the common slide along them needs the polish (pair_crossing.cc)
    if (type == PtcType::EECross &&
        tangents_sine(scene, X_BA, a, b, p.p_A, p.p_B) < scene.tol.near_collinear_sine) {
      system.polish_crossing(z, scene.tol.distinct_points, scene.tol.solve_max_iterations);
      p = system.points(z);
    }
    c.p_A = p.p_A;
    c.p_B = p.p_B;
    c.gap = p.gap;
    c.normal_B = p.normal_B;
    out.k = p.k;
  }
  out.converged = true;
  fill_contact_conditions(scene, X_BA, c);
  return out;
}

void fill_contact_conditions(const SceneGeometry& scene, const Pose& X_BA, PointContact& c) {
  const Eigen::Matrix3d R = X_BA.rotation();
  const Eigen::Vector3d x_A = X_BA.apply(c.p_A);
  const Eigen::Vector3d D = x_A - c.p_B;
  c.point_B = 0.5 * (x_A + c.p_B);
  c.tangent_a_B.setZero();
  c.tangent_b_B.setZero();
  CurveJet ja, jb;
  if (c.a.kind == ElementKind::Edge) {
    ja = edge_jet(scene.A, c.a.index, c.p_A);
    c.tangent_a_B = R * ja.tangent;
  }
  if (c.b.kind == ElementKind::Edge) {
    jb = edge_jet(scene.B, c.b.index, c.p_B);
    c.tangent_b_B = jb.tangent;
  }
  const int rows = ptc_codimension(c.type);
  c.residual.resize(rows);
  c.jacobian.resize(rows, 6);
  switch (c.type) {
    case PtcType::FF: case PtcType::FE: case PtcType::EF: case PtcType::EECross:
    case PtcType::FV: case PtcType::VF:
      // Envelope theorem: the gap is stationary in the contact points, so its rate is the
      // normal velocity of A's point.
      c.residual[0] = c.gap;
      c.jacobian.row(0) = separation_row(c.normal_B, x_A);
      break;
    case PtcType::VE: case PtcType::EV: {
      // The foot moves along the contact line, so only the two normal separations count.
      const Eigen::Vector3d line = c.type == PtcType::VE ? c.tangent_b_B : c.tangent_a_B;
      const Eigen::Vector3d e2 = line.cross(c.normal_B).normalized();
      c.residual << D.dot(c.normal_B), D.dot(e2);
      c.jacobian.row(0) = separation_row(c.normal_B, x_A);
      c.jacobian.row(1) = separation_row(e2, x_A);
      break;
    }
    case PtcType::VV:
      c.residual = D;
      for (int i = 0; i < 3; ++i) c.jacobian.row(i) = separation_row(Eigen::Vector3d::Unit(i), x_A);
      break;
    case PtcType::EETouch: {
      // Rows: the separation normal to the common tangent t (two), and the tangents'
      // misalignment across their relative curvature k. Along k the misalignment is absorbed
      // by sliding (the solve's free parameter); across it, m = t x k / |t x k|, it is not.
      // Sliding moves the foot by du - dv = -t . (v + w x x), which changes the misalignment
      // along m at the rate mu = m . kappa_b of B's curvature vector (m . kappa_a is the same).
      const Eigen::Vector3d t = jb.tangent;
      const Eigen::Vector3d e2 = t.cross(c.normal_B).normalized();
      const double sigma = c.tangent_a_B.dot(t) < 0 ? -1 : 1;
      const Eigen::Vector3d kappa_a = R * ja.curvature, kappa_b = jb.curvature;
      Eigen::Vector3d k = kappa_a - kappa_b;
      k -= t * t.dot(k);
      const Eigen::Vector3d m = k.norm() > 0 ? Eigen::Vector3d(t.cross(k).normalized()) : e2;
      const double mu = m.dot(kappa_b);
      c.residual << D.dot(c.normal_B), D.dot(e2), (sigma * c.tangent_a_B - t).dot(m);
      c.jacobian.row(0) = separation_row(c.normal_B, x_A);
      c.jacobian.row(1) = separation_row(e2, x_A);
      c.jacobian.row(2) << -mu * t.transpose(), (t.cross(m) - mu * x_A.cross(t)).transpose();
      break;
    }
  }
}

}  // namespace pcsg
