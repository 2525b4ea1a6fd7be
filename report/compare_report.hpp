// The comparison report of several recorded runs: a verdict computed from
// the numbers, the runs side by side (settings, failures), every metric with
// its relative difference to the first run, overlay plots and energy totals.
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

#include "report/comparison.hpp"
#include "report/run_data.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report {

struct ComparisonFiles {
  std::filesystem::path html;  // <out>/report.html
  std::filesystem::path json;  // <tables>/comparison.json
  std::filesystem::path csv;   // <tables>/comparison.csv
  FigureSet figures;           // <out>/plots/*.png
  Comparison comparison;
};

// Where the comparison's tables go and what their first column is called.
struct ComparisonTables {
  std::filesystem::path folder;        // empty: the report's folder
  std::string first_header = "run";    // comparison.csv's first column ("variant" for variants)
};

// comparison.json and comparison.csv of a comparison into tables.folder; returns their paths.
std::pair<std::filesystem::path, std::filesystem::path> write_comparison_tables(
    const Comparison& comparison, const ComparisonTables& tables);

// The comparison of `runs` (labels already unique): comparison.json and
// comparison.csv into tables.folder, and the report (report.html, plots/)
// into `out`. Throws std::runtime_error naming the file that cannot be written.
ComparisonFiles write_comparison_report(const std::vector<RunData>& runs,
                                        const std::filesystem::path& out,
                                        const ComparisonTables& tables = {});

}  // namespace elbowsim::report
