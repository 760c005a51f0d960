// Expressions: numbers, precedence, nesting, unary minus, functions, names of
// any length, and errors at the right column.
#include <gtest/gtest.h>

#include <cmath>

#include "macro/deck/DeckReader.h"
#include "macro/deck/Expression.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::expectDeckError;

double ev(const std::string& text, const Parameters& p = {}) {
  return Expression::parse(text, {"e.inp", 1, 1}).eval(p);
}

// A field at column col of line 5 of "x.inp".
Field field(const std::string& text, int col) {
  auto line = std::make_shared<const std::string>(std::string(col - 1, ' ') + text);
  return {text, {"x.inp", 5, col}, line};
}

TEST(ExpressionNumbers, FortranAndCForms) {
  EXPECT_EQ(ev("3"), 3.0);
  EXPECT_EQ(ev("-4.5"), -4.5);
  EXPECT_EQ(ev("1.34e+5"), 1.34e5);
  EXPECT_EQ(ev("1.0d-3"), 1.0e-3);
  EXPECT_EQ(ev("2.D2"), 200.0);
  EXPECT_EQ(ev(".5"), 0.5);
  EXPECT_EQ(ev("7E0"), 7.0);
  EXPECT_EQ(ev(""), 0.0);  // an empty field is 0
  EXPECT_EQ(Expression().eval({}), 0.0);
  EXPECT_EQ(Expression::constant(2.5).eval({}), 2.5);
}

TEST(ExpressionPrecedence, OperatorsBindAsInFortran) {
  EXPECT_EQ(ev("2+3*4"), 14.0);
  EXPECT_EQ(ev("(2+3)*4"), 20.0);
  EXPECT_EQ(ev("2-3-4"), -5.0);   // left associative
  EXPECT_EQ(ev("10/4/2"), 1.25);  // left associative
  EXPECT_EQ(ev("2^3^2"), 512.0);  // right associative
  EXPECT_EQ(ev("-2^2"), -4.0);    // ^ above unary minus
  EXPECT_EQ(ev("(-2)^2"), 4.0);
  EXPECT_EQ(ev("2^-1"), 0.5);
  EXPECT_EQ(ev("2*-3"), -6.0);
  EXPECT_EQ(ev("--2"), 2.0);
  EXPECT_EQ(ev("-3+5"), 2.0);
  EXPECT_EQ(ev("+3"), 3.0);
  EXPECT_EQ(ev("2*3^2"), 18.0);
  EXPECT_EQ(ev("1 + 2 * 3 - 4 / 2"), 5.0);  // blanks allowed where a whole record is the expression
}

TEST(ExpressionPrecedence, UnaryMinusOnNames) {
  Parameters p;
  p.set("a", 3);
  p.set("b", 4);
  EXPECT_EQ(ev("a*-b", p), -12.0);
  EXPECT_EQ(ev("-a^2", p), -9.0);
  EXPECT_EQ(ev("a/-b*2", p), -1.5);
  EXPECT_EQ(ev("-(a-b)", p), 1.0);
}

TEST(ExpressionNesting, ParenthesesNestToAnyDepth) {
  EXPECT_EQ(ev("((((1+2))*((3))))"), 9.0);
  std::string deep = "1";
  for (int i = 0; i < 120; ++i) deep = "(" + deep + "+1)";
  EXPECT_EQ(ev(deep), 121.0);
  EXPECT_EQ(ev("2*(3+(4-(5*(6-7))))"), 24.0);
}

TEST(ExpressionFunctions, AllOfThem) {
  const double pi = std::acos(-1.0);
  EXPECT_DOUBLE_EQ(ev("abs(-3)"), 3.0);
  EXPECT_DOUBLE_EQ(ev("exp(log(5))"), 5.0);
  EXPECT_DOUBLE_EQ(ev("int(-2.7)"), -2.0);  // truncation, as Fortran's int
  EXPECT_DOUBLE_EQ(ev("int(2.7)"), 2.0);
  EXPECT_DOUBLE_EQ(ev("sqrt(16)"), 4.0);
  EXPECT_NEAR(ev("sin(0.5)"), std::sin(0.5), 1e-15);
  EXPECT_NEAR(ev("cos(0.5)"), std::cos(0.5), 1e-15);
  EXPECT_NEAR(ev("tan(0.5)"), std::tan(0.5), 1e-15);
  EXPECT_NEAR(ev("asin(0.5)"), pi / 6, 1e-15);
  EXPECT_NEAR(ev("acos(0.5)"), pi / 3, 1e-15);
  EXPECT_NEAR(ev("atan(1)"), pi / 4, 1e-15);
  EXPECT_NEAR(ev("sind(30)"), 0.5, 1e-15);
  EXPECT_NEAR(ev("cosd(60)"), 0.5, 1e-15);
  EXPECT_NEAR(ev("tand(45)"), 1.0, 1e-15);
  EXPECT_NEAR(ev("asind(0.5)"), 30.0, 1e-13);
  EXPECT_NEAR(ev("acosd(0.5)"), 60.0, 1e-13);
  EXPECT_NEAR(ev("atand(1)"), 45.0, 1e-13);
  EXPECT_NEAR(ev("cosh(0.3)^2-sinh(0.3)^2"), 1.0, 1e-14);
  EXPECT_NEAR(ev("tanh(0.3)"), std::tanh(0.3), 1e-15);
  EXPECT_NEAR(ev("SQRT(2)*Sqrt(2)"), 2.0, 1e-15);  // case-insensitive
  EXPECT_NEAR(ev("-sqrt(4)^2"), -4.0, 1e-15);
}

TEST(ExpressionNames, AnyLengthCaseInsensitive) {
  Parameters p;
  p.set("KS_beam", -2.5);
  p.set("e", 30e6);
  p.set("n2", 3);
  p.set("_x", 1);
  EXPECT_TRUE(p.has("ks_BEAM"));
  EXPECT_EQ(ev("ks_beam*2", p), -5.0);
  EXPECT_EQ(ev("E/1e6", p), 30.0);
  EXPECT_EQ(ev("N2+_X", p), 4.0);
  EXPECT_EQ(ev("sin",
               [] {
                 Parameters q;
                 q.set("sin", 7);
                 return q;
               }()),
            7.0);  // a function name without '(' is a parameter
  const Expression e = Expression::parse(field("a*b+a", 1));
  EXPECT_EQ(e.names(), (std::vector<std::string>{"a", "b"}));
  EXPECT_FALSE(e.isConstant());
  EXPECT_TRUE(Expression::parse(field("2*3", 1)).isConstant());
  EXPECT_EQ(p.names(), (std::vector<std::string>{"_x", "e", "ks_beam", "n2"}));
}

TEST(ExpressionNames, EvaluatedWhenUsed) {
  Parameters p;
  const Expression e = Expression::parse(field("2*L", 3));
  p.set("L", 1.5);
  EXPECT_EQ(e.eval(p), 3.0);
  p.set("l", 4);  // same name
  EXPECT_EQ(e.eval(p), 8.0);
}

TEST(ExpressionErrors, UndefinedNameAtItsColumn) {
  Parameters p;
  p.set("length", 3);
  const Expression e = Expression::parse(field("2*lenght+1", 10));
  expectDeckError([&] { e.eval(p); }, "x.inp", 5, 12, "undefined parameter 'lenght'");
  try {
    e.eval(p);
  } catch (const DeckError& err) {
    EXPECT_EQ(err.hint(), "did you mean 'length'?");
    EXPECT_NE(err.text().find("^"), std::string::npos);
  }
  expectDeckError([&] { Expression::parse(field("zz", 1)).eval({}); }, "x.inp", 5, 1,
                  "undefined parameter 'zz'");
}

TEST(ExpressionErrors, DivisionByZeroAtTheOperator) {
  Parameters p;
  p.set("a", 1);
  p.set("b", 0);
  expectDeckError([&] { Expression::parse(field("a+1/b", 4)).eval(p); }, "x.inp", 5, 7,
                  "division by zero");
  expectDeckError([&] { Expression::parse(field("1/(a-1)", 1)).eval(p); }, "x.inp", 5, 2,
                  "division by zero");
}

TEST(ExpressionErrors, DomainErrorsAtTheFunction) {
  expectDeckError([] { Expression::parse(field("2+sqrt(-1)", 1)).eval({}); }, "x.inp", 5, 3,
                  "sqrt(-1) is undefined");
  expectDeckError([] { Expression::parse(field("log(0)", 2)).eval({}); }, "x.inp", 5, 2,
                  "log(0) is undefined");
  expectDeckError([] { Expression::parse(field("asin(2)", 1)).eval({}); }, "x.inp", 5, 1,
                  "undefined");
  expectDeckError([] { Expression::parse(field("0^-1", 1)).eval({}); }, "x.inp", 5, 2,
                  "invalid power");
}

TEST(ExpressionErrors, SyntaxErrorsAtTheBadCharacter) {
  expectDeckError([] { Expression::parse(field("2*(3+4", 6)); }, "x.inp", 5, 8, "never closed");
  expectDeckError([] { Expression::parse(field("2+", 1)); }, "x.inp", 5, 3, "ends too early");
  expectDeckError([] { Expression::parse(field("3a", 1)); }, "x.inp", 5, 2, "malformed number");
  expectDeckError([] { Expression::parse(field("1.2.3", 1)); }, "x.inp", 5, 4, "malformed number");
  expectDeckError([] { Expression::parse(field("2e+", 1)); }, "x.inp", 5, 2, "malformed exponent");
  expectDeckError([] { Expression::parse(field("foo(2)", 3)); }, "x.inp", 5, 3,
                  "unknown function 'foo'");
  expectDeckError([] { Expression::parse(field("sqr(2)", 1)); }, "x.inp", 5, 1,
                  "unknown function 'sqr'");
  expectDeckError([] { Expression::parse(field("(1))", 1)); }, "x.inp", 5, 4, "unmatched ')'");
  expectDeckError([] { Expression::parse(field("sqrt()", 1)); }, "x.inp", 5, 6,
                  "needs an argument");
  expectDeckError([] { Expression::parse(field("2*#", 1)); }, "x.inp", 5, 3, "unexpected '#'");
  expectDeckError([] { Expression::parse(field("()", 1)); }, "x.inp", 5, 2, "empty parentheses");
  expectDeckError([] { Expression::parse(field("2**3", 1)); }, "x.inp", 5, 3, "unexpected '*'");
  expectDeckError(
      [] {
        Expression::parse("1 + 2 3", {"p.inp", 2, 5});
      },
      "p.inp", 2, 11, "unexpected '3'");
  try {
    Expression::parse(field("sqr(2)", 1));
  } catch (const DeckError& e) {
    EXPECT_EQ(e.hint(), "did you mean 'sqrt'?");
  }
}

TEST(ExpressionIntegers, WholeNumbersOnly) {
  Parameters p;
  p.set("n", 4);
  EXPECT_EQ(Expression::parse(field("n/2", 1)).evalInt(p, "node number"), 2);
  EXPECT_EQ(Expression::parse(field("3*(1/3)*3", 1)).evalInt(p, "count"), 3);  // round-off
  expectDeckError([&] { Expression::parse(field("n/8", 2)).evalInt(p, "node number"); }, "x.inp", 5,
                  2, "node number must be a whole number, got 0.5");
}

TEST(ExpressionParameters, ValidNames) {
  EXPECT_TRUE(Parameters::validName("a"));
  EXPECT_TRUE(Parameters::validName("ks_beam2"));
  EXPECT_TRUE(Parameters::validName("_t"));
  EXPECT_FALSE(Parameters::validName("2a"));
  EXPECT_FALSE(Parameters::validName(""));
  EXPECT_FALSE(Parameters::validName("a-b"));
  Parameters p;
  EXPECT_THROW(p.get("none"), std::out_of_range);
  EXPECT_FALSE(p.find("none").has_value());
}

}  // namespace
}  // namespace c2d
