#include "engine/geometry/curve_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace pcsg {

CircleFit fit_circle(const Edge& edge) {
  CircleFit fit;
  const auto& S = edge.samples;
  if (S.size() < 3) return fit;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& s : S) c += s.point;
  c /= static_cast<double>(S.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& s : S) cov += (s.point - c) * (s.point - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d u = eig.eigenvectors().col(2), v = eig.eigenvectors().col(1);
  fit.normal = eig.eigenvectors().col(0);
  if (fit.normal.dot(Eigen::Vector3d(1e-3, 2e-3, 1)) < 0) fit.normal = -fit.normal;  // stable sign
  // x^2 + y^2 + D x + E y + F = 0 in the plane's coordinates
  Eigen::MatrixXd A(S.size(), 3);
  Eigen::VectorXd b(S.size());
  for (std::size_t k = 0; k < S.size(); ++k) {
    const double x = (S[k].point - c).dot(u), y = (S[k].point - c).dot(v);
    A.row(k) << x, y, 1;
    b[k] = -(x * x + y * y);
  }
  const Eigen::Vector3d sol = A.colPivHouseholderQr().solve(b);
  const double cx = -sol[0] / 2, cy = -sol[1] / 2;
  fit.radius = std::sqrt(std::max(0.0, cx * cx + cy * cy - sol[2]));
  fit.centre = c + cx * u + cy * v;
  for (const auto& s : S) {
    const Eigen::Vector3d d = s.point - fit.centre;
    const double h = d.dot(fit.normal);
    const double r = (d - h * fit.normal).norm();
    fit.max_deviation = std::max(fit.max_deviation, std::hypot(h, r - fit.radius));
  }
  return fit;
}

}  // namespace pcsg
