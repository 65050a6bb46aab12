#include "engine/poly/polynomial.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace pcsg {
namespace {

// Exact arithmetic on small integers and dyadic values: round-off of a few ulps only.
constexpr double kExact = 1e-12;

Polynomial X() { return Polynomial::variable(0); }
Polynomial Y() { return Polynomial::variable(1); }
Polynomial Z() { return Polynomial::variable(2); }

TEST(Polynomial, ValueGradientHessianOfEllipsoid) {
  // 225x^2 + 100y^2 + 36z^2 - 225 (paper's Example 1, object A)
  const Polynomial g =
      X().pow(2) * 225 + Y().pow(2) * 100 + Z().pow(2) * 36 - Polynomial::constant(225);
  EXPECT_EQ(g.degree(), 2);
  const Eigen::Vector3d p(0.5, -0.25, 2.0);
  EXPECT_NEAR(g.value(p), 225 * 0.25 + 100 * 0.0625 + 36 * 4 - 225, kExact);
  EXPECT_TRUE(g.gradient(p).isApprox(Eigen::Vector3d(450 * 0.5, 200 * -0.25, 72 * 2.0)));
  EXPECT_TRUE(g.hessian(p).isApprox(Eigen::Vector3d(450, 200, 72).asDiagonal().toDenseMatrix()));
}

TEST(Polynomial, QuarticDerivativesMatchFiniteDifferences) {
  // A torus, R = 2, r = 0.5: (x^2+y^2+z^2+R^2-r^2)^2 - 4R^2(x^2+y^2).
  const Polynomial s = X().pow(2) + Y().pow(2) + Z().pow(2) + Polynomial::constant(4 - 0.25);
  const Polynomial g = s.pow(2) - (X().pow(2) + Y().pow(2)) * 16;
  EXPECT_EQ(g.degree(), 4);
  const Eigen::Vector3d p(0.7, -1.3, 0.4);
  // Central differences with h = 1e-5 have truncation error ~h^2 * |g'''| ~ 1e-8.
  constexpr double kFiniteDifference = 1e-6;
  const double h = 1e-5;
  for (int a = 0; a < 3; ++a) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[a] = h;
    EXPECT_NEAR(g.gradient(p)[a], (g.value(p + e) - g.value(p - e)) / (2 * h), kFiniteDifference);
    const Eigen::Vector3d dg = (g.gradient(p + e) - g.gradient(p - e)) / (2 * h);
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(g.hessian(p)(b, a), dg[b], kFiniteDifference);
  }
}

TEST(Polynomial, AlongLineMatchesEvaluation) {
  const Polynomial g = X().pow(3) * Y() - Z().pow(2) * 3 + X() * 2 - Polynomial::constant(1);
  const Eigen::Vector3d p(0.3, -0.2, 1.1), d(0.5, 1.5, -0.7);
  const auto c = g.along_line(p, d);
  for (double t : {-1.0, 0.0, 0.4, 2.0}) {
    const double poly = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4])));
    EXPECT_NEAR(poly, g.value(p + t * d), kExact * 100);
  }
}

TEST(Polynomial, SubstitutionIsComposition) {
  const Polynomial g = X().pow(2) + Y().pow(2) * 4 - Z() * 3 + X() * Y() * Z();
  const Eigen::Matrix3d M =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() * 1.7;
  const Eigen::Vector3d c(0.2, -1.0, 0.5);
  const Polynomial h = g.substituted(M, c);
  const Eigen::Vector3d p(0.4, 0.9, -0.3);
  EXPECT_NEAR(h.value(p), g.value(M * p + c), 1e-12);
}

TEST(Polynomial, RecentringIsTheTaylorExpansionAboutTheNewOrigin) {
  // a quartic (a torus) moved by a small integer vector: every coefficient of the moved
  // expansion is an exact small integer or dyadic value, so recentring back is exact
  const Eigen::Vector3d c(3, -2, 1);
  const Polynomial s = X().pow(2) + Y().pow(2) + Z().pow(2) + Polynomial::constant(4 - 0.25);
  const Polynomial local = s.pow(2) - (X().pow(2) + Y().pow(2)) * 16;  // about the origin
  const Polynomial moved = local.substituted(Eigen::Matrix3d::Identity(), -c);
  const Polynomial back = moved.recentred(c);
  EXPECT_EQ(back.origin(), c);
  for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
    EXPECT_EQ(back.coeffs()[n], local.coeffs()[n]) << "coefficient " << n;
  // value, derivatives and lines at world points are the moved polynomial's
  const Eigen::Vector3d q(0.7, -1.3, 0.4), d(0.5, 1.5, -0.7);
  EXPECT_NEAR(back.value(c + q), moved.value(c + q), kExact * 100);
  EXPECT_TRUE(back.gradient(c + q).isApprox(moved.gradient(c + q), kExact));
  EXPECT_TRUE(back.hessian(c + q).isApprox(moved.hessian(c + q), kExact));
  const auto lb = back.along_line(c + q, d), lm = moved.along_line(c + q, d);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(lb[k], lm[k], kExact * 100) << k;
  // recentring again, or substituting, composes with the origin
  EXPECT_NEAR(back.recentred(c + q).value(c), back.value(c), kExact * 100);
  EXPECT_TRUE(back.recentred(Eigen::Vector3d::Zero()).origin().isZero());
  EXPECT_NEAR(back.substituted(Eigen::Matrix3d::Identity(), c).value(q), local.value(q),
              kExact * 100);
  // sums need one origin; a product by a constant keeps it
  EXPECT_THROW(back + local, std::invalid_argument);
  EXPECT_EQ((back * 2.0).origin(), c);
  EXPECT_EQ(X().recentred(Eigen::Vector3d(1, 0, 0)).str(), "x + 1 about (1, 0, 0)");
}

// Example 1's sphere moved 1.32e5 away (scenes/stress/example1_far_rotated.yaml): its
// expanded coefficients (integers up to 1.7e10) are exact, but evaluating them near the
// sphere cancels ten digits. Recentred at the sphere's centre it is x^2 + y^2 + z^2 - 16
// again, exact to the last bit near the surface.
TEST(Polynomial, RecentringAFarSphereRemovesTheCancellation) {
  const Eigen::Vector3d c(120000, -50000, 20000);
  const Polynomial local = X().pow(2) + Y().pow(2) + Z().pow(2) - Polynomial::constant(16);
  const Polynomial far = local.substituted(Eigen::Matrix3d::Identity(), -c);
  EXPECT_EQ(far.coeff(0, 0, 0), 120000.0 * 120000 + 50000.0 * 50000 + 20000.0 * 20000 - 16);
  const Polynomial back = far.recentred(c);
  for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
    EXPECT_EQ(back.coeffs()[n], local.coeffs()[n]) << "coefficient " << n;
  // at points of the sphere that c + q represents exactly: the recentred value is exact,
  // the far one is round-off of terms ~1.7e10
  for (const Eigen::Vector3d& q :
       {Eigen::Vector3d(0, 0, 4), Eigen::Vector3d(0, -4, 0), Eigen::Vector3d(4, 0, 0)}) {
    EXPECT_EQ(back.value(c + q), local.value(q));
    EXPECT_NEAR(far.value(c + q), 0, 1e-15 * far.coeff(0, 0, 0)) << "the cancellation's size";
  }
}

// The evaluation pcsg had before its terms were compiled (session 58's, unchanged since
// session 27 but for the non-zero mask): each term formed as c * exponents * powers, left to
// right, summed in monomial order. The solves' results depend on these bits, so evaluate must
// reproduce them exactly.
void evaluate_term_by_term(const Polynomial& g, const Eigen::Vector3d& p, double& v,
                           Eigen::Vector3d& grad, Eigen::Matrix3d& H) {
  double pw[3][Polynomial::kMaxDegree + 1];
  for (int a = 0; a < 3; ++a) {
    pw[a][0] = 1.0;
    const double q = p[a] - g.origin()[a];
    for (int e = 1; e <= Polynomial::kMaxDegree; ++e) pw[a][e] = pw[a][e - 1] * q;
  }
  v = 0;
  double g0 = 0, g1 = 0, g2 = 0, h00 = 0, h01 = 0, h02 = 0, h11 = 0, h12 = 0, h22 = 0;
  for (int n = 0; n < Polynomial::kNumCoeffs; ++n) {
    const double c = g.coeffs()[n];
    if (c == 0.0) continue;
    const auto e = Polynomial::exponents(n);
    const int e0 = e[0], e1 = e[1], e2 = e[2];
    const double x0 = pw[0][e0], x1 = pw[1][e1], x2 = pw[2][e2];
    v += c * x0 * x1 * x2;
    if (e0) g0 += c * e0 * pw[0][e0 - 1] * x1 * x2;
    if (e1) g1 += c * e1 * x0 * pw[1][e1 - 1] * x2;
    if (e2) g2 += c * e2 * x0 * x1 * pw[2][e2 - 1];
    if (e0 >= 2) h00 += c * e0 * (e0 - 1) * (pw[0][e0 - 2] * x1 * x2);
    if (e0 && e1) h01 += c * e0 * e1 * (pw[0][e0 - 1] * pw[1][e1 - 1] * x2);
    if (e0 && e2) h02 += c * e0 * e2 * (pw[0][e0 - 1] * x1 * pw[2][e2 - 1]);
    if (e1 >= 2) h11 += c * e1 * (e1 - 1) * (x0 * pw[1][e1 - 2] * x2);
    if (e1 && e2) h12 += c * e1 * e2 * (x0 * pw[1][e1 - 1] * pw[2][e2 - 1]);
    if (e2 >= 2) h22 += c * e2 * (e2 - 1) * (x0 * x1 * pw[2][e2 - 2]);
  }
  grad = Eigen::Vector3d(g0, g1, g2);
  H << h00, h01, h02, h01, h11, h12, h02, h12, h22;
}

// Bit for bit, NaN for NaN.
bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

TEST(Polynomial, EvaluationIsTheTermByTermSumBitForBit) {
  // Polynomials made by every operation that writes coefficients (each must leave the
  // compiled terms matching them): products and powers, sums, differences, scaling, negation,
  // recentring, substitution, homogeneous parts, set_coeff, and random dense quartics.
  const Polynomial s = X().pow(2) + Y().pow(2) + Z().pow(2) + Polynomial::constant(4 - 0.25);
  const Polynomial torus = s.pow(2) - (X().pow(2) + Y().pow(2)) * 16;
  const Polynomial ellipsoid =
      X().pow(2) * 225 + Y().pow(2) * 100 + Z().pow(2) * 36 - Polynomial::constant(225);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  std::vector<Polynomial> gs = {Polynomial(),
                                Polynomial::constant(-3.5),
                                X(),
                                -Z(),
                                ellipsoid,
                                torus,
                                torus.recentred(Eigen::Vector3d(2.1, -0.3, 0.45)),
                                ellipsoid.recentred(Eigen::Vector3d(1e4, -5e3, 1)),
                                torus.substituted(R.transpose(), Eigen::Vector3d(0.3, 1e-3, -2)),
                                torus.homogeneous_part(4),
                                torus.homogeneous_part(2),
                                ellipsoid * 1e-8 - X() * Y() * 3};
  Polynomial edited = torus;
  edited.set_coeff(1, 1, 1, -0.125);
  edited.set_coeff(4, 0, 0, 0.0);
  gs.push_back(edited);
  Polynomial with_nan = ellipsoid;
  with_nan.set_coeff(0, 1, 0, std::numeric_limits<double>::quiet_NaN());
  gs.push_back(with_nan);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int r = 0; r < 20; ++r) {
    Polynomial dense;
    for (int n = 0; n < Polynomial::kNumCoeffs; ++n) {
      const auto e = Polynomial::exponents(n);
      // A third of the coefficients zero, the rest spread over 16 orders of magnitude.
      if (rng() % 3 == 0) continue;
      dense.set_coeff(e[0], e[1], e[2], u(rng) * std::pow(10.0, 8 * u(rng)));
    }
    gs.push_back(r % 2 ? dense : dense.recentred(Eigen::Vector3d(u(rng), u(rng), u(rng)) * 50));
  }
  int compared = 0;
  for (size_t i = 0; i < gs.size(); ++i)
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3d p =
          gs[i].origin() + Eigen::Vector3d(u(rng), u(rng), u(rng)) * std::pow(10.0, 3 * u(rng));
      double v0, v1;
      Eigen::Vector3d g0, g1;
      Eigen::Matrix3d H0, H1;
      evaluate_term_by_term(gs[i], p, v0, g0, H0);
      gs[i].evaluate(p, &v1, &g1, &H1);
      bool same = same_bits(v0, v1);
      for (int a = 0; a < 3; ++a) same = same && same_bits(g0[a], g1[a]);
      for (int a = 0; a < 9; ++a) same = same && same_bits(H0(a), H1(a));
      // Each output alone is the same sum.
      same = same && same_bits(gs[i].value(p), v0);
      for (int a = 0; a < 3; ++a) same = same && same_bits(gs[i].gradient(p)[a], g0[a]);
      for (int a = 0; a < 9; ++a) same = same && same_bits(gs[i].hessian(p)(a), H0(a));
      ASSERT_TRUE(same) << "polynomial " << i << " (" << gs[i].str() << ") at (" << p.transpose()
                        << ")";
      ++compared;
    }
  EXPECT_EQ(compared, 200 * static_cast<int>(gs.size()));
}

TEST(Polynomial, DegreeOverflowThrows) {
  EXPECT_THROW(X().pow(3) * Y().pow(2), std::domain_error);
  EXPECT_THROW(X().pow(5), std::domain_error);
}

TEST(Polynomial, PrintsReadably) {
  const Polynomial g = X().pow(2) * 225 + Y().pow(2) * 100 - Polynomial::constant(225);
  EXPECT_EQ(g.str(), "225x^2 + 100y^2 - 225");
}

}  // namespace
}  // namespace pcsg
