#pragma once
// The e-e-touch problem (paper Section II-B: two edges whose tangent lines at the contact point
// are collinear). There the common-perpendicular system of pair_systems.h is singular: sliding
// both points along the shared tangent changes the distance only at fourth order. Instead the
// points are pinned by the tangents: p_A and p_B on their curves, p_B the foot of x_A on B's
// curve (D . t_b = 0), and among those the pair whose tangents are best aligned, i.e. the
// least-squares minimum of |sigma R t_a - t_b| along the remaining one-parameter family.
// The minimiser is regular wherever the curves' relative curvature is not zero, and the
// misalignment it leaves is the sine that decides touch (Tolerances::collinear_sine).
#include <Eigen/Core>

#include "engine/contact/newton_solver.h"
#include "engine/contact/pair_systems.h"

namespace pcsg {

struct TouchSolution {
  bool converged = false;
  Eigen::Vector3d p_A = Eigen::Vector3d::Zero();  // A's frame
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();  // B's frame
  double misalignment = 0;                        // sine of the tangents' angle
};

// Constrained Gauss-Newton from the starting points: minimum-norm steps restore the five
// constraints, and the step along their null direction minimises the misalignment.
TouchSolution solve_touch(const PairSetup& setup, const Eigen::Vector3d& start_A,
                          const Eigen::Vector3d& start_B, const NewtonOptions& options);

}  // namespace pcsg
