// The report of a Monte Carlo study over several cases (a scenario's study:
// section, elbowsim montecarlo): report.html and plots/ beside study.json,
// from that file alone. The verdict over the cases first (how many cases
// show each outcome), then one row per case with each variant's means and
// the paired ratios with their 95 % intervals (linking the case's own
// report), and a plot of the ratios per case.
#pragma once

#include <filesystem>

namespace elbowsim::report {

// Reads folder/study.json, writes folder/report.html and folder/plots/*.png.
// Throws std::runtime_error naming the file on failure.
void write_study_report(const std::filesystem::path& folder);

}  // namespace elbowsim::report
