#pragma once
// Differential geometry of one implicit surface g = 0 and of the curve where two meet, all from
// the polynomial's exact value, gradient and Hessian: unit normals, a pole-free tangent frame,
// principal curvatures, and Newton projections onto a surface, onto a curve g1 = g2 = 0 and onto
// the point where three surfaces meet. The solid lies on g <= 0, so grad g points outward.
#include <Eigen/Geometry>
#include <optional>

#include "engine/core/tolerances.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

// grad g / |grad g|: the outward unit normal at p; zero where the gradient vanishes.
Eigen::Vector3d unit_normal(const Polynomial& g, const Eigen::Vector3d& p);

// |g(p)| / |grad g(p)|: the first-order distance from p to g = 0 (infinite where grad g = 0).
double surface_distance(const Polynomial& g, const Eigen::Vector3d& p);

// A right-handed orthonormal frame (u, v, n) with u x v = n.
struct TangentFrame {
  Eigen::Vector3d u, v, n;
};

// A tangent frame at a unit normal n with no pole anywhere: the reference axis is the
// coordinate axis least aligned with n, so u never degenerates (unlike a frame built from a
// fixed "up" axis, which is singular where n is parallel to it: ellipsoid poles, paraboloid
// tips). The frame is piecewise smooth in n; the switch of axis is harmless for local use.
TangentFrame tangent_frame(const Eigen::Vector3d& n);
// The same at a point of g = 0 (n = unit_normal(g, p)).
TangentFrame tangent_frame(const Polynomial& g, const Eigen::Vector3d& p);

// Principal curvatures and directions. Sign convention: positive where the surface bends away
// from its outward normal (every curvature of a sphere is +1/R seen from its solid side), so
// convex faces have k1, k2 > 0 and concave ones (a dish seen from inside) negative ones.
struct PrincipalCurvatures {
  double k1 = 0, k2 = 0;   // k1 <= k2, in 1/length
  Eigen::Vector3d d1, d2;  // unit principal directions, d1 x d2 = normal
  Eigen::Vector3d normal;  // outward unit normal
};

// The shape operator (the Hessian projected onto the tangent plane, divided by |grad g|) in the
// frame's (u, v) basis: the normal curvature along t = a u + b v is [a b] S [a b]^T.
Eigen::Matrix2d shape_operator(const Polynomial& g, const Eigen::Vector3d& p,
                               const TangentFrame& frame);
// nullopt where grad g vanishes (a singular point of the surface).
std::optional<PrincipalCurvatures> principal_curvatures(const Polynomial& g,
                                                        const Eigen::Vector3d& p);

// Unit tangent of the curve g1 = g2 = 0 at p, along grad g1 x grad g2; zero where the two
// surfaces are tangent.
Eigen::Vector3d curve_tangent(const Polynomial& g1, const Polynomial& g2, const Eigen::Vector3d& p);
// |n1 x n2| at p: the sine of the angle at which the two surfaces cross.
double normals_sine(const Polynomial& g1, const Polynomial& g2, const Eigen::Vector3d& p);

// The point of g = 0 near `start` whose outward unit normal is u (unit): grad g parallel to u
// and of its sense, by Newton on g = 0 and grad g . e1 = grad g . e2 = 0 (e1, e2 orthogonal
// to u), rows scaled to lengths. It is the extreme point of a convex patch along u (a tip's
// apex) and, with u opposite a face's normal, where a strongly curved face meets that face.
// nullopt when Newton does not converge or converges to the opposite normal.
std::optional<Eigen::Vector3d> point_with_normal(const Polynomial& g, const Eigen::Vector3d& u,
                                                 const Eigen::Vector3d& start,
                                                 const Tolerances& tol);

// Result of a Newton projection.
struct Projection {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  bool converged = false;
  int iterations = 0;
  double residual = 0;  // max_i |g_i| / |grad g_i| at `point`
};

// Newton projection onto g = 0 with minimum-norm steps dp = -g grad g / |grad g|^2, halved while
// they do not reduce |g| (poor starts). Converges when the residual is below
// tol.solve_residual, within tol.solve_max_iterations steps.
Projection project_onto_surface(const Polynomial& g, const Eigen::Vector3d& start,
                                const Tolerances& tol);
// Onto the curve g1 = g2 = 0: minimum-norm Newton steps dp = -J^T (J J^T)^-1 r with the stacked
// Jacobian J = [grad g1; grad g2]. Near-tangent surfaces make J J^T near singular; its
// pseudo-inverse keeps the steps finite (convergence is then linear, and normals_sine tells).
Projection project_onto_curve(const Polynomial& g1, const Polynomial& g2,
                              const Eigen::Vector3d& start, const Tolerances& tol);
// The point where three surfaces meet (a vertex): Newton on the square 3x3 system.
Projection solve_three_surfaces(const Polynomial& g1, const Polynomial& g2, const Polynomial& g3,
                                const Eigen::Vector3d& start, const Tolerances& tol);

}  // namespace pcsg
