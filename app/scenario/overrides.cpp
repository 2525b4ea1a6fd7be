#include "app/scenario/overrides.hpp"

#include <cctype>
#include <charconv>
#include <vector>

#include "app/scenario/scenario.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

struct Override {
  Source::Origin origin;  // where it was given: "command line --set <text>" or a file line
  std::string note;       // appended to messages (Source::note)
  std::vector<KeyStep> steps;
  std::string path;   // normalized "a.b[0].c"
  std::string value;  // YAML text
};

[[noreturn]] void fail(const Override& o, const std::string& key, const std::string& message) {
  throw ScenarioError(o.origin.file, o.origin.line, o.origin.column, key, message + o.note);
}

std::string join_path(const std::vector<KeyStep>& steps, std::size_t count) {
  std::string path;
  for (std::size_t i = 0; i < count; ++i) {
    // Appended piece by piece: `"[" + std::to_string(...)` trips GCC 12's -Wrestrict.
    if (steps[i].index >= 0) {
      path.append("[").append(std::to_string(steps[i].index)).append("]");
    } else {
      path.append(path.empty() ? "" : ".").append(steps[i].key);
    }
  }
  return path;
}

Override parse(const std::string& text, Source::Origin origin, std::string note) {
  Override o{std::move(origin), std::move(note), {}, "", ""};
  std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) fail(o, "", "expected key.path=value");
  const std::string problem = parse_key_path(text.substr(0, eq), false, o.steps);
  if (!problem.empty()) fail(o, "", "expected key.path=value (" + problem + ")");
  o.path = join_path(o.steps, o.steps.size());
  o.value = text.substr(eq + 1);
  return o;
}

// The child named by step k of `o`: a list item that must exist, or a map
// entry (undefined until assigned when the key is new).
YAML::Node descend(YAML::Node node, const Override& o, std::size_t k) {
  const KeyStep& s = o.steps[k];
  std::string here = join_path(o.steps, k);
  std::string there = join_path(o.steps, k + 1);
  if (s.index >= 0) {
    if (!node.IsSequence())
      fail(o, there, (here.empty() ? "the document" : here) + " is not a list");
    if (static_cast<std::size_t>(s.index) >= node.size())
      fail(o, there,
           "index out of range (the list has " +
               counted(static_cast<long long>(node.size()), "item") + ")");
    return node[static_cast<std::size_t>(s.index)];
  }
  if (!node.IsMap() && !node.IsNull()) fail(o, there, here + " is not a map");
  return node[s.key];
}

YAML::Node parse_value(const Override& o) {
  try {
    return YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    fail(o, o.path, "invalid YAML value: " + e.msg);
  }
}

}  // namespace

std::string parse_key_path(const std::string& path, bool every_item, std::vector<KeyStep>& out) {
  auto is_key_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  };
  for (std::size_t start = 0; start <= path.size();) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string segment = path.substr(start, dot - start);
    start = dot + 1;
    // "links[2][0]" -> key "links", indices 2, 0.
    std::size_t i = 0;
    while (i < segment.size() && is_key_char(segment[i])) ++i;
    if (i == 0) return "bad key \"" + segment + "\"";
    out.push_back({segment.substr(0, i)});
    while (i < segment.size()) {
      const std::size_t close = segment.find(']', i);
      if (segment[i] != '[' || close == std::string::npos) return "bad index in \"" + segment + "\"";
      const std::string inside = segment.substr(i + 1, close - i - 1);
      long index = -1;
      const auto [end, ec] = std::from_chars(inside.data(), inside.data() + inside.size(), index);
      if (every_item && inside == "*")
        index = kEveryItem;
      else if (ec != std::errc{} || end != inside.data() + inside.size() || index < 0)
        return "bad index in \"" + segment + "\"";
      out.push_back({"", index});
      i = close + 1;
    }
  }
  return "";
}

void apply_override(YAML::Node& root, const std::string& text, Source& source) {
  apply_override(root, text, source, {"command line --set " + text, 0, 0});
}

void apply_override(YAML::Node& root, const std::string& text, Source& source,
                    const Source::Origin& origin) {
  Override o = parse(text, origin, source.note());
  YAML::Node value = parse_value(o);
  YAML::Node node = root;
  // Walk to the parent of the last step, creating missing maps on the way.
  for (std::size_t k = 0; k + 1 < o.steps.size(); ++k) {
    YAML::Node next = descend(node, o, k);
    if (!next.IsDefined()) {
      next = YAML::Node(YAML::NodeType::Map);  // defines the new entry in `node`
    }
    node.reset(next);  // rebind only: YAML::Node::operator= would write to the tree
  }
  YAML::Node target = descend(node, o, o.steps.size() - 1);
  target = value;
  source.add_override(o.path, o.origin);
}

}  // namespace elbowsim::loader
