// The figures a report leads with, after its headline numbers: the hand path
// in the task plane (desired against actual) with its error-magnified view,
// and where the energy went (the energy account, energy_flow.hpp): a
// waterfall for one run, the terms side by side for a comparison.
#pragma once

#include <filesystem>
#include <vector>

#include "report/run_data.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report {

// plots/hand_path.png, plots/hand_path_error.png (with a task) and
// plots/energy_flow.png (with an energy account) into `folder`, appended to
// `set` (group "hand_path" or "energy"); what a run cannot have goes to set.skipped.
void add_lead_figures(const RunData& run, const std::filesystem::path& folder, FigureSet& set);

// The same for a comparison: the runs' hand paths overlaid (one
// magnification for all) and plots/energy_terms.png, the account's terms per run.
void add_comparison_lead_figures(const std::vector<RunData>& runs,
                                 const std::filesystem::path& folder, FigureSet& set);

}  // namespace elbowsim::report
