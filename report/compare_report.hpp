// The comparison report of several recorded runs: a verdict computed from
// the numbers, the runs side by side (settings, failures), every metric with
// its relative difference to the first run, overlay plots and energy totals.
#pragma once

#include <filesystem>
#include <vector>

#include "report/comparison.hpp"
#include "report/run_data.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report {

struct ComparisonFiles {
  std::filesystem::path html;  // <out>/report.html
  std::filesystem::path json;  // <out>/comparison.json
  FigureSet figures;           // <out>/plots/*.png
  Comparison comparison;
};

// Writes the comparison of `runs` (labels already unique) into `out`.
// Throws std::runtime_error naming the file that cannot be written.
ComparisonFiles write_comparison_report(const std::vector<RunData>& runs,
                                        const std::filesystem::path& out);

}  // namespace elbowsim::report
