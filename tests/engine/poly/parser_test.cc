#include "engine/poly/parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace pcsg {
namespace {

// Small integers and short decimals: exact up to a few ulps of the values involved.
constexpr double kExact = 1e-12;
// The paper prints its example's coefficients to 6-7 digits, so its quoted surface points
// satisfy the equations only to ~1e-5 relative.
constexpr double kPaperDigits = 1e-4;

Polynomial X() { return Polynomial::variable(0); }
Polynomial Y() { return Polynomial::variable(1); }
Polynomial Z() { return Polynomial::variable(2); }
Polynomial C(double c) { return Polynomial::constant(c); }

void expect_same(const Polynomial& a, const Polynomial& b) {
  for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
    EXPECT_NEAR(a.coeffs()[n], b.coeffs()[n], kExact) << "coefficient " << n << ": got "
                                                      << a.str() << ", expected " << b.str();
}

TEST(Parser, EllipsoidOfExampleOne) {
  const Inequality q = parse_inequality("225x^2 + 100y^2 + 36z^2 <= 225");
  expect_same(q.g, X().pow(2) * 225 + Y().pow(2) * 100 + Z().pow(2) * 36 - C(225));
  EXPECT_EQ(q.operator_offset, 24u);
  // semi-axes 1, 1.5, 2.5 (paper, Example 1)
  EXPECT_NEAR(q.g.value({1, 0, 0}), 0, kExact);
  EXPECT_NEAR(q.g.value({0, 1.5, 0}), 0, kExact);
  EXPECT_NEAR(q.g.value({0, 0, 2.5}), 0, kExact);
  EXPECT_LT(q.g.value({0, 0, 0}), 0) << "the solid side must be g <= 0";
}

TEST(Parser, GreaterEqualIsNormalisedToSolidSideNegative) {
  // B's concave dish of Example 1: g = rhs - lhs
  const Inequality q = parse_inequality("4x^2 + 4y^2 - 10.07047z >= 15.75982");
  expect_same(q.g, C(15.75982) - X().pow(2) * 4 - Y().pow(2) * 4 + Z() * 10.07047);
  EXPECT_NEAR(q.g.value({0, 0, -1.56495}), 0, kPaperDigits * 15.75982);
  EXPECT_LT(q.g.value({0, 0, -3}), 0) << "below the dish is inside B";
  EXPECT_GT(q.g.value({0, 0, 0}), 0) << "above the dish is outside B";
}

TEST(Parser, TermsOnBothSides) {
  expect_same(parse_inequality("x^2 + 1 <= 2y^2 - z").g, X().pow(2) - Y().pow(2) * 2 + Z() + C(1));
  expect_same(parse_inequality("z >= x^2 + y^2 - 3").g, X().pow(2) + Y().pow(2) - Z() - C(3));
}

TEST(Parser, ImplicitMultiplication) {
  expect_same(parse_polynomial("225x^2"), X().pow(2) * 225);
  expect_same(parse_polynomial("2xy"), X() * Y() * 2);
  expect_same(parse_polynomial("x y z"), X() * Y() * Z());
  expect_same(parse_polynomial("4(x^2 + y^2)"), (X().pow(2) + Y().pow(2)) * 4);
  expect_same(parse_polynomial("(x + 1)(x - 1)"), X().pow(2) - C(1));
  expect_same(parse_polynomial("2(x + 1)^2"), (X() + C(1)).pow(2) * 2);
  expect_same(parse_polynomial("3x(y - 2)z"), X() * (Y() - C(2)) * Z() * 3);
}

TEST(Parser, SignsPowersAndExplicitProducts) {
  expect_same(parse_polynomial("-x^2"), -X().pow(2));  // -(x^2), not (-x)^2
  expect_same(parse_polynomial("(-x)^3"), -X().pow(3));
  expect_same(parse_polynomial("x * -y"), -(X() * Y()));
  expect_same(parse_polynomial("x - -y + +z"), X() + Y() + Z());
  expect_same(parse_polynomial("2^3 x"), X() * 8);
  expect_same(parse_polynomial("x^0 + y^1"), C(1) + Y());
  expect_same(parse_polynomial("(x^2)^2"), X().pow(4));
}

TEST(Parser, DecimalsAndExponents) {
  expect_same(parse_polynomial("1.5e-3x + 2.5E2"), X() * 1.5e-3 + C(250));
  expect_same(parse_polynomial(".5y - 3.z + 1e+1"), Y() * 0.5 - Z() * 3 + C(10));
}

TEST(Parser, TorusOfDegreeFour) {
  // R = 2, r = 0.5
  const Inequality q = parse_inequality("(x^2 + y^2 + z^2 + 3.75)^2 <= 16(x^2 + y^2)");
  EXPECT_EQ(q.g.degree(), 4);
  EXPECT_NEAR(q.g.value({2.5, 0, 0}), 0, kExact);
  EXPECT_NEAR(q.g.value({0, 1.5, 0}), 0, kExact);
  EXPECT_NEAR(q.g.value({2, 0, 0.5}), 0, kExact);
  EXPECT_LT(q.g.value({0, 2, 0}), 0);  // inside the tube
  EXPECT_GT(q.g.value({0, 0, 0}), 0);  // the hole
}

// Each malformed input with the column (1-based, the text starting at column 10 of line 3) and
// the words the message must contain.
struct BadCase {
  std::string text;
  int column;
  std::vector<std::string> words;
};

TEST(Parser, ErrorsPointAtTheOffendingCharacter) {
  const std::vector<BadCase> cases = {
      {"x^2 + $ <= 1", 16, {"unexpected character '$'", "expected a number, x, y, z"}},
      {"(x^2 + 1 <= 2", 10, {"unbalanced parenthesis", "never closed", "'<='"}},
      {"x^2 + 1) <= 2", 17, {"unbalanced parenthesis", "')' has no matching '('"}},
      {"x^2 + <= 1", 14, {"missing operand after '+'", "'<='"}},
      {"<= 1", 10, {"missing operand before '<='"}},
      {"x^2 <= ", 17, {"missing operand at the end"}},
      {"x^2 * <= 1", 14, {"missing operand after '*'"}},
      {"x^1.5 <= 1", 12, {"non-integer power '1.5'", "non-negative integers"}},
      {"x^-2 <= 1", 12, {"negative power"}},
      {"x^ <= 1", 13, {"expected a non-negative integer power", "'<='"}},
      {"x^5 <= 1", 11, {"'^5'", "exceeds the maximum degree 4"}},
      {"(x^2 + 1)^3 <= 1", 19, {"'^3'", "degree-2", "maximum degree 4"}},
      {"(x^2 + y)(x^2 + z)^2 <= 1", 19, {"product has degree 6", "maximum degree is 4"}},
      {"x^2 * y^3 <= 1", 16, {"product has degree 5"}},
      {"x^2 + y^2 + z^2", 10, {"no inequality operator", "'<=' or '>='"}},
      {"x^2 < 1", 14, {"'<' is not supported", "'<='"}},
      {"x^2 > 1", 14, {"'>' is not supported", "'>='"}},
      {"x^2 = 1", 14, {"'=' is not an inequality operator", "'<=' or '>='"}},
      {"x^2 == 1", 14, {"'==' is not an inequality operator"}},
      {"x^2 =< 1", 14, {"'=<' is not an inequality operator"}},
      {"x^2 \u2264 1", 14, {"'\u2264' is not supported", "ASCII '<='"}},
      {"0 <= x^2 <= 1", 19, {"more than one inequality operator", "'<='"}},
      {"a^2 <= 1", 10, {"unknown variable 'a'", "x, y and z"}},
      {"X^2 <= 1", 10, {"unknown variable 'X'", "lowercase"}},
      {"x2 <= 1", 11, {"unexpected number '2'", "2x, not x2"}},
      {"2 3x <= 1", 12, {"unexpected number '3'"}},
      {"1.2.3x <= 1", 10, {"malformed number '1.2.'"}},
      {"2e <= x^2", 10, {"malformed number '2e'", "1.5e-3"}},
      {"1e400x^2 <= 1", 10, {"number '1e400' is out of range"}},
      {"() <= x^2", 10, {"empty parentheses"}},
      {"x^2^2 <= 1", 13, {"repeated '^'", "(x^2)^2"}},
      {"(x^2 + y) <= )", 23, {"unbalanced parenthesis", "')' has no matching '('"}},
  };
  for (const BadCase& c : cases) {
    try {
      parse_inequality(c.text, locate_from({"scene.yaml", 3, 10}));
      ADD_FAILURE() << "accepted \"" << c.text << "\"";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(e.where().line, 3) << msg;
      EXPECT_EQ(e.where().column, c.column) << msg;
      EXPECT_NE(msg.find("scene.yaml:3:" + std::to_string(c.column) + ": "), std::string::npos)
          << msg;
      EXPECT_NE(msg.find("\"" + c.text + "\""), std::string::npos) << "quotes the text: " << msg;
      for (const std::string& w : c.words)
        EXPECT_NE(msg.find(w), std::string::npos) << "'" << w << "' missing from: " << msg;
    }
  }
}

// The dish's bottom moved 1.2e5 along x and 2e4 along z (scenes/stress/needle_far_rotated.yaml
// moves B so): about the moved origin it is the paper's polynomial again, to the last bit of
// each literal. Expanded about zero first, its constant ~5.76e10 rounds at ~1e-5, which
// recentring cannot undo.
TEST(Parser, InequalityParsedAboutAFarOriginKeepsItsDigits) {
  const std::string text = "4(x - 120000)^2 + 4y^2 - 10.07047(z - 20000) >= 15.75982";
  const Eigen::Vector3d o(120000, 0, 20000);
  const Polynomial about = parse_inequality_about(text, o).g;
  EXPECT_EQ(about.origin(), o);
  Polynomial paper = X().pow(2) * -4 - Y().pow(2) * 4 + Z() * 10.07047 + C(15.75982);
  for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
    EXPECT_EQ(about.coeffs()[n], paper.coeffs()[n]) << "coefficient " << n << ": " << about.str();
  // The same text expanded about zero and recentred: its constant is off by far more than
  // the literal's own rounding (~2e-15).
  const Polynomial recentred = parse_inequality(text).g.recentred(o);
  EXPECT_GT(std::abs(recentred.coeff(0, 0, 0) - 15.75982), 1e-9) << recentred.str();
  // Parsed about zero, the origin argument changes nothing.
  const Polynomial zero = parse_inequality_about(text, Eigen::Vector3d::Zero()).g;
  EXPECT_EQ(zero.coeffs(), parse_inequality(text).g.coeffs());
}

TEST(Parser, PolynomialRejectsAnInequality) {
  try {
    parse_polynomial("x^2 <= 1");
    ADD_FAILURE() << "accepted an inequality as a polynomial";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("unexpected '<='"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().column, 5);  // default locator: the text starts at column 1
  }
}

TEST(Parser, EmptyTextIsAnError) {
  EXPECT_THROW(parse_polynomial(""), SceneError);
  EXPECT_THROW(parse_polynomial("   "), SceneError);
}

}  // namespace
}  // namespace pcsg
