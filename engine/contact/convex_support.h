#pragma once
// A necessary condition on contact formations from convexity: contacts that must be a
// configuration's only one.
//
// A solid lies inside every one of its inequalities (solid.h), so inside the support set of
// each element, S = {g <= 0 for every surface g through the element}. Let a contact join
// element a of A and b of B at p, with S_a and S_b convex and one of them strictly convex (no
// segment on its boundary). Near p the solids are S_a and S_b (no other surface is active
// there) and do not penetrate, so the tangent cones of S_a and S_b at p have disjoint
// interiors and a plane through p separates them, hence separates S_a from S_b. A and B can
// only meet in that plane, which meets the strictly convex set at p alone: p is the only point
// where A and B touch. Any CF holding such a pair has cardinality 1.
#include <optional>

#include "engine/contact/contact_formation.h"

namespace pcsg {

struct Convexity {
  bool convex = false;    // the set {g <= 0} (or the support set) is convex
  bool strictly = false;  // ... and its boundary holds no segment
};

// Of the set {g <= 0} for a polynomial of degree 2 (its Hessian is constant: convex when it is
// positive semidefinite; strictly when positive definite, or when its one null direction d
// is not tangent to any level set, grad g . d != 0, which rules out lines on the surface).
// `at` is a point where the surface matters (its solid's box centre): the slope grad g . d is
// compared with the gradient's size there, so that the verdict moves with the solid.
// Other degrees: not known, so {} (convex false).
Convexity quadric_convexity(const Polynomial& g, const Eigen::Vector3d& at);

// The support set of one element: convex when every surface through it is, strictly when every
// one is strictly (an intersection of strictly convex sets is strictly convex).
Convexity support_convexity(const Solid& solid, ElementId element);

// Whether a contact between a of A and b of B must be the only one: both support sets convex,
// one of them strictly.
bool lone_contact(const SceneGeometry& scene, ElementId a, ElementId b);

// For a CF of cardinality >= 2: its first entry whose elements' support sets are convex, one of
// them strictly (no configuration has that CF, see above); nullopt otherwise.
std::optional<PtcCount> lone_contact_pair(const SceneGeometry& scene, const ContactFormation& cf);

}  // namespace pcsg
