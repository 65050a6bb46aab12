#pragma once
// Real roots of a univariate polynomial of degree <= 4, as used along rays: the restriction
// t -> g(p + t d) of a face polynomial (Polynomial::along_line).
#include <array>
#include <vector>

namespace pcsg {

// Sorted real roots of c[0] + c[1] t + ... + c[4] t^4 (exact zeros in the highest coefficients
// lower the degree). Isolated by recursion on the derivative: between consecutive critical
// points the polynomial is monotone, so each sign change holds exactly one root, found by
// safeguarded Newton to full precision. Roots of even multiplicity (no sign change) are
// reported only when they coincide with a critical point where the value is exactly zero.
std::vector<double> real_roots(const std::array<double, 5>& c);

// Value of the polynomial at t (Horner).
double evaluate_univariate(const std::array<double, 5>& c, double t);

}  // namespace pcsg
