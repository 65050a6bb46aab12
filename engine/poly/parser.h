#pragma once
// Text -> Polynomial for the scene files' face inequalities, e.g.
//   "225x^2 + 100y^2 + 36z^2 <= 225",  "4(x^2 + y^2) - 10.07047z >= 15.75982".
// Grammar (x, y, z are the only variables; total degree at most Polynomial::kMaxDegree):
//   inequality := expr ("<=" | ">=") expr
//   expr       := term (("+" | "-") term)*
//   term       := signed (["*"] factor)*     a missing "*" is allowed before x, y, z or "("
//   signed     := ("+" | "-") signed | factor
//   factor     := primary ["^" non-negative integer]
//   primary    := number | "x" | "y" | "z" | "(" expr ")"
// Numbers are decimal with an optional exponent ("1.5e-3"). Every error is a SceneError whose
// location points at the offending character in the source file.
#include <cstddef>
#include <functional>
#include <string>

#include "engine/core/error.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

// Maps a byte offset inside the parsed text to its place in the source file (the scene loader
// knows where a quoted YAML string starts and how its escapes shift columns).
using OffsetLocator = std::function<SourceLocation(std::size_t offset)>;

// The locator of a single-line text whose first character is at `start`: column + offset.
OffsetLocator locate_from(const SourceLocation& start);

// "lhs <= rhs" or "lhs >= rhs", normalised so that the solid side is g <= 0.
struct Inequality {
  Polynomial g;                     // lhs - rhs for "<=", rhs - lhs for ">="
  std::size_t operator_offset = 0;  // byte offset of "<=" / ">=" in the text
};

// Parses a polynomial expression (no inequality operator). Throws SceneError.
Polynomial parse_polynomial(const std::string& text,
                            const OffsetLocator& locate = locate_from({"", 1, 1}));

// Parses an inequality with exactly one "<=" or ">=". "<", "=", "==" and a missing operator
// are rejected with a message saying what to write instead. Throws SceneError.
Inequality parse_inequality(const std::string& text,
                            const OffsetLocator& locate = locate_from({"", 1, 1}));
// The same, with every coefficient expanded about `origin` (Polynomial::origin) as it is
// parsed: each literal and variable is written about the origin before any arithmetic, so a
// face written as "(x - 120000)^2 + ..." far from its frame's origin keeps the digits that
// expanding about zero first and recentring after would round away (its coefficients there
// are ~1e10 and their sums round at ~1e-6).
Inequality parse_inequality_about(const std::string& text, const Eigen::Vector3d& origin,
                                  const OffsetLocator& locate = locate_from({"", 1, 1}));

}  // namespace pcsg
