// The comparison report of several recorded runs. It leads with the answer:
// the verdict computed from the numbers (with its confidence: none from one
// run each), the headline numbers side by side, the hand paths overlaid and
// the energy accounts; then the side-by-side video, overlays, the runs'
// settings and every metric, grouped as results, numerics, timing and
// settings, with differences below the noise floor shown as "same".
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
// into `out`. `video`: out/video.mp4 (the runs side by side) was made by this
// run, and the report embeds it; no other video is embedded. `differing`:
// the scenario keys whose values differ between the runs, each with its
// value per run (app/scenario/scenario_keys.hpp), shown as the first row
// of the side-by-side table and in comparison.json. Throws
// std::runtime_error naming the file that cannot be written.
ComparisonFiles write_comparison_report(
    const std::vector<RunData>& runs, const std::filesystem::path& out, const ComparisonTables& tables = {},
    bool video = false, const std::vector<std::pair<std::string, std::vector<std::string>>>& differing = {});

}  // namespace elbowsim::report
