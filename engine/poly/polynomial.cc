#include "engine/poly/polynomial.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace pcsg {
namespace {

// Exponent table and reverse index, built at compile time (no guard on the evaluations' path).
struct MonomialTable {
  std::array<std::array<int, 3>, Polynomial::kNumCoeffs> exps{};
  int idx[5][5][5]{};
  constexpr MonomialTable() {
    int n = 0;
    for (int d = 0; d <= Polynomial::kMaxDegree; ++d)
      for (int i = d; i >= 0; --i)
        for (int j = d - i; j >= 0; --j) {
          const int k = d - i - j;
          exps[n] = {i, j, k};
          idx[i][j][k] = n++;
        }
  }
};

constexpr MonomialTable kTable;

constexpr const MonomialTable& table() { return kTable; }

}  // namespace

int Polynomial::index(int i, int j, int k) {
  if (i < 0 || j < 0 || k < 0 || i + j + k > kMaxDegree) return -1;
  return table().idx[i][j][k];
}

std::array<int, 3> Polynomial::exponents(int idx) { return table().exps[idx]; }

Polynomial Polynomial::constant(double c) {
  Polynomial p;
  p.coeffs_[0] = c;
  p.compile();
  return p;
}

Polynomial Polynomial::variable(int axis) {
  Polynomial p;
  int e[3] = {0, 0, 0};
  e[axis] = 1;
  p.coeffs_[index(e[0], e[1], e[2])] = 1.0;
  p.compile();
  return p;
}

int Polynomial::degree() const {
  int deg = -1;
  for (int n = 0; n < kNumCoeffs; ++n)
    if (coeffs_[n] != 0.0) {
      const auto& e = table().exps[n];
      deg = std::max(deg, e[0] + e[1] + e[2]);
    }
  return deg;
}

double Polynomial::max_abs_coeff() const {
  double m = 0;
  for (double c : coeffs_) m = std::max(m, std::abs(c));
  return m;
}

void Polynomial::require_same_origin(const Polynomial& o) const {
  if (origin_ != o.origin_)
    throw std::invalid_argument(
        "polynomials expanded about different origins cannot be "
        "combined; recentre one first");
}

Polynomial Polynomial::recentred(const Eigen::Vector3d& o) const {
  // g(p) = sum_n c_n (p - o_old)^e_n with p - o_old = q + d, q = p - o, d = o - o_old:
  // expand each power binomially, sum in long double (64-bit mantissa on x86) and round once
  const Eigen::Vector3d d = o - origin_;
  long double acc[kNumCoeffs] = {};
  long double dp[3][kMaxDegree + 1];
  for (int a = 0; a < 3; ++a) {
    dp[a][0] = 1;
    for (int e = 1; e <= kMaxDegree; ++e) dp[a][e] = dp[a][e - 1] * static_cast<long double>(d[a]);
  }
  static constexpr long double kBinomial[kMaxDegree + 1][kMaxDegree + 1] = {
      {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
  const auto& t = table();
  for (int n = 0; n < kNumCoeffs; ++n) {
    if (coeffs_[n] == 0.0) continue;
    const auto& e = t.exps[n];
    for (int i = 0; i <= e[0]; ++i)
      for (int j = 0; j <= e[1]; ++j)
        for (int k = 0; k <= e[2]; ++k)
          acc[index(i, j, k)] += static_cast<long double>(coeffs_[n]) * kBinomial[e[0]][i] *
                                 dp[0][e[0] - i] * kBinomial[e[1]][j] * dp[1][e[1] - j] *
                                 kBinomial[e[2]][k] * dp[2][e[2] - k];
  }
  Polynomial r;
  for (int n = 0; n < kNumCoeffs; ++n) r.coeffs_[n] = static_cast<double>(acc[n]);
  r.origin_ = o;
  r.compile();
  return r;
}

Polynomial Polynomial::operator+(const Polynomial& o) const {
  require_same_origin(o);
  Polynomial r;
  r.origin_ = origin_;
  for (int n = 0; n < kNumCoeffs; ++n) r.coeffs_[n] = coeffs_[n] + o.coeffs_[n];
  r.compile();
  return r;
}

Polynomial Polynomial::operator-(const Polynomial& o) const {
  require_same_origin(o);
  Polynomial r;
  r.origin_ = origin_;
  for (int n = 0; n < kNumCoeffs; ++n) r.coeffs_[n] = coeffs_[n] - o.coeffs_[n];
  r.compile();
  return r;
}

Polynomial Polynomial::operator-() const { return *this * -1.0; }

Polynomial Polynomial::operator*(double s) const {
  Polynomial r;
  r.origin_ = origin_;
  for (int n = 0; n < kNumCoeffs; ++n) r.coeffs_[n] = coeffs_[n] * s;
  r.compile();
  return r;
}

Polynomial Polynomial::operator*(const Polynomial& o) const {
  require_same_origin(o);
  const int da = degree(), db = o.degree();
  if (da < 0 || db < 0) {
    Polynomial zero;
    zero.origin_ = origin_;
    return zero;
  }
  if (da + db > kMaxDegree)
    throw std::domain_error("degree " + std::to_string(da + db) + " exceeds the maximum " +
                            std::to_string(kMaxDegree));
  Polynomial r;
  const auto& t = table();
  for (int a = 0; a < kNumCoeffs; ++a) {
    if (coeffs_[a] == 0.0) continue;
    for (int b = 0; b < kNumCoeffs; ++b) {
      if (o.coeffs_[b] == 0.0) continue;
      const int i = t.exps[a][0] + t.exps[b][0], j = t.exps[a][1] + t.exps[b][1],
                k = t.exps[a][2] + t.exps[b][2];
      r.coeffs_[index(i, j, k)] += coeffs_[a] * o.coeffs_[b];
    }
  }
  r.origin_ = origin_;
  r.compile();
  return r;
}

Polynomial Polynomial::pow(int n) const {
  if (n < 0) throw std::domain_error("negative power " + std::to_string(n));
  const int d = degree();
  if (d > 0 && d * n > kMaxDegree)
    throw std::domain_error("degree " + std::to_string(d * n) + " exceeds the maximum " +
                            std::to_string(kMaxDegree));
  Polynomial r = constant(1.0);
  r.origin_ = origin_;
  for (int k = 0; k < n; ++k) r = r * *this;
  return r;
}

void Polynomial::set_coeff(int i, int j, int k, double c) {
  coeffs_[index(i, j, k)] = c;
  compile();
}

void Polynomial::compile() {
  terms_.clear();
  const auto& t = table();
  // d[a]: how often list l differentiates axis a.
  static constexpr int kDerivatives[kLists][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                                  {2, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 2, 0},
                                                  {0, 1, 1}, {0, 0, 2}};
  for (int l = 0; l < kLists; ++l) {
    list_begin_[l] = static_cast<std::uint16_t>(terms_.size());
    const int* d = kDerivatives[l];
    // The non-zero coefficients (NaN counts as not zero) in monomial order, each whose term
    // has the derivative d.
    for (int n = 0; n < kNumCoeffs; ++n) {
      const auto& e = t.exps[n];
      if (coeffs_[n] == 0.0 || e[0] < d[0] || e[1] < d[1] || e[2] < d[2]) continue;
      // c e_a (e_a - 1) for a second derivative in a, c e_a e_b for a mixed one, in this order
      double k = coeffs_[n];
      for (int a = 0; a < 3; ++a)
        for (int m = 0; m < d[a]; ++m) k = k * (e[a] - m);
      Term term{k, {}};
      for (int a = 0; a < 3; ++a) term.e[a] = static_cast<std::uint8_t>(e[a] - d[a]);
      terms_.push_back(term);
    }
  }
  list_begin_[kLists] = static_cast<std::uint16_t>(terms_.size());
}

void Polynomial::evaluate(const Eigen::Vector3d& p, double* value, Eigen::Vector3d* gradient,
                          Eigen::Matrix3d* hessian) const {
  // Powers q^0..q^4 of each coordinate of q = p - origin. A value or gradient term is formed
  // as k * powers left to right, a Hessian term as k * (powers), and each list is summed in
  // monomial order (the solves' results depend on these bits).
  double pw[3][kMaxDegree + 1];
  for (int a = 0; a < 3; ++a) {
    pw[a][0] = 1.0;
    const double q = p[a] - origin_[a];
    for (int e = 1; e <= kMaxDegree; ++e) pw[a][e] = pw[a][e - 1] * q;
  }
  const Term* terms = terms_.data();
  auto sum = [&](int l) {
    double s = 0;
    for (int n = list_begin_[l]; n < list_begin_[l + 1]; ++n) {
      const Term& t = terms[n];
      s += t.k * pw[0][t.e[0]] * pw[1][t.e[1]] * pw[2][t.e[2]];
    }
    return s;
  };
  auto sum_second = [&](int l) {
    double s = 0;
    for (int n = list_begin_[l]; n < list_begin_[l + 1]; ++n) {
      const Term& t = terms[n];
      s += t.k * (pw[0][t.e[0]] * pw[1][t.e[1]] * pw[2][t.e[2]]);
    }
    return s;
  };
  if (value) *value = sum(0);
  if (gradient) *gradient = Eigen::Vector3d(sum(1), sum(2), sum(3));
  if (hessian) {
    const double h00 = sum_second(4), h01 = sum_second(5), h02 = sum_second(6);
    const double h11 = sum_second(7), h12 = sum_second(8), h22 = sum_second(9);
    *hessian << h00, h01, h02, h01, h11, h12, h02, h12, h22;
  }
}

double Polynomial::value(const Eigen::Vector3d& p) const {
  double v;
  evaluate(p, &v, nullptr, nullptr);
  return v;
}

Eigen::Vector3d Polynomial::gradient(const Eigen::Vector3d& p) const {
  Eigen::Vector3d g;
  evaluate(p, nullptr, &g, nullptr);
  return g;
}

Eigen::Matrix3d Polynomial::hessian(const Eigen::Vector3d& p) const {
  Eigen::Matrix3d H;
  evaluate(p, nullptr, nullptr, &H);
  return H;
}

std::array<double, 5> Polynomial::along_line(const Eigen::Vector3d& p,
                                             const Eigen::Vector3d& d) const {
  // Substitute x = p + t d: each coordinate is a degree-1 polynomial in t; multiply out.
  const Eigen::Vector3d q = p - origin_;
  std::array<double, 5> out{};
  const auto& tb = table();
  for (int n = 0; n < kNumCoeffs; ++n) {
    const double c = coeffs_[n];
    if (c == 0.0) continue;
    std::array<double, 5> acc{};
    acc[0] = c;
    int deg = 0;
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < tb.exps[n][a]; ++e) {
        // acc *= (p[a] + d[a] t)
        for (int k = deg + 1; k >= 0; --k)
          acc[k] = acc[k] * q[a] + (k > 0 ? acc[k - 1] * d[a] : 0.0);
        ++deg;
      }
    for (int k = 0; k < 5; ++k) out[k] += acc[k];
  }
  return out;
}

Polynomial Polynomial::substituted(const Eigen::Matrix3d& M, const Eigen::Vector3d& c) const {
  // h(x) = sum_n c_n (M x + c - origin)^e_n
  Polynomial lin[3];
  for (int a = 0; a < 3; ++a) {
    lin[a] = constant(c[a] - origin_[a]);
    for (int b = 0; b < 3; ++b) lin[a] = lin[a] + variable(b) * M(a, b);
  }
  Polynomial r;
  const auto& t = table();
  for (int n = 0; n < kNumCoeffs; ++n) {
    if (coeffs_[n] == 0.0) continue;
    r = r +
        lin[0].pow(t.exps[n][0]) * lin[1].pow(t.exps[n][1]) * lin[2].pow(t.exps[n][2]) * coeffs_[n];
  }
  return r;
}

Polynomial Polynomial::homogeneous_part(int d) const {
  Polynomial r;
  r.origin_ = origin_;
  const auto& t = table();
  for (int n = 0; n < kNumCoeffs; ++n)
    if (t.exps[n][0] + t.exps[n][1] + t.exps[n][2] == d) r.coeffs_[n] = coeffs_[n];
  r.compile();
  return r;
}

std::string Polynomial::str() const {
  std::string s;
  const auto& t = table();
  const char* names = "xyz";
  // Highest degree first reads like the usual notation.
  for (int d = kMaxDegree; d >= 0; --d)
    for (int n = 0; n < kNumCoeffs; ++n) {
      const auto& e = t.exps[n];
      if (e[0] + e[1] + e[2] != d || coeffs_[n] == 0.0) continue;
      const double c = coeffs_[n];
      char buf[64];
      const double a = std::abs(c);
      if (s.empty())
        s += c < 0 ? "-" : "";
      else
        s += c < 0 ? " - " : " + ";
      if (a != 1.0 || d == 0) {
        std::snprintf(buf, sizeof buf, "%.10g", a);
        s += buf;
      }
      for (int k = 0; k < 3; ++k) {
        if (e[k] == 0) continue;
        s += names[k];
        if (e[k] > 1) s += "^" + std::to_string(e[k]);
      }
    }
  if (s.empty()) s = "0";
  if (!origin_.isZero()) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " about (%.17g, %.17g, %.17g)", origin_.x(), origin_.y(),
                  origin_.z());
    s += buf;
  }
  return s;
}

}  // namespace pcsg
