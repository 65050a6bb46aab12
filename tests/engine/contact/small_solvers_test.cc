#include "engine/contact/small_solvers.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace pcsg {
namespace {

// Equal bit for bit (so +0 and -0 differ, and a NaN equals a NaN of the same payload).
bool same_bits(double a, double b) {
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

void expect_same(const SmallVector& ours, const SmallVector& eigen, const SmallMatrix& a,
                 const std::string& what) {
  ASSERT_EQ(ours.size(), eigen.size()) << what;
  for (int i = 0; i < eigen.size(); ++i)
    EXPECT_TRUE(same_bits(ours[i], eigen[i])) << what << ", n " << a.rows() << ", entry " << i
                                              << ": " << ours[i] << " against " << eigen[i] << "\n"
                                              << a;
}

// SmallLu's solution against Eigen's PartialPivLU's, bit for bit.
void expect_as_eigen(const SmallMatrix& a, const SmallVector& b, const std::string& what) {
  expect_same(SmallLu(a).solve(b), a.partialPivLu().solve(b), a, "LU, " + what);
}

// SmallLdlt's against Eigen's LDLT's (both read the lower triangle only).
void expect_ldlt_as_eigen(const SmallMatrix& a, const SmallVector& b, const std::string& what) {
  expect_same(SmallLdlt(a).solve(b), a.ldlt().solve(b), a, "LDLT, " + what);
}

TEST(SmallLu, SolvesAsEigenDoesBitForBitOnRandomMatrices) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 400; ++trial) {
      SmallMatrix a(n, n);
      SmallVector b(n);
      for (int i = 0; i < n; ++i) {
        b[i] = u(rng);
        for (int j = 0; j < n; ++j) a(i, j) = u(rng);
      }
      expect_as_eigen(a, b, "random");
      if (HasFailure()) return;
    }
}

TEST(SmallLu, SolvesAsEigenDoesOnGradedAndNearlySingularMatrices) {
  // Rows and columns scaled over twelve decades (the Newton systems mix lengths and
  // dimensionless rows), and a matrix made nearly singular by a repeated row plus 1e-14.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), e(-6, 6);
  for (int n = 2; n <= 8; ++n)
    for (int trial = 0; trial < 300; ++trial) {
      SmallMatrix a(n, n);
      SmallVector b(n);
      for (int i = 0; i < n; ++i) {
        b[i] = u(rng) * std::pow(10.0, e(rng));
        for (int j = 0; j < n; ++j) a(i, j) = u(rng) * std::pow(10.0, e(rng));
      }
      expect_as_eigen(a, b, "graded");
      a.row(n - 1) = a.row(0) + SmallMatrix::Constant(1, n, 1e-14);
      expect_as_eigen(a, b, "nearly singular");
      if (HasFailure()) return;
    }
}

TEST(SmallLu, SolvesAsEigenDoesOnTiesZerosAndNonFiniteEntries) {
  // Ties between pivot candidates, exactly zero pivots and columns, sparse right-hand sides
  // (the solve skips zero entries), and an infinity or NaN in the matrix or the right side.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> pick(-2, 2);
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 300; ++trial) {
      SmallMatrix a(n, n);
      SmallVector b(n);
      for (int i = 0; i < n; ++i) {
        b[i] = pick(rng);  // small integers: many ties and zeros
        for (int j = 0; j < n; ++j) a(i, j) = pick(rng);
      }
      expect_as_eigen(a, b, "integers");
      SmallMatrix c = a;
      c(trial % n, (trial / 3) % n) = trial % 2 ? inf : nan;
      expect_as_eigen(c, b, "non-finite matrix entry");
      SmallVector d = b;
      d[trial % n] = trial % 2 ? -inf : nan;
      expect_as_eigen(a, d, "non-finite right side");
      if (HasFailure()) return;
    }
}

TEST(SmallLdlt, SolvesAsEigenDoesBitForBitOnDampedNormalMatrices) {
  // The solver's matrices: J^T J plus a damping times its largest diagonal, J graded over
  // six decades, the damping from 1e-12 to 1e8 (its range in newton_solver.cc).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), e(-3, 3), damp(-12, 8);
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 400; ++trial) {
      SmallMatrix j(n, n);
      SmallVector b(n);
      for (int r = 0; r < n; ++r) {
        b[r] = u(rng) * std::pow(10.0, e(rng));
        for (int c = 0; c < n; ++c) j(r, c) = u(rng) * std::pow(10.0, e(rng));
      }
      if (trial % 4 == 1) j.row(n - 1) = j.row(0);  // a singular J: only the damping lifts it
      SmallMatrix a(n, n);
      a.noalias() = j.transpose() * j;
      double scale = 1.0;
      for (int r = 0; r < n; ++r) scale = std::max(scale, a(r, r));
      a.diagonal().array() += std::pow(10.0, damp(rng)) * scale;
      expect_ldlt_as_eigen(a, b, "damped normal matrix");
      expect_ldlt_as_eigen(a, j.transpose() * b, "damped normal matrix, J^T b");
      if (HasFailure()) return;
    }
}

TEST(SmallLdlt, SolvesAsEigenDoesOnIndefiniteUnsymmetricAndDegenerateMatrices) {
  // Symmetric indefinite matrices, unsymmetric ones (the upper triangle must be ignored by
  // both), small integers (ties between diagonal pivots, zero pivots, a zero diagonal, which
  // Eigen leaves unfactorised), and infinities or NaNs.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(-2, 2);
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 300; ++trial) {
      SmallMatrix a(n, n), c(n, n);
      SmallVector b(n), d(n);
      for (int r = 0; r < n; ++r) {
        b[r] = u(rng);
        d[r] = pick(rng);
        for (int q = 0; q < n; ++q) {
          a(r, q) = u(rng);
          c(r, q) = pick(rng);
        }
      }
      expect_ldlt_as_eigen(a, b, "unsymmetric");
      const SmallMatrix sym = a + a.transpose();
      expect_ldlt_as_eigen(sym, b, "symmetric indefinite");
      const SmallMatrix isym = c + c.transpose();
      expect_ldlt_as_eigen(isym, d, "integers");
      SmallMatrix zero_diagonal = isym;
      zero_diagonal.diagonal().setZero();
      expect_ldlt_as_eigen(zero_diagonal, d, "zero diagonal");
      SmallMatrix bad = sym;
      bad(trial % n, (trial / 3) % n) = trial % 2 ? -inf : nan;
      expect_ldlt_as_eigen(bad, b, "non-finite matrix entry");
      SmallVector bad_b = b;
      bad_b[trial % n] = trial % 2 ? inf : nan;
      expect_ldlt_as_eigen(sym, bad_b, "non-finite right side");
      if (HasFailure()) return;
    }
}

// The solver's products against Eigen's, entry by entry: J^T J, J^T x and J x.
void expect_products_as_eigen(const SmallMatrix& j, const SmallVector& x, const std::string& what) {
  const SmallMatrix gram = j.transpose() * j;
  const SmallMatrix ours = small_gram(j);
  ASSERT_EQ(ours.rows(), gram.rows());
  ASSERT_EQ(ours.cols(), gram.cols());
  for (int c = 0; c < gram.cols(); ++c)
    expect_same(ours.col(c), gram.col(c), j, "J^T J, column " + std::to_string(c) + ", " + what);
  expect_same(small_transpose_times(j, x), j.transpose() * x, j, "J^T x, " + what);
  expect_same(small_times(j, x), j * x, j, "J x, " + what);
}

TEST(SmallProducts, FormAsEigenDoesBitForBitOnGradedMatrices) {
  // Entries over sixteen decades of either sign, so that the order of each sum shows in its
  // last bits (a sum in any other order differs on most entries from 4 rows on).
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u(-1, 1), e(-8, 8);
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 400; ++trial) {
      SmallMatrix j(n, n);
      SmallVector x(n);
      for (int r = 0; r < n; ++r) {
        x[r] = u(rng) * std::pow(10.0, e(rng));
        for (int c = 0; c < n; ++c) j(r, c) = u(rng) * std::pow(10.0, e(rng));
      }
      expect_products_as_eigen(j, x, "graded");
      if (HasFailure()) return;
    }
}

TEST(SmallProducts, FormAsEigenDoesOnSignedZerosAndNonFiniteEntries) {
  // Small integers and signed zeros: a sum of -0 terms is -0 in Eigen's packet sums and +0 in
  // its GEMM and GEMV sums, which start from +0. And an infinity or NaN in J or x.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = {0.0, -0.0, 1.0, -1.0, 2.0, -3.0};
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int> pick(0, 5);
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 2000; ++trial) {
      SmallMatrix j(n, n);
      SmallVector x(n);
      for (int r = 0; r < n; ++r) {
        x[r] = values[pick(rng)];
        for (int c = 0; c < n; ++c) j(r, c) = values[pick(rng)];
      }
      expect_products_as_eigen(j, x, "signed zeros");
      SmallMatrix bad = j;
      bad(trial % n, (trial / 3) % n) = trial % 2 ? -inf : nan;
      expect_products_as_eigen(bad, x, "non-finite matrix entry");
      SmallVector bad_x = x;
      bad_x[trial % n] = trial % 2 ? inf : nan;
      expect_products_as_eigen(j, bad_x, "non-finite vector entry");
      if (HasFailure()) return;
    }
}

}  // namespace
}  // namespace pcsg
