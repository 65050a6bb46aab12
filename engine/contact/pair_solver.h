#pragma once
// One element pair's local distance problem solved at a pose and turned into a PointContact:
// points, signed gap, normal, edge tangents, and the contact's conditions r(X) with their
// twist Jacobian (contact.h). Classification (which elements really hold the points) is in
// contact_classification.h; this layer solves the pair it is given.
#include <Eigen/Core>

#include "engine/contact/contact.h"
#include "engine/contact/pair_systems.h"

namespace pcsg {

struct PairSolution {
  bool converged = false;
  PointContact contact;  // complete when converged
  double k = 1;          // f-f: normals ratio, +1 for opposite normals
  int iterations = 0;
};

// Solves the pair (a, b) with the formulation of `type` (pair_systems.h; e-e-touch:
// pair_touch.h) from the starting points, and fills the contact on convergence. An e-e-touch
// solve also converges where the tangents are not aligned (its residual's third row says by
// how much); classification decides whether they are collinear.
// Newton runs at most `max_iterations` (the first overload: Tolerances::solve_max_iterations).
PairSolution solve_pair_problem(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                ElementId b, PtcType type, const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B);
PairSolution solve_pair_problem(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                ElementId b, PtcType type, const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B, int max_iterations);

// Fills point_B, tangents, residual and jacobian of a contact whose a, b, type, p_A, p_B,
// gap and normal_B are set (the rules are in contact.h's PointContact comment).
void fill_contact_conditions(const SceneGeometry& scene, const Pose& X_BA, PointContact& c);

}  // namespace pcsg
