#pragma once
// Which elements really hold a solved pair's points (paper Section II-B names a PtC by the
// pair of elements whose relative interiors hold it), and the walk from a candidate pair to
// the pair that forms the contact: a face-face solution whose B point violates another of
// B's inequalities is no f-f contact; the contact is then with the edge on that inequality,
// and that pair is solved next. Likewise a contact normal outside an edge's (vertex's)
// normal cone means that one of its faces (edges) is the closer element.
#include <string>

#include "engine/contact/pair_solver.h"

namespace pcsg {

enum class Verdict {
  Contact,     // the points are in the elements' relative interiors, a local distance minimum
  NotMinimum,  // as Contact but a saddle or maximum of the distance (not an isolated contact)
  Redirect,    // another pair holds the points: solve (a, b) next
  Rejected,    // no contact of this pair here (reason says why)
};

struct Classification {
  Verdict verdict = Verdict::Rejected;
  ElementId a, b;      // Redirect: the next pair
  std::string reason;  // Rejected: why
};

Classification classify_solution(const SceneGeometry& scene, const Pose& X_BA,
                                 const PairSolution& solution);

// Second-order test of a solved pair: the relative curvature along the directions the points
// can slide is positive semi-definite, within Tolerances::curvature.
bool is_local_minimum(const SceneGeometry& scene, const Pose& X_BA, const PointContact& c);
// The smallest relative curvature (1/length) along the directions an f-f, f-e or e-f
// contact's points can slide (infinite for the other types): near zero next to a bifurcation
// where two local minima of the pair merge.
double sliding_curvature(const SceneGeometry& scene, const Pose& X_BA, const PointContact& c);
// Whether an f-f, f-e or e-f contact touches along a curve rather than at a point: its sliding
// curvature vanishes within Tolerances::ring_curvature (a torus against a sphere centred on its
// axis). Such a pose is not a point-contact configuration (paper Section II).
bool is_ring_contact(const SceneGeometry& scene, const Pose& X_BA, const PointContact& c);

// Follows redirections from a candidate pair and starting points to a classified solution.
// e-e pairs are solved as crossing edges first and as touching edges when their tangents are
// nearly parallel (Tolerances::near_collinear_sine). The solves run at most
// Tolerances::detection_solve_max_iterations.
struct ResolvedContact {
  bool found = false;     // a converged, classified solution
  bool minimum = false;   // it is a local minimum of the distance (a contact when |gap| small)
  bool diverged = false;  // !found because a solve did not converge (not a rejection)
  PointContact contact;
  std::string reason;  // !found: why
};
ResolvedContact resolve_contact(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                ElementId b, const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B);

// Does p (in `solid`'s frame) lie inside the solid, deeper than `depth` (>= 0)?
bool strictly_inside(const Solid& solid, const Eigen::Vector3d& p, double depth);

}  // namespace pcsg
