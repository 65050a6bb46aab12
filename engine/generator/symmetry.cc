#include "engine/generator/symmetry.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
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

std::vector<SymmetryAxis> half_turn_axes(const Solid& S, const Tolerances& tol,
                                         const std::optional<SymmetryAxis>& revolution) {
  std::vector<SymmetryAxis> out;
  if (S.surfaces.empty() || S.bbox.isEmpty()) return out;
  const std::vector<Eigen::Vector3d> points = box_grid(S);
  std::vector<Eigen::Vector3d> centres = {Eigen::Vector3d::Zero()};
  if (S.bbox.center().norm() > tol.distinct_points) centres.push_back(S.bbox.center());
  for (const Eigen::Vector3d& c : centres)
    for (int a = 0; a < 3; ++a) {
      SymmetryAxis axis;
      axis.point = c;
      axis.direction = Eigen::Vector3d::Unit(a);
      // parallel to the axis of revolution: the continuous turn covers it
      if (revolution && revolution->direction.cross(axis.direction).norm() < 1e-6) continue;
      const Eigen::Matrix3d R = rotation_about(axis.direction, M_PI);
      auto turned = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return c + R * (p - c); };
      bool ok = true;
      // every surface onto itself
      for (const Polynomial& g : S.surfaces) {
        double scale = 0, worst = 0;
        for (const Eigen::Vector3d& p : points) {
          const double v = g.value(p);
          scale = std::max(scale, std::abs(v));
          worst = std::max(worst, std::abs(v - g.value(turned(p))));
        }
        ok = ok && worst <= tol.symmetry_relative * scale;
      }
      // every face, edge and vertex onto itself (one surface may hold several patches, two
      // surfaces several curves)
      const double near = tol.distinct_points;
      for (size_t f = 0; ok && f < S.faces.size(); ++f)
        ok = S.face_at(S.faces[f].surface, turned(S.faces[f].interior_point), near) ==
             static_cast<int>(f);
      for (size_t e = 0; ok && e < S.edges.size(); ++e) {
        const Edge& E = S.edges[e];
        if (E.samples.empty()) continue;
        ok = S.edge_at(E.surface1, E.surface2, turned(E.samples[E.samples.size() / 2].point),
                       near) == static_cast<int>(e);
      }
      for (const Vertex& v : S.vertices) ok = ok && (turned(v.point) - v.point).norm() <= near;
      if (ok) out.push_back(axis);
    }
  return out;
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
