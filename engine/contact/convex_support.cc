#include "engine/contact/convex_support.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "engine/contact/element_geometry.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg {

Convexity quadric_convexity(const Polynomial& g, const Eigen::Vector3d& at) {
  if (g.degree() != 2) return {};
  // Constant for a quadric; evaluated at its expansion point.
  const Eigen::Matrix3d H = g.hessian(g.origin());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(H);
  const Eigen::Vector3d lambda = eig.eigenvalues();  // increasing
  const double scale = lambda.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return {};
  // The eigenvalues of a constant symmetric 3x3 matrix are exact to a few ulps of its norm:
  // 64 ulps tell a true zero (a paraboloid's axis) from round-off, and any negative value
  // beyond them (a saddle, however flat) makes the set non-convex.
  const double round_off = 64 * std::numeric_limits<double>::epsilon() * scale;
  Convexity out;
  if (lambda[0] < -round_off) return out;
  out.convex = true;
  if (lambda[0] > round_off) {
    out.strictly = true;
  } else if (lambda[1] > round_off) {
    // One null direction d: along it g is linear with slope grad g . d, the same everywhere
    // (H d = 0). A slope well above round-off (1e-6 of the gradient's size at `at`) means no
    // line lies on the surface (a paraboloid); a zero slope is a cylinder. A slope below that
    // is taken as a cylinder: the answer errs toward "not strictly", which prunes nothing.
    const Eigen::Vector3d d = eig.eigenvectors().col(0);
    const Eigen::Vector3d grad = g.gradient(at);
    constexpr double kSlopeRelative = 1e-6;
    out.strictly = std::abs(grad.dot(d)) > kSlopeRelative * grad.norm() && grad.norm() > 0;
  }
  return out;
}

Convexity support_convexity(const Solid& solid, ElementId element) {
  const SurfaceSet set = element_surfaces(solid, element);
  if (set.size == 0) return {};
  Convexity out{true, true};
  for (int k = 0; k < set.size; ++k) {
    const Convexity c = quadric_convexity(solid.surfaces[set.index[k]], solid.bbox.center());
    out.convex = out.convex && c.convex;
    out.strictly = out.strictly && c.strictly;
  }
  out.strictly = out.strictly && out.convex;
  return out;
}

bool lone_contact(const SceneGeometry& scene, ElementId a, ElementId b) {
  const Convexity ca = support_convexity(scene.A, a), cb = support_convexity(scene.B, b);
  return ca.convex && cb.convex && (ca.strictly || cb.strictly);
}

std::optional<PtcCount> lone_contact_pair(const SceneGeometry& scene, const ContactFormation& cf) {
  if (cf.cardinality() < 2) return std::nullopt;
  for (const PtcCount& e : cf.entries())
    if (lone_contact(scene, e.a, e.b)) return e;
  return std::nullopt;
}

}  // namespace pcsg
