// What a run shows, for the first screen of its report (and, run beside
// run, of a comparison): its validity and the few numbers a reader wants
// first, with units: hand error, electrical energy, Joule loss, power,
// currents, the elbow's rest and force, how well the energy balance closed,
// and the accuracy check when --check-step ran. All read from summary.json
// under the paths --expect uses.
#pragma once

#include <string>
#include <vector>

#include "report/run_data.hpp"

namespace elbowsim::report {

// "elbow_experiment · elbow_on": the scenario and, when the folder's name
// differs from it, the folder (a variant's name): titles carry the variant.
std::string run_title(const RunData& run);

// "elbow_experiment · elbow_on vs elbow_off": the runs of a comparison.
std::string comparison_title(const std::vector<RunData>& runs);

// "valid", "NOT VALID: <failure>" or "STOPPED EARLY at t = 1.2 s: <failure>".
std::string validity(const RunData& run);

struct HeadlineItem {
  std::string label;  // "hand error, RMS"
  std::string path;   // the summary.json path it shows ("metrics.hand_error_rms")
  std::string unit;
};

// The items any of `runs` has, in reading order.
std::vector<HeadlineItem> headline_items(const std::vector<const RunData*>& runs);

// The item's value in `run`, with units ("14.1 µm"; per joint "42 mA, 71 mA";
// the energy in with its drawn and regenerated parts); "—" where absent.
std::string headline_value(const RunData& run, const HeadlineItem& item);

// The parts of the arm the scene does not plan to rest on the table that
// rested all the same (summary.json contact.bodies), one phrase each:
// "link3 (a link, not a declared elbow) 99 % of the run, mean 8.7 N, peak 14.5 N".
std::vector<std::string> unplanned_rests(const RunData& run);

// The step check's entry (step_check.metrics.<metric>: value, floor, ...) of a
// one-value metric that is below its integration floor, or nullptr.
const nlohmann::ordered_json* below_floor(const RunData& run, const std::string& metric);

// One or two sentences: the run's status and what it shows.
std::string headline_sentence(const RunData& run);

// The step-halving check in words ("at half the step (0.5 ms) the RMS hand
// error changes by 1.0 %, the electrical energy in by 0.005 %"), or why there is none.
std::string accuracy_check(const RunData& run);

}  // namespace elbowsim::report
