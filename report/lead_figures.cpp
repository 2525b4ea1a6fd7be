#include "report/lead_figures.hpp"

#include <algorithm>
#include <cmath>

#include "engine/recording/metrics.hpp"
#include "report/energy_flow.hpp"
#include "report/hand_path.hpp"
#include "report/headline.hpp"
#include "report/plot/plot.hpp"

namespace elbowsim::report {

namespace {

namespace fs = std::filesystem;

template <typename Chart>
void add(const Chart& chart, const fs::path& folder, const std::string& name,
         const std::string& caption, const std::string& group, int height, FigureSet& set) {
  fs::create_directories(folder / "plots");
  const std::string file = "plots/" + name + ".png";
  plot::write_png(chart, folder / file);
  set.figures.push_back({file, chart.title, caption, chart.width, height, group});
}

void add_hand_path(const std::vector<const RunData*>& runs, const std::string& title,
                   const fs::path& folder, FigureSet& set) {
  for (const RunData* run : runs)
    if (!run->has_trajectory()) {
      set.skipped.push_back("hand_path: " + run->label + " has no trajectory.csv samples");
      return;
    }
  const HandPathFigures f = hand_path_figures(runs, title);
  add(f.path, folder, "hand_path", f.path_caption, "hand_path", f.path.height, set);
  std::string integrator_noise;  // runs whose hand error is below the integration floor
  for (const RunData* run : runs)
    if (below_floor(*run, metric::hand_error_rms))
      integrator_noise += (integrator_noise.empty() ? "" : ", ") + run->label;
  if (f.magnified && !integrator_noise.empty())
    set.skipped.push_back("hand_path_error: the hand error of " + integrator_noise +
                          " is below the integration floor (step check): magnified, it would "
                          "show the integrator's error, not the arm's");
  else if (f.magnified)
    add(*f.magnified, folder, "hand_path_error", f.magnified_caption, "hand_path",
        f.magnified->height, set);
  else
    set.skipped.push_back("hand_path_error: no desired hand path (no task): no error to magnify");
}

// Terms smaller than this share of the largest energy in are left out of
// the comparison's chart (named in its caption): bars too thin to see.
constexpr double kVisibleShare = 1e-3;

// A term's value in a flow ("in:drawn", "out:joule"); 0 when the run lacks it.
double value_of(const EnergyFlow& flow, const std::string& key) {
  for (bool sources : {true, false})
    for (const EnergyTerm& t : sources ? flow.in : flow.out)
      if (key == (sources ? "in:" : "out:") + t.key) return t.value;
  return 0;
}

// Categories: every visible term of any run, sources first, in the first
// run's order; `left_out` names the others.
plot::BarChart energy_terms(const std::vector<EnergyFlow>& flows, const std::vector<RunData>& runs,
                            std::string& left_out) {
  plot::BarChart chart;
  chart.title = "Where the energy went — " + comparison_title(runs);
  chart.y = plot::linear_axis("energy", "J");
  chart.value_digits = 3;
  double largest = 0;
  for (const EnergyFlow& flow : flows) largest = std::max(largest, flow.total_in);
  std::vector<std::string> keys, seen;
  for (bool sources : {true, false})
    for (const EnergyFlow& flow : flows)
      for (const EnergyTerm& t : sources ? flow.in : flow.out) {
        const std::string key = (sources ? "in:" : "out:") + t.key;
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
        seen.push_back(key);
        double most = 0;
        for (const EnergyFlow& f : flows) most = std::max(most, value_of(f, key));
        if (most >= kVisibleShare * largest) {
          keys.push_back(key);
          chart.categories.push_back(t.short_label);
        } else {
          left_out += (left_out.empty() ? "" : ", ") + t.label;
        }
      }
  for (std::size_t r = 0; r < flows.size(); ++r) {
    plot::BarGroup group{runs[r].label, {}};
    for (const std::string& key : keys) group.values.push_back(value_of(flows[r], key));
    chart.groups.push_back(group);
  }
  return chart;
}

}  // namespace

void add_lead_figures(const RunData& run, const fs::path& folder, FigureSet& set) {
  add_hand_path({&run}, run_title(run), folder, set);
  const auto flow = energy_flow(run.summary);
  if (!flow) {
    set.skipped.push_back("energy_flow: no energy_final in summary.json");
    return;
  }
  const plot::Waterfall chart =
      energy_waterfall(*flow, "Where the energy went — " + run_title(run));
  add(chart, folder, "energy_flow",
      "The energy account of the run, from summary.json: what came in (green; the bar "
      "ends at the energy in), then where it went (red: losses and stored energy gained; blue: "
      "fed back to the supply), down to the residual the account leaves unexplained.",
      "energy", plot::waterfall_height(chart.steps.size()), set);
}

void add_comparison_lead_figures(const std::vector<RunData>& runs, const fs::path& folder,
                                 FigureSet& set) {
  std::vector<const RunData*> pointers;
  for (const RunData& run : runs) pointers.push_back(&run);
  add_hand_path(pointers, comparison_title(runs), folder, set);
  std::vector<EnergyFlow> flows;
  for (const RunData& run : runs) {
    const auto flow = energy_flow(run.summary);
    if (!flow) {
      set.skipped.push_back("energy_terms: " + run.label + " has no energy_final in summary.json");
      return;
    }
    flows.push_back(*flow);
  }
  std::string left_out;
  const plot::BarChart chart = energy_terms(flows, runs, left_out);
  add(chart, folder, "energy_terms",
      "The energy account of each run, term by term (summary.json): where it came from (drawn "
      "from the supply, stored energy given up), then where it went (fed back to the supply, "
      "losses, stored energy gained). Left out, each below 0.1 % of the largest energy in: " +
          (left_out.empty() ? std::string("none") : left_out) +
          "; each run's report has its whole account as a waterfall, residual included.",
      "energy", chart.height, set);
}

}  // namespace elbowsim::report
