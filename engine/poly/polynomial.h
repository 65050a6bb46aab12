#pragma once
// A trivariate polynomial of total degree <= 4, stored densely (35 coefficients), with exact
// value, gradient and Hessian. Faces are given as g(p) <= 0 (the solid side), g(p) = 0 on the
// face's surface.
#include <Eigen/Core>
#include <array>
#include <string>

namespace pcsg {

class Polynomial {
 public:
  static constexpr int kMaxDegree = 4;
  static constexpr int kNumCoeffs = 35;  // monomials x^i y^j z^k with i + j + k <= 4

  Polynomial() { coeffs_.fill(0.0); }
  static Polynomial constant(double c);
  // The coordinate x (axis 0), y (1) or z (2).
  static Polynomial variable(int axis);
  // Index of x^i y^j z^k in the coefficient array; -1 when i + j + k > kMaxDegree.
  static int index(int i, int j, int k);
  // Exponents of coefficient `idx`.
  static std::array<int, 3> exponents(int idx);

  double coeff(int i, int j, int k) const { return coeffs_[index(i, j, k)]; }
  void set_coeff(int i, int j, int k, double c) { coeffs_[index(i, j, k)] = c; }
  const std::array<double, kNumCoeffs>& coeffs() const { return coeffs_; }

  // Highest total degree with a non-zero coefficient; -1 for the zero polynomial.
  int degree() const;
  bool is_zero() const { return degree() < 0; }
  // Largest |coefficient|.
  double max_abs_coeff() const;

  Polynomial operator+(const Polynomial& o) const;
  Polynomial operator-(const Polynomial& o) const;
  Polynomial operator-() const;
  Polynomial operator*(double s) const;
  // Throws std::domain_error when the product's degree exceeds kMaxDegree.
  Polynomial operator*(const Polynomial& o) const;
  // Throws std::domain_error when the power's degree exceeds kMaxDegree.
  Polynomial pow(int n) const;

  double value(const Eigen::Vector3d& p) const;
  Eigen::Vector3d gradient(const Eigen::Vector3d& p) const;
  Eigen::Matrix3d hessian(const Eigen::Vector3d& p) const;
  // All three at once (any output may be null).
  void evaluate(const Eigen::Vector3d& p, double* value, Eigen::Vector3d* gradient,
                Eigen::Matrix3d* hessian) const;
  // Coefficients c[0..4] of the univariate t -> g(p + t d).
  std::array<double, 5> along_line(const Eigen::Vector3d& p, const Eigen::Vector3d& d) const;

  // h(x) = g(M x + c): the same surface seen through an affine change of coordinates. For a
  // rigid motion X (x_new = R x_old + t) pass M = R^T, c = -R^T t.
  Polynomial substituted(const Eigen::Matrix3d& M, const Eigen::Vector3d& c) const;
  // The homogeneous part of degree d.
  Polynomial homogeneous_part(int d) const;

  // Readable form, e.g. "225x^2 + 100y^2 + 36z^2 - 225".
  std::string str() const;

 private:
  std::array<double, kNumCoeffs> coeffs_;
};

inline Polynomial operator*(double s, const Polynomial& p) { return p * s; }

}  // namespace pcsg
