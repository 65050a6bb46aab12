#include "engine/poly/parser.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pcsg {
namespace {

enum class Tok { Number, Var, Plus, Minus, Star, Caret, LParen, RParen, Le, Ge, End };

struct Token {
  Tok kind = Tok::End;
  std::size_t offset = 0;  // byte offset in the text
  std::string text;        // as written, for messages
  double number = 0;
  int axis = -1;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

// Length of the UTF-8 sequence starting with byte c (1 for ASCII and stray bytes).
std::size_t utf8_length(unsigned char c) {
  if (c >= 0xF0) return 4;
  if (c >= 0xE0) return 3;
  if (c >= 0xC0) return 2;
  return 1;
}

class Parser {
 public:
  Parser(const std::string& text, const OffsetLocator& locate,
         const Eigen::Vector3d& origin = Eigen::Vector3d::Zero())
      : text_(text), locate_(locate), origin_(origin) {
    lex();
  }

  Polynomial polynomial() {
    Polynomial p = expr();
    expect_end();
    return checked(p);
  }

  Inequality inequality() {
    // find the operator first, so that a missing or doubled one gets its own message
    std::size_t n_ops = 0;
    for (const Token& t : tokens_) {
      if (t.kind != Tok::Le && t.kind != Tok::Ge) continue;
      if (++n_ops == 2)
        fail(t.offset, "more than one inequality operator (second '" + t.text +
                           "'); a face is one inequality 'lhs <= rhs' or 'lhs >= rhs'");
    }
    if (n_ops == 0)
      fail(0, "no inequality operator; expected '<=' or '>=' between two sides, "
              "e.g. \"x^2 + y^2 + z^2 <= 1\"");
    const Polynomial lhs = expr();
    const Token op = peek();
    if (op.kind != Tok::Le && op.kind != Tok::Ge) expect_end();  // reports what is there
    ++pos_;
    const Polynomial rhs = expr();
    expect_end();
    Inequality r;
    r.g = checked(op.kind == Tok::Le ? lhs - rhs : rhs - lhs);
    r.operator_offset = op.offset;
    return r;
  }

 private:
  [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
    throw SceneError(locate_(offset), what + " (in \"" + text_ + "\")");
  }

  // --- lexer -------------------------------------------------------------------------------
  void lex() {
    std::size_t i = 0;
    const std::size_t n = text_.size();
    auto push = [&](Tok kind, std::size_t len) {
      tokens_.push_back({kind, i, text_.substr(i, len), 0, -1});
      i += len;
    };
    while (i < n) {
      const char c = text_[i];
      const char next = i + 1 < n ? text_[i + 1] : '\0';
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        ++i;
      } else if (is_digit(c) || (c == '.' && is_digit(next))) {
        lex_number(i);
      } else if (c == 'x' || c == 'y' || c == 'z') {
        tokens_.push_back({Tok::Var, i, std::string(1, c), 0, c - 'x'});
        ++i;
      } else if (is_alpha(c)) {
        std::size_t j = i;
        while (j < n && (is_alpha(text_[j]) || is_digit(text_[j]))) ++j;
        const std::string word = text_.substr(i, j - i);
        const bool upper = j == i + 1 && (c == 'X' || c == 'Y' || c == 'Z');
        fail(i, "unknown variable '" + word + "'; the variables are lowercase x, y and z" +
                    (upper ? "" : " (write products with '*' or side by side, e.g. 2xy)"));
      } else if (c == '+') {
        push(Tok::Plus, 1);
      } else if (c == '-') {
        push(Tok::Minus, 1);
      } else if (c == '*') {
        push(Tok::Star, 1);
      } else if (c == '^') {
        push(Tok::Caret, 1);
      } else if (c == '(') {
        push(Tok::LParen, 1);
      } else if (c == ')') {
        push(Tok::RParen, 1);
      } else if ((c == '<' || c == '>') && next == '=') {
        push(c == '<' ? Tok::Le : Tok::Ge, 2);
      } else if (c == '<' || c == '>') {
        fail(i, std::string("'") + c + "' is not supported: faces are closed sets; write '" +
                    c + "='");
      } else if (c == '=') {
        const std::string op = next == '=' ? "==" : next == '<' || next == '>'
                                                       ? std::string("=") + next
                                                       : "=";
        fail(i, "'" + op + "' is not an inequality operator; expected '<=' or '>='");
      } else {
        const std::string ch = text_.substr(i, utf8_length(static_cast<unsigned char>(c)));
        if (ch == "\u2264" || ch == "\u2265")
          fail(i, "'" + ch + "' is not supported; write the ASCII '" +
                      (ch == "\u2264" ? "<=" : ">=") + "'");
        fail(i, "unexpected character '" + ch +
                    "'; expected a number, x, y, z, + - * ^ ( ) or '<=' / '>='");
      }
    }
    tokens_.push_back({Tok::End, n, "", 0, -1});
  }

  // digits [. digits] [e|E [+|-] digits], converted locale-independently
  void lex_number(std::size_t& i) {
    const std::size_t n = text_.size(), start = i;
    while (i < n && is_digit(text_[i])) ++i;
    if (i < n && text_[i] == '.') {
      ++i;
      while (i < n && is_digit(text_[i])) ++i;
    }
    if (i < n && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < n && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j >= n || !is_digit(text_[j]))
        fail(start, "malformed number '" + text_.substr(start, j - start) +
                        "'; an exponent needs digits, e.g. 1.5e-3");
      i = j;
      while (i < n && is_digit(text_[i])) ++i;
    }
    if (i < n && text_[i] == '.')
      fail(start, "malformed number '" + text_.substr(start, i + 1 - start) + "'");
    Token t{Tok::Number, start, text_.substr(start, i - start), 0, -1};
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), t.number);
    if (ec != std::errc() || end != t.text.data() + t.text.size())
      fail(start, "number '" + t.text + "' is out of range");
    tokens_.push_back(t);
  }

  // --- recursive descent ---------------------------------------------------------------------
  const Token& peek() const { return tokens_[pos_]; }
  static bool starts_operand(Tok k) {
    return k == Tok::Number || k == Tok::Var || k == Tok::LParen || k == Tok::Plus ||
           k == Tok::Minus;
  }
  // A binary operator must be followed by an operand.
  void require_operand_after(const Token& op) const {
    if (!starts_operand(peek().kind))
      fail(op.offset, "missing operand after '" + op.text + "'" + found());
  }
  std::string found() const {
    return peek().kind == Tok::End ? " (the text ends)" : " (found '" + peek().text + "')";
  }

  Polynomial expr() {
    Polynomial p = term();
    while (peek().kind == Tok::Plus || peek().kind == Tok::Minus) {
      const Token op = tokens_[pos_++];
      require_operand_after(op);
      const Polynomial rhs = term();
      p = op.kind == Tok::Plus ? p + rhs : p - rhs;
    }
    return p;
  }

  Polynomial term() {
    Polynomial p = signed_factor();
    for (;;) {
      const Token t = peek();
      if (t.kind == Tok::Star) {
        ++pos_;
        require_operand_after(t);
        const std::size_t at = peek().offset;
        p = multiply(p, signed_factor(), at);
      } else if (t.kind == Tok::Var || t.kind == Tok::LParen) {
        p = multiply(p, factor(), t.offset);  // implicit product: "225x^2", "2xy", "4(x+y)"
      } else if (t.kind == Tok::Number) {
        fail(t.offset, "unexpected number '" + t.text +
                           "' after a factor; write '*' between numbers, put a coefficient "
                           "before its variables (2x, not x2), or use '^' for powers");
      } else {
        return p;
      }
    }
  }

  Polynomial signed_factor() {
    const Token t = peek();
    if (t.kind != Tok::Plus && t.kind != Tok::Minus) return factor();
    ++pos_;
    require_operand_after(t);
    const Polynomial p = signed_factor();
    return t.kind == Tok::Minus ? -p : p;
  }

  Polynomial factor() {
    const Polynomial base = primary();
    if (peek().kind != Tok::Caret) return base;
    const Token caret = tokens_[pos_++];
    const Token e = peek();
    if (e.kind == Tok::Minus)
      fail(e.offset, "negative power after '^'; powers must be non-negative integers");
    if (e.kind != Tok::Number)
      fail(e.kind == Tok::End ? caret.offset : e.offset,
           "expected a non-negative integer power after '^'" + found());
    ++pos_;
    if (e.number != std::floor(e.number))
      fail(e.offset, "non-integer power '" + e.text + "'; powers must be non-negative integers");
    if (peek().kind == Tok::Caret)
      fail(peek().offset, "repeated '^' is ambiguous; use parentheses, e.g. (x^2)^2");
    const int d = base.degree();
    if (d > 0 && e.number * d > Polynomial::kMaxDegree)
      fail(caret.offset, "power '^" + e.text + "' of a degree-" + std::to_string(d) +
                             " factor exceeds the maximum degree " +
                             std::to_string(Polynomial::kMaxDegree));
    // a constant base: cap the power so that a typo cannot loop for long
    if (e.number > 64) fail(e.offset, "power '" + e.text + "' is too large (at most 64)");
    return base.pow(static_cast<int>(e.number));
  }

  Polynomial primary() {
    const Token t = peek();
    switch (t.kind) {
      case Tok::Number:
        ++pos_;
        return about_origin(Polynomial::constant(t.number));
      case Tok::Var:
        ++pos_;
        return about_origin(Polynomial::variable(t.axis));
      case Tok::LParen: {
        ++pos_;
        ++depth_;
        if (peek().kind == Tok::RParen) fail(t.offset, "empty parentheses '()'");
        const Polynomial p = expr();
        if (peek().kind != Tok::RParen)
          fail(t.offset, "unbalanced parenthesis: this '(' is never closed; expected ')'" +
                             found());
        ++pos_;
        --depth_;
        return p;
      }
      case Tok::RParen:
        if (depth_ == 0) fail(t.offset, "unbalanced parenthesis: ')' has no matching '('");
        fail(t.offset, "missing operand before ')'");
      case Tok::End:
        fail(t.offset, text_.find_first_not_of(" \t\r\n") == std::string::npos
                           ? "empty expression; expected a polynomial in x, y, z"
                           : "missing operand at the end of the text");
      default:
        fail(t.offset, "missing operand before '" + t.text + "'");
    }
  }

  Polynomial multiply(const Polynomial& a, const Polynomial& b, std::size_t at) const {
    try {
      return a * b;
    } catch (const std::domain_error&) {
      fail(at, "the product has degree " + std::to_string(a.degree() + b.degree()) +
                   "; the maximum degree is " + std::to_string(Polynomial::kMaxDegree));
    }
  }

  void expect_end() const {
    const Token& t = peek();
    if (t.kind == Tok::End) return;
    if (t.kind == Tok::RParen) fail(t.offset, "unbalanced parenthesis: ')' has no matching '('");
    fail(t.offset, "unexpected '" + t.text + "'");
  }

  // Sums of huge literals can overflow to inf; a face must have finite coefficients.
  Polynomial checked(const Polynomial& p) const {
    for (double c : p.coeffs())
      if (!std::isfinite(c)) fail(0, "a coefficient overflows (is not finite)");
    return p;
  }

  // A literal or variable expanded about origin_: exact (a constant stays itself; x becomes
  // o_x + (x - o_x)), so all rounding happens in the arithmetic about the origin.
  Polynomial about_origin(const Polynomial& p) const {
    return origin_.isZero() ? p : p.recentred(origin_);
  }

  const std::string& text_;
  const OffsetLocator& locate_;
  const Eigen::Vector3d origin_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  int depth_ = 0;  // open parentheses, to tell "unbalanced" from "missing operand"
};

}  // namespace

OffsetLocator locate_from(const SourceLocation& start) {
  return [start](std::size_t offset) {
    SourceLocation at = start;
    at.column = start.column + static_cast<int>(offset);
    return at;
  };
}

Polynomial parse_polynomial(const std::string& text, const OffsetLocator& locate) {
  return Parser(text, locate).polynomial();
}

Inequality parse_inequality(const std::string& text, const OffsetLocator& locate) {
  return Parser(text, locate).inequality();
}

Inequality parse_inequality_about(const std::string& text, const Eigen::Vector3d& origin,
                                  const OffsetLocator& locate) {
  return Parser(text, locate, origin).inequality();
}

}  // namespace pcsg
