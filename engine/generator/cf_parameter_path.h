#pragma once
// A join of two witnesses of one CF planned in the contact's own parameters (paper Section
// II-C: one region when a CF-compliant motion connects them), for where straight pose
// interpolation leaves the region: a single contact of a plane type (f-f, f-e, e-f,
// e-e-cross) is fixed by its point on A's element, its point on B's element, its normal's
// place in each side's normal cone (an edge's cone is the arc between its faces' normals; a
// face's is its normal) and the twist about the normal. Between two witnesses of one region
// these parameters vary in a product of intervals (for e-e-cross the twist, the crossing
// angle, stays in the half turn of its crossing sign, never reaching e-e-touch), so moving
// them together in small pieces is a candidate path that does not leave the CF by its own
// parameters; what may still cut it is another part of A meeting B. Each piece is therefore a
// waypoint projected onto the CF (exact contacts, no other contact, no penetration) and
// reached from the previous one by connected_within_cf: the chain is a checked CF-compliant
// motion, and `true` is a proof.
#include <vector>

#include "engine/generator/state_identity.h"
#include "engine/generator/transition_motion.h"

namespace pcsg {

// The parameters of one plane-type contact at a pose (the frames of each side: its point and
// its outward normal in its own frame, and a reference tangent at the point; the twist is
// the angle about n_B from B's reference tangent to A's, carried into B's frame).
struct ContactChart {
  Eigen::Vector3d p_A, p_B;            // points on the elements, own frames
  Eigen::Vector3d normal_A, normal_B;  // outward normals, own frames (normal_A = -R^T normal_B)
  Eigen::Vector3d ref_A, ref_B;        // unit reference tangents, own frames
  double twist = 0;
};

// The pose whose contact has the chart's points, normals and twist: A's frame (normal_A,
// ref_A) is turned onto B's (-normal_B, ref_B turned by `twist` about normal_B) and p_A is
// placed on p_B.
Pose pose_of_chart(const ContactChart& chart);

// The chart of contact `c` at pose X, with an edge's tangent as its side's reference tangent
// and `face_ref_A` / `face_ref_B` (projected onto the tangent plane) on a face.
ContactChart chart_of(const SceneGeometry& scene, const Pose& X, const PointContact& c,
                      const Eigen::Vector3d& face_ref_A, const Eigen::Vector3d& face_ref_B);

// Whether the witnesses a and b of `cf` are joined by a chain of waypoints along a path in
// one contact's parameters (every contact of a plane type in turn leads; with more than one
// contact the projection onto `cf` restores the others), each reached from the one before by
// connected_within_cf in either direction. The walk may end at b or at any of its symmetric
// images (the same configuration relabelled), and may start from a or from a turned by the
// solids' symmetries toward that image (aligned_by_symmetry: every contact kept), all in
// state_identity.h.
bool joined_by_parameter_path(const SceneGeometry& scene, const Pose& a, const Pose& b,
                              const ContactFormation& cf, MotionCounters& counters,
                              const SceneSymmetry& symmetry = {});

}  // namespace pcsg
