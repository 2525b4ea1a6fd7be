// report.html for one recorded run: what ran (scenario, effects, model,
// solver settings), how it went (failure and warnings in plain sight, wall
// time, steps), every summary.json metric, the plots, the video when there is
// one, contact events and the scenario as run.
#pragma once

#include <filesystem>

#include "report/run_data.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report {

struct ReportFiles {
  std::filesystem::path html;  // report.html
  FigureSet figures;
};

// Writes <run.folder>/report.html and <run.folder>/plots/*.png. Throws
// std::runtime_error naming the file that cannot be written.
ReportFiles write_run_report(const RunData& run);

// The page alone (write_run_report writes it), for figures already drawn.
std::string run_report_html(const RunData& run, const FigureSet& figures);

}  // namespace elbowsim::report
