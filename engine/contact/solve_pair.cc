// solve_pair (contact.h): one pair's local problem for tracking a contact through a motion.
#include <stdexcept>

#include "engine/contact/contact_classification.h"

namespace pcsg {

std::optional<PointContact> solve_pair(const SceneGeometry& scene, const Pose& X_BA,
                                       ElementId a, ElementId b, PtcType type,
                                       const Eigen::Vector3d& start_A,
                                       const Eigen::Vector3d& start_B) {
  if (ptc_kind_a(type) != a.kind || ptc_kind_b(type) != b.kind)
    throw std::invalid_argument(std::string("solve_pair: type ") + ptc_type_name(type) +
                                " does not join the elements' kinds");
  const PairSolution sol = solve_pair_problem(scene, X_BA, a, b, type, start_A, start_B);
  if (!sol.converged) return std::nullopt;
  // The points must stay in the elements' relative interiors (and the direction in their
  // normal cones): otherwise another pair holds the contact now. A saddle is still this
  // pair's solution (tracking may pass one); whether it is a contact is detection's call.
  const Classification cls = classify_solution(scene, X_BA, sol);
  if (cls.verdict == Verdict::Redirect || cls.verdict == Verdict::Rejected) return std::nullopt;
  return sol.contact;
}

}  // namespace pcsg
