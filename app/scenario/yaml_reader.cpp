#include "app/scenario/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <system_error>

#include "app/scenario/scenario.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

// True if `key` is `prefix` or lies below it ("a.b" is below "a", "a[0]" too).
bool is_under(const std::string& key, const std::string& prefix) {
  if (key.compare(0, prefix.size(), prefix) != 0) return false;
  return key.size() == prefix.size() || key[prefix.size()] == '.' || key[prefix.size()] == '[';
}

int one_based(int zero_based) { return zero_based < 0 ? 0 : zero_based + 1; }

// How a node that is not what was expected looks, for messages.
std::string describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return "\"" + node.Scalar() + "\"";
}

bool is_quoted(const YAML::Node& scalar) { return scalar.Tag() == "!"; }

// YAML's spellings of infinity and not-a-number (core schema).
bool is_yaml_non_finite(std::string_view s) {
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
  return s == ".inf" || s == ".Inf" || s == ".INF" || s == ".nan" || s == ".NaN" || s == ".NAN";
}

// Parses all of `s` as T (a leading '+' allowed); false if anything is left.
template <class T>
bool parse_all(std::string_view s, T& out, std::errc& error) {
  if (s.size() > 1 && s.front() == '+' && s[1] != '-') s.remove_prefix(1);
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  error = ec;
  return end == s.data() + s.size() && !s.empty();
}

// Optimal string alignment distance: insertions, deletions, substitutions and
// swaps of neighbours each cost 1 ("stpe" -> "step" is 1).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

// ---------------------------------------------------------------------------
// Source

void Source::add_override(std::string path, Origin origin) {
  overrides_.push_back({std::move(path), std::move(origin)});
}

Source::Origin Source::origin(const YAML::Mark& mark, const std::string& key) const {
  for (auto it = overrides_.rbegin(); it != overrides_.rend(); ++it) {
    if (is_under(key, it->path)) return it->origin;
  }
  return {file_, one_based(mark.line), one_based(mark.column)};
}

void Source::fail(const YAML::Mark& mark, const std::string& key,
                  const std::string& message) const {
  const Origin o = origin(mark, key);
  throw ScenarioError(o.file, o.line, o.column, key, message + note_);
}

// ---------------------------------------------------------------------------
// Value: construction and maps

Value::Value(const Source& source, YAML::Node root) : Value(&source, root, "", root.Mark(), true) {}

Value::Value(const Source* source, YAML::Node node, std::string path, YAML::Mark mark, bool exists)
    : source_(source), node_(node), path_(std::move(path)), mark_(mark), exists_(exists) {}

// YAML::Node's operator= writes through to the tree; reset() only rebinds.
Value& Value::operator=(const Value& other) {
  source_ = other.source_;
  node_.reset(other.node_);
  path_ = other.path_;
  mark_ = other.mark_;
  exists_ = other.exists_;
  return *this;
}

bool Value::present() const { return exists_ && node_.IsDefined() && !node_.IsNull(); }

void Value::fail(const std::string& message) const { source_->fail(mark_, path_, message); }

Source::Origin Value::origin() const { return source_->origin(mark_, path_); }

namespace {

// Flow-style YAML of a node. Quoted scalars stay quoted ("1.0" stays a
// string), which yaml-cpp's own emitter of a node would drop.
void emit_flow(YAML::Emitter& out, const YAML::Node& node) {
  if (node.IsScalar()) {
    if (is_quoted(node)) out << YAML::DoubleQuoted;
    out << node.Scalar();
  } else if (node.IsSequence()) {
    out << YAML::Flow << YAML::BeginSeq;
    for (const auto& item : node) emit_flow(out, item);
    out << YAML::EndSeq;
  } else if (node.IsMap()) {
    out << YAML::Flow << YAML::BeginMap;
    for (const auto& entry : node) {
      out << YAML::Key;
      emit_flow(out, entry.first);
      out << YAML::Value;
      emit_flow(out, entry.second);
    }
    out << YAML::EndMap;
  } else {
    out << YAML::Null;
  }
}

}  // namespace

std::string Value::flow_yaml() const {
  if (!present()) return "";
  YAML::Emitter out;
  emit_flow(out, node_);
  return out.c_str();
}

std::string Value::child_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

// A child node; a null one is located at its key, where the eye looks for it.
Value Value::child(std::string path, const YAML::Node& node, const YAML::Mark& key_mark) const {
  YAML::Mark mark = node.IsNull() || node.Mark().is_null() ? key_mark : node.Mark();
  return Value(source_, node, std::move(path), mark, true);
}

void Value::expect_map() const {
  if (!is_map()) fail("expected a map (got " + (exists_ ? describe(node_) : "nothing") + ")");
}

void Value::allow_keys(std::initializer_list<std::string_view> keys) const {
  expect_map();
  const std::vector<std::string_view> allowed(keys);
  std::map<std::string, int> seen;  // key -> 1-based line of its first use
  // By reference: `it->first` of a yaml-cpp iterator dangles after the statement.
  for (const auto& entry : node_) {
    const YAML::Node& key = entry.first;
    if (!key.IsScalar()) source_->fail(key.Mark(), path_, "keys must be plain names");
    const std::string& name = key.Scalar();
    Value here(source_, key, child_path(name), key.Mark(), true);
    auto [first, inserted] = seen.emplace(name, one_based(key.Mark().line));
    if (!inserted) here.fail("duplicate key (first at line " + std::to_string(first->second) + ")");
    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
    std::string guess = closest(name, allowed);
    here.fail("unknown key \"" + name + "\"" +
              (guess.empty() ? "" : " (did you mean \"" + guess + "\"?)") +
              "; allowed here: " + join(allowed));
  }
}

Value Value::get(std::string_view key) const {
  expect_map();
  for (const auto& entry : node_) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key)
      return child(child_path(key), entry.second, entry.first.Mark());
  }
  return Value(source_, YAML::Node(), child_path(key), mark_, false);
}

Value Value::require(std::string_view key) const {
  Value value = get(key);
  if (!value.exists_) value.fail("required key is missing");  // located at this map
  if (!value.present()) value.fail("has no value");
  return value;
}

std::vector<std::pair<Value, Value>> Value::entries() const {
  expect_map();
  std::vector<std::pair<Value, Value>> out;
  for (const auto& entry : node_) {
    const YAML::Node& key = entry.first;
    std::string path = child_path(key.IsScalar() ? key.Scalar() : "?");
    Value key_value(source_, key, path, key.Mark(), true);
    out.emplace_back(key_value, child(path, entry.second, key.Mark()));
  }
  return out;
}

// ---------------------------------------------------------------------------
// Value: sequences and scalars

std::vector<Value> Value::items() const {
  if (!is_sequence()) fail("expected a list (got " + (exists_ ? describe(node_) : "nothing") + ")");
  std::vector<Value> out;
  for (std::size_t i = 0; i < node_.size(); ++i)
    out.push_back(child(path_ + "[" + std::to_string(i) + "]", node_[i], mark_));
  return out;
}

void Value::expect_scalar(std::string_view expected) const {
  if (!exists_ || !node_.IsScalar())
    fail("expected " + std::string(expected) + " (got " + (exists_ ? describe(node_) : "nothing") +
         ")");
}

double Value::number() const {
  expect_scalar("a number");
  const std::string& s = node_.Scalar();
  if (is_quoted(node_)) fail("expected a number (got the string \"" + s + "\")");
  if (is_yaml_non_finite(s)) fail("must be a finite number (got " + s + ")");
  double x = 0;
  std::errc error{};
  bool whole = parse_all(s, x, error);
  if (whole && error == std::errc::result_out_of_range)
    fail("must be a finite number (got " + s + ")");
  if (!whole || error != std::errc{}) fail("expected a number (got \"" + s + "\")");
  if (!std::isfinite(x)) fail("must be a finite number (got " + s + ")");
  return x;
}

long Value::integer() const {
  expect_scalar("a whole number");
  const std::string& s = node_.Scalar();
  long n = 0;
  std::errc error{};
  if (!is_quoted(node_) && parse_all(s, n, error) && error == std::errc{}) return n;
  fail("expected a whole number (got \"" + s + "\")");
}

bool Value::boolean() const {
  expect_scalar("true or false");
  const std::string& s = node_.Scalar();
  if (!is_quoted(node_)) {
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
  }
  fail("expected true or false (got \"" + s + "\")");
}

std::string Value::text() const {
  expect_scalar("a string");
  return node_.Scalar();
}

Eigen::VectorXd Value::numbers(long size, std::string_view what) const {
  std::string expected =
      size < 0 ? std::string("a list of numbers") : "a list of " + counted(size, "number");
  if (!what.empty()) expected += " (" + std::string(what) + ")";
  if (!is_sequence())
    fail("expected " + expected + " (got " + (exists_ ? describe(node_) : "nothing") + ")");
  std::vector<Value> list = items();
  if (size >= 0 && static_cast<long>(list.size()) != size)
    fail("expected " + expected + " (got " + std::to_string(list.size()) + ")");
  Eigen::VectorXd out(static_cast<Eigen::Index>(list.size()));
  for (std::size_t i = 0; i < list.size(); ++i)
    out[static_cast<Eigen::Index>(i)] = list[i].number();
  return out;
}

Eigen::Vector3d Value::vec3() const { return numbers(3, "x, y, z"); }

// ---------------------------------------------------------------------------
// Messages

std::string join(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out += w;
  }
  return out;
}

std::string closest(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string best;
  std::size_t best_distance = 3;
  for (std::string_view c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace elbowsim::loader
