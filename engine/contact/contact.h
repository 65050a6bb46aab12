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
// The element kinds a type joins: A's and B's.
ElementKind ptc_kind_a(PtcType t);
ElementKind ptc_kind_b(PtcType t);
// The type of a pair of element kinds; e-e gives EECross (touch is decided by the tangents).
PtcType ptc_type_between(ElementKind a, ElementKind b);
// Section II-B: f-f, f-e, e-f, f-v, v-f and e-e-cross have a contact plane; v-e, e-v and
// e-e-touch a contact line; v-v neither.
bool has_contact_plane(PtcType t);
bool has_contact_line(PtcType t);

// One isolated contact point (or near-contact, when |gap| is above the contact tolerance).
struct PointContact {
  ElementId a, b;  // A's element, B's element
  PtcType type = PtcType::FF;
  Eigen::Vector3d p_A = Eigen::Vector3d::Zero();      // A's closest point, in A's frame
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();      // B's closest point, in B's frame
  Eigen::Vector3d point_B = Eigen::Vector3d::Zero();  // contact point, B's frame (midpoint)
  // Unit, from B toward A; zero for v-v. For the types with a contact plane it is the plane's
  // normal; for v-e, e-v and e-e-touch it is the bisector of the edge's face normals (B's edge
  // for v-e and e-e-touch, A's for e-v), normal to the contact line.
  Eigen::Vector3d normal_B = Eigen::Vector3d::Zero();
  // Unit edge tangents at the contact in B's frame (zero when the element is not an edge):
  // the contact line, and the axes of the paper's task frames (Section III-B).
  Eigen::Vector3d tangent_a_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d tangent_b_B = Eigen::Vector3d::Zero();
  double gap = 0;  // signed distance: > 0 apart, < 0 penetrating
  // The contact's conditions at this pose, r(X) (ptc_codimension rows; r = 0 on the contact)
  // and their derivative with respect to a twist of A, J = dr/d(v, w), where A's points move
  // with velocity v + w x p_B (v, w in B's frame, about B's origin). For the codimension-1
  // types r = [gap] and J = [n^T, (p x n)^T] with p A's closest point in B's frame. For v-e and
  // e-v, r is the separation of the two closest points along the two unit directions normal
  // to the contact line (normal_B first); for v-v, r = the separation (x, y, z); for
  // e-e-touch, r = (separation along normal_B, along line x normal_B, misalignment of the
  // tangents across their relative curvature).
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;  // rows x 6
};

// Section II-B's contact plane (point and unit normal) and contact line (point, unit
// direction), both in B's frame; nullopt for the types that have none.
struct ContactPlane {
  Eigen::Vector3d point_B, normal_B;
};
struct ContactLine {
  Eigen::Vector3d point_B, direction_B;
};
std::optional<ContactPlane> contact_plane(const PointContact& c);
std::optional<ContactLine> contact_line(const PointContact& c);

// For an e-e-cross contact, the sign of (t_A x t_B) . n_B (+1 or -1): which way the edges
// cross. It changes only where the tangents are parallel (e-e-touch, another CF), so it is
// constant on each CF-connected region (region_signature, state_identity.h).
int crossing_sign(const PointContact& c);

struct Penetration {
  ElementId a, b;
  Eigen::Vector3d point_B = Eigen::Vector3d::Zero();  // deepest point found, B's frame
  double depth = 0;                                   // > 0
};

struct ContactReport {
  std::vector<PointContact> contacts;     // |gap| <= tol.contact_gap, canonical order
  std::vector<PointContact> near;         // local minima with gap in (contact_gap, margin]
  std::vector<Penetration> penetrations;  // empty unless A and B interpenetrate
  int failed_solves = 0;  // candidate pair solves that did not converge (diagnostics)
  // Answered from the context's recent reports (report_cache.h): no detection was run.
  bool recalled = false;
  // Cut short at its first penetration (DetectOptions::stop_at_penetration): `penetrations`
  // holds that one alone; `contacts`, `near` and `failed_solves` are left empty.
  bool cut_short = false;
  bool penetrating() const { return !penetrations.empty(); }
};

class ContactContext;    // engine/contact/contact_context.h: one FCL model per solid, built once
struct NearbyTriangles;  // contact_context.h: the triangle pairs that may overlap near a pose

struct DetectOptions {
  // Local distance minima up to this gap are reported in `near` (0: only contacts). At most
  // the context's guaranteed band (ContactContext::guaranteed_band()).
  double near_margin = 0;
  // When the pose lies within `nearby`'s margin, its overlapping triangle pairs are taken from
  // these (same result, far cheaper than a BVH query); otherwise the BVHs are queried.
  const NearbyTriangles* nearby = nullptr;
  // Whether a repeated query may be answered from the context's recent reports (benchmarks
  // that time detection itself turn this off).
  bool recall = true;
  // Stop at the first penetration found, for callers that need only whether the objects
  // penetrate and the first penetration (a motion's collision verdict): the penetrations are
  // found in a fixed order, so penetrations.front() is the full report's. Measured on Example 2
  // (session 27): 854 s to 802 s on one thread, graph.json identical but for the time.
  bool stop_at_penetration = false;
};

// All isolated contacts at the pose, each classified by the elements whose relative interiors
// hold its two closest points; two separate contacts of the same pair are reported twice.
// Thread-safe: any number of threads may query one context. A query repeated bit for bit is
// answered from the context's recent reports (report_cache.h), with `recalled` set.
ContactReport detect_contacts(const ContactContext& context, const Pose& X_BA,
                              const DetectOptions& options = {});
// The same with the scene's context from a small process-wide cache (contact_context.h:
// built on the first call for a scene, ~0.1 s for the paper's examples, then reused).
ContactReport detect_contacts(const SceneGeometry& scene, const Pose& X_BA,
                              const DetectOptions& options = {});

// Tracks one element pair's local distance problem from nearby starting points (A's point in
// A's frame, B's in B's frame): Newton on the stationarity conditions with analytic
// derivatives. `type` must join the kinds of a and b (e-e pairs: EECross or EETouch).
// Returns nullopt when it does not converge or the solution leaves the elements (then the
// contact has changed type: the caller asks the detector).
std::optional<PointContact> solve_pair(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                       ElementId b, PtcType type, const Eigen::Vector3d& start_A,
                                       const Eigen::Vector3d& start_B);

}  // namespace pcsg
