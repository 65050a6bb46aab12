#include "engine/contact/newton_solver.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "engine/contact/small_solvers.h"

namespace pcsg {
namespace {

// Levenberg-Marquardt damping, relative to the largest diagonal of J^T J: the first value,
// the growth per rejected step, the shrink per accepted one, and the range it is kept in.
// The damping is carried from one iteration to the next and shrinks while steps succeed
// (Nielsen's rule). Restarting every iteration at the first value throttled a step along a
// direction of singular value sigma to sigma^2 / damping of its Newton length: in a long
// curved valley, where the Newton step itself leaves the valley along its tangent, the solve
// crawled (a nearly conformal ring contact, f-f of scenes/torus.yaml with the torus tilted
// 0.031 rad around B's convex bottom: 0.0006 per iteration along a ring of radius 1.27,
// residual 0.018 after 50 iterations; of 519 starts from A's mesh vertices near the ring 43
// converged, 377 with the carried damping and the bent steps below). At the upper end steps
// are pure gradient steps of negligible length: the solve gives up.
constexpr double kFirstDamping = 1e-3;
constexpr double kDampingGrowth = 10;
constexpr double kDampingShrink = 10;
constexpr double kMinDamping = 1e-12;
constexpr double kMaxDamping = 1e8;

struct State {
  SmallVector z, F, rs;
  SmallMatrix J;
  bool has_jacobian = false;  // J is at z (a trial's is formed once the trial is taken)
  double merit = 0;           // |F .* rs|^2 / L^2
  double residual = 0;        // max |F .* rs|
};

void evaluate(const SquareSystem& sys, const SmallVector& z, double L, State& s,
              bool with_jacobian) {
  s.z = z;
  if (with_jacobian)
    sys.evaluate(z, s.F, s.J, s.rs);
  else
    sys.evaluate_residual(z, s.F, s.rs);
  s.has_jacobian = with_jacobian;
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
  // The current point and the trial, swapped by pointer when a step is accepted.
  State states[2];
  State* cur = &states[0];
  State* trial = &states[1];
  evaluate(system, z, L, *cur, true);
  NewtonResult result;
  bool polishing = false;
  double damping = 0;  // relative LM damping, carried between iterations (0: not yet used)
  for (int it = 0; it < options.max_iterations; ++it) {
    result.iterations = it;
    if (cur->residual <= options.residual) {
      if (polishing) break;
      polishing = true;  // one more Newton step takes the solution to round-off
    }
    // The taken trial's Jacobian (F and the row factors come out the same bits again).
    if (!cur->has_jacobian) {
      system.evaluate(cur->z, cur->F, cur->J, cur->rs);
      cur->has_jacobian = true;
    }
    // Dimensionless system: rows in units of L, unknowns in units of their scales.
    const SmallVector Ft = cur->F.cwiseProduct(cur->rs) / L;
    SmallMatrix Jt = (cur->rs / L).asDiagonal() * cur->J * cs.asDiagonal();
    // A step, clipped to the step bound, is accepted when it lowers the merit.
    auto try_step = [&](SmallVector step) {
      if (!step.allFinite()) return false;
      const double big = step.cwiseAbs().maxCoeff();
      if (big > options.max_step) step *= options.max_step / big;
      evaluate(system, cur->z + cs.cwiseProduct(step), L, *trial, false);
      return trial->merit < cur->merit;
    };
    // A rejected step v bent along the solution curve (second-order correction, geodesic
    // acceleration with the trial point as its difference): v + a / 2, where a takes the
    // model's curvature error F(z + v) - F(z) - J v back through the same linear solve. A
    // straight step along a curved valley leaves it by its length squared over the valley's
    // radius (a nearly conformal ring contact: the Newton step along the ring's tangent),
    // so without the bend only short steps are accepted and the solve crawls.
    auto try_bent = [&](const auto& solve) {
      if (polishing) return false;  // at round-off already: nothing to bend
      if (!trial->z.allFinite() || !std::isfinite(trial->merit)) return false;
      const SmallVector v = (trial->z - cur->z).cwiseQuotient(cs);  // as taken (clipped)
      const SmallVector curvature = trial->F.cwiseProduct(cur->rs) / L - Ft - small_times(Jt, v);
      return try_step(v + solve(curvature));
    };
    const SmallLu lu(Jt);  // Eigen's partialPivLu, bit for bit, without its set-up
    const SmallVector newton = -lu.solve(Ft);
    bool accepted = try_step(newton) ||
                    try_bent([&](const SmallVector& r) { return SmallVector(-lu.solve(r)); });
    if (!accepted) {
      // Eigen's products, bit for bit, without its dispatch and GEMM packing.
      const SmallMatrix JtJ = small_gram(Jt);
      const SmallVector g = small_transpose_times(Jt, Ft);
      // (A zero Jacobian still gets a positive damping: pure, tiny gradient steps.)
      const double scale = std::max(JtJ.diagonal().maxCoeff(), 1.0);
      if (damping <= 0) damping = kFirstDamping;
      damping = std::max(damping, kMinDamping);
      while (!accepted && damping <= kMaxDamping) {
        SmallMatrix A = JtJ;
        A.diagonal().array() += damping * scale;
        const SmallLdlt ldlt(A);  // Eigen's ldlt, bit for bit, without its set-up
        const SmallVector v = -ldlt.solve(g);
        accepted = try_step(v) || try_bent([&](const SmallVector& r) {
                     return SmallVector(-ldlt.solve(small_transpose_times(Jt, r)));
                   });
        damping = accepted ? damping / kDampingShrink : damping * kDampingGrowth;
      }
    }
    if (!accepted) break;  // stuck: converged already (polishing) or a failed solve
    std::swap(cur, trial);
  }
  z = cur->z;
  result.residual = cur->residual;
  result.converged = cur->residual <= options.residual;
  return result;
}

}  // namespace pcsg
