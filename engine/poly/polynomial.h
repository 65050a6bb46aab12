#pragma once
// A trivariate polynomial of total degree <= 4, stored densely (35 coefficients), with exact
// value, gradient and Hessian. Faces are given as g(p) <= 0 (the solid side), g(p) = 0 on the
// face's surface.
//
// The coefficients are those of the expansion about an origin o (zero unless `recentred`):
// g(p) = sum_n c_n (p - o)^e_n. A surface far from the frame's origin (a scene whose B sits
// 1e4 sizes away) has expanded coefficients ~|p|^d while g ~ 1 near it, so evaluating them
// at p cancels ~d log10(|p| / size) digits; expanded about a point near the surface the same
// function is evaluated from coordinates of the surface's own size, without cancellation.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

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

  // Coefficients about origin().
  double coeff(int i, int j, int k) const { return coeffs_[index(i, j, k)]; }
  void set_coeff(int i, int j, int k, double c);
  const std::array<double, kNumCoeffs>& coeffs() const { return coeffs_; }
  // The expansion point of the coefficients (zero unless recentred).
  const Eigen::Vector3d& origin() const { return origin_; }
  // The same function expanded about `o`: the new coefficients are the Taylor coefficients
  // at o, accumulated in extended precision and rounded once, so they are as exact as the
  // data allow. Evaluation near o is then free of the cancellation of a far expansion.
  Polynomial recentred(const Eigen::Vector3d& o) const;

  // Highest total degree with a non-zero coefficient; -1 for the zero polynomial.
  int degree() const;
  bool is_zero() const { return degree() < 0; }
  // Largest |coefficient|.
  double max_abs_coeff() const;

  // Sums and products need both operands expanded about the same origin (they throw
  // std::invalid_argument otherwise; parsed polynomials all have origin zero).
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
  // rigid motion X (x_new = R x_old + t) pass M = R^T, c = -R^T t. The result has origin zero.
  Polynomial substituted(const Eigen::Matrix3d& M, const Eigen::Vector3d& c) const;
  // The homogeneous part of degree d of the coefficients about origin() (the top degree's is
  // the same about every origin), with the same origin.
  Polynomial homogeneous_part(int d) const;

  // Readable form, e.g. "225x^2 + 100y^2 + 36z^2 - 225"; a recentred polynomial is written in
  // the shifted variables and names its origin, "x^2 + y^2 - 1 about (120000, -50000, 0)".
  std::string str() const;

 private:
  void require_same_origin(const Polynomial& o) const;
  // Rebuilds terms_ from coeffs_; every function that writes coeffs_ calls it last.
  void compile();

  std::array<double, kNumCoeffs> coeffs_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();

  // The evaluation's terms, compiled from the non-zero coefficients: k q0^e0 q1^e1 q2^e2 with
  // q = p - origin. List 0 sums to the value, lists 1-3 to the gradient, lists 4-9 to the
  // Hessian's h00 h01 h02 h11 h12 h22, each in monomial order; a derivative's k is the
  // coefficient times its exponent factors, multiplied in the order evaluate used to (so the
  // sums are bit for bit those of the term-by-term loop they replace).
  struct Term {
    double k;
    std::uint8_t e[3];
  };
  static constexpr int kLists = 10;
  std::vector<Term> terms_;
  std::array<std::uint16_t, kLists + 1> list_begin_{};
};

inline Polynomial operator*(double s, const Polynomial& p) { return p * s; }

}  // namespace pcsg
