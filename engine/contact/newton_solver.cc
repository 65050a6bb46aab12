#include "engine/contact/newton_solver.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace pcsg {
namespace {

// Levenberg-Marquardt: first damping relative to the largest diagonal of J^T J, growth per
// rejected step, and attempts before the solve gives up (damping then ~1e9 x the start:
// steps are pure gradient steps of negligible length).
constexpr double kFirstDamping = 1e-3;
constexpr double kDampingGrowth = 10;
constexpr int kDampingAttempts = 12;

struct State {
  SmallVector z, F, rs;
  SmallMatrix J;
  double merit = 0;     // |F .* rs|^2 / L^2
  double residual = 0;  // max |F .* rs|
};

void evaluate(const SquareSystem& sys, const SmallVector& z, double L, State& s) {
  s.z = z;
  sys.evaluate(z, s.F, s.J, s.rs);
  const SmallVector Fs = s.F.cwiseProduct(s.rs);
  s.residual = Fs.cwiseAbs().maxCoeff();
  s.merit = Fs.squaredNorm() / (L * L);
  if (!std::isfinite(s.merit)) s.merit = s.residual = INFINITY;
}

}  // namespace

NewtonResult solve_square_system(const SquareSystem& system, SmallVector& z,
                                 const NewtonOptions& options) {
  const double L = options.length_scale;
  const int n = system.size();
  SmallVector cs(n);
  system.unknown_scales(cs);
  State cur, trial;
  evaluate(system, z, L, cur);
  NewtonResult result;
  bool polishing = false;
  for (int it = 0; it < options.max_iterations; ++it) {
    result.iterations = it;
    if (cur.residual <= options.residual) {
      if (polishing) break;
      polishing = true;  // one more Newton step takes the solution to round-off
    }
    // Dimensionless system: rows in units of L, unknowns in units of their scales.
    const SmallVector Ft = cur.F.cwiseProduct(cur.rs) / L;
    SmallMatrix Jt = (cur.rs / L).asDiagonal() * cur.J * cs.asDiagonal();
    auto try_step = [&](SmallVector step) {
      if (!step.allFinite()) return false;
      const double big = step.cwiseAbs().maxCoeff();
      if (big > options.max_step) step *= options.max_step / big;
      evaluate(system, cur.z + cs.cwiseProduct(step), L, trial);
      return trial.merit < cur.merit;
    };
    bool accepted = try_step(-Jt.partialPivLu().solve(Ft));
    if (!accepted) {
      const SmallMatrix JtJ = Jt.transpose() * Jt;
      const SmallVector g = Jt.transpose() * Ft;
      // (A zero Jacobian still gets a positive damping: pure, tiny gradient steps.)
      double mu = kFirstDamping * std::max(JtJ.diagonal().maxCoeff(), 1.0);
      for (int k = 0; k < kDampingAttempts && !accepted; ++k, mu *= kDampingGrowth) {
        SmallMatrix A = JtJ;
        A.diagonal().array() += mu;
        accepted = try_step(-A.ldlt().solve(g));
      }
    }
    if (!accepted) break;  // stuck: converged already (polishing) or a failed solve
    std::swap(cur, trial);
  }
  z = cur.z;
  result.residual = cur.residual;
  result.converged = cur.residual <= options.residual;
  return result;
}

}  // namespace pcsg
