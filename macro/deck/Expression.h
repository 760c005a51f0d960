#pragma once
// Arithmetic expressions of numeric fields: numbers (3, -4.5, 1.34e+5, 1.0d-3),
// parameter names of any length (case-insensitive), + - * / ^, parentheses and
// one-argument functions (abs exp int log sqrt sin cos tan asin acos atan sind
// cosd tand asind acosd atand sinh cosh tanh; the *d forms work in degrees).
// ^ binds tighter than unary minus and is right associative: -2^2 = -4,
// 2^3^2 = 512; unary minus works anywhere (a*-b).
//
// An expression is parsed once, when the deck is parsed (syntax errors point at
// the bad character), and evaluated against the parameter table when it is
// used: an undefined name, a division by zero or a function outside its domain
// is a DeckError at the column where it happens.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/Error.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"

namespace c2d {

class Expression {
 public:
  Expression();  // the constant 0 (an empty field)

  static Expression parse(const Field& field);
  // Parses text whose first character is at loc; blanks are allowed between tokens.
  // line, when given, is the whole record (shown in messages).
  static Expression parse(std::string_view text, const SourceLoc& loc,
                          std::shared_ptr<const std::string> line = {});
  static Expression constant(double value);

  double eval(const Parameters& params) const;
  // Evaluates a value that must be a whole number (node, element, count);
  // what names it in the message ("node number").
  int evalInt(const Parameters& params, std::string_view what) const;

  bool isConstant() const;                 // no parameter names in it
  std::vector<std::string> names() const;  // parameter names used (lower case)
  const std::string& text() const;
  const SourceLoc& loc() const;

  struct Node;  // parse tree node (defined in Expression.cpp)
  struct Source;

 private:
  std::shared_ptr<const Node> root_;
  std::shared_ptr<const Source> source_;
};

}  // namespace c2d
