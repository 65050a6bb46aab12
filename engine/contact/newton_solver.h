#pragma once
// Damped Newton (Levenberg-Marquardt fallback) on a small square system F(z) = 0, as used by
// every element-pair contact problem. Rows and unknowns carry scales that make them lengths
// in units of the scene's length scale, so the iterates, the step bound, the damping and the
// stopping test are all unchanged when the scene is scaled (Tolerances: "scaled by s gives
// the same results scaled by s").
#include <Eigen/Core>

namespace pcsg {

// Fixed-capacity dynamic vectors and matrices: no heap allocation in the solver loop.
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 8, 1>;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;

class SquareSystem {
 public:
  virtual ~SquareSystem() = default;
  virtual int size() const = 0;
  // F(z) and dF/dz, and per-row factors that turn each row into a length (for g rows
  // 1 / |grad g|, for dimensionless rows the length scale).
  virtual void evaluate(const SmallVector& z, SmallVector& F, SmallMatrix& J,
                        SmallVector& row_scale) const = 0;
  // F(z) and the row factors alone, the same bits as evaluate's: a trial step reads only these,
  // and most trials are rejected (63% of Example 1's), so their Jacobians would go unread.
  virtual void evaluate_residual(const SmallVector& z, SmallVector& F,
                                 SmallVector& row_scale) const = 0;
  // Per-unknown scales: the length scale for positions and gaps, 1 for dimensionless ones.
  virtual void unknown_scales(SmallVector& scale) const = 0;
};

struct NewtonOptions {
  double length_scale = 1;  // L
  double residual = 1e-12;  // stop when every scaled row is below this (a length)
  int max_iterations = 50;
  // Largest step of any unknown, in units of its scale: keeps poor starts from jumping to a
  // far branch of the surfaces (a quarter of the scene).
  double max_step = 0.25;
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0;  // max_i |F_i row_scale_i| at the returned z
};

// Solves from z (updated in place). Newton steps are taken while they reduce |F|; otherwise
// Levenberg-Marquardt steps with growing damping. On convergence one more Newton step is
// taken, so the result is accurate to round-off rather than to the tolerance.
NewtonResult solve_square_system(const SquareSystem& system, SmallVector& z,
                                 const NewtonOptions& options);

}  // namespace pcsg
