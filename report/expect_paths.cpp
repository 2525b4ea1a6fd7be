#include "report/expect_paths.hpp"

#include <algorithm>

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 10 && s.find_first_not_of("0123456789") == std::string::npos;
}

// The node `segments` leads to, or nullptr (lists: any index in shape mode,
// where the walk stops at the list).
const Json* walk(const Json& root, const std::vector<std::string>& segments, PathCheck check,
                 std::size_t& stopped) {
  const Json* node = &root;
  for (stopped = 0; stopped < segments.size(); ++stopped) {
    const std::string& s = segments[stopped];
    if (check == PathCheck::shape && (node->is_array() || node->is_null())) return node;
    if (node->is_object() && node->contains(s)) {
      node = &(*node)[s];
    } else if (node->is_array() && is_index(s) && std::stoul(s) < node->size()) {
      node = &(*node)[std::stoul(s)];
    } else {
      return nullptr;
    }
  }
  return node;
}

std::string join(const std::vector<std::string>& segments, std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count && i < segments.size(); ++i)
    out += (i ? "." : "") + segments[i];
  return out;
}

std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> out(1);
  for (char c : path) {
    if (c == '.')
      out.emplace_back();
    else
      out.back().push_back(c);
  }
  return out;
}

// Levenshtein distance (two rows).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> before(b.size() + 1), now(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) before[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    now[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      now[j] = std::min({before[j] + 1, now[j - 1] + 1, before[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(before, now);
  }
  return before[b.size()];
}

// Every path to a leaf (lists count as leaves), dotted.
void leaf_paths(const Json& node, const std::string& prefix, std::vector<std::string>& out) {
  if (!node.is_object() || node.empty()) {
    if (!prefix.empty()) out.push_back(prefix);
    return;
  }
  for (const auto& [key, value] : node.items())
    leaf_paths(value, prefix.empty() ? key : prefix + "." + key, out);
}

std::string keys_of(const Json& node) {
  std::string keys;
  int shown = 0;
  for (const auto& [key, value] : node.items()) {
    if (++shown > 12) return keys + ", ...";
    keys += (keys.empty() ? "" : ", ") + key;
  }
  return keys;
}

}  // namespace

std::string nearest_path(const Json& root, const std::string& path) {
  const std::vector<std::string> segments = split(path);
  // Under a top-level key: a variant's or run's summary.
  std::vector<std::string> prefixed;
  if (root.is_object())
    for (const auto& [key, value] : root.items()) {
      std::size_t stopped = 0;
      if (value.is_object() && walk(value, segments, PathCheck::shape, stopped))
        prefixed.push_back(key + "." + path);
    }
  if (!prefixed.empty()) {
    std::string out = prefixed[0];
    for (std::size_t i = 1; i < prefixed.size(); ++i)
      out += (i + 1 == prefixed.size() ? " or " : ", ") + prefixed[i];
    return out;
  }
  std::vector<std::string> leaves;
  leaf_paths(root, "", leaves);
  std::string best;
  std::size_t best_distance = path.size() / 3 + 1;
  for (const std::string& leaf : leaves) {
    const std::size_t d = edit_distance(path, leaf);
    if (d < best_distance) best_distance = d, best = leaf;
  }
  return best;
}

std::optional<std::string> path_problem(const Json& root, const std::vector<std::string>& segments,
                                        PathCheck check) {
  std::size_t depth = 0;
  if (walk(root, segments, check, depth)) return std::nullopt;
  std::size_t again = 0;
  const Json* at = walk(root, {segments.begin(), segments.begin() + long(depth)}, check, again);
  const std::string walked = join(segments, depth);
  const std::string& missing = segments[depth];
  std::string hint;
  if (at->is_object())
    hint =
        " (" + (walked.empty() ? std::string("top level") : walked) + " has: " + keys_of(*at) + ")";
  else if (at->is_array())
    hint = " (" + walked + " is a list of " + std::to_string(at->size()) + ")";
  else
    hint = " (" + walked + " is a value, not a section)";
  std::string message = "nothing at \"" + missing + "\"" + hint;
  const std::string near = nearest_path(root, join(segments, segments.size()));
  if (!near.empty()) message += "; did you mean " + near + "?";
  return message;
}

}  // namespace elbowsim::report
