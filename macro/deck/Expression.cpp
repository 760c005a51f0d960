#include "macro/deck/Expression.h"

#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <sstream>

#include "macro/deck/Suggest.h"

namespace c2d {

namespace {

enum class Func {
  Abs,
  Exp,
  Int,
  Log,
  Sqrt,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sind,
  Cosd,
  Tand,
  Asind,
  Acosd,
  Atand,
  Sinh,
  Cosh,
  Tanh
};

struct FuncName {
  const char* name;
  Func f;
};

constexpr std::array<FuncName, 20> kFunctions{{
    {"abs", Func::Abs},     {"exp", Func::Exp},   {"int", Func::Int},     {"log", Func::Log},
    {"sqrt", Func::Sqrt},   {"sin", Func::Sin},   {"cos", Func::Cos},     {"tan", Func::Tan},
    {"asin", Func::Asin},   {"acos", Func::Acos}, {"atan", Func::Atan},   {"sind", Func::Sind},
    {"cosd", Func::Cosd},   {"tand", Func::Tand}, {"asind", Func::Asind}, {"acosd", Func::Acosd},
    {"atand", Func::Atand}, {"sinh", Func::Sinh}, {"cosh", Func::Cosh},   {"tanh", Func::Tanh},
}};

std::string functionList() {
  std::string s;
  for (const auto& f : kFunctions) {
    if (!s.empty()) s.push_back(' ');
    s.append(f.name);
  }
  return s;
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

}  // namespace

struct Expression::Source {
  std::string text;                         // the expression as written
  SourceLoc loc;                            // of text[0]
  std::shared_ptr<const std::string> line;  // whole record, may be null

  std::string excerpt(int col) const { return Field{text, loc, line}.excerpt(col); }
};

struct Expression::Node {
  enum class Kind { Number, Name, Neg, Add, Sub, Mul, Div, Pow, Call };
  Kind kind = Kind::Number;
  double value = 0;
  std::string name;  // lower case (Name), function name (Call)
  Func func = Func::Abs;
  std::shared_ptr<const Node> a, b;
  int col = 0;  // source column of the token that defines the node
};

namespace {

using Node = Expression::Node;
using NodePtr = std::shared_ptr<const Node>;

// Recursive descent over one expression:
//   expr  := term (('+' | '-') term)*
//   term  := unary (('*' | '/') unary)*
//   unary := ('-' | '+') unary | power
//   power := primary ('^' unary)?          (right associative, above unary minus)
//   primary := number | name | name '(' expr ')' | '(' expr ')'
class Parser {
 public:
  Parser(std::string_view text, const Expression::Source& src) : s_(text), src_(src) {}

  NodePtr parseAll() {
    NodePtr n = expr();
    skipBlanks();
    if (pos_ < s_.size()) {
      if (s_[pos_] == ')') fail(pos_, "unmatched ')'");
      fail(pos_, std::string("unexpected '") + s_[pos_] + "'");
    }
    return n;
  }

 private:
  int col(std::size_t p) const { return src_.loc.col + static_cast<int>(p); }

  [[noreturn]] void fail(std::size_t p, const std::string& what,
                         const std::string& hint = {}) const {
    SourceLoc l = src_.loc;
    l.col = col(p);
    throw DeckError(l, "syntax error in expression '" + src_.text + "': " + what,
                    src_.excerpt(l.col), hint);
  }

  void skipBlanks() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
  }
  bool peek(char c) {
    skipBlanks();
    return pos_ < s_.size() && s_[pos_] == c;
  }

  std::shared_ptr<Node> make(Node::Kind k, std::size_t p, NodePtr a = {}, NodePtr b = {}) const {
    auto n = std::make_shared<Node>();
    n->kind = k;
    n->col = col(p);
    n->a = std::move(a);
    n->b = std::move(b);
    return n;
  }

  NodePtr expr() {
    NodePtr left = term();
    while (true) {
      skipBlanks();
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) {
        const std::size_t p = pos_;
        const char op = s_[pos_++];
        NodePtr right = term();
        left = make(op == '+' ? Node::Kind::Add : Node::Kind::Sub, p, left, right);
      } else {
        return left;
      }
    }
  }

  NodePtr term() {
    NodePtr left = unary();
    while (true) {
      skipBlanks();
      if (pos_ < s_.size() && (s_[pos_] == '*' || s_[pos_] == '/')) {
        const std::size_t p = pos_;
        const char op = s_[pos_++];
        NodePtr right = unary();
        left = make(op == '*' ? Node::Kind::Mul : Node::Kind::Div, p, left, right);
      } else {
        return left;
      }
    }
  }

  NodePtr unary() {
    skipBlanks();
    if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) {
      const std::size_t p = pos_;
      const char op = s_[pos_++];
      NodePtr operand = unary();
      return op == '-' ? make(Node::Kind::Neg, p, operand) : operand;
    }
    return power();
  }

  NodePtr power() {
    NodePtr base = primary();
    skipBlanks();
    if (pos_ < s_.size() && s_[pos_] == '^') {
      const std::size_t p = pos_++;
      NodePtr exponent = unary();  // right associative; allows 2^-1
      return make(Node::Kind::Pow, p, base, exponent);
    }
    return base;
  }

  NodePtr primary() {
    skipBlanks();
    if (pos_ >= s_.size()) fail(pos_, "expression ends too early");
    const char c = s_[pos_];
    if (c == '(') {
      const std::size_t open = pos_++;
      if (peek(')')) fail(pos_, "empty parentheses");
      NodePtr inner = expr();
      if (!peek(')')) fail(open, "'(' is never closed");
      ++pos_;
      return inner;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return nameOrCall();
    if (c == ')') fail(pos_, "expected a value before ')'");
    fail(pos_, std::string("unexpected '") + c + "'");
  }

  NodePtr number() {
    const std::size_t start = pos_;
    auto digits = [&] {
      std::size_t n = 0;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_, ++n;
      return n;
    };
    std::size_t nd = digits();
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      nd += digits();
    }
    if (nd == 0) fail(start, "'.' is not a number");
    if (pos_ < s_.size() && std::strchr("eEdD", s_[pos_]) != nullptr) {
      const std::size_t e = pos_++;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      if (digits() == 0)
        fail(e,
             "malformed exponent in number '" + std::string(s_.substr(start, pos_ - start)) + "'");
    }
    if (pos_ < s_.size() &&
        (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_' || s_[pos_] == '.'))
      fail(pos_, "malformed number '" + std::string(s_.substr(start, pos_ - start + 1)) + "'");
    std::string t(s_.substr(start, pos_ - start));
    for (char& ch : t)
      if (ch == 'd' || ch == 'D') ch = 'e';  // Fortran double exponent
    auto n = std::make_shared<Node>();
    n->kind = Node::Kind::Number;
    n->value = std::strtod(t.c_str(), nullptr);
    n->col = col(start);
    if (!std::isfinite(n->value)) fail(start, "number out of range");
    return n;
  }

  NodePtr nameOrCall() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() &&
           (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
      ++pos_;
    const std::string name = toLower(s_.substr(start, pos_ - start));
    if (peek('(')) {
      const FuncName* f = nullptr;
      for (const auto& cand : kFunctions)
        if (name == cand.name) f = &cand;
      if (!f) {
        std::vector<std::string> names;
        for (const auto& cand : kFunctions) names.emplace_back(cand.name);
        std::string hint = didYouMean(name, names);
        if (hint.empty()) hint = "functions: " + functionList();
        fail(start, "unknown function '" + name + "'", hint);
      }
      const std::size_t open = pos_++;
      if (peek(')')) fail(pos_, "function '" + name + "' needs an argument");
      NodePtr arg = expr();
      if (!peek(')')) fail(open, "'(' is never closed");
      ++pos_;
      auto n = make(Node::Kind::Call, start, arg);
      n->func = f->f;
      n->name = name;
      return n;
    }
    auto n = std::make_shared<Node>();
    n->kind = Node::Kind::Name;
    n->name = name;
    n->col = col(start);
    return n;
  }

  std::string_view s_;
  const Expression::Source& src_;
  std::size_t pos_ = 0;
};

class Evaluator {
 public:
  Evaluator(const Parameters& p, const Expression::Source& src) : p_(p), src_(src) {}

  double eval(const Node& n) const {
    switch (n.kind) {
      case Node::Kind::Number:
        return n.value;
      case Node::Kind::Name: {
        if (auto v = p_.find(n.name)) return *v;
        std::string hint = didYouMean(n.name, p_.names());
        if (hint.empty())
          hint = p_.size() == 0
                     ? "no parameter is defined yet: define it in a PARAmeter block first"
                     : "define it in a PARAmeter block before it is used";
        fail(n, "undefined parameter '" + n.name + "'", hint);
      }
      case Node::Kind::Neg:
        return -eval(*n.a);
      case Node::Kind::Add:
        return check(n, eval(*n.a) + eval(*n.b), "overflow");
      case Node::Kind::Sub:
        return check(n, eval(*n.a) - eval(*n.b), "overflow");
      case Node::Kind::Mul:
        return check(n, eval(*n.a) * eval(*n.b), "overflow");
      case Node::Kind::Div: {
        const double num = eval(*n.a), den = eval(*n.b);
        if (den == 0) fail(n, "division by zero");
        return check(n, num / den, "overflow");
      }
      case Node::Kind::Pow: {
        const double base = eval(*n.a), ex = eval(*n.b);
        return check(n, std::pow(base, ex),
                     "invalid power " + formatNumber(base) + "^" + formatNumber(ex));
      }
      case Node::Kind::Call:
        return call(n, eval(*n.a));
    }
    return 0;
  }

 private:
  [[noreturn]] void fail(const Node& n, const std::string& what,
                         const std::string& hint = {}) const {
    SourceLoc l = src_.loc;
    l.col = n.col;
    // Name the whole expression only when it is more than the offending token.
    const bool alone = toLower(src_.text) == n.name;
    throw DeckError(l, alone ? what : what + " in expression '" + src_.text + "'",
                    src_.excerpt(n.col), hint);
  }

  double check(const Node& n, double v, const std::string& what) const {
    if (!std::isfinite(v)) fail(n, what);
    return v;
  }

  double call(const Node& n, double x) const {
    constexpr double deg = std::numbers::pi / 180.0;
    auto domain = [&](bool ok) {
      if (!ok) fail(n, n.name + "(" + formatNumber(x) + ") is undefined");
    };
    double r = 0;
    switch (n.func) {
      case Func::Abs:
        r = std::fabs(x);
        break;
      case Func::Exp:
        r = std::exp(x);
        break;
      case Func::Int:
        r = std::trunc(x);
        break;
      case Func::Log:
        domain(x > 0);
        r = std::log(x);
        break;
      case Func::Sqrt:
        domain(x >= 0);
        r = std::sqrt(x);
        break;
      case Func::Sin:
        r = std::sin(x);
        break;
      case Func::Cos:
        r = std::cos(x);
        break;
      case Func::Tan:
        r = std::tan(x);
        break;
      case Func::Asin:
        domain(x >= -1 && x <= 1);
        r = std::asin(x);
        break;
      case Func::Acos:
        domain(x >= -1 && x <= 1);
        r = std::acos(x);
        break;
      case Func::Atan:
        r = std::atan(x);
        break;
      case Func::Sind:
        r = std::sin(x * deg);
        break;
      case Func::Cosd:
        r = std::cos(x * deg);
        break;
      case Func::Tand:
        r = std::tan(x * deg);
        break;
      case Func::Asind:
        domain(x >= -1 && x <= 1);
        r = std::asin(x) / deg;
        break;
      case Func::Acosd:
        domain(x >= -1 && x <= 1);
        r = std::acos(x) / deg;
        break;
      case Func::Atand:
        r = std::atan(x) / deg;
        break;
      case Func::Sinh:
        r = std::sinh(x);
        break;
      case Func::Cosh:
        r = std::cosh(x);
        break;
      case Func::Tanh:
        r = std::tanh(x);
        break;
    }
    return check(n, r, n.name + "(" + formatNumber(x) + ") overflows");
  }

  const Parameters& p_;
  const Expression::Source& src_;
};

void collectNames(const Node& n, std::vector<std::string>& out) {
  if (n.kind == Node::Kind::Name) {
    for (const auto& s : out)
      if (s == n.name) return;
    out.push_back(n.name);
  }
  if (n.a) collectNames(*n.a, out);
  if (n.b) collectNames(*n.b, out);
}

}  // namespace

Expression::Expression() {
  auto n = std::make_shared<Node>();
  n->kind = Node::Kind::Number;
  n->col = 1;
  auto src = std::make_shared<Source>();
  src->text.push_back('0');
  src->loc.line = 0;
  src->loc.col = 1;
  root_ = std::move(n);
  source_ = std::move(src);
}

Expression Expression::constant(double value) {
  Expression e;
  auto n = std::make_shared<Node>();
  n->kind = Node::Kind::Number;
  n->value = value;
  n->col = 1;
  auto src = std::make_shared<Source>();
  src->text = formatNumber(value);
  src->loc = {"", 0, 1};
  e.root_ = std::move(n);
  e.source_ = std::move(src);
  return e;
}

Expression Expression::parse(std::string_view text, const SourceLoc& loc,
                             std::shared_ptr<const std::string> line) {
  auto src = std::make_shared<Source>();
  src->text = std::string(text);
  src->loc = loc;
  src->line = std::move(line);

  Expression e;
  std::size_t first = 0;
  while (first < text.size() && (text[first] == ' ' || text[first] == '\t')) ++first;
  if (first == text.size()) {
    e.root_ = constant(0.0).root_;  // an empty field is the number 0
  } else {
    e.root_ = Parser(text, *src).parseAll();
  }
  e.source_ = std::move(src);
  return e;
}

Expression Expression::parse(const Field& field) {
  return parse(field.text, field.loc, field.line);
}

double Expression::eval(const Parameters& params) const {
  return Evaluator(params, *source_).eval(*root_);
}

int Expression::evalInt(const Parameters& params, std::string_view what) const {
  const double v = eval(params);
  const double r = std::round(v);
  if (std::fabs(v - r) > 1e-9 * std::max(1.0, std::fabs(v)) || std::fabs(r) > INT_MAX) {
    throw DeckError(source_->loc,
                    std::string(what) + " must be a whole number, got " + formatNumber(v) +
                        (isConstant() ? "" : " from '" + source_->text + "'"),
                    source_->excerpt(source_->loc.col));
  }
  return static_cast<int>(r);
}

bool Expression::isConstant() const { return names().empty(); }

std::vector<std::string> Expression::names() const {
  std::vector<std::string> out;
  collectNames(*root_, out);
  return out;
}

const std::string& Expression::text() const { return source_->text; }
const SourceLoc& Expression::loc() const { return source_->loc; }

}  // namespace c2d
