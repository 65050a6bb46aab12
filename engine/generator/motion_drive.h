#pragma once
// The drive of a transition motion: hard rows (contacts kept exact, to first order) and drive
// rows (what the changing and separating contacts should do), combined into one small scaled
// twist by least squares in the null space of the hard rows.
#include <optional>
#include <vector>

#include "engine/contact/contact.h"
#include "engine/generator/twist_frame.h"

namespace pcsg {

// Rates of one contact with respect to the scaled twist (finite differences of the exact
// pair solve; used for directions only).
struct ContactRates {
  Eigen::Matrix<double, 3, 6> point_A;   // A's contact point, A's frame
  Eigen::Matrix<double, 3, 6> point_B;   // B's contact point, B's frame
  Eigen::Matrix<double, 3, 6> normal_A;  // A's outward normal at the contact, A's frame
  Eigen::Matrix<double, 3, 6> normal_B;  // B's outward normal at the contact, B's frame
};

// Follows one contact's pair problem to the pose X from its previous points, without asking
// whether the solution still lies in the elements' interiors: during a motion the contact's
// classification is the detector's call (transition_motion.cc), so that a contact can be
// followed exactly up to and across an element boundary.
std::optional<PointContact> track_pair(const SceneGeometry& scene, const Pose& X, ElementId a,
                                       ElementId b, PtcType type, const Eigen::Vector3d& start_A,
                                       const Eigen::Vector3d& start_B);

std::optional<ContactRates> contact_rates(const SceneGeometry& scene, const Pose& X,
                                          const TwistFrame& frame, const PointContact& c,
                                          long& pair_solves);

// A's outward unit normal at the contact, in A's frame (-R^T n_B).
Eigen::Vector3d normal_in_A(const Pose& X, const PointContact& c);

// Rows and targets accumulated for one step.
struct DriveSystem {
  std::vector<Eigen::Matrix<double, 1, 6>> hard;   // rows that must stay zero
  std::vector<Eigen::Matrix<double, 1, 6>> drive;  // rows driven toward `target`
  std::vector<double> target;
  void add_hard(const Eigen::MatrixXd& rows);
  void add_drive(const Eigen::MatrixXd& rows, const Eigen::VectorXd& t, double weight);
  // The least-squares drive twist in the null space of the hard rows; nullopt when the hard
  // rows leave no motion that makes progress on the drive (relative progress below 1e-6).
  std::optional<Twist> solve() const;
};

// Least-norm correction twist for residuals r with rows J (Gauss-Newton, minimum norm); zero
// when J or r is not finite, so the caller's iteration makes no progress and gives up.
Twist minimum_norm_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& r);

// Geometry of a target element on solid S (directions in S's own frame).
// The nearest point of edge `edge` of S to x near x's nearest sample: the foot of the
// perpendicular, exact to tol.solve_residual (not the nearest sample: directions toward a
// sample turn with the spacing over the distance, differently for every tracing of the same
// curve, so they would depend on the solid's frame). nullopt for an edge without samples.
std::optional<Eigen::Vector3d> nearest_point_on_edge(const Solid& S, int edge,
                                                     const Eigen::Vector3d& x,
                                                     const Tolerances& tol);
// Unit direction on the tangent plane (normal n_S) from x toward the nearest point of `el`
// (exact for an edge, nearest_point_on_edge).
std::optional<Eigen::Vector3d> direction_toward(const Solid& S, ElementId el,
                                                const Eigen::Vector3d& x,
                                                const Eigen::Vector3d& n_S, const Tolerances& tol);
// The middle of the outward normal cone of an edge or vertex at x (normalised sum of the
// normals of the surfaces through it); the face normal for a face.
Eigen::Vector3d cone_middle(const Solid& S, ElementId el, const Eigen::Vector3d& x);
// Outward normal of face `face` of S at x.
Eigen::Vector3d face_normal(const Solid& S, int face, const Eigen::Vector3d& x);
// Unit direction on the tangent plane of face `face` at x pointing from its boundary element
// `from` into the face's interior.
Eigen::Vector3d into_face(const Solid& S, int face, ElementId from, const Eigen::Vector3d& x);
// Direction (S's frame, on the tangent plane at x) in which a contact point on element `el`
// of S should move to reach `target` on the same element, scaled by the distance still to go:
// along an edge by arc length (the shorter way round a closed curve); on a face along the chord
// projected on the tangent plane, turned sideways when the target lies nearly opposite (on a
// surface of revolution the projected chord of antipodal points vanishes).
Eigen::Vector3d step_toward_on_element(const Solid& S, ElementId el, const Eigen::Vector3d& x,
                                       const Eigen::Vector3d& target, const Eigen::Vector3d& n);
// The boundary element (edge or vertex) of face `face` nearest to x; the face itself when it
// has none.
ElementId nearest_boundary(const Solid& S, ElementId face, const Eigen::Vector3d& x);
// Dimension of an element: 2 face, 1 edge, 0 vertex.
int element_dimension(ElementId el);

}  // namespace pcsg
