#include "engine/poly/polynomial.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace pcsg {
namespace {

// Exact arithmetic on small integers and dyadic values: round-off of a few ulps only.
constexpr double kExact = 1e-12;

Polynomial X() { return Polynomial::variable(0); }
Polynomial Y() { return Polynomial::variable(1); }
Polynomial Z() { return Polynomial::variable(2); }

TEST(Polynomial, ValueGradientHessianOfEllipsoid) {
  // 225x^2 + 100y^2 + 36z^2 - 225 (paper's Example 1, object A)
  const Polynomial g = X().pow(2) * 225 + Y().pow(2) * 100 + Z().pow(2) * 36 -
                       Polynomial::constant(225);
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
  const Eigen::Matrix3d M = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized())
                                .toRotationMatrix() * 1.7;
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
  for (const Eigen::Vector3d& q : {Eigen::Vector3d(0, 0, 4), Eigen::Vector3d(0, -4, 0),
                                  Eigen::Vector3d(4, 0, 0)}) {
    EXPECT_EQ(back.value(c + q), local.value(q));
    EXPECT_NEAR(far.value(c + q), 0, 1e-15 * far.coeff(0, 0, 0)) << "the cancellation's size";
  }
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
