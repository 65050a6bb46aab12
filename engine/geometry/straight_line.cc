#include "engine/geometry/straight_line.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>

namespace pcsg {
namespace {

// Where the second fundamental form vanishes (planes, flat points) every tangent direction is
// asymptotic: try 12 directions 15 degrees apart plus the form's eigenvectors. A plane passes
// with any of them; a curved surface's flat point is decided by the cubic and quartic terms.
constexpr int kFlatDirections = 12;

// Unit tangent directions d at a surface point with normal `n` and Hessian `H` where the
// normal curvature d^T H d is zero to within `flat`. Empty where the form is definite.
std::vector<Eigen::Vector3d> asymptotic_directions(const Eigen::Vector3d& n,
                                                   const Eigen::Matrix3d& H, double flat) {
  const Eigen::Vector3d u = n.unitOrthogonal();
  const Eigen::Vector3d v = n.normalized().cross(u);
  Eigen::Matrix<double, 3, 2> T;
  T << u, v;
  const Eigen::Matrix2d II = T.transpose() * H * T;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(II);
  const double l0 = eig.eigenvalues()[0], l1 = eig.eigenvalues()[1];  // l0 <= l1
  const Eigen::Vector2d e0 = eig.eigenvectors().col(0), e1 = eig.eigenvectors().col(1);

  std::vector<Eigen::Vector3d> out;
  if (l0 > flat || l1 < -flat) return out;  // definite: curved along every tangent direction
  if (std::abs(l0) <= flat && std::abs(l1) <= flat) {
    for (int k = 0; k < kFlatDirections; ++k) {
      const double a = M_PI * k / kFlatDirections;
      out.push_back(std::cos(a) * u + std::sin(a) * v);
    }
    out.push_back(T * e0);
    out.push_back(T * e1);
    return out;
  }
  // l0 x^2 + l1 y^2 = 0 at (x, y) = (sqrt(l1), +-sqrt(-l0)); a zero eigenvalue gives its
  // eigenvector once
  const double a = std::sqrt(std::max(-l0, 0.0)), b = std::sqrt(std::max(l1, 0.0));
  out.push_back((T * (b * e0 + a * e1)).normalized());
  if (a > 0 && b > 0) out.push_back((T * (b * e0 - a * e1)).normalized());
  return out;
}

}  // namespace

std::optional<StraightLineWitness> find_straight_line(
    const Polynomial& g, const std::vector<Eigen::Vector3d>& surface_points, double length_scale,
    double relative_tolerance) {
  const double L = length_scale;
  for (const Eigen::Vector3d& p : surface_points) {
    Eigen::Vector3d grad;
    Eigen::Matrix3d H;
    g.evaluate(p, nullptr, &grad, &H);
    // how much g varies over the length L around p: the yardstick of every coefficient below
    const double scale = grad.norm() * L + H.norm() * L * L;
    if (!(scale > 0) || grad.norm() * L <= relative_tolerance * scale) continue;  // singular
    const double flat = relative_tolerance * scale / (L * L);
    for (const Eigen::Vector3d& d : asymptotic_directions(grad, H, flat)) {
      // g(p + t d) = sum c_k t^k; in units t = s L the k-th term is c_k L^k s^k
      const std::array<double, 5> c = g.along_line(p, d);
      double residual = 0, Lk = 1;
      for (int k = 1; k <= 4; ++k) {
        Lk *= L;
        residual = std::max(residual, std::abs(c[k]) * Lk / scale);
      }
      if (residual <= relative_tolerance) return StraightLineWitness{p, d, residual};
    }
  }
  return std::nullopt;
}

std::vector<Eigen::Vector3d> sample_surface(const Polynomial& g, const Eigen::AlignedBox3d& box,
                                            int n, unsigned seed) {
  std::vector<Eigen::Vector3d> out;
  if (n <= 0 || box.isEmpty()) return out;
  const double L = box.diagonal().norm();
  const Tolerances tol = Tolerances::for_length_scale(L > 0 ? L : 1.0);
  // mt19937's output sequence is fixed by the standard (unlike the distributions), so the
  // points are the same with every standard library
  std::mt19937 rng(seed);
  auto uniform = [&rng] { return static_cast<double>(rng()) / 4294967296.0; };
  // most starts converge inside the box for surfaces that cross it; 50 per point leaves room
  // for surfaces that fill a small corner of it
  const int max_starts = 50 * n;
  for (int start = 0; start < max_starts && static_cast<int>(out.size()) < n; ++start) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p[a] = box.min()[a] + uniform() * (box.max()[a] - box.min()[a]);
    bool converged = false;
    for (int it = 0; it < tol.solve_max_iterations; ++it) {
      double value;
      Eigen::Vector3d grad;
      g.evaluate(p, &value, &grad, nullptr);
      const double gn = grad.norm();
      if (!(gn > 0) || !std::isfinite(value)) break;  // a critical point: no direction to go
      if (std::abs(value) <= tol.solve_residual * gn) {
        converged = true;
        break;
      }
      // Newton along the gradient; a nearly flat g far from the surface would jump out of the
      // box in one step, so cap a step at half the box diagonal
      Eigen::Vector3d step = grad * (value / (gn * gn));
      const double len = step.norm();
      if (len > 0.5 * L) step *= 0.5 * L / len;
      p -= step;
    }
    if (converged && box.contains(p)) out.push_back(p);
  }
  return out;
}

}  // namespace pcsg
