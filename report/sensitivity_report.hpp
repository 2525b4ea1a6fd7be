// The report of `elbowsim sensitivity`, from DIR/sensitivity.json alone: per
// compared ratio a tornado chart (each uncertain parameter held at either end
// of its range; those that change the verdict first, then by swing) and the
// sentences saying which parameter changes the verdict and where; then a
// table of every point (each a Monte Carlo folder under points/).
#pragma once

#include <filesystem>

namespace elbowsim::report {

// Reads folder/sensitivity.json, writes folder/plots/tornado_<metric>.png.
// Throws std::runtime_error naming the file on failure.
void write_sensitivity_plots(const std::filesystem::path& folder);

// Reads folder/sensitivity.json, writes folder/report.html (after
// write_sensitivity_plots). Throws std::runtime_error naming the file on failure.
void write_sensitivity_report(const std::filesystem::path& folder);

}  // namespace elbowsim::report
