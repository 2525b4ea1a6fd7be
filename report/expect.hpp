// --expect: checks over summary.json metrics that set a CI job's exit code.
//
//   elbowsim run SCENARIO --expect "energy_final.electrical_in < 120"
//   elbowsim compare A B --expect "A.energy_final.electrical_in < B.energy_final.electrical_in"
//
// The language (docs/cli.md, "Expectations", has the full reference):
//   metric paths   dotted paths into summary.json: energy_final.joule,
//                  contact.landings, completed, warnings.0; in compare the
//                  first segment is a run label (its folder name). A segment
//                  that is not a plain name is quoted: 'elbow-on'.steps.
//   literals       numbers (120, 1e-3), 'text' or "text", true, false
//   arithmetic     + - * / and unary -, on numbers
//   comparisons    < <= > >= == != (numbers; == and != also strings, booleans)
//   logic          and/&&, or/||, not/!, parentheses
//   functions      abs(x), min(x, y, ...), max(x, y, ...), len(list or text)
// A NaN metric (written as null) fails every comparison except !=.
#pragma once

#include <iosfwd>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace elbowsim::report {

// A malformed expression (column > 0: where), or one that names a metric
// that is not there or mixes types (column: where that part starts).
class ExpectError : public std::runtime_error {
 public:
  ExpectError(const std::string& expression, std::size_t column, const std::string& message);
  std::string expression;
  std::size_t column;   // 1-based character position in the expression
  std::string message;  // without the expression and position
};

class Expectation {
 public:
  // Parses `text`. Throws ExpectError at the first malformed token.
  explicit Expectation(std::string text);
  ~Expectation();
  Expectation(Expectation&&) noexcept;
  Expectation& operator=(Expectation&&) noexcept;

  struct Outcome {
    bool passed = false;
    // Every metric path the expression read, with its value as text, in order.
    std::vector<std::pair<std::string, std::string>> values;
  };

  // Evaluates against `metrics` (summary.json; for compare, an object of
  // run label -> summary.json). Throws ExpectError when a path is not there,
  // an operator gets the wrong types, or the result is not true/false.
  Outcome evaluate(const nlohmann::ordered_json& metrics) const;

  // Before a run: every metric path resolves in `shape`, a summary.json of
  // the same scenario with placeholder values (lists and nulls there hold
  // anything). Throws ExpectError naming the path, what is there and the
  // nearest path that resolves (with a variant's prefix where one is needed).
  void check_paths(const nlohmann::ordered_json& shape) const;

  const std::string& text() const { return text_; }

  struct Node;

 private:
  std::string text_;
  std::unique_ptr<Node> root_;
};

enum class ExpectStatus { met, failed, invalid };

// Parses every text; prints each malformed one to `err` (expression, column,
// a caret under it) and returns an empty list with ok = false.
std::vector<Expectation> parse_expectations(const std::vector<std::string>& texts,
                                            std::ostream& err, bool& ok);

// Evaluates every expectation. Met ones are listed on `out` ("expect: ok ..."),
// failed ones on `err` with the value of every metric they read. `invalid`
// when one names a missing metric or mixes types (also on `err`), else
// `failed` when one does not hold, else `met`.
ExpectStatus check_expectations(const std::vector<Expectation>& expectations,
                                const nlohmann::ordered_json& metrics, std::ostream& out,
                                std::ostream& err);

// "error: --expect \"...\": column 7: message" and, for a column, the
// expression again with a caret under that column.
std::string describe(const ExpectError& e);

}  // namespace elbowsim::report
