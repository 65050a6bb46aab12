#pragma once
// Exact point contacts between A (at pose X_BA) and B, computed on the smooth surfaces
// (paper Section II-B). Meshes only propose candidate element pairs and starting points.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/pose.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg {

// The PtC types of the paper, Section II-B. The first letter is A's element.
enum class PtcType { FF, FE, EF, EECross, EETouch, FV, VF, EV, VE, VV };
const char* ptc_type_name(PtcType t);  // "f-f", "f-e", "e-f", "e-e-cross", ... "v-v"
std::optional<PtcType> parse_ptc_type(const std::string& s);
// Number of independent scalar conditions the contact puts on the pose (its codimension in
// configuration space): 1 for f-f, f-e, e-f, e-e-cross, f-v, v-f; 2 for e-v, v-e;
// 3 for e-e-touch, v-v.
int ptc_codimension(PtcType t);

// One isolated contact point (or near-contact, when |gap| is above the contact tolerance).
struct PointContact {
  ElementId a, b;                // A's element, B's element
  PtcType type = PtcType::FF;
  Eigen::Vector3d p_A;           // A's closest point, in A's frame
  Eigen::Vector3d p_B;           // B's closest point, in B's frame
  Eigen::Vector3d point_B;       // the contact point in B's frame (midpoint of the two)
  Eigen::Vector3d normal_B;      // unit, from B toward A; zero for v-v
  double gap = 0;                // signed distance along the normal: > 0 apart, < 0 penetrating
  // The contact's conditions at this pose, r(X) (ptc_codimension rows; r = 0 on the contact)
  // and their derivative with respect to a twist of A, J = dr/d(v, w), where A's points move
  // with velocity v + w x p_B (v, w in B's frame, about B's origin). For the codimension-1
  // types r = [gap] and J = [n^T, (p x n)^T].
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;      // rows x 6
};

struct Penetration {
  ElementId a, b;
  Eigen::Vector3d point_B;       // deepest point found, B's frame
  double depth = 0;              // > 0
};

struct ContactReport {
  std::vector<PointContact> contacts;         // |gap| <= tol.contact_gap, canonical order
  std::vector<PointContact> near;             // local minima with gap in (contact_gap, margin]
  std::vector<Penetration> penetrations;      // empty unless A and B interpenetrate
  bool penetrating() const { return !penetrations.empty(); }
};

struct DetectOptions {
  // Local distance minima up to this gap are reported in `near` (0: only contacts).
  double near_margin = 0;
};

// All isolated contacts at the pose, each classified by the elements whose relative interiors
// hold its two closest points; two separate contacts of the same pair are reported twice.
ContactReport detect_contacts(const SceneGeometry& scene, const Pose& X_BA,
                              const DetectOptions& options = {});

// Tracks one element pair's local distance problem from nearby starting points (A's point in
// A's frame, B's in B's frame): Newton on the stationarity conditions with analytic
// derivatives. Returns nullopt when it does not converge or the solution leaves the elements
// (then the contact has changed type: the caller asks the detector).
std::optional<PointContact> solve_pair(const SceneGeometry& scene, const Pose& X_BA,
                                       ElementId a, ElementId b, PtcType type,
                                       const Eigen::Vector3d& start_A,
                                       const Eigen::Vector3d& start_B);

}  // namespace pcsg
