#pragma once
// State identity (paper Section II-C): two witnesses of one CF are the same point-contact
// state only when a CF-compliant motion joins them; otherwise they are distinct states.
//
// Two tools: an invariant of a CF's connected regions that tells two regions apart without
// any motion (the crossing signs of e-e-cross contacts), and a joining test that is stronger
// than one straight motion (both directions, then through the midpoint of the two witnesses
// re-projected onto the CF, which lies in the region's interior far more often than the
// witnesses themselves, which transitions leave a few steps inside a boundary).
#include <tuple>
#include <vector>

#include "engine/generator/symmetry.h"
#include "engine/generator/transition_motion.h"

namespace pcsg {

// For every e-e-cross contact, its pair and the sign of (t_A x t_B) . n_B, where t_A, t_B are
// the edges' tangents (oriented by their faces' gradients, grad g1 x grad g2, so consistently
// along each whole edge) and n_B is B's outward contact normal. Along a CF-compliant motion
// the contact stays e-e-cross, t_A x t_B never vanishes (that would be e-e-touch, another
// CF) and everything is continuous, so the sign cannot change: witnesses with different
// signatures lie in different regions. Sorted, so that it compares as a multiset. Invariant
// under scaling and rigid motions of the scene (both tangents and the normal turn together).
using RegionSignature = std::vector<std::tuple<int, int, int, int, int>>;
RegionSignature region_signature(const std::vector<PointContact>& contacts);

// A witness (`pose`, its exact `contacts`) turned by `angle` about the normal of the contact
// `pivot` through its point, by CF-compliant travel in pieces: ok with the turned pose and its
// contacts in the order of `contacts` (the same pair, nearest on A), or not ok when the turn
// leaves the CF. The turn keeps that contact's point and normal and turns A's tangents there.
struct TurnedWitness {
  bool ok = false;
  Pose pose;
  std::vector<PointContact> contacts;
};
TurnedWitness turned_about_normal(const SceneGeometry& scene, const Pose& pose,
                                  const std::vector<PointContact>& contacts, int pivot,
                                  double angle, MotionCounters& counters);

// The solids' axes of revolution (symmetry.h), when they have one.
struct SceneSymmetry {
  std::optional<SymmetryAxis> B;           // in B's frame
  std::optional<SymmetryAxis> A;           // in A's frame
  std::vector<SymmetryAxis> half_turns_A;  // in A's frame (half_turn_axes)
  std::vector<SymmetryAxis> half_turns_B;  // in B's frame
  // Half turns that exchange elements (relabelling_half_turns), in each solid's frame.
  std::vector<SymmetryAxis> relabelling_A, relabelling_B;
  // Planes of mirror symmetry (mirror_planes), in each solid's frame.
  std::vector<MirrorPlane> mirrors_A, mirrors_B;
  // Where each of those maps the solid's elements, index for index (every one a map: the
  // lists above hold only symmetries whose element maps exist).
  std::vector<ElementMap> relabelling_A_elements, relabelling_B_elements;
  std::vector<ElementMap> mirror_A_elements, mirror_B_elements;
  static SceneSymmetry of(const SceneGeometry& scene);
};

// b and b turned about each half-turn axis of A and of B: the same configuration, its points
// relabelled (the targets a join may reach instead of b itself).
std::vector<Pose> symmetric_images(const Pose& b, const SceneSymmetry& symmetry);

// `a` turned about B's axis until A's centre is over b's, then about A's own axis until the
// orientations agree best (each turn only when that solid is one of revolution): the same
// contacts as `a`, placed as near `b` as the symmetries allow.
Pose aligned_by_symmetry(const SceneGeometry& scene, const Pose& a, const Pose& b,
                         const SceneSymmetry& sym);

// Whether the witnesses `a` and `b` of `cf` are shown to lie in one CF-connected region:
//  1. a CF-compliant motion (connected_within_cf) from a to b or from b to a;
//  2. when B (A) is a solid of revolution: a turned about B's axis until A's centre is over
//     b's, then about A's own axis until the orientations agree best (both turns keep every
//     contact, symmetry.h), then 1. from there;
//  2'. for each half-turn symmetry of A (of B): 1. and 2. toward b turned about its axis by
//     pi, the same configuration as b with A's (B's) points relabelled (Example 1's ellipsoid
//     across the rim: two witnesses that differ by a half turn about its long axis are joined in a
//     few steps, while every travel toward b itself runs into the dish);
//  2''. for a single e-e-cross contact, when `midpoint_levels` > 0: 1. and 2. between the
//     witnesses each turned about its contact normal until the edges cross at right angles
//     (keeping the crossing sign), where the contact is farthest from e-e-touch;
//  3. with `midpoint_levels` > 0, the pose halfway between them (positions averaged,
//     orientations slerped) projected onto `cf` and checked by exact detection serves as a
//     waypoint that each end must reach the same way (with one level fewer).
// Every accepted path is a chain of CF-compliant motions, so `true` is a proof; `false`
// proves nothing.
bool joined_within_cf(const SceneGeometry& scene, const Pose& a, const Pose& b,
                      const ContactFormation& cf, MotionCounters& counters,
                      const SceneSymmetry& symmetry = {}, int midpoint_levels = 1);

// Whether the witnesses `a` and `b` of `cf` (both with region signature `signature`) are
// joined through a roadmap of the CF's region: nodes are a, b and sample poses projected onto
// `cf` (exact contacts, no other contact, no penetration, the same signature), edges are
// CF-compliant motions between near nodes (connected_within_cf either way), tried nearest
// pair first until a and b are connected. The samples: poses interpolated between a and b,
// each also turned about A's own axes; and a and b themselves moved and turned along A's axes
// (all moving with A, so the roadmap does not depend on B's frame or the scene's unit). Every
// edge is a checked motion, so `true` is a proof; `false` proves nothing. `stats` (optional)
// receives the nodes and the motions tried. `threads`: how many projections and motions run at
// once (the answer and the counters are those of one thread).
struct RoadmapStats {
  int nodes = 0;
  int motions = 0;
};
bool joined_by_roadmap(const SceneGeometry& scene, const Pose& a, const Pose& b,
                       const ContactFormation& cf, const RegionSignature& signature,
                       MotionCounters& counters, RoadmapStats* stats = nullptr, int threads = 1);

// Whether the witnesses `a` and `b` of `cf` are joined by a walk on the CF's configurations
// toward the other: from each witness, turned by the solids' symmetries toward the other
// (aligned_by_symmetry), toward the other and each of its symmetric images, each
// piece the twist toward the goal with the part that would change the contacts' conditions
// taken out (their Jacobians), projected back onto `cf` from the contacts just left, and
// reached from the piece before by connected_within_cf; the direct travel to the goal is tried
// every few pieces. A piece that fails is halved; the walk stops where no piece brings it
// nearer the goal. For regions too narrow for straight interpolation between poses (the
// needle's {(fA-e1, 1), (fA-f1, 1)} far from the origin: every pose between the witnesses
// left the CF, and projections from them landed on other branches of the tips' contacts).
// Every piece is a checked motion, so `true` is a proof; `false` proves nothing.
bool joined_by_tangent_walk(const SceneGeometry& scene, const Pose& a, const Pose& b,
                            const ContactFormation& cf, MotionCounters& counters,
                            const SceneSymmetry& symmetry = {});

}  // namespace pcsg
