// The report of a Monte Carlo study (elbowsim montecarlo): report.html and
// plots/ beside montecarlo.json, from that file alone. The verdict comes
// first, then each variant's metrics with their confidence intervals, the
// paired comparison, the invalid draws, and the distributions (ECDFs of hand
// error and energy, energy against hand error per draw).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace elbowsim::report {

// Reads folder/montecarlo.json and writes folder/report.html and
// folder/plots/*.png. Throws std::runtime_error naming the file on failure.
void write_montecarlo_report(const std::filesystem::path& folder);

}  // namespace elbowsim::report
