#pragma once
// Continuous rotational symmetry of a solid (a solid of revolution), used to prove CF
// connectivity (state_identity.h): turning A about B's axis, or about its own, maps a
// configuration onto one with the same contacts at every intermediate angle, since every
// element is mapped onto itself (a continuous family of maps starting at the identity cannot
// exchange elements). That is a CF-compliant motion (paper Section II-C) with no steps to
// check.
#include <optional>
#include <vector>

#include "engine/contact/contact_formation.h"
#include "engine/core/pose.h"
#include "engine/core/tolerances.h"
#include "engine/geometry/solid.h"

namespace pcsg {

// An axis of rotational symmetry, in the solid's own frame.
struct SymmetryAxis {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit
};

// The solid's axis of revolution, when it has exactly one. Found from the infinitesimal
// condition grad g(x) . (u x (x - c)) = 0 for every polynomial g and point x, which is linear
// in the axis's Plücker coordinates (u, c x u): the null vector of the stacked conditions at
// a grid of points over the solid's box. Confirmed by rotating each polynomial by one radian
// (tol.symmetry_relative). nullopt when there is no such axis, or more than one (a ball).
std::optional<SymmetryAxis> axis_of_revolution(const Solid& S, const Tolerances& tol);

// The axes of the solid's half-turn symmetries: turns by pi that map every surface onto
// itself (checked like the axis of revolution, on a grid, to tol.symmetry_relative) and every
// face, edge and vertex onto itself, so that the turned solid has the same elements where they
// were. Candidates are the coordinate axes through the solid's origin and through its box
// centre (solids are written in frames that show their symmetry, like Example 1's ellipsoid,
// whose three axes are all half-turn axes). Axes along `revolution` (covered by the
// continuous turn) are left out. A witness X and X turned about such an axis by pi (X R) are
// the same configuration of A, so either stands for it.
std::vector<SymmetryAxis> half_turn_axes(const Solid& S, const Tolerances& tol,
                                         const std::optional<SymmetryAxis>& revolution);

// The axes of the half turns (same candidates and checks) that map the solid onto itself but
// exchange some of its elements: Example 2's lens turned upside down, fA1 <-> fA2. X and X
// turned about such an axis are one configuration under two labellings, so a state of A's CF
// implies the state of the exchanged CF there, with the same contacts in space.
std::vector<SymmetryAxis> relabelling_half_turns(const Solid& S, const Tolerances& tol,
                                                 const std::optional<SymmetryAxis>& revolution);

// Where a symmetry of a solid puts each of its elements: faces[f], edges[e], vertices[v] are
// the indices of the elements that f, e and v are mapped onto (the identity for a symmetry
// that moves no element; fA1 <-> fA2 for Example 2's lens turned over).
struct ElementMap {
  std::vector<int> faces, edges, vertices;
  ElementId operator()(ElementId x) const;
  bool identity() const;
};

// The CF of a configuration's image under a symmetry that maps A's elements by `in_A` and B's
// by `in_B` (nullptr: that solid's elements stay): each PtC on the images of its elements,
// its type and count kept.
ContactFormation image_cf(const ContactFormation& cf, const ElementMap* in_A,
                          const ElementMap* in_B);

// The element map of the half turn about `axis` (in S's frame), when that turn maps S onto
// itself (checked as half_turn_axes does); nullopt otherwise.
std::optional<ElementMap> half_turn_elements(const Solid& S, const Tolerances& tol,
                                             const SymmetryAxis& axis);

// A plane of mirror symmetry, in the solid's own frame.
struct MirrorPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit
  Eigen::Matrix3d linear() const {
    return Eigen::Matrix3d::Identity() - 2 * normal * normal.transpose();
  }
  Eigen::Vector3d reflect(const Eigen::Vector3d& p) const {
    return p - 2 * normal.dot(p - point) * normal;
  }
};

// The planes whose reflection maps the solid onto itself (every surface onto a surface and
// every face, edge and vertex onto one, checked like the half turns). Candidates: for a solid
// of revolution, planes through its axis; the coordinate planes through the solid's origin and
// through its box centre. Example 1's ellipsoid has its three principal planes, the dish the
// planes through its axis.
std::vector<MirrorPlane> mirror_planes(const Solid& S, const Tolerances& tol,
                                       const std::optional<SymmetryAxis>& revolution);

// The mirror image of the configuration X: the scene reflected in B's plane `in_B`, A's points
// relabelled by its reflection `in_A` so that the result is a rigid placement again:
// X' = M_B X M_A. A lies where M_B puts X's A (M_A maps A onto itself), so X' touches B at
// the mirror images of X's contacts, on the images of its elements.
Pose mirrored(const Pose& X, const MirrorPlane& in_A, const MirrorPlane& in_B);

// The element map of the reflection in `plane` (in S's frame), when it maps S onto itself;
// nullopt otherwise.
std::optional<ElementMap> mirror_elements(const Solid& S, const Tolerances& tol,
                                          const MirrorPlane& plane);

// The pose reached by turning A about B's axis `axis_B` by `angle` (radians): X' = R X.
Pose turned_about_B(const Pose& X, const SymmetryAxis& axis_B, double angle);
// The pose reached by turning A about its own axis `axis_A` by `angle`: A's points move, B's
// frame stays: X' = X R_A.
Pose turned_about_A(const Pose& X, const SymmetryAxis& axis_A, double angle);

}  // namespace pcsg
