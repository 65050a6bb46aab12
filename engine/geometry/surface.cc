#include "engine/geometry/surface.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace pcsg {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A step-halving cap for Newton from poor starts: 2^-12 ~ 2.4e-4 of a step is far below any
// useful progress, so more halvings only hide divergence.
constexpr int kMaxHalvings = 12;

// Relative size below which an eigenvalue of J J^T counts as zero in the pseudo-inverse: the
// round-off of the 2x2 product (~eps times its norm), with a margin.
constexpr double kPseudoInverseCut = 1e-14;

}  // namespace

Eigen::Vector3d unit_normal(const Polynomial& g, const Eigen::Vector3d& p) {
  const Eigen::Vector3d grad = g.gradient(p);
  const double n = grad.norm();
  return n > 0 ? Eigen::Vector3d(grad / n) : Eigen::Vector3d::Zero();
}

double surface_distance(const Polynomial& g, const Eigen::Vector3d& p) {
  double v = 0;
  Eigen::Vector3d grad;
  g.evaluate(p, &v, &grad, nullptr);
  const double n = grad.norm();
  if (n > 0) return std::abs(v) / n;
  return v == 0 ? 0 : kInf;
}

TangentFrame tangent_frame(const Eigen::Vector3d& n) {
  // The axis least aligned with n is at least 54.7 degrees from it, so u is well conditioned.
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[axis])) axis = k;
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
  TangentFrame f;
  f.n = n;
  f.u = (e - n * n.dot(e)).normalized();
  f.v = n.cross(f.u);
  return f;
}

TangentFrame tangent_frame(const Polynomial& g, const Eigen::Vector3d& p) {
  return tangent_frame(unit_normal(g, p));
}

Eigen::Matrix2d shape_operator(const Polynomial& g, const Eigen::Vector3d& p,
                               const TangentFrame& frame) {
  Eigen::Vector3d grad;
  Eigen::Matrix3d H;
  g.evaluate(p, nullptr, &grad, &H);
  // Normal curvature along a unit tangent t is t^T H t / |grad g| (differentiate g = 0 twice
  // along a surface curve): positive when the surface bends away from grad g.
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = frame.u;
  T.col(1) = frame.v;
  return T.transpose() * H * T / grad.norm();
}

std::optional<PrincipalCurvatures> principal_curvatures(const Polynomial& g,
                                                        const Eigen::Vector3d& p) {
  const Eigen::Vector3d n = unit_normal(g, p);
  if (n.isZero()) return std::nullopt;
  const TangentFrame f = tangent_frame(n);
  const Eigen::Matrix2d S = shape_operator(g, p, f);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(S);  // ascending eigenvalues
  PrincipalCurvatures pc;
  pc.normal = n;
  pc.k1 = eig.eigenvalues()[0];
  pc.k2 = eig.eigenvalues()[1];
  const Eigen::Vector2d a = eig.eigenvectors().col(0);
  pc.d1 = (a[0] * f.u + a[1] * f.v).normalized();
  pc.d2 = n.cross(pc.d1);
  return pc;
}

Eigen::Vector3d curve_tangent(const Polynomial& g1, const Polynomial& g2,
                              const Eigen::Vector3d& p) {
  const Eigen::Vector3d t = g1.gradient(p).cross(g2.gradient(p));
  const double n = t.norm();
  return n > 0 ? Eigen::Vector3d(t / n) : Eigen::Vector3d::Zero();
}

double normals_sine(const Polynomial& g1, const Polynomial& g2, const Eigen::Vector3d& p) {
  return unit_normal(g1, p).cross(unit_normal(g2, p)).norm();
}

Projection project_onto_surface(const Polynomial& g, const Eigen::Vector3d& start,
                                const Tolerances& tol) {
  Projection r;
  r.point = start;
  double v = 0;
  Eigen::Vector3d grad;
  g.evaluate(r.point, &v, &grad, nullptr);
  for (; r.iterations <= tol.solve_max_iterations; ++r.iterations) {
    const double gn2 = grad.squaredNorm();
    r.residual = gn2 > 0 ? std::abs(v) / std::sqrt(gn2) : kInf;
    if (r.residual <= tol.residual_at(r.point.norm())) {
      r.converged = true;
      return r;
    }
    if (gn2 == 0) return r;  // a singular point: no direction to move in
    // minimum-norm Newton step, halved while it does not reduce |g|
    Eigen::Vector3d step = -v / gn2 * grad;
    double v_new = 0;
    Eigen::Vector3d grad_new;
    int h = 0;
    for (; h <= kMaxHalvings; ++h, step *= 0.5) {
      g.evaluate(r.point + step, &v_new, &grad_new, nullptr);
      if (std::abs(v_new) < std::abs(v)) break;
    }
    if (h > kMaxHalvings) return r;
    r.point += step;
    v = v_new;
    grad = grad_new;
  }
  return r;
}

Projection project_onto_curve(const Polynomial& g1, const Polynomial& g2,
                              const Eigen::Vector3d& start, const Tolerances& tol) {
  Projection r;
  r.point = start;
  // Each row divided by its gradient's norm: the residuals become first-order distances and
  // J's rows unit normals, so J J^T = [1 c; c 1] (c the normals' cosine) whatever the
  // inequalities' scales. Unnormalised, two faces written 1e8 and 1e-8 times their natural
  // scale (scenes/stress/example1_ill_scaled.yaml) gave J J^T eigenvalues 1e32 apart, the
  // small one fell below kPseudoInverseCut and the step never moved toward the small face.
  auto evaluate = [&](const Eigen::Vector3d& p, Eigen::Vector2d& res,
                      Eigen::Matrix<double, 2, 3>& J) {
    double v1 = 0, v2 = 0;
    Eigen::Vector3d a, b;
    g1.evaluate(p, &v1, &a, nullptr);
    g2.evaluate(p, &v2, &b, nullptr);
    const double na = a.norm(), nb = b.norm();
    if (na == 0 || nb == 0) return kInf;
    res << v1 / na, v2 / nb;
    J.row(0) = a.transpose() / na;
    J.row(1) = b.transpose() / nb;
    return res.cwiseAbs().maxCoeff();
  };
  Eigen::Vector2d res;
  Eigen::Matrix<double, 2, 3> J;
  r.residual = evaluate(r.point, res, J);
  for (; r.iterations <= tol.solve_max_iterations; ++r.iterations) {
    if (r.residual <= tol.residual_at(r.point.norm())) {
      r.converged = true;
      return r;
    }
    if (!std::isfinite(r.residual)) return r;
    // dp = -J^T (J J^T)^+ r, the pseudo-inverse cutting eigenvalues at round-off level
    const Eigen::Matrix2d JJt = J * J.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(JJt);
    const double cut = kPseudoInverseCut * eig.eigenvalues()[1];
    Eigen::Vector2d w = eig.eigenvectors().transpose() * res;
    for (int k = 0; k < 2; ++k) w[k] = eig.eigenvalues()[k] > cut ? w[k] / eig.eigenvalues()[k] : 0;
    Eigen::Vector3d step = -J.transpose() * (eig.eigenvectors() * w);
    Eigen::Vector2d res_new;
    Eigen::Matrix<double, 2, 3> J_new;
    double residual_new = kInf;
    int h = 0;
    for (; h <= kMaxHalvings; ++h, step *= 0.5) {
      residual_new = evaluate(r.point + step, res_new, J_new);
      if (residual_new < r.residual) break;
    }
    if (h > kMaxHalvings) return r;
    r.point += step;
    r.residual = residual_new;
    res = res_new;
    J = J_new;
  }
  return r;
}

Projection solve_three_surfaces(const Polynomial& g1, const Polynomial& g2,
                                const Polynomial& g3, const Eigen::Vector3d& start,
                                const Tolerances& tol) {
  const Polynomial* gs[3] = {&g1, &g2, &g3};
  Projection r;
  r.point = start;
  for (; r.iterations <= tol.solve_max_iterations; ++r.iterations) {
    // rows divided by their gradients' norms (as in project_onto_curve): the LU's pivoting
    // and invertibility test then compare unit normals, not the inequalities' scales
    Eigen::Vector3d res;
    Eigen::Matrix3d J;
    r.residual = 0;
    for (int k = 0; k < 3; ++k) {
      double v = 0;
      Eigen::Vector3d grad;
      gs[k]->evaluate(r.point, &v, &grad, nullptr);
      const double n = grad.norm();
      if (n == 0) return r;  // a singular point of one surface
      res[k] = v / n;
      J.row(k) = grad.transpose() / n;
      r.residual = std::max(r.residual, std::abs(res[k]));
    }
    if (r.residual <= tol.residual_at(r.point.norm())) {
      r.converged = true;
      return r;
    }
    Eigen::FullPivLU<Eigen::Matrix3d> lu(J);
    if (!lu.isInvertible() || !std::isfinite(r.residual)) return r;
    r.point -= lu.solve(res);
  }
  return r;
}

std::optional<Eigen::Vector3d> point_with_normal(const Polynomial& g, const Eigen::Vector3d& u,
                                                 const Eigen::Vector3d& start,
                                                 const Tolerances& tol) {
  // Quadratic from a start within a few mesh cells; 30 iterations leave room for the first,
  // farther steps.
  constexpr int kIterations = 30;
  const Eigen::Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
  Eigen::Vector3d p = start;
  for (int it = 0; it < kIterations; ++it) {
    double val = 0;
    Eigen::Vector3d grad;
    Eigen::Matrix3d H;
    g.evaluate(p, &val, &grad, &H);
    const double gn = grad.norm();
    if (!(gn > 0)) return std::nullopt;
    const double gl = gn / tol.length_scale;
    const Eigen::Vector3d F(val / gn, grad.dot(e1) / gl, grad.dot(e2) / gl);
    if (std::max(std::abs(F[0]), std::hypot(F[1], F[2])) <= tol.residual_at(p.norm())) {
      if (grad.dot(u) > 0) return p;
      return std::nullopt;
    }
    Eigen::Matrix3d J;
    J.row(0) = grad.transpose() / gn;
    J.row(1) = (H * e1).transpose() / gl;
    J.row(2) = (H * e2).transpose() / gl;
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(J);
    if (!lu.isInvertible()) return std::nullopt;
    p -= lu.solve(F);
    if (!p.allFinite()) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace pcsg
