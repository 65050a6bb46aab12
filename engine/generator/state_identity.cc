#include "engine/generator/state_identity.h"

#include <algorithm>
#include <cmath>

namespace pcsg {

RegionSignature region_signature(const std::vector<PointContact>& contacts) {
  RegionSignature sig;
  for (const PointContact& c : contacts) {
    if (c.type != PtcType::EECross) continue;
    const double s = c.tangent_a_B.cross(c.tangent_b_B).dot(c.normal_B);
    sig.emplace_back(static_cast<int>(c.a.kind), c.a.index, static_cast<int>(c.b.kind),
                     c.b.index, s > 0 ? 1 : -1);
  }
  std::sort(sig.begin(), sig.end());
  return sig;
}

namespace {

Pose halfway(const Pose& a, const Pose& b) {
  Pose m;
  m.position = 0.5 * (a.position + b.position);
  // Eigen's slerp takes the shorter arc (it flips the sign of a negative dot product).
  m.quaternion = a.quaternion.slerp(0.5, b.quaternion).normalized();
  return m;
}

bool moved_either_way(const SceneGeometry& scene, const Pose& a, const Pose& b,
                      const ContactFormation& cf, MotionCounters& counters) {
  return connected_within_cf(scene, a, b, cf, counters) ||
         connected_within_cf(scene, b, a, cf, counters);
}

}  // namespace

Pose aligned_by_symmetry(const SceneGeometry& scene, const Pose& a, const Pose& b,
                         const SceneSymmetry& sym) {
  Pose x = a;
  if (sym.B) {
    const Eigen::Vector3d& u = sym.B->direction;
    const Eigen::Vector3d cA = scene.A.bbox.center();
    auto radial = [&](const Pose& X) {
      Eigen::Vector3d r = X.apply(cA) - sym.B->point;
      return Eigen::Vector3d(r - u * u.dot(r));
    };
    const Eigen::Vector3d ra = radial(a), rb = radial(b);
    // A's centre on the axis: no turn aligns better than another.
    if (ra.norm() > scene.tol.distinct_points && rb.norm() > scene.tol.distinct_points)
      x = turned_about_B(x, *sym.B, std::atan2(u.dot(ra.cross(rb)), ra.dot(rb)));
  }
  if (sym.A) {
    // The turn about A's axis closest to the remaining relative rotation (its twist part).
    const Eigen::Quaterniond d = x.quaternion.conjugate() * b.quaternion;
    const double phi = 2 * std::atan2(d.vec().dot(sym.A->direction), d.w());
    x = turned_about_A(x, *sym.A, phi);
  }
  return x;
}

SceneSymmetry SceneSymmetry::of(const SceneGeometry& scene) {
  SceneSymmetry s{axis_of_revolution(scene.B, scene.tol), axis_of_revolution(scene.A, scene.tol),
                  {}, {}};
  s.half_turns_A = half_turn_axes(scene.A, scene.tol, s.A);
  s.half_turns_B = half_turn_axes(scene.B, scene.tol, s.B);
  return s;
}

bool joined_within_cf(const SceneGeometry& scene, const Pose& a, const Pose& b,
                      const ContactFormation& cf, MotionCounters& counters,
                      const SceneSymmetry& symmetry, int midpoint_levels) {
  // b and b turned about each half-turn axis of A or of B: the same configuration
  std::vector<Pose> targets = {b};
  for (const SymmetryAxis& h : symmetry.half_turns_A) targets.push_back(turned_about_A(b, h, M_PI));
  for (const SymmetryAxis& h : symmetry.half_turns_B) targets.push_back(turned_about_B(b, h, M_PI));
  for (const Pose& target : targets) {
    if (moved_either_way(scene, a, target, cf, counters)) return true;
    if (symmetry.A || symmetry.B) {
      // The turns keep every contact: the turned pose is in a's region by construction.
      const Pose t = aligned_by_symmetry(scene, a, target, symmetry);
      if (moved_either_way(scene, t, target, cf, counters)) return true;
    }
  }
  if (midpoint_levels <= 0) return false;
  // A waypoint: the pose halfway, moved onto the CF (the projection checks it by detection:
  // exactly `cf`, no penetration).
  const ProjectionResult mid = project_onto_cf(scene, halfway(a, b), cf);
  ++counters.detections;
  if (!mid.ok) return false;
  return joined_within_cf(scene, a, mid.pose, cf, counters, symmetry, midpoint_levels - 1) &&
         joined_within_cf(scene, mid.pose, b, cf, counters, symmetry, midpoint_levels - 1);
}

}  // namespace pcsg
