#include "engine/generator/symmetry.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace pcsg {

namespace {

// Grid points per side of the solid's box: 7^3 points give hundreds of independent rows for
// the six unknowns of an axis, on polynomials of degree <= 4.
constexpr int kGrid = 7;
// Relative size below which a singular value of the normalised conditions counts as null:
// round-off gives ~1e-15, and any genuine second axis gives exactly zero too, while the
// conditions of a non-symmetric direction are O(1).
constexpr double kNullRelative = 1e-6;

Eigen::Matrix3d rotation_about(const Eigen::Vector3d& u, double angle) {
  return Eigen::AngleAxisd(angle, u).toRotationMatrix();
}

// The centres of a kGrid^3 grid of cells over the solid's bounding box.
std::vector<Eigen::Vector3d> box_grid(const Solid& S) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      for (int k = 0; k < kGrid; ++k) {
        const Eigen::Vector3d f((i + 0.5) / kGrid, (j + 0.5) / kGrid, (k + 0.5) / kGrid);
        points.push_back(S.bbox.min() + f.cwiseProduct(S.bbox.sizes()));
      }
  return points;
}

}  // namespace

std::optional<SymmetryAxis> axis_of_revolution(const Solid& S, const Tolerances& tol) {
  if (S.surfaces.empty() || S.bbox.isEmpty()) return std::nullopt;
  // Coordinates centred on the box and in units of its diagonal, for conditioning and so
  // that the result does not depend on the scene's unit of length or placement.
  const Eigen::Vector3d centre = S.bbox.center();
  const double size = S.bbox.diagonal().norm();
  const std::vector<Eigen::Vector3d> points = box_grid(S);
  std::vector<Eigen::Matrix<double, 1, 6>> rows;
  for (const Polynomial& g : S.surfaces)
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d grad = g.gradient(p);
      const double n = grad.norm();
      if (n == 0) continue;
      const Eigen::Vector3d x = (p - centre) / size;
      Eigen::Matrix<double, 1, 6> r;
      // grad . (u x x + w) = u . (x x grad) + w . grad, with w = c x u.
      r << x.cross(grad).transpose() / n, grad.transpose() / n;
      rows.push_back(r);
    }
  if (rows.size() < 6) return std::nullopt;
  Eigen::MatrixXd M(rows.size(), 6);
  for (size_t i = 0; i < rows.size(); ++i) M.row(i) = rows[i];
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  // The smallest singular vector proposes the axis; the one-radian check below decides.
  // A second (near-)null direction means more than one axis (a ball): left out.
  if (sv(4) <= kNullRelative * sv(0)) return std::nullopt;
  const Eigen::Matrix<double, 6, 1> v = svd.matrixV().col(5);
  Eigen::Vector3d u = v.head<3>();
  if (u.norm() < 0.5) return std::nullopt;  // a translation, not a rotation
  const Eigen::Vector3d w = v.tail<3>() / u.norm();
  u.normalize();
  if (std::abs(u.dot(w)) > 1e-6) return std::nullopt;  // a screw, not a rotation
  // Deterministic orientation: the largest component positive.
  int big = 0;
  u.cwiseAbs().maxCoeff(&big);
  SymmetryAxis axis;
  axis.direction = u(big) < 0 ? -u : u;
  // w = c x u with c perpendicular to u: c = u x w.
  axis.point = centre + size * u.cross(w);
  // Confirm: every polynomial unchanged by a turn of one radian about the axis.
  const Eigen::Matrix3d R = rotation_about(axis.direction, 1.0);
  for (const Polynomial& g : S.surfaces) {
    double scale = 0, worst = 0;
    for (const Eigen::Vector3d& p : points) {
      const double a = g.value(p);
      const double b = g.value(axis.point + R * (p - axis.point));
      scale = std::max(scale, std::abs(a));
      worst = std::max(worst, std::abs(a - b));
    }
    if (worst > tol.symmetry_relative * scale) return std::nullopt;
  }
  return axis;
}

namespace {

// The element map of the affine map `image_of`, when it maps the solid onto itself: every
// surface onto a surface (checked on the grid `points`, to tol.symmetry_relative) and every
// face, edge and vertex onto one (one surface may hold several patches, two surfaces several
// curves); nullopt when it does not.
template <typename Map>
std::optional<ElementMap> maps_onto_itself(const Solid& S, const Tolerances& tol,
                                           const std::vector<Eigen::Vector3d>& points,
                                           Map&& image_of) {
  const int n_surfaces = static_cast<int>(S.surfaces.size());
  // Each surface's image: the first surface that the mapped polynomial equals.
  std::vector<int> image(n_surfaces, -1);
  for (int i = 0; i < n_surfaces; ++i) {
    const Polynomial& g = S.surfaces[i];
    for (int j = 0; j < n_surfaces && image[i] < 0; ++j) {
      double scale = 0, worst = 0;
      for (const Eigen::Vector3d& p : points) {
        const double v = g.value(p);
        scale = std::max(scale, std::abs(v));
        worst = std::max(worst, std::abs(S.surfaces[j].value(image_of(p)) - v));
      }
      if (worst <= tol.symmetry_relative * scale) image[i] = j;
    }
    if (image[i] < 0) return std::nullopt;
  }
  const double near = tol.distinct_points;
  ElementMap map;
  for (size_t f = 0; f < S.faces.size(); ++f) {
    const int to = S.face_at(image[S.faces[f].surface], image_of(S.faces[f].interior_point), near);
    if (to < 0) return std::nullopt;
    map.faces.push_back(to);
  }
  for (size_t e = 0; e < S.edges.size(); ++e) {
    const Edge& E = S.edges[e];
    if (E.samples.empty()) {
      map.edges.push_back(static_cast<int>(e));
      continue;
    }
    const Eigen::Vector3d q = image_of(E.samples[E.samples.size() / 2].point);
    int to = S.edge_at(image[E.surface1], image[E.surface2], q, near);
    if (to < 0) to = S.edge_at(image[E.surface2], image[E.surface1], q, near);
    if (to < 0) return std::nullopt;
    map.edges.push_back(to);
  }
  for (size_t v = 0; v < S.vertices.size(); ++v) {
    const Eigen::Vector3d q = image_of(S.vertices[v].point);
    int to = -1;
    for (size_t w = 0; w < S.vertices.size() && to < 0; ++w)
      if ((S.vertices[w].point - q).norm() <= near) to = static_cast<int>(w);
    if (to < 0) return std::nullopt;
    map.vertices.push_back(to);
  }
  return map;
}

std::optional<ElementMap> half_turn_map(const Solid& S, const Tolerances& tol,
                                        const std::vector<Eigen::Vector3d>& points,
                                        const SymmetryAxis& axis) {
  const Eigen::Matrix3d R = rotation_about(axis.direction, M_PI);
  const Eigen::Vector3d& c = axis.point;
  return maps_onto_itself(
      S, tol, points, [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return c + R * (p - c); });
}

// The candidate centres: the solid's origin and its box centre.
std::vector<Eigen::Vector3d> candidate_centres(const Solid& S, const Tolerances& tol) {
  std::vector<Eigen::Vector3d> centres = {Eigen::Vector3d::Zero()};
  if (S.bbox.center().norm() > tol.distinct_points) centres.push_back(S.bbox.center());
  return centres;
}

// The half turns about the candidate axes (the coordinate axes through the solid's origin and
// through its box centre; those along `revolution` left out, the continuous turn covers them)
// that map the solid onto itself. `relabelling` picks those that exchange some elements (else
// those that map every element onto itself).
std::vector<SymmetryAxis> half_turns(const Solid& S, const Tolerances& tol,
                                     const std::optional<SymmetryAxis>& revolution,
                                     bool relabelling) {
  std::vector<SymmetryAxis> out;
  if (S.surfaces.empty() || S.bbox.isEmpty()) return out;
  const std::vector<Eigen::Vector3d> points = box_grid(S);
  for (const Eigen::Vector3d& c : candidate_centres(S, tol))
    for (int a = 0; a < 3; ++a) {
      SymmetryAxis axis;
      axis.point = c;
      axis.direction = Eigen::Vector3d::Unit(a);
      if (revolution && revolution->direction.cross(axis.direction).norm() < 1e-6) continue;
      const std::optional<ElementMap> map = half_turn_map(S, tol, points, axis);
      if (map && map->identity() != relabelling) out.push_back(axis);
    }
  return out;
}

}  // namespace

ElementId ElementMap::operator()(ElementId x) const {
  const std::vector<int>& to = x.kind == ElementKind::Face   ? faces
                               : x.kind == ElementKind::Edge ? edges
                                                             : vertices;
  if (x.index >= 0 && x.index < static_cast<int>(to.size())) x.index = to[x.index];
  return x;
}

bool ElementMap::identity() const {
  for (const std::vector<int>* to : {&faces, &edges, &vertices})
    for (size_t i = 0; i < to->size(); ++i)
      if ((*to)[i] != static_cast<int>(i)) return false;
  return true;
}

ContactFormation image_cf(const ContactFormation& cf, const ElementMap* in_A,
                          const ElementMap* in_B) {
  ContactFormation image;
  for (const PtcCount& e : cf.entries())
    image.add(in_A ? (*in_A)(e.a) : e.a, in_B ? (*in_B)(e.b) : e.b, e.type, e.count);
  return image;
}

std::optional<ElementMap> half_turn_elements(const Solid& S, const Tolerances& tol,
                                             const SymmetryAxis& axis) {
  if (S.surfaces.empty() || S.bbox.isEmpty()) return std::nullopt;
  return half_turn_map(S, tol, box_grid(S), axis);
}

std::optional<ElementMap> mirror_elements(const Solid& S, const Tolerances& tol,
                                          const MirrorPlane& plane) {
  if (S.surfaces.empty() || S.bbox.isEmpty()) return std::nullopt;
  return maps_onto_itself(S, tol, box_grid(S),
                          [&](const Eigen::Vector3d& p) { return plane.reflect(p); });
}

std::vector<SymmetryAxis> half_turn_axes(const Solid& S, const Tolerances& tol,
                                         const std::optional<SymmetryAxis>& revolution) {
  return half_turns(S, tol, revolution, false);
}

std::vector<SymmetryAxis> relabelling_half_turns(const Solid& S, const Tolerances& tol,
                                                 const std::optional<SymmetryAxis>& revolution) {
  return half_turns(S, tol, revolution, true);
}

std::vector<MirrorPlane> mirror_planes(const Solid& S, const Tolerances& tol,
                                       const std::optional<SymmetryAxis>& revolution) {
  std::vector<MirrorPlane> candidates, out;
  if (S.surfaces.empty() || S.bbox.isEmpty()) return out;
  // A solid of revolution: the planes through its axis first (every one is a mirror when one
  // is; a coordinate direction picks it), then the coordinate planes.
  if (revolution)
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d n = revolution->direction.cross(Eigen::Vector3d::Unit(a));
      if (n.norm() > 0.5) candidates.push_back({revolution->point, n.normalized()});
    }
  for (const Eigen::Vector3d& c : candidate_centres(S, tol))
    for (int a = 0; a < 3; ++a) candidates.push_back({c, Eigen::Vector3d::Unit(a)});
  const std::vector<Eigen::Vector3d> points = box_grid(S);
  for (const MirrorPlane& m : candidates) {
    bool known = false;  // the same plane twice (a candidate centre on another's plane)
    for (const MirrorPlane& o : out)
      known = known || (o.normal.cross(m.normal).norm() < 1e-9 &&
                        std::abs(o.normal.dot(m.point - o.point)) <= tol.distinct_points);
    if (known) continue;
    if (maps_onto_itself(S, tol, points, [&](const Eigen::Vector3d& p) { return m.reflect(p); }))
      out.push_back(m);
  }
  return out;
}

Pose mirrored(const Pose& X, const MirrorPlane& in_A, const MirrorPlane& in_B) {
  // X' = M_B X M_A, with M(p) = L p + (c - L c) and L = I - 2 n n^T for each plane.
  const Eigen::Matrix3d LA = in_A.linear(), LB = in_B.linear();
  const Eigen::Matrix3d R = X.quaternion.toRotationMatrix();
  const Eigen::Vector3d a = in_A.point - LA * in_A.point, b = in_B.point - LB * in_B.point;
  Pose Y;
  Y.quaternion = Eigen::Quaterniond(Eigen::Matrix3d(LB * R * LA)).normalized();
  Y.position = LB * (R * a + X.position) + b;
  return Y;
}

Pose turned_about_B(const Pose& X, const SymmetryAxis& axis_B, double angle) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis_B.direction));
  Pose Y;
  Y.position = axis_B.point + q * (X.position - axis_B.point);
  Y.quaternion = (q * X.quaternion).normalized();
  return Y;
}

Pose turned_about_A(const Pose& X, const SymmetryAxis& axis_A, double angle) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis_A.direction));
  // p_B = R_X (c + q (p_A - c)) + t_X.
  Pose Y;
  Y.position = X.position + X.quaternion * (axis_A.point - q * axis_A.point);
  Y.quaternion = (X.quaternion * q).normalized();
  return Y;
}

}  // namespace pcsg
