// Polish of an e-e-cross solution whose tangents are nearly parallel, and a descent for the
// starts where the Newton solve fails there (pair_systems.h).
//
// The common-perpendicular rows D . t_a = D . t_b = 0 hardly change when both points slide
// together along two nearly parallel rims: at tangents a sine phi apart, a common slide delta
// changes them by ~delta phi^2, far below the round-off of the curve rows that dominate the
// Newton merit. Newton therefore stops with both points slid by delta ~ 1e-8 L at phi = 3e-7
// (scenes/stress/collinear_edges.yaml), and since the tangents turn by kappa delta, their cross
// product, the normal, is off by kappa delta / phi = 5e-2. The polish solves the two rows in
// the two arc lengths alone, with the points kept on their curves, and forms the ill-conditioned
// combination directly: the common slide is -(D . (t_a - t_b)) / |t_a x t_b|^2 (times the
// curvature terms), where D . (t_a - t_b) keeps its own accuracy instead of being the
// difference of two rows. Round-off in D of eps |D| then moves the point by eps |D| / phi.
//
// Off the touch the stationary point moves fast: translating A by 4.4e-7 L across two rims
// at phi = 1e-4 moves it ~3e-4 along them (the slide balances phi^2 u against the rims'
// relative curvature, ~u^3), and the full Newton step (~eps / phi, 10x too far) is rejected,
// after which the damped steps crawl; contact_rates then found no rates at all ("contact
// eA-eB has no rates at step 0", collinear_edges.yaml). descend_crossing minimises |D|^2 in
// the two arc lengths with halved Newton steps instead.
#include <Eigen/Dense>
#include <cmath>

#include "engine/contact/pair_systems.h"

namespace pcsg {
namespace {

// Gauss-Newton steps that put a point back on the curve g1 = g2 = 0 after a step along its
// tangent (which leaves it by ~kappa^3 s^3): each squares the residual, two reach round-off.
constexpr int kCurveProjectionSteps = 2;

Eigen::Vector3d onto_curve(const Polynomial& g1, const Polynomial& g2, Eigen::Vector3d p) {
  for (int k = 0; k < kCurveProjectionSteps; ++k) {
    double v1 = 0, v2 = 0;
    Eigen::Vector3d a, b;
    g1.evaluate(p, &v1, &a, nullptr);
    g2.evaluate(p, &v2, &b, nullptr);
    Eigen::Matrix<double, 2, 3> J;
    J << a.transpose(), b.transpose();
    // minimum-norm step: J^T (J J^T)^-1 (the edge is transversal: J J^T is regular)
    const Eigen::Vector2d w = (J * J.transpose()).ldlt().solve(Eigen::Vector2d(v1, v2));
    if (!w.allFinite()) break;
    p -= J.transpose() * w;
  }
  return p;
}

// Halvings of a descent step before the descent gives up (the step is then ~1e-9 of the
// Newton step: the start is not in a basin of |D|^2).
constexpr int kDescentHalvings = 30;

}  // namespace

bool PairSystem::descend_crossing(SmallVector& z, const NewtonOptions& options) const {
  if (type_ != PtcType::EECross) return false;
  const Eigen::Matrix3d& R = s_.R;
  const double max_step = options.max_step * s_.length_scale;
  Eigen::Vector3d p_A = onto_curve(ga(0), ga(1), z.segment<3>(0));
  Eigen::Vector3d p_B = onto_curve(gb(0), gb(1), z.segment<3>(3));
  auto separation = [&](const Eigen::Vector3d& q_A, const Eigen::Vector3d& q_B) {
    return Eigen::Vector3d(R * q_A + s_.t - q_B);
  };
  // Rows below the residual do not end the descent: along nearly parallel rims they leave
  // the point free by residual / (the Hessian's small eigenvalue), 5e-6 L at sine 1e-4 a
  // slide of 3e-4 L away from the touch. It stops where |D|^2, which the points on their
  // curves give to its own round-off, no longer drops.
  bool converged = false;
  for (int it = 0; it <= options.max_iterations; ++it) {
    const CurveJet ca = CurveJet::of(SurfaceJet::at(ga(0), p_A), SurfaceJet::at(ga(1), p_A));
    const CurveJet cb = CurveJet::of(SurfaceJet::at(gb(0), p_B), SurfaceJet::at(gb(1), p_B));
    const Eigen::Vector3d t_a = R * ca.tangent, k_a = R * ca.curvature;
    const Eigen::Vector3d& t_b = cb.tangent;
    const Eigen::Vector3d D = separation(p_A, p_B);
    // |D|^2 / 2 in the arc lengths (u, v), D' = D + u t_a - v t_b: gradient (D . t_a,
    // -D . t_b), Hessian [[1 + D . k_a, -c], [-c, 1 - D . k_b]]
    const Eigen::Vector2d g(D.dot(t_a), -D.dot(t_b));
    converged = g.cwiseAbs().maxCoeff() <= options.residual;
    if (it == options.max_iterations) break;
    Eigen::Matrix2d H;
    H << 1 + D.dot(k_a), -t_a.dot(t_b), -t_a.dot(t_b), 1 - D.dot(cb.curvature);
    // Newton where H is positive definite, else the gradient (unit Hessian)
    Eigen::Vector2d step = -H.ldlt().solve(g);
    if (!step.allFinite() || step.dot(g) >= 0) step = -g;
    if (step.norm() > max_step) step *= max_step / step.norm();
    const double merit = D.squaredNorm();
    bool accepted = false;
    for (int h = 0; h <= kDescentHalvings && !accepted; ++h, step *= 0.5) {
      const double u = step[0], v = step[1];
      const Eigen::Vector3d q_A =
          onto_curve(ga(0), ga(1), p_A + u * ca.tangent + 0.5 * u * u * ca.curvature);
      const Eigen::Vector3d q_B =
          onto_curve(gb(0), gb(1), p_B + v * t_b + 0.5 * v * v * cb.curvature);
      if (separation(q_A, q_B).squaredNorm() < merit) {
        p_A = q_A;
        p_B = q_B;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  if (converged) {
    z.segment<3>(0) = p_A;
    z.segment<3>(3) = p_B;
  }
  return converged;
}

void PairSystem::polish_crossing(SmallVector& z, double max_shift, int max_iterations) const {
  if (type_ != PtcType::EECross) return;
  const Eigen::Matrix3d& R = s_.R;
  Eigen::Vector3d p_A = onto_curve(ga(0), ga(1), z.segment<3>(0));
  Eigen::Vector3d p_B = onto_curve(gb(0), gb(1), z.segment<3>(3));
  double previous = INFINITY, shifted = 0;
  for (int it = 0; it < max_iterations; ++it) {
    const CurveJet ca = CurveJet::of(SurfaceJet::at(ga(0), p_A), SurfaceJet::at(ga(1), p_A));
    const CurveJet cb = CurveJet::of(SurfaceJet::at(gb(0), p_B), SurfaceJet::at(gb(1), p_B));
    const Eigen::Vector3d t_a = R * ca.tangent, k_a = R * ca.curvature;
    const Eigen::Vector3d& t_b = cb.tangent;
    const Eigen::Vector3d& k_b = cb.curvature;
    const Eigen::Vector3d D = R * p_A + s_.t - p_B;
    // rows f1 = D . t_a, f2 = D . t_b in the arc lengths (u, v) of the points, D' = D + u t_a
    // - v t_b: Jacobian [[1 + a, -c], [c, -1 + b]], a = D . k_a, b = D . k_b, c = t_a . t_b
    const double f1 = D.dot(t_a), f2 = D.dot(t_b), fd = D.dot(t_a - t_b);
    const double one_minus_c = 0.5 * (t_a - t_b).squaredNorm();
    const double a = D.dot(k_a), b = D.dot(k_b);
    const double det = -t_a.cross(t_b).squaredNorm() - a + b + a * b;
    // Cramer's rule with f1 - f2 and 1 - c formed without cancellation
    const double u = (fd + one_minus_c * f2 - b * f1) / det;
    const double v = (fd - one_minus_c * f1 - a * f2) / det;
    const double step = std::max(std::abs(u), std::abs(v));
    // stop once the steps no longer shrink (round-off reached) or would leave the solution
    if (!std::isfinite(step) || step == 0 || step > 0.5 * previous ||
        shifted + step > max_shift)
      break;
    p_A = onto_curve(ga(0), ga(1), p_A + u * ca.tangent + 0.5 * u * u * ca.curvature);
    p_B = onto_curve(gb(0), gb(1), p_B + v * t_b + 0.5 * v * v * k_b);
    previous = step;
    shifted += step;
  }
  z.segment<3>(0) = p_A;
  z.segment<3>(3) = p_B;
}

}  // namespace pcsg
