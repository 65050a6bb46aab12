#pragma once
// The two factorisations of the Newton solver (newton_solver.cc) for its matrices of at most 8
// rows: LU with partial pivoting, and the pivoted LDL^T of a symmetric matrix; and the three
// products of its Levenberg-Marquardt steps (J^T J, J^T x, J x) below. Each does the
// same arithmetic, in the same order, as Eigen 3.4 does on a dynamic-size matrix
// (PartialPivLU's unblocked factorisation, taken below 17 rows; LDLT's; their triangular
// solves in one panel of 8, the GEMV and the vectorised sums inside them as SSE2 forms them),
// so every result equals Eigen's bit for bit and every graph stays the same. What is left out
// is what the solver never reads and Eigen forms on every call: the L1 norms kept for rcond(),
// the permutation matrix built from the transpositions, the sign and info flags, the GEMM
// kernel's packing of its operands, and Eigen's dispatch for general sizes.
// tests/engine/contact/small_solvers_test.cc compares each with Eigen, bit for bit, on random,
// graded, nearly singular, integer (ties, zero pivots, signed zeros) and non-finite matrices. Built
// for x86-64 without FMA (the project's flags): with FMA Eigen's GEMV would fuse its multiply-adds,
// and that test would say so. The kernels take the size as a template argument (one instance per
// size 1-8), and every loop in them is unrolled in full (`#pragma GCC unroll 8`: none runs more
// than 8 times), so each kernel is straight-line code for its size. GCC's -O3 otherwise
// vectorises the short inner loops, whose trip counts then depend on the outer loop's index, and
// the solves took 2.5-3 times as long (session 60: an 8-row LDL^T solve 90 ns rolled, 32 ns
// unrolled). The operations and their order are the same either way.
#include <Eigen/Core>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <type_traits>
#include <utility>

#include "engine/contact/newton_solver.h"

namespace pcsg {
namespace small_solvers_detail {

// Calls f(std::integral_constant<int, n>) for n in 1..8 (nothing for other n).
template <int N = 1, typename F>
void with_size(int n, F&& f) {
  if constexpr (N <= 8) {
    if (n == N)
      f(std::integral_constant<int, N>{});
    else
      with_size<N + 1>(n, f);
  }
}

// Column-major N x N in a[i + N j].
template <int N>
inline double& at(double* a, int i, int j) {
  return a[i + N * j];
}
template <int N>
inline double at(const double* a, int i, int j) {
  return a[i + N * j];
}

template <int N>
void lu_factor(double* a, int* transposition) {
#pragma GCC unroll 8
  for (int k = 0; k < N; ++k) {
    // The first row of the largest |entry| in column k at or below the diagonal (Eigen's
    // maxCoeff visitor: a later entry replaces it only when strictly larger; NaN never).
    int pivot = k;
    double biggest = std::abs(at<N>(a, k, k));
#pragma GCC unroll 8
    for (int i = k + 1; i < N; ++i) {
      const double v = std::abs(at<N>(a, i, k));
      if (v > biggest) {
        biggest = v;
        pivot = i;
      }
    }
    transposition[k] = pivot;
    if (biggest != 0.0) {
      if (pivot != k)
#pragma GCC unroll 8
        for (int j = 0; j < N; ++j) std::swap(at<N>(a, k, j), at<N>(a, pivot, j));
      const double d = at<N>(a, k, k);
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) at<N>(a, i, k) /= d;
    }
// The rank-one update, column by column: a_ij - a_kj * a_ik (Eigen's outer product).
#pragma GCC unroll 8
    for (int j = k + 1; j < N; ++j) {
      const double r = at<N>(a, k, j);
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) at<N>(a, i, j) -= r * at<N>(a, i, k);
    }
  }
}

// P applied as the transpositions in order (Eigen forms the permutation from them and applies
// it: the same entries land in the same places).
template <int N>
void permute(const int* transposition, double* x) {
#pragma GCC unroll 8
  for (int k = 0; k < N; ++k)
    if (transposition[k] != k) std::swap(x[k], x[transposition[k]]);
}

// L y = x in place, L unit lower, column by column. A zero entry is skipped as Eigen skips it
// (which keeps an infinity or NaN in the matrix from reaching a zero entry of the solution).
template <int N>
void unit_lower_solve(const double* a, double* x) {
#pragma GCC unroll 8
  for (int i = 0; i < N; ++i) {
    if (x[i] == 0.0) continue;
    const double xi = x[i];
#pragma GCC unroll 8
    for (int s = i + 1; s < N; ++s) x[s] -= xi * at<N>(a, s, i);
  }
}

template <int N>
void lu_solve(const double* a, const int* transposition, double* x) {
  permute<N>(transposition, x);
  unit_lower_solve<N>(a, x);
#pragma GCC unroll 8
  for (int i = N - 1; i >= 0; --i) {  // U, column by column from the last
    if (x[i] == 0.0) continue;
    x[i] /= at<N>(a, i, i);
    const double xi = x[i];
#pragma GCC unroll 8
    for (int s = 0; s < i; ++s) x[s] -= xi * at<N>(a, s, i);
  }
}

// sum_i a_i b_i as Eigen 3.4 sums a contiguous product with SSE2 (two-wide packets, two
// packet accumulators from four terms on, the pair added last, the odd term after).
inline double packet_dot(const double* a, const double* b, int k) {
  const int pairs = k / 2 * 2, quads = k / 4 * 4;
  if (pairs == 0) return a[0] * b[0];
  double p0 = a[0] * b[0], q0 = a[1] * b[1];
  if (pairs > 2) {
    double p1 = a[2] * b[2], q1 = a[3] * b[3];
#pragma GCC unroll 8
    for (int i = 4; i < quads; i += 4) {
      p0 = p0 + a[i] * b[i];
      q0 = q0 + a[i + 1] * b[i + 1];
      p1 = p1 + a[i + 2] * b[i + 2];
      q1 = q1 + a[i + 3] * b[i + 3];
    }
    p0 = p0 + p1;
    q0 = q0 + q1;
    if (pairs > quads) {
      p0 = p0 + a[quads] * b[quads];
      q0 = q0 + a[quads + 1] * b[quads + 1];
    }
  }
  double res = p0 + q0;
#pragma GCC unroll 8
  for (int i = pairs; i < k; ++i) res = res + a[i] * b[i];
  return res;
}

template <int N>
void ldlt_factor(double* m, int* transposition) {
#pragma GCC unroll 8
  for (int k = 0; k < N; ++k) transposition[k] = k;
  if (N <= 1) return;  // Eigen factorises nothing below two rows
  double temp[N];
#pragma GCC unroll 8
  for (int k = 0; k < N; ++k) {
    // The largest |diagonal entry| at or after k, moved to k by a symmetric swap of the
    // lower triangle.
    int big = k;
    double biggest = std::abs(at<N>(m, k, k));
#pragma GCC unroll 8
    for (int i = k + 1; i < N; ++i) {
      const double v = std::abs(at<N>(m, i, i));
      if (v > biggest) {
        biggest = v;
        big = i;
      }
    }
    transposition[k] = big;
    if (big != k) {
#pragma GCC unroll 8
      for (int j = 0; j < k; ++j) std::swap(at<N>(m, k, j), at<N>(m, big, j));
#pragma GCC unroll 8
      for (int i = big + 1; i < N; ++i) std::swap(at<N>(m, i, k), at<N>(m, i, big));
      std::swap(at<N>(m, k, k), at<N>(m, big, big));
#pragma GCC unroll 8
      for (int i = k + 1; i < big; ++i) {
        const double t = at<N>(m, i, k);
        at<N>(m, i, k) = at<N>(m, big, i);
        at<N>(m, big, i) = t;
      }
    }
    const int rest = N - k - 1;
    if (k > 0) {
#pragma GCC unroll 8
      for (int j = 0; j < k; ++j) temp[j] = at<N>(m, j, j) * at<N>(m, k, j);
      // The row times temp, summed in order (a strided row: Eigen does not vectorise it).
      double d = at<N>(m, k, 0) * temp[0];
#pragma GCC unroll 8
      for (int j = 1; j < k; ++j) d = d + at<N>(m, k, j) * temp[j];
      at<N>(m, k, k) -= d;
      if (rest == 1) {
        // One row: Eigen's GEMV falls back to the same in-order dot product.
        double r = at<N>(m, k + 1, 0) * temp[0];
#pragma GCC unroll 8
        for (int j = 1; j < k; ++j) r = r + at<N>(m, k + 1, j) * temp[j];
        at<N>(m, k + 1, k) += -1.0 * r;
      } else if (rest > 1) {
// Eigen's column-major GEMV with alpha = -1: each row's sum formed from zero, in
// column order, then added scaled.
#pragma GCC unroll 8
        for (int i = k + 1; i < N; ++i) {
          double c = 0.0;
#pragma GCC unroll 8
          for (int j = 0; j < k; ++j) c = at<N>(m, i, j) * temp[j] + c;
          at<N>(m, i, k) = c * -1.0 + at<N>(m, i, k);
        }
      }
    }
    const double akk = at<N>(m, k, k);
    const bool pivot_is_valid = std::abs(akk) > 0.0;
    if (k == 0 && !pivot_is_valid) {
// A zero diagonal: Eigen stops here, with no permutation, the matrix as it stands.
#pragma GCC unroll 8
      for (int j = 0; j < N; ++j) transposition[j] = j;
      return;
    }
    if (rest > 0 && pivot_is_valid)
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) at<N>(m, i, k) /= akk;
  }
}

template <int N>
void ldlt_solve(const double* m, const int* transposition, double* x) {
  permute<N>(transposition, x);
  unit_lower_solve<N>(m, x);
#pragma GCC unroll 8
  for (int i = 0; i < N; ++i) {  // D (entries below the smallest normal double count as 0)
    const double d = at<N>(m, i, i);
    if (std::abs(d) > DBL_MIN)
      x[i] /= d;
    else
      x[i] = 0.0;
  }
#pragma GCC unroll 8
  for (int k = 1; k < N; ++k) {  // L^T, unit upper, row by row from the last
    const int i = N - 1 - k;
    x[i] -= packet_dot(&m[(i + 1) + N * i], &x[i + 1], k);
  }
#pragma GCC unroll 8
  for (int k = N - 1; k >= 0; --k)  // P^T
    if (transposition[k] != k) std::swap(x[k], x[transposition[k]]);
}

// The products of the solver's square matrices, as Eigen 3.4 forms them with SSE2 (each
// checked against Eigen in tests/engine/contact/small_solvers_test.cc). J is N x N,
// column-major.

// G = J^T J, both triangles (entry (r, c) and (c, r) are the same sums). Below 7 rows Eigen
// takes the lazy product, each entry a packet sum of two columns (packet_dot); from 7 on
// (rows + rows + columns >= 20) its GEMM kernel, each entry summed in order from +0.
template <int N>
void gram(const double* j, double* g) {
#pragma GCC unroll 8
  for (int c = 0; c < N; ++c)
#pragma GCC unroll 8
    for (int r = c; r < N; ++r) {
      const double* jr = j + N * r;
      const double* jc = j + N * c;
      double s;
      if constexpr (N < 7) {
        s = packet_dot(jr, jc, N);
      } else {
        s = 0.0;
#pragma GCC unroll 8
        for (int k = 0; k < N; ++k) s = s + jr[k] * jc[k];
      }
      g[r + N * c] = s;
      g[c + N * r] = s;
    }
}

// y = J^T x: Eigen's row-major GEMV, each entry in two lanes (the even and the odd terms, each
// in order from +0), the lanes added, then the odd term left over.
template <int N>
void transpose_times(const double* j, const double* x, double* y) {
#pragma GCC unroll 8
  for (int c = 0; c < N; ++c) {
    const double* jc = j + N * c;
    double even = 0.0, odd = 0.0;
    int k = 0;
#pragma GCC unroll 8
    for (; k + 1 < N; k += 2) {
      even = even + jc[k] * x[k];
      odd = odd + jc[k + 1] * x[k + 1];
    }
    double s = even + odd;
    if (k < N) s = s + jc[k] * x[k];
    y[c] = s;
  }
}

// y = J x: Eigen's column-major GEMV, each entry summed over the columns in order from +0.
template <int N>
void times(const double* j, const double* x, double* y) {
  double s[N];
#pragma GCC unroll 8
  for (int r = 0; r < N; ++r) s[r] = 0.0;
#pragma GCC unroll 8
  for (int c = 0; c < N; ++c)
#pragma GCC unroll 8
    for (int r = 0; r < N; ++r) s[r] = s[r] + at<N>(j, r, c) * x[c];
#pragma GCC unroll 8
  for (int r = 0; r < N; ++r) y[r] = s[r];
}

}  // namespace small_solvers_detail

// J^T J of a square J, equal bit for bit to Eigen's J.transpose() * J.
inline SmallMatrix small_gram(const SmallMatrix& j) {
  SmallMatrix g(j.cols(), j.cols());
  small_solvers_detail::with_size(static_cast<int>(j.rows()), [&](auto n) {
    small_solvers_detail::gram<decltype(n)::value>(j.data(), g.data());
  });
  return g;
}

// J^T x of a square J, equal bit for bit to Eigen's J.transpose() * x.
inline SmallVector small_transpose_times(const SmallMatrix& j, const SmallVector& x) {
  SmallVector y(j.cols());
  small_solvers_detail::with_size(static_cast<int>(j.rows()), [&](auto n) {
    small_solvers_detail::transpose_times<decltype(n)::value>(j.data(), x.data(), y.data());
  });
  return y;
}

// J x of a square J, equal bit for bit to Eigen's J * x.
inline SmallVector small_times(const SmallMatrix& j, const SmallVector& x) {
  SmallVector y(j.rows());
  small_solvers_detail::with_size(static_cast<int>(j.rows()), [&](auto n) {
    small_solvers_detail::times<decltype(n)::value>(j.data(), x.data(), y.data());
  });
  return y;
}

// A = P^T L U, as Eigen's PartialPivLU.
class SmallLu {
 public:
  explicit SmallLu(const SmallMatrix& a) : n_(static_cast<int>(a.rows())) {
    std::copy(a.data(), a.data() + n_ * n_, m_);
    small_solvers_detail::with_size(n_, [&](auto n) {
      small_solvers_detail::lu_factor<decltype(n)::value>(m_, transposition_);
    });
  }
  // x with A x = b.
  SmallVector solve(const SmallVector& b) const {
    SmallVector x = b;
    small_solvers_detail::with_size(n_, [&](auto n) {
      small_solvers_detail::lu_solve<decltype(n)::value>(m_, transposition_, x.data());
    });
    return x;
  }

 private:
  double m_[64];
  int n_;
  int transposition_[8] = {};
};

// A = P^T L D L^T P of a symmetric matrix (its lower triangle is read), as Eigen's LDLT.
class SmallLdlt {
 public:
  explicit SmallLdlt(const SmallMatrix& a) : n_(static_cast<int>(a.rows())) {
    std::copy(a.data(), a.data() + n_ * n_, m_);
    small_solvers_detail::with_size(n_, [&](auto n) {
      small_solvers_detail::ldlt_factor<decltype(n)::value>(m_, transposition_);
    });
  }
  // x with A x = b (D's entries below the smallest normal double count as zero, as Eigen's).
  SmallVector solve(const SmallVector& b) const {
    SmallVector x = b;
    small_solvers_detail::with_size(n_, [&](auto n) {
      small_solvers_detail::ldlt_solve<decltype(n)::value>(m_, transposition_, x.data());
    });
    return x;
  }

 private:
  double m_[64];
  int n_;
  int transposition_[8] = {};
};

}  // namespace pcsg
