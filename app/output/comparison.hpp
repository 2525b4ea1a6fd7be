// Side-by-side tables of runs: comparison.csv / comparison.json (the variants
// of one scenario, each against the first) and sweep.csv (one row per swept
// value and variant). The numbers are those of each run's summary.json.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace elbowsim {

// One run as the tables see it.
struct RunRecord {
  std::string variant;             // "" for a scenario without variants
  std::string folder;              // its run folder, relative to the table's folder
  nlohmann::ordered_json summary;  // as written to summary.json
};

// The numeric metrics of a summary, flattened in order: its "metrics" object
// (arrays become name[0], name[1], ...; nested objects name.key; a null value
// is NaN), or, for a summary without one, energy_final.electrical_in,
// energy_final.joule and balance_residual.
std::vector<std::pair<std::string, double>> summary_metrics(const nlohmann::ordered_json& summary);

// The unit of a metric, from its name ("hand_error_rms" -> "m"); "" if unknown.
std::string metric_unit(const std::string& name);

// (x - reference) / |reference|; 0 when both are 0; NaN when undefined.
double relative_difference(double x, double reference);

// comparison.json, shaped like `elbowsim compare`'s (report/comparison.hpp):
// scenario, runs (the variant names), reference (the first), folder,
// completed and failure per variant, and metrics: a list of {path, unit,
// values: {variant: x}, relative: {variant: (x - x_ref)/|x_ref|}}, null where
// undefined.
nlohmann::ordered_json comparison_json(const std::string& scenario,
                                       const std::vector<RunRecord>& runs);

// comparison.csv: one row per variant: variant, completed, each metric
// ("name [unit]"), then each metric's relative difference to the first variant
// ("name rel"). Numbers as in summary.json; an undefined one is an empty cell.
void write_comparison_csv(std::ostream& out, const std::vector<RunRecord>& runs);

// One run of a sweep: the value the swept key had.
struct SweepRow {
  std::string value;  // as given on the command line
  RunRecord run;
};

// sweep.csv: one row per (value, variant): the key's value, variant,
// completed, then each metric ("name [unit]").
void write_sweep_csv(std::ostream& out, const std::string& key, const std::vector<SweepRow>& rows);

}  // namespace elbowsim
