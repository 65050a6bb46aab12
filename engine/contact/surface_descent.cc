#include "engine/contact/surface_descent.h"

#include <Eigen/Geometry>
#include <cmath>

#include "engine/contact/contact_classification.h"

namespace pcsg {
namespace {

// Newton iterations that put a point back on its surface after a tangent step: the step is
// at most a few percent of L, so the surface's curvature leaves an offset that three
// iterations take to round-off.
constexpr int kProjections = 4;
// First tangent step (units of L) and the smallest tried before stopping: steps adapt by
// doubling on success and halving on failure; below 1e-15 L they no longer move a point.
constexpr double kFirstStep = 1e-2;
constexpr double kSmallestStep = 1e-15;

double signed_distance(const Polynomial& g, const Eigen::Vector3d& x, Eigen::Vector3d* unit) {
  double v;
  Eigen::Vector3d grad;
  g.evaluate(x, &v, &grad, nullptr);
  const double n = grad.norm();
  if (!(n > 0)) return INFINITY;
  if (unit) *unit = grad / n;
  return v / n;
}

// p moved back onto g = 0 along the gradient (Newton on the line).
Eigen::Vector3d onto_surface(const Polynomial& g, Eigen::Vector3d p) {
  for (int k = 0; k < kProjections; ++k) {
    double v;
    Eigen::Vector3d grad;
    g.evaluate(p, &v, &grad, nullptr);
    const double n2 = grad.squaredNorm();
    if (!(n2 > 0)) break;
    p -= (v / n2) * grad;
  }
  return p;
}

// On the solid's boundary within its face: no other surface of the solid positive there.
bool within_face(const Solid& solid, int surface, const Eigen::Vector3d& p) {
  for (int i = 0; i < static_cast<int>(solid.surfaces.size()); ++i)
    if (i != surface && solid.surfaces[i].value(p) > 0) return false;
  return true;
}

}  // namespace

SurfaceDescent descend_into(const Solid& solid, int face, const Pose& X, const Solid& other,
                            int other_surface, const Eigen::Vector3d& start, double length_scale,
                            double proof_depth, int iterations) {
  const int surface = solid.faces[face].surface;
  const Polynomial& g = solid.surfaces[surface];
  const Polynomial& h = other.surfaces[other_surface];
  const Eigen::Matrix3d R_T = X.rotation().transpose();
  Eigen::Vector3d t = Eigen::Vector3d::Zero(), n_other = Eigen::Vector3d::Zero();
  SurfaceDescent cur{start, signed_distance(h, X.apply(start), &n_other)};
  double step = kFirstStep * length_scale;
  // The descent direction at cur.point, and its norm: recomputed only when the point moves (a
  // rejected step changes only the step length, so its successor would repeat the same
  // evaluations). The other surface's unit normal at an accepted point comes from the distance
  // evaluation that placed it there (the same evaluation at the same point), as does
  // cur.distance, so a point whose distance is not finite stops the descent as before.
  double tn = 0;
  bool moved = true;
  for (int it = 0; it < iterations && step > kSmallestStep * length_scale; ++it) {
    if (moved) {
      if (strictly_inside(other, X.apply(cur.point), proof_depth)) break;  // proved
      // the other surface's unit normal, in this solid's frame, less its part along the face's
      Eigen::Vector3d n_face = Eigen::Vector3d::Zero();
      if (!std::isfinite(cur.distance)) break;
      if (!std::isfinite(signed_distance(g, cur.point, &n_face))) break;
      t = R_T * n_other;
      t -= n_face * n_face.dot(t);
      tn = t.norm();
      if (!(tn > 0)) break;  // stationary: the normals are parallel
      moved = false;
    }
    const Eigen::Vector3d q = onto_surface(g, cur.point - (step / tn) * t);
    Eigen::Vector3d n_q;
    const double d = signed_distance(h, X.apply(q), &n_q);
    if (d < cur.distance && within_face(solid, surface, q)) {
      cur = {q, d};
      n_other = n_q;
      step *= 2;
      moved = true;
    } else {
      step *= 0.5;
    }
  }
  return cur;
}

}  // namespace pcsg
