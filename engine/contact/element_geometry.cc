#include "engine/contact/element_geometry.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <vector>

namespace pcsg {
namespace {

// Round-off level of the non-negative least squares below (unit vectors, at most 8 of them):
// a multiplier or gradient within this of zero is zero.
constexpr double kNnlsRoundoff = 64 * std::numeric_limits<double>::epsilon();

// Least squares d ~ N_P z on the columns listed in `cols`.
Eigen::VectorXd least_squares(const Eigen::Matrix<double, 3, Eigen::Dynamic>& N,
                              const std::vector<int>& cols, const Eigen::Vector3d& d) {
  Eigen::MatrixXd A(3, cols.size());
  for (size_t k = 0; k < cols.size(); ++k) A.col(k) = N.col(cols[k]);
  return A.colPivHouseholderQr().solve(d);
}

}  // namespace

SurfaceJet SurfaceJet::at(const Polynomial& g, const Eigen::Vector3d& p, bool with_hessian) {
  SurfaceJet j;
  g.evaluate(p, &j.value, &j.gradient, with_hessian ? &j.hessian : nullptr);
  j.gradient_norm = j.gradient.norm();
  if (j.gradient_norm > 0) j.normal = j.gradient / j.gradient_norm;
  return j;
}

Eigen::Matrix3d SurfaceJet::normal_derivative() const {
  if (!(gradient_norm > 0)) return Eigen::Matrix3d::Zero();
  return (Eigen::Matrix3d::Identity() - normal * normal.transpose()) * hessian / gradient_norm;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

CurveJet CurveJet::of(const SurfaceJet& j1, const SurfaceJet& j2, bool with_derivatives) {
  CurveJet c;
  c.c = j1.gradient.cross(j2.gradient);
  const double n = c.c.norm();
  if (n > 0) c.tangent = c.c / n;
  if (!with_derivatives) return c;
  // d(a x b) = da x b + a x db = -[b]x H1 dp + [a]x H2 dp.
  c.dc = -skew(j2.gradient) * j1.hessian + skew(j1.gradient) * j2.hessian;
  if (n > 0) {
    const Eigen::Vector3d dcds = c.dc * c.tangent;
    c.curvature = (dcds - c.tangent * c.tangent.dot(dcds)) / n;
  }
  return c;
}

Eigen::Matrix3d CurveJet::tangent_derivative() const {
  const double n = c.norm();
  if (n == 0) return Eigen::Matrix3d::Zero();
  return (Eigen::Matrix3d::Identity() - tangent * tangent.transpose()) * dc / n;
}

bool SurfaceSet::contains(int s) const {
  for (int k = 0; k < size; ++k)
    if (index[k] == s) return true;
  return false;
}

void SurfaceSet::add(int s) {
  if (!contains(s) && size < kMax) index[size++] = s;
}

void SurfaceSet::remove(int s) {
  for (int k = 0; k < size; ++k)
    if (index[k] == s) {
      index[k] = index[--size];
      return;
    }
}

SurfaceSet element_surfaces(const Solid& solid, ElementId id) {
  SurfaceSet set;
  switch (id.kind) {
    case ElementKind::Face:
      set.add(solid.faces[id.index].surface);
      break;
    case ElementKind::Edge:
      set.add(solid.edges[id.index].surface1);
      set.add(solid.edges[id.index].surface2);
      break;
    case ElementKind::Vertex:
      for (int s : solid.vertices[id.index].surfaces) set.add(s);
      break;
  }
  return set;
}

CurveJet edge_jet(const Solid& solid, int edge, const Eigen::Vector3d& p) {
  const Edge& e = solid.edges[edge];
  return CurveJet::of(SurfaceJet::at(solid.surfaces[e.surface1], p),
                      SurfaceJet::at(solid.surfaces[e.surface2], p));
}

ConeFit fit_normal_cone(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                        const Eigen::Vector3d& d) {
  // Lawson-Hanson non-negative least squares on at most SurfaceSet::kMax unit normals.
  const int m = set.size;
  Eigen::Matrix<double, 3, Eigen::Dynamic> N(3, m);
  for (int k = 0; k < m; ++k) N.col(k) = solid.surfaces[set.index[k]].gradient(p).normalized();
  Eigen::VectorXd alpha = Eigen::VectorXd::Zero(m);
  std::vector<bool> passive(m, false);
  for (int outer = 0; outer < 3 * m + 3; ++outer) {
    const Eigen::VectorXd w = N.transpose() * (d - N * alpha);
    int j = -1;
    for (int k = 0; k < m; ++k)
      if (!passive[k] && w[k] > kNnlsRoundoff && (j < 0 || w[k] > w[j])) j = k;
    if (j < 0) break;
    passive[j] = true;
    for (int inner = 0; inner < 3 * m + 3; ++inner) {
      std::vector<int> cols;
      for (int k = 0; k < m; ++k)
        if (passive[k]) cols.push_back(k);
      const Eigen::VectorXd z = least_squares(N, cols, d);
      bool positive = true;
      for (int k = 0; k < z.size(); ++k) positive = positive && z[k] > kNnlsRoundoff;
      if (positive) {
        alpha.setZero();
        for (size_t k = 0; k < cols.size(); ++k) alpha[cols[k]] = z[k];
        break;
      }
      // Move toward z until the first passive coefficient reaches zero, and drop it.
      double t = 1;
      for (size_t k = 0; k < cols.size(); ++k)
        if (z[k] <= kNnlsRoundoff) {
          const double a = alpha[cols[k]];
          t = std::min(t, a / std::max(a - z[k], kNnlsRoundoff));
        }
      for (size_t k = 0; k < cols.size(); ++k) alpha[cols[k]] += t * (z[k] - alpha[cols[k]]);
      for (int k = 0; k < m; ++k)
        if (passive[k] && alpha[k] <= kNnlsRoundoff) {
          passive[k] = false;
          alpha[k] = 0;
        }
    }
  }
  ConeFit fit;
  fit.distance = (d - N * alpha).norm();
  for (int k = 0; k < m; ++k)
    if (alpha[k] > kNnlsRoundoff) fit.support.add(set.index[k]);
  return fit;
}

Eigen::Vector3d outward_bisector(const Solid& solid, const SurfaceSet& set,
                                 const Eigen::Vector3d& p, const Eigen::Vector3d& tangent) {
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int k = 0; k < set.size; ++k) b += solid.surfaces[set.index[k]].gradient(p).normalized();
  b -= tangent * tangent.dot(b);
  return b.normalized();
}

Violation worst_violation(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p) {
  Violation v;
  v.distance = -std::numeric_limits<double>::infinity();
  for (int s = 0; s < static_cast<int>(solid.surfaces.size()); ++s) {
    if (set.contains(s)) continue;
    double g;
    Eigen::Vector3d grad;
    solid.surfaces[s].evaluate(p, &g, &grad, nullptr);
    const double gn = grad.norm();
    // A vanishing gradient off the surface: the point is far from it on its g's side.
    const double dist = gn > 0 ? g / gn : (g > 0 ? std::numeric_limits<double>::infinity()
                                                 : -std::numeric_limits<double>::infinity());
    if (dist > v.distance) {
      v.distance = dist;
      v.surface = s;
    }
  }
  return v;
}

Violation bounding_violation(const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                             double on_boundary, double tangential_sine) {
  // Only faces and edges: a vertex's normals span every direction, and a further surface
  // through a vertex is a degenerate vertex, not a tangency.
  if (set.size == 0 || set.size >= 3) return worst_violation(solid, set, p);
  // orthonormal basis of the span of the set's normals at p
  Eigen::Matrix<double, 3, Eigen::Dynamic> N(3, set.size);
  for (int k = 0; k < set.size; ++k) N.col(k) = solid.surfaces[set.index[k]].gradient(p);
  const Eigen::MatrixXd Q =
      Eigen::HouseholderQR<Eigen::MatrixXd>(N).householderQ() * Eigen::MatrixXd::Identity(3, set.size);
  SurfaceSet skip = set;
  for (;;) {
    const Violation v = worst_violation(solid, skip, p);
    if (v.surface < 0 || std::abs(v.distance) > on_boundary || skip.size == SurfaceSet::kMax)
      return v;
    const Eigen::Vector3d n = solid.surfaces[v.surface].gradient(p).normalized();
    // distance of the unit normal from the span: the sine of its angle to it
    const double sine = (n - Q * (Q.transpose() * n)).norm();
    if (!(sine < tangential_sine)) return v;
    skip.add(v.surface);
  }
}

namespace {

bool same_surfaces(const SurfaceSet& a, const SurfaceSet& b) {
  if (a.size != b.size) return false;
  for (int k = 0; k < a.size; ++k)
    if (!b.contains(a.index[k])) return false;
  return true;
}

// The elements adjacent to `near` (its faces, edges and vertices), for preferring them.
bool adjacent_to(const Solid& solid, ElementId near, ElementId id) {
  if (near.index < 0) return false;
  auto has = [](const std::vector<int>& v, int x) {
    for (int y : v)
      if (y == x) return true;
    return false;
  };
  switch (near.kind) {
    case ElementKind::Face: {
      const Face& f = solid.faces[near.index];
      return (id.kind == ElementKind::Edge && has(f.edges, id.index)) ||
             (id.kind == ElementKind::Vertex && has(f.vertices, id.index));
    }
    case ElementKind::Edge: {
      const Edge& e = solid.edges[near.index];
      return (id.kind == ElementKind::Face && (e.face1 == id.index || e.face2 == id.index)) ||
             (id.kind == ElementKind::Vertex && has(e.vertices, id.index));
    }
    case ElementKind::Vertex: {
      const Vertex& v = solid.vertices[near.index];
      return (id.kind == ElementKind::Face && has(v.faces, id.index)) ||
             (id.kind == ElementKind::Edge && has(v.edges, id.index));
    }
  }
  return false;
}

// Distance from p to an element's representative geometry, for choosing among elements on the
// same surfaces (a surface whose solid patch is disconnected gives several faces).
double element_distance(const Solid& solid, ElementId id, const Eigen::Vector3d& p) {
  switch (id.kind) {
    case ElementKind::Face: {
      const Face& f = solid.faces[id.index];
      return f.bbox.isEmpty() ? (f.interior_point - p).norm() : f.bbox.exteriorDistance(p);
    }
    case ElementKind::Edge: {
      double best = std::numeric_limits<double>::infinity();
      for (const CurveSample& s : solid.edges[id.index].samples)
        best = std::min(best, (s.point - p).squaredNorm());
      return std::sqrt(best);
    }
    case ElementKind::Vertex:
      return (solid.vertices[id.index].point - p).norm();
  }
  return 0;
}

}  // namespace

ElementId element_on_surfaces(const Solid& solid, const SurfaceSet& set,
                              const Eigen::Vector3d& p, ElementId near) {
  ElementId best{ElementKind::Face, -1};
  double best_score = std::numeric_limits<double>::infinity();
  auto consider = [&](ElementId id) {
    // Adjacent elements win outright; among the others the nearest.
    const double score =
        adjacent_to(solid, near, id) ? -1.0 : element_distance(solid, id, p);
    if (score < best_score) {
      best_score = score;
      best = id;
    }
  };
  if (set.size == 1) {
    for (int f = 0; f < static_cast<int>(solid.faces.size()); ++f)
      if (solid.faces[f].surface == set.index[0]) consider({ElementKind::Face, f});
  } else if (set.size == 2) {
    for (int e = 0; e < static_cast<int>(solid.edges.size()); ++e) {
      SurfaceSet es = element_surfaces(solid, {ElementKind::Edge, e});
      if (same_surfaces(es, set)) consider({ElementKind::Edge, e});
    }
  } else if (set.size >= 3) {
    for (int v = 0; v < static_cast<int>(solid.vertices.size()); ++v) {
      bool all = true;
      for (int k = 0; k < set.size; ++k) {
        bool found = false;
        for (int s : solid.vertices[v].surfaces) found = found || s == set.index[k];
        all = all && found;
      }
      if (all) consider({ElementKind::Vertex, v});
    }
  }
  return best;
}

}  // namespace pcsg
