#pragma once
// Local differential geometry of boundary elements (paper Section II-A), evaluated exactly on
// the polynomials: a surface's value, gradient, Hessian and unit-normal derivative; an edge
// curve's tangent, its derivative and curvature vector; the normal cone of a solid at a point
// on an edge or vertex. The contact solvers (pair_systems.h) are built from these pieces.
#include <Eigen/Core>
#include <array>

#include "engine/geometry/solid.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

// g, grad g, Hess g at a point, with the outward unit normal n = grad g / |grad g| and its
// derivative dn/dp = (I - n n^T) Hess g / |grad g|.
struct SurfaceJet {
  double value = 0;
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
  double gradient_norm = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();

  // Without the Hessian (left zero) when `with_hessian` is false: the value, gradient and
  // normal are the same bits either way (a Newton trial reads no more, newton_solver.h).
  static SurfaceJet at(const Polynomial& g, const Eigen::Vector3d& p, bool with_hessian = true);
  // dn/dp, zero where grad g is. Formed on demand: the edge systems take only the gradients
  // and Hessians of their two surfaces (CurveJet), and most jets are theirs.
  Eigen::Matrix3d normal_derivative() const;
  // g / |grad g|: the first-order signed distance to g = 0 (> 0 outside).
  double distance_estimate() const { return value / gradient_norm; }
  // Normal curvature along the unit tangent t, positive where the face bends away from its
  // outward normal (a convex face): t^T Hess t / |grad g|.
  double normal_curvature(const Eigen::Vector3d& t) const {
    return t.dot(hessian * t) / gradient_norm;
  }
};

// The curve g1 = g2 = 0: c = grad g1 x grad g2 (unnormalised tangent), dc/dp, the unit
// tangent and the curvature vector d(tangent)/ds (normal to the tangent).
struct CurveJet {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  Eigen::Matrix3d dc = Eigen::Matrix3d::Zero();
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
  Eigen::Vector3d curvature = Eigen::Vector3d::Zero();

  // Without dc and the curvature (left zero) when `with_derivatives` is false: c and the
  // tangent read only the gradients.
  static CurveJet of(const SurfaceJet& j1, const SurfaceJet& j2, bool with_derivatives = true);
  // d(unit tangent)/dp = (I - t t^T) dc / |c|.
  Eigen::Matrix3d tangent_derivative() const;
};

Eigen::Matrix3d skew(const Eigen::Vector3d& v);  // skew(v) x = v x x

// The surfaces an element lies on: a face 1, an edge 2, a vertex 3 or more.
struct SurfaceSet {
  static constexpr int kMax = 8;
  int size = 0;
  std::array<int, kMax> index{};
  bool contains(int s) const;
  void add(int s);
  void remove(int s);
};
SurfaceSet element_surfaces(const Solid& solid, ElementId id);

// Tangent orientation convention of an edge: grad g(surface1) x grad g(surface2).
CurveJet edge_jet(const Solid& solid, int edge, const Eigen::Vector3d& p);

// Decomposes the direction d (unit) on the outward unit normals of the surfaces in `set` at p
// with non-negative coefficients (the normal cone of the solid at a point where those
// surfaces meet). `distance` is |d - N alpha| for the best alpha >= 0: zero inside the cone.
// `support` holds the surfaces with positive coefficients: the element whose normal cone
// the direction is closest to.
struct ConeFit {
  double distance = 0;
  SurfaceSet support;
};
ConeFit fit_normal_cone(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                        const Eigen::Vector3d& d);

// The unit bisector of the outward normals of the surfaces in `set` at p, made normal to
// `tangent` when that is not zero: an outward direction of the solid at an edge or vertex.
Eigen::Vector3d outward_bisector(const Solid& solid, const SurfaceSet& set,
                                 const Eigen::Vector3d& p, const Eigen::Vector3d& tangent);

// The surface (not in `set`) whose inequality p violates most, with its first-order distance
// g / |grad g|; surface -1 when p satisfies all others. Decides whether a point of an element
// is in its relative interior (paper Section II-A: the element is bounded by the others).
struct Violation {
  int surface = -1;
  double distance = 0;
};
Violation worst_violation(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p);

// worst_violation for deciding whether p leaves the face or edge on the surfaces of `set`: a
// surface through p (within `on_boundary`) whose normal there lies in the span of the set's
// normals (sine below `tangential_sine`) touches the element tangentially and does not bound
// it, so it is passed over (for a vertex's set, worst_violation itself). (B-reps have no edge where
// surfaces meet tangentially, see brep_builder: Example 1's sphere x^2 + y^2 + z^2 = 16 touches the
// paraboloid f3 at its vertex (0, 0, -4), an interior point of f3 far from edge e2, scenes/stress/
// pole_on_bottom_tip.yaml.)
Violation bounding_violation(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                             double on_boundary, double tangential_sine);

// The element of `solid` on exactly the surfaces of `set` nearest to p, preferring elements
// adjacent to `near` (the element the point came from); index -1 when there is none.
ElementId element_on_surfaces(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                              ElementId near);

}  // namespace pcsg
