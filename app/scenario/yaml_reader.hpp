// Typed, located access to a parsed YAML tree. Every Value knows its key path
// ("robot.planar.links[2].mass") and where it came from (a file line or a
// command-line override), so any check can fail with a ScenarioError that
// names both. Parsing and the section readers build on this; nothing here
// knows the scenario schema.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace elbowsim::loader {

// The origin of a tree: one file plus the overrides applied to it, in order
// (a variant's entries, then --set). Decides where an error is reported: at the
// override whose key path contains the offending key (the last one applied
// wins), else at the file mark.
class Source {
 public:
  // Where a value came from: a file position, or "command line --set <text>"
  // (line and column 0).
  struct Origin {
    std::string file;
    int line = 0;    // 1-based, 0 if none
    int column = 0;  // 1-based, 0 if none
  };

  explicit Source(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  void add_override(std::string path, Origin origin);
  // Appended to every message, e.g. " (in variant elbow_off)".
  void set_note(std::string note) { note_ = std::move(note); }
  const std::string& note() const { return note_; }
  // Where the node at `mark` with key path `key` came from.
  Origin origin(const YAML::Mark& mark, const std::string& key) const;
  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& key,
                         const std::string& message) const;

 private:
  struct Override {
    std::string path;  // normalized key path it set
    Origin origin;
  };
  std::string file_;
  std::vector<Override> overrides_;
  std::string note_;
};

// One node of the tree, possibly missing (a key that is not there).
class Value {
 public:
  Value(const Source& source, YAML::Node root);  // the document, key path ""
  Value(const Value& other) = default;
  Value& operator=(const Value& other);  // rebinds; never writes to the tree

  const std::string& path() const { return path_; }
  bool exists() const { return exists_; }  // the key is there (maybe with no value)
  bool present() const;                    // there, and not null
  bool is_map() const { return present() && node_.IsMap(); }
  bool is_sequence() const { return present() && node_.IsSequence(); }
  [[noreturn]] void fail(const std::string& message) const;
  Source::Origin origin() const;  // where this node came from (file line or --set)
  std::string flow_yaml() const;  // the node as one line of YAML ("" if null)

  // --- maps ---------------------------------------------------------------
  // Fails unless a map whose keys are plain, unique and among `allowed`
  // (suggesting the closest allowed key for a typo).
  void allow_keys(std::initializer_list<std::string_view> allowed) const;
  Value get(std::string_view key) const;      // missing/null -> !present()
  Value require(std::string_view key) const;  // if missing, fails at this map, naming the key
  // Key and value of each entry, in file order.
  std::vector<std::pair<Value, Value>> entries() const;

  // --- sequences ------------------------------------------------------------
  std::vector<Value> items() const;  // fails unless a sequence

  // --- scalars --------------------------------------------------------------
  double number() const;     // finite number; quoted strings are not numbers
  long integer() const;      // whole number
  bool boolean() const;      // true / false
  std::string text() const;  // any scalar
  // A list of numbers; with `size` >= 0 it must have exactly that many, and
  // `what` says what the count is ("one per joint", "x, y, z").
  Eigen::VectorXd numbers(long size = -1, std::string_view what = "") const;
  Eigen::Vector3d vec3() const;  // [x, y, z]

 private:
  Value(const Source* source, YAML::Node node, std::string path, YAML::Mark mark, bool exists);
  Value child(std::string path, const YAML::Node& node, const YAML::Mark& key_mark) const;
  std::string child_path(std::string_view key) const;
  void expect_map() const;
  void expect_scalar(std::string_view expected) const;

  const Source* source_;
  YAML::Node node_;  // valid only when exists_
  std::string path_;
  YAML::Mark mark_;  // the node's; its key's when null; the parent map's when missing
  bool exists_;
};

// "a, b, c"
std::string join(const std::vector<std::string_view>& words);

// The candidate closest to `word` by edit distance (with transpositions), if
// that distance is <= 2; else empty.
std::string closest(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace elbowsim::loader
