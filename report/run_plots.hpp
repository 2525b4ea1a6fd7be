// The figures of one run and of a comparison, drawn from recorded columns
// into PNGs under <report folder>/plots/.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/run_data.hpp"

namespace elbowsim::report {

struct Figure {
  std::string file;  // relative to the report folder, "plots/joint_angles.png"
  std::string title;
  std::string caption;        // what it shows, one sentence
  int width = 0, height = 0;  // [px]
  std::string group = "";     // the report section it leads: "hand_path", "energy"; "" the rest
};

struct FigureSet {
  std::vector<Figure> figures;
  std::vector<std::string> skipped;  // figures this run cannot have, and why
};

// The lead figures (lead_figures.hpp: hand path, error-magnified hand path,
// energy flow), then joint angles; hand position (and hand error when recorded); motor currents,
// voltages; joint torques; electrical power and cumulative energy; elbow
// normal forces with the resting timeline; |d| while resting (log); the
// energy-balance residual (log). Throws std::runtime_error when a PNG cannot
// be written.
FigureSet write_run_plots(const RunData& run, const std::filesystem::path& report_folder);

// The lead figures of the runs (their hand paths overlaid, the energy
// account per run), then overlays (cumulative energy, hand position,
// currents, hand error) and a bar chart of their totals (electrical energy in, Joule loss).
FigureSet write_comparison_plots(const std::vector<RunData>& runs,
                                 const std::filesystem::path& report_folder);

}  // namespace elbowsim::report
