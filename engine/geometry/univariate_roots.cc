#include "engine/geometry/univariate_roots.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcsg {
namespace {

// Bisection/Newton cap: 200 halvings reach double precision from brackets as wide as 1e300.
constexpr int kMaxRootIterations = 200;

int degree_of(const std::array<double, 5>& c) {
  int n = 4;
  while (n >= 0 && c[n] == 0.0) --n;
  return n;
}

double derivative_at(const std::array<double, 5>& c, double t) {
  double d = 0;
  for (int k = 4; k >= 1; --k) d = d * t + k * c[k];
  return d;
}

// The single root of a monotone polynomial on [a, b] where the signs at the ends differ.
double root_in_bracket(const std::array<double, 5>& c, double a, double b) {
  double fa = evaluate_univariate(c, a);
  double t = 0.5 * (a + b);
  for (int it = 0; it < kMaxRootIterations; ++it) {
    const double f = evaluate_univariate(c, t);
    if (f == 0) return t;
    if ((f < 0) == (fa < 0)) {
      a = t;
      fa = f;
    } else {
      b = t;
    }
    // a Newton step when it stays inside the bracket, bisection otherwise
    const double d = derivative_at(c, t);
    double next = d != 0 ? t - f / d : 0.5 * (a + b);
    if (!(next > std::min(a, b) && next < std::max(a, b))) next = 0.5 * (a + b);
    if (next == t || a == b) return t;
    t = next;
  }
  return t;
}

}  // namespace

double evaluate_univariate(const std::array<double, 5>& c, double t) {
  double v = 0;
  for (int k = 4; k >= 0; --k) v = v * t + c[k];
  return v;
}

std::vector<double> real_roots(const std::array<double, 5>& c) {
  const int n = degree_of(c);
  std::vector<double> roots;
  if (n <= 0) return roots;
  if (n == 1) return {-c[0] / c[1]};
  // critical points split the line into monotone pieces
  std::array<double, 5> d{};
  for (int k = 1; k <= n; ++k) d[k - 1] = k * c[k];
  std::vector<double> crit = real_roots(d);
  // Cauchy's bound holds every root: the unbounded pieces become finite brackets
  double bound = 0;
  for (int k = 0; k < n; ++k) bound = std::max(bound, std::abs(c[k] / c[n]));
  bound += 1;
  std::vector<double> pts;
  pts.push_back(-bound);
  for (double x : crit)
    if (x > -bound && x < bound) pts.push_back(x);
  pts.push_back(bound);
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double fa = evaluate_univariate(c, pts[k]), fb = evaluate_univariate(c, pts[k + 1]);
    if (fa == 0) {
      if (roots.empty() || roots.back() != pts[k]) roots.push_back(pts[k]);
      continue;
    }
    if (fb == 0 || (fa < 0) == (fb < 0)) continue;
    roots.push_back(root_in_bracket(c, pts[k], pts[k + 1]));
  }
  if (evaluate_univariate(c, pts.back()) == 0 &&
      (roots.empty() || roots.back() != pts.back()))
    roots.push_back(pts.back());
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace pcsg
