#include "engine/geometry/element_extents.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/geometry/surface.h"

namespace pcsg {
namespace {

// Newton iterations for an extreme: quadratic convergence from a sample within a step needs
// < 10; 30 leaves room without hiding divergence.
constexpr int kExtremeIterations = 30;
// Samples per face used for the interior point and the largest curvature: curvature varies on
// the scale of the face, so ~500 spread samples (plus the refined extremes, where paraboloid
// tips and ellipsoid poles are) bound it well.
constexpr std::size_t kSampleSubset = 500;

// Solves F(p) = 0 from `start` by Newton with the 3x3 Jacobian J(p); false when J is singular
// (a whole curve of extremes, e.g. a horizontal circle's z) or it does not converge. The
// systems scale each row (F_i and J's row i alike) to a length at the current point: the
// Newton step is unchanged, but the LU's pivots and invertibility test no longer see the
// inequalities' arbitrary scales (a face written 1e8 times over, scenes/stress/).
template <class System>
bool newton3(System system, Eigen::Vector3d* p, double residual_tol) {
  for (int it = 0; it < kExtremeIterations; ++it) {
    Eigen::Vector3d F;
    Eigen::Matrix3d J;
    const double residual = system(*p, &F, &J);
    if (residual <= residual_tol) return true;
    Eigen::FullPivLU<Eigen::Matrix3d> lu(J);
    if (!lu.isInvertible()) return false;
    *p -= lu.solve(F);
    if (!p->allFinite()) return false;
  }
  return false;
}

double others_measure(const Solid& solid, const Eigen::Vector3d& p, int s1, int s2) {
  double m = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(solid.surfaces.size()); ++i)
    if (i != s1 && i != s2)
      m = std::max(m, solid.surfaces[i].value(p) / solid.surfaces[i].gradient(p).norm());
  return m;
}

}  // namespace

Eigen::AlignedBox3d edge_bbox(const std::vector<Polynomial>& gs, const Edge& edge,
                              const Tolerances& tol) {
  Eigen::AlignedBox3d box;
  for (const auto& s : edge.samples) box.extend(s.point);
  const Polynomial &ga = gs[edge.surface1], &gb = gs[edge.surface2];
  const int n = static_cast<int>(edge.samples.size());
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      int m = 0;
      for (int k = 1; k < n; ++k)
        if (sign * edge.samples[k].point[axis] > sign * edge.samples[m].point[axis]) m = k;
      if (!edge.closed && (m == 0 || m == n - 1)) continue;  // the extreme is an end vertex
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
      // g_a = g_b = 0 and (grad g_a x grad g_b)_axis = 0, with its exact derivative
      auto system = [&](const Eigen::Vector3d& p, Eigen::Vector3d* F, Eigen::Matrix3d* J) {
        double va = 0, vb = 0;
        Eigen::Vector3d a, b;
        Eigen::Matrix3d Ha, Hb;
        ga.evaluate(p, &va, &a, &Ha);
        gb.evaluate(p, &vb, &b, &Hb);
        const double na = a.norm(), nb = b.norm(), nab = na * nb / tol.length_scale;
        *F << va / na, vb / nb, e.dot(a.cross(b)) / nab;
        J->row(0) = a.transpose() / na;
        J->row(1) = b.transpose() / nb;
        J->row(2) = (Ha * b.cross(e) + Hb * e.cross(a)).transpose() / nab;
        return F->cwiseAbs().maxCoeff();
      };
      Eigen::Vector3d p = edge.samples[m].point;
      if (!newton3(system, &p, tol.solve_residual)) continue;
      if ((p - edge.samples[m].point).norm() > 2 * tol.edge_sample_step) continue;
      box.extend(p);
    }
  return box;
}

void compute_face_extents(Solid& solid, double search_radius, const Tolerances& tol) {
  for (int f = 0; f < static_cast<int>(solid.faces.size()); ++f) {
    Face& face = solid.faces[f];
    const Polynomial& g = solid.surfaces[face.surface];
    Eigen::AlignedBox3d box;
    for (const auto& p : face.samples) box.extend(p);
    for (int e : face.edges) box.extend(solid.edges[e].bbox);
    std::vector<Eigen::Vector3d> criticals;
    for (int axis = 0; axis < 3 && !face.samples.empty(); ++axis)
      for (int sign : {-1, 1}) {
        std::size_t m = 0;
        for (std::size_t k = 1; k < face.samples.size(); ++k)
          if (sign * face.samples[k][axis] > sign * face.samples[m][axis]) m = k;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        // g = 0 and the gradient's other two components vanish: grad g is along the axis
        auto system = [&](const Eigen::Vector3d& p, Eigen::Vector3d* F, Eigen::Matrix3d* J) {
          double val = 0;
          Eigen::Vector3d grad;
          Eigen::Matrix3d H;
          g.evaluate(p, &val, &grad, &H);
          const double gn = grad.norm(), gl = gn / tol.length_scale;
          *F << val / gn, grad[u] / gl, grad[v] / gl;
          J->row(0) = grad.transpose() / gn;
          J->row(1) = H.row(u) / gl;
          J->row(2) = H.row(v) / gl;
          return std::max(std::abs((*F)[0]), std::hypot((*F)[1], (*F)[2]));
        };
        Eigen::Vector3d p = face.samples[m];
        if (!newton3(system, &p, tol.solve_residual)) continue;
        if ((p - face.samples[m]).norm() > search_radius) continue;
        if (solid.face_at(face.surface, p, tol.on_boundary) != f) continue;
        box.extend(p);
        criticals.push_back(p);
      }
    face.bbox = box;
    // a spread subset of the samples for the interior point and the curvature bound
    std::vector<Eigen::Vector3d> subset;
    const std::size_t stride = std::max<std::size_t>(1, face.samples.size() / kSampleSubset);
    for (std::size_t k = 0; k < face.samples.size(); k += stride) subset.push_back(face.samples[k]);
    // the interior point: the sample deepest inside the other inequalities
    double best = std::numeric_limits<double>::infinity();
    for (const auto& p : subset) {
      const double m = others_measure(solid, p, face.surface, -1);
      if (m < best) {
        best = m;
        face.interior_point = p;
      }
    }
    face.max_curvature = 0;
    criticals.insert(criticals.end(), subset.begin(), subset.end());
    for (const auto& p : criticals)
      if (const auto pc = principal_curvatures(g, p))
        face.max_curvature = std::max({face.max_curvature, std::abs(pc->k1), std::abs(pc->k2)});
  }
}

}  // namespace pcsg
