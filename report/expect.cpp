#include "report/expect.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <ostream>

#include "engine/recording/number_text.hpp"
#include "report/expect_paths.hpp"

namespace elbowsim::report {

// ---- tokens ----------------------------------------------------------------

namespace {

enum class Tok { number, name, text, op, end };

struct Token {
  Tok kind;
  std::string text;    // operator, name, string contents, number as written
  std::size_t column;  // 1-based
};

// Splits an expression into tokens; operators are matched longest first.
class Lexer {
 public:
  explicit Lexer(const std::string& s) : s_(s) {}

  std::vector<Token> tokens() {
    std::vector<Token> out;
    for (;;) {
      while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
      if (i_ == s_.size()) return out.push_back({Tok::end, "", i_ + 1}), out;
      // After a "." come keys: "warnings.0.x" is not warnings, 0.0, x.
      const bool key = !out.empty() && out.back().kind == Tok::op && out.back().text == ".";
      out.push_back(key && std::isdigit(static_cast<unsigned char>(s_[i_])) ? digits() : next());
    }
  }

 private:
  Token next() {
    const std::size_t start = i_;
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c))) return number(start);
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_'))
        ++i_;
      return {Tok::name, s_.substr(start, i_ - start), start + 1};
    }
    if (c == '\'' || c == '"') return quoted(start);
    for (const char* op : {"<=", ">=", "==", "!=", "&&", "||", "<", ">", "+", "-", "*", "/", "(",
                           ")", ",", ".", "!"}) {
      const std::string o = op;
      if (s_.compare(i_, o.size(), o) == 0) return i_ += o.size(), Token{Tok::op, o, start + 1};
    }
    throw ExpectError(s_, start + 1, std::string("unexpected character '") + c + "'");
  }

  Token digits() {
    const std::size_t start = i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    return {Tok::number, s_.substr(start, i_ - start), start + 1};
  }

  // Digits, an optional fraction and exponent: 120, 0.5, 1e-3, 2.5E+4.
  Token number(std::size_t start) {
    const char* begin = s_.c_str() + start;
    char* end = nullptr;
    std::strtod(begin, &end);
    i_ = start + (end - begin);
    return {Tok::number, s_.substr(start, i_ - start), start + 1};
  }

  Token quoted(std::size_t start) {
    const char quote = s_[i_++];
    const std::size_t close = s_.find(quote, i_);
    if (close == std::string::npos)
      throw ExpectError(s_, start + 1, std::string("unterminated string: no closing ") + quote);
    i_ = close + 1;
    return {Tok::text, s_.substr(start + 1, close - start - 1), start + 1};
  }

  const std::string& s_;
  std::size_t i_ = 0;
};

}  // namespace

// ---- syntax tree ----------------------------------------------------------

struct Expectation::Node {
  enum Kind { literal, path, unary, binary, call } kind;
  nlohmann::ordered_json value;       // literal
  std::vector<std::string> segments;  // path
  std::string text;                   // path as written; operator; function name
  std::vector<std::unique_ptr<Node>> operands;
  std::size_t column = 0;
};

namespace {

using Node = Expectation::Node;
using NodePtr = std::unique_ptr<Node>;

NodePtr make(Node::Kind kind, std::size_t column, std::string text = "") {
  auto n = std::make_unique<Node>();
  n->kind = kind;
  n->column = column;
  n->text = std::move(text);
  return n;
}

bool is_keyword(const std::string& s) {
  return s == "and" || s == "or" || s == "not" || s == "true" || s == "false";
}

bool is_function(const std::string& s) {
  return s == "abs" || s == "min" || s == "max" || s == "len";
}

std::string describe_token(const Token& t) {
  if (t.kind == Tok::end) return "the end of the expression";
  if (t.kind == Tok::text) return "'" + t.text + "'";
  return "\"" + t.text + "\"";
}

// Recursive descent, one function per precedence level:
//   or := and (("or" | "||") and)*        and := not (("and" | "&&") not)*
//   not := ("not" | "!") not | compare     compare := sum (cmp sum)?
//   sum := product (("+" | "-") product)*  product := unary (("*" | "/") unary)*
//   unary := "-" unary | primary
//   primary := number | string | true | false | path | function "(" args ")" | "(" or ")"
class Parser {
 public:
  Parser(const std::string& text, std::vector<Token> tokens)
      : text_(text), tokens_(std::move(tokens)) {}

  NodePtr parse() {
    NodePtr root = parse_or();
    if (peek().kind != Tok::end)
      fail(peek(), "expected an operator or the end, found " + describe_token(peek()));
    return root;
  }

 private:
  const Token& peek() const { return tokens_[k_]; }
  bool at(const char* op) const {
    const Token& t = peek();
    return (t.kind == Tok::op || t.kind == Tok::name) && t.text == op;
  }
  Token take() { return tokens_[k_++]; }
  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    throw ExpectError(text_, t.column, message);
  }

  NodePtr binary(std::string op, std::size_t column, NodePtr a, NodePtr b) {
    NodePtr n = make(Node::binary, column, std::move(op));
    n->operands.push_back(std::move(a));
    n->operands.push_back(std::move(b));
    return n;
  }

  NodePtr parse_or() {
    NodePtr left = parse_and();
    while (at("or") || at("||")) {
      const Token op = take();
      left = binary("or", op.column, std::move(left), parse_and());
    }
    return left;
  }

  NodePtr parse_and() {
    NodePtr left = parse_not();
    while (at("and") || at("&&")) {
      const Token op = take();
      left = binary("and", op.column, std::move(left), parse_not());
    }
    return left;
  }

  NodePtr parse_not() {
    if (!at("not") && !at("!")) return parse_compare();
    const Token op = take();
    NodePtr n = make(Node::unary, op.column, "not");
    n->operands.push_back(parse_not());
    return n;
  }

  static bool is_comparison(const Token& t) {
    return t.kind == Tok::op && (t.text == "<" || t.text == "<=" || t.text == ">" ||
                                 t.text == ">=" || t.text == "==" || t.text == "!=");
  }

  NodePtr parse_compare() {
    NodePtr left = parse_sum();
    if (!is_comparison(peek())) return left;
    const Token op = take();
    left = binary(op.text, op.column, std::move(left), parse_sum());
    if (is_comparison(peek())) fail(peek(), "comparisons do not chain: write a < b and b < c");
    return left;
  }

  NodePtr parse_sum() {
    NodePtr left = parse_product();
    while (at("+") || at("-")) {
      const Token op = take();
      left = binary(op.text, op.column, std::move(left), parse_product());
    }
    return left;
  }

  NodePtr parse_product() {
    NodePtr left = parse_unary();
    while (at("*") || at("/")) {
      const Token op = take();
      left = binary(op.text, op.column, std::move(left), parse_unary());
    }
    return left;
  }

  NodePtr parse_unary() {
    if (!at("-")) return parse_primary();
    const Token op = take();
    NodePtr n = make(Node::unary, op.column, "-");
    n->operands.push_back(parse_unary());
    return n;
  }

  NodePtr literal(const Token& t, nlohmann::ordered_json value) {
    NodePtr n = make(Node::literal, t.column, t.text);
    n->value = std::move(value);
    return n;
  }

  NodePtr parse_primary() {
    const Token t = take();
    if (t.kind == Tok::number) return literal(t, std::strtod(t.text.c_str(), nullptr));
    if (t.kind == Tok::op && t.text == "(") {
      NodePtr inner = parse_or();
      if (!at(")"))
        fail(peek(), "expected \")\" to close the \"(\" at column " + std::to_string(t.column) +
                         ", found " + describe_token(peek()));
      take();
      return inner;
    }
    if (t.kind == Tok::text && !at(".")) return literal(t, t.text);
    if (t.kind == Tok::name && (t.text == "true" || t.text == "false"))
      return literal(t, t.text == "true");
    if (t.kind == Tok::name && !is_keyword(t.text) && at("(")) return parse_call(t);
    if (t.kind == Tok::text || (t.kind == Tok::name && !is_keyword(t.text))) return parse_path(t);
    fail(t, "expected a number, a metric path, a string, true/false, a function or \"(\", found " +
                describe_token(t));
  }

  NodePtr parse_call(const Token& name) {
    if (!is_function(name.text))
      fail(name, "unknown function \"" + name.text + "\" (there are abs, min, max, len)");
    take();  // "("
    NodePtr n = make(Node::call, name.column, name.text);
    n->operands.push_back(parse_or());
    while (at(",")) take(), n->operands.push_back(parse_or());
    if (!at(")"))
      fail(peek(),
           "expected \",\" or \")\" in " + name.text + "(...), found " + describe_token(peek()));
    take();
    const std::size_t args = n->operands.size();
    if ((name.text == "abs" || name.text == "len") && args != 1)
      fail(name, name.text + "() takes one argument, got " + std::to_string(args));
    return n;
  }

  // segment ("." segment)*, a segment being a name, a quoted text or digits.
  NodePtr parse_path(const Token& first) {
    NodePtr n = make(Node::path, first.column);
    n->segments.push_back(first.text);
    while (at(".")) {
      take();
      const Token s = take();
      const bool index =
          s.kind == Tok::number && s.text.find_first_not_of("0123456789") == std::string::npos;
      if (s.kind != Tok::name && s.kind != Tok::text && !index)
        fail(s, "expected a key after \".\", found " + describe_token(s));
      n->segments.push_back(s.text);
    }
    for (std::size_t k = 0; k < n->segments.size(); ++k) {
      const std::string& s = n->segments[k];
      const bool plain =
          !s.empty() &&
          s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
              std::string::npos;
      n->text += (k ? "." : "") + (plain ? s : "'" + s + "'");
    }
    return n;
  }

  const std::string& text_;
  std::vector<Token> tokens_;
  std::size_t k_ = 0;
};

// ---- evaluation -------------------------------------------------------------

std::string value_text(const nlohmann::ordered_json& v) {
  if (v.is_null()) return "NaN (null)";
  if (v.is_number()) return significant(v.get<double>(), 10);
  if (v.is_string()) return "'" + v.get<std::string>() + "'";
  return v.dump();
}

const char* type_name(const nlohmann::ordered_json& v) {
  if (v.is_number() || v.is_null()) return "a number";
  if (v.is_boolean()) return "true/false";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "a list";
  return "an object";
}

class Evaluator {
 public:
  Evaluator(const std::string& text, const nlohmann::ordered_json& metrics)
      : text_(text), metrics_(metrics) {}

  nlohmann::ordered_json eval(const Node& n) {
    switch (n.kind) {
      case Node::literal:
        return n.value;
      case Node::path:
        return lookup(n);
      case Node::unary:
        return unary(n);
      case Node::binary:
        return binary(n);
      case Node::call:
        return call(n);
    }
    return nullptr;
  }

  std::vector<std::pair<std::string, std::string>> values;

 private:
  [[noreturn]] void fail(const Node& n, const std::string& message) const {
    throw ExpectError(text_, n.column, message);
  }

  nlohmann::ordered_json lookup(const Node& n) {
    if (const auto problem = path_problem(metrics_, n.segments, PathCheck::exact))
      fail(n, "no metric \"" + n.text + "\": " + *problem);
    const nlohmann::ordered_json* node = &metrics_;
    for (const std::string& s : n.segments)
      node = node->is_array() ? &(*node)[std::stoul(s)] : &(*node)[s];
    bool seen = false;
    for (const auto& v : values) seen = seen || v.first == n.text;
    if (!seen) values.push_back({n.text, value_text(*node)});
    return *node;
  }

  double number(const Node& n, const nlohmann::ordered_json& v, const std::string& what) const {
    if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!v.is_number()) fail(n, what + " needs numbers, got " + type_name(v) + " " + value_text(v));
    return v.get<double>();
  }

  bool boolean(const Node& n, const nlohmann::ordered_json& v, const std::string& what) const {
    if (!v.is_boolean())
      fail(n, what + " needs true/false, got " + type_name(v) + " " + value_text(v) +
                  " (compare it, e.g. x > 0)");
    return v.get<bool>();
  }

  nlohmann::ordered_json unary(const Node& n) {
    const nlohmann::ordered_json a = eval(*n.operands[0]);
    if (n.text == "not") return !boolean(*n.operands[0], a, "not");
    return -number(*n.operands[0], a, "unary -");
  }

  nlohmann::ordered_json binary(const Node& n) {
    const nlohmann::ordered_json a = eval(*n.operands[0]), b = eval(*n.operands[1]);
    const std::string& op = n.text;
    if (op == "and" || op == "or") {
      const bool x = boolean(*n.operands[0], a, op), y = boolean(*n.operands[1], b, op);
      return op == "and" ? (x && y) : (x || y);
    }
    if (op == "==" || op == "!=") return equality(n, a, b);
    const double x = number(n, a, "\"" + op + "\""), y = number(n, b, "\"" + op + "\"");
    if (op == "+") return x + y;
    if (op == "-") return x - y;
    if (op == "*") return x * y;
    if (op == "/") return x / y;
    if (op == "<") return x < y;
    if (op == "<=") return x <= y;
    if (op == ">") return x > y;
    return x >= y;  // ">="
  }

  // Numbers (null = NaN) compare as IEEE doubles; strings and booleans by value.
  nlohmann::ordered_json equality(const Node& n, const nlohmann::ordered_json& a,
                                  const nlohmann::ordered_json& b) const {
    const bool numeric = (a.is_number() || a.is_null()) && (b.is_number() || b.is_null());
    bool equal;
    if (numeric)
      equal = number(n, a, "==") == number(n, b, "==");
    else if (std::string(type_name(a)) != type_name(b))
      fail(n, std::string("cannot compare ") + type_name(a) + " " + value_text(a) + " with " +
                  type_name(b) + " " + value_text(b));
    else
      equal = a == b;
    return n.text == "==" ? equal : !equal;
  }

  nlohmann::ordered_json call(const Node& n) {
    std::vector<nlohmann::ordered_json> args;
    for (const auto& operand : n.operands) args.push_back(eval(*operand));
    if (n.text == "len") {
      if (!args[0].is_array() && !args[0].is_string() && !args[0].is_object())
        fail(n, "len() needs a list or a string, got " + std::string(type_name(args[0])));
      return args[0].is_string() ? args[0].get<std::string>().size() : args[0].size();
    }
    if (n.text == "abs") return std::abs(number(n, args[0], "abs()"));
    double result = number(n, args[0], n.text + "()");
    for (std::size_t k = 1; k < args.size(); ++k) {
      const double v = number(n, args[k], n.text + "()");
      result = n.text == "min" ? std::fmin(result, v) : std::fmax(result, v);
    }
    return result;
  }

  const std::string& text_;
  const nlohmann::ordered_json& metrics_;
};

}  // namespace

// ---- public -----------------------------------------------------------------

ExpectError::ExpectError(const std::string& expression, std::size_t column,
                         const std::string& message)
    : std::runtime_error("--expect \"" + expression + "\": column " + std::to_string(column) +
                         ": " + message),
      expression(expression),
      column(column),
      message(message) {}

Expectation::Expectation(std::string text) : text_(std::move(text)) {
  root_ = Parser(text_, Lexer(text_).tokens()).parse();
}

Expectation::~Expectation() = default;
Expectation::Expectation(Expectation&&) noexcept = default;
Expectation& Expectation::operator=(Expectation&&) noexcept = default;

Expectation::Outcome Expectation::evaluate(const nlohmann::ordered_json& metrics) const {
  Evaluator evaluator(text_, metrics);
  const nlohmann::ordered_json result = evaluator.eval(*root_);
  if (!result.is_boolean())
    throw ExpectError(text_, 1,
                      "the expression gives " + std::string(type_name(result)) + " (" +
                          value_text(result) + "), not true/false: compare it, e.g. " + "... < 1");
  return {result.get<bool>(), std::move(evaluator.values)};
}

namespace {

void check_paths_of(const Expectation::Node& n, const std::string& text,
                    const nlohmann::ordered_json& shape) {
  if (n.kind == Expectation::Node::path)
    if (const auto problem = path_problem(shape, n.segments, PathCheck::shape))
      throw ExpectError(text, n.column, "no metric \"" + n.text + "\": " + *problem);
  for (const auto& operand : n.operands) check_paths_of(*operand, text, shape);
}

}  // namespace

void Expectation::check_paths(const nlohmann::ordered_json& shape) const {
  check_paths_of(*root_, text_, shape);
}

std::string describe(const ExpectError& e) {
  std::string out = std::string("error: ") + e.what() + "\n  " + e.expression + "\n  ";
  out += std::string(e.column > 0 ? e.column - 1 : 0, ' ') + "^\n";
  return out;
}

std::vector<Expectation> parse_expectations(const std::vector<std::string>& texts,
                                            std::ostream& err, bool& ok) {
  std::vector<Expectation> parsed;
  ok = true;
  for (const std::string& text : texts) {
    try {
      parsed.emplace_back(text);
    } catch (const ExpectError& e) {
      err << describe(e);
      ok = false;
    }
  }
  if (!ok) parsed.clear();
  return parsed;
}

ExpectStatus check_expectations(const std::vector<Expectation>& expectations,
                                const nlohmann::ordered_json& metrics, std::ostream& out,
                                std::ostream& err) {
  ExpectStatus status = ExpectStatus::met;
  for (const Expectation& e : expectations) {
    try {
      const Expectation::Outcome outcome = e.evaluate(metrics);
      std::ostream& stream = outcome.passed ? out : err;
      stream << (outcome.passed ? "expect: ok     " : "expect: FAILED ") << e.text() << '\n';
      for (const auto& [path, value] : outcome.values)
        stream << "                 " << path << " = " << value << '\n';
      if (!outcome.passed && status == ExpectStatus::met) status = ExpectStatus::failed;
    } catch (const ExpectError& error) {
      err << describe(error);
      status = ExpectStatus::invalid;
    }
  }
  return status;
}

}  // namespace elbowsim::report
