// Metric paths of --expect (expect.hpp) against a summary.json tree: where a
// path stops resolving, what is there instead, and the nearest path that does
// resolve ("did you mean"), so that a misspelled metric is named with its fix
// before any simulation runs.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim::report {

// How lists and nulls count when a path walks into them.
enum class PathCheck {
  exact,  // a run's own summary: a list index must be within the list
  shape,  // a summary's shape before the run: lists and nulls hold anything
};

// Why `segments` does not resolve in `root` ("nothing at \"x\" (metrics has:
// ...)"), with a suggestion when one is close; nullopt when it resolves.
std::optional<std::string> path_problem(const nlohmann::ordered_json& root,
                                        const std::vector<std::string>& segments, PathCheck check);

// The resolving path nearest to `path` (dotted): the same path under a
// top-level key (a variant or run label: "elbow_on.metrics.energy_in"), or the
// leaf path with the smallest edit distance when it is within a third of the
// path's length; "" when none is near.
std::string nearest_path(const nlohmann::ordered_json& root, const std::string& path);

}  // namespace elbowsim::report
