// The subcommands of the elbowsim command line. Each returns the exit code:
// 0 success, 1 I/O failure, 2 bad input (scenario or usage), 3 the run
// stopped early (diverged); what it recorded is still written; 4 an
// --expect expression does not hold; 128 + the signal (130 SIGINT, 143
// SIGTERM): interrupted, nothing more started (app/commands/interrupt.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim {

struct Scenario;
struct Recording;
namespace report {
struct Comparison;
}

// A run folder a command wrote: its variant ("" without variants) and where it is.
struct RunRecord {
  std::string variant;
  std::filesystem::path folder;
};

enum ExitCode {
  exit_ok = 0,
  exit_io = 1,
  exit_bad_input = 2,
  exit_run_failed = 3,
  exit_expectation_failed = 4
};

struct RunArguments {
  std::string scenario;
  std::optional<std::string> out;   // overrides output.folder
  std::vector<std::string> sets;    // "key.path=value" overrides
  bool render = true;               // false: --no-render (skip output.video / output.frames)
  bool report = true;               // false: --no-report (skip report.html, plots/)
  std::vector<std::string> expect;  // --expect expressions over summary.json
  bool check_step = true;           // false: --no-check-step (no rerun refined, no step_check)
  int render_jobs = 0;  // --jobs: variants drawn at once at most; 0: the cores available
};

// elbowsim render RUN_DIR [--camera preset] [--size WxH] [--fps N]
struct RenderArguments {
  std::string folder;                 // a run folder: scenario.yaml, trajectory.csv
  std::optional<std::string> camera;  // preset name or eye=..,target=..,fov=.. (camera_option.hpp)
  std::optional<std::string> follow;  // hand or none, replaces render.camera.follow
  std::optional<std::string> size;    // "WxH", replaces render.size
  std::optional<std::string> fps;     // replaces render.fps
};

int run_command(const RunArguments& args);

// Runs `scenario` (loaded from args.scenario with args.sets) into `folder`:
// alone, or, when it declares variants, each variant into folder/<variant>/
// then folder/comparison.csv and comparison.json (--expect paths then start
// with a variant name). Appends one record per run. Used by run and sweep.
int run_scenario(const RunArguments& args, const Scenario& scenario,
                 const std::filesystem::path& folder, std::vector<RunRecord>& records);

// elbowsim sweep SCENARIO --key K --values V1,V2,... [--out DIR] [--set ...]
struct SweepArguments {
  RunArguments run;    // scenario, out (default: output.folder + "/sweep"), sets, render, report
  std::string key;     // the swept key path, e.g. task.duration
  std::string values;  // comma-separated YAML values
};
int sweep_command(const SweepArguments& args);
int validate_command(const std::string& scenario, const std::vector<std::string>& sets);
int render_command(const RenderArguments& args);

// elbowsim report RUN_DIR [--expect EXPR ...]
struct ReportArguments {
  std::string folder;
  std::vector<std::string> expect;
};
// elbowsim compare RUN_DIR RUN_DIR ... [--out DIR] [--expect EXPR ...]
struct CompareArguments {
  std::vector<std::string> folders;
  std::optional<std::string> out;  // default: "compare" beside the first run folder
  std::vector<std::string> expect;  // paths start with a run label (folder name, or --label)
  std::vector<std::string> labels;  // --label: one per run, in order; empty: folder names
};
// elbowsim montecarlo SCENARIO [--samples N] [--seed S] [--jobs J] [--out DIR] [--set ...]
struct MonteCarloArguments {
  std::string scenario;
  std::optional<std::string> out;  // default: output.folder + "/montecarlo"
  std::vector<std::string> sets;
  long samples = 30;
  std::optional<std::uint64_t> seed;  // default: uncertainty.seed
  int jobs = 1;
  bool report = true;  // false: --no-report
  std::string cases;   // --case "axis=level,...": the study cases to run; "": all
  // Uncertain parameters (as the file gives them) held at one deviation (a
  // relative law) or value (a range) in every draw, the others drawn as usual:
  // sensitivity's points. Empty: every parameter drawn.
  std::vector<std::pair<std::string, double>> held;
  // --variants A,B,...: only these of the scenario's variants, in this order
  // (the first pair's ratio is A over B). Empty: every variant.
  std::vector<std::string> variants;
};
int montecarlo_command(const MonteCarloArguments& args);

// elbowsim sensitivity SCENARIO [--samples N] [--seed S] [--jobs J] [--out DIR] [--set ...]
// [--case ...] [--no-report]: montecarlo with every draw, then each uncertain
// parameter held at either end of its range (app/study/sensitivity.hpp).
int sensitivity_command(const MonteCarloArguments& args);

// elbowsim study STUDY [--grid KEY=V1,V2 ...] [--draws N] [--seed S] [--out DIR] [--set ...]
//                      [--jobs N] [--shard I/N] [--case K [--video]] [--list] [--slurm] [--k8s]
struct StudyArguments {
  std::string study;               // a study file, or a scenario with --grid
  std::vector<std::string> grid;   // KEY=V1,V2,... (a scenario only)
  std::vector<std::string> sets;   // over every case
  std::optional<std::string> out;  // default: output.folder + "/" + the study's name
  std::optional<long> draws;       // replaces the file's draws:
  std::optional<std::uint64_t> seed;
  int jobs = 1;                    // local processes
  std::optional<std::string> shard;  // "I/N": cases I-1, I-1+N, ...
  std::optional<std::string> only;   // --case: one case, by index or folder name
  bool video = false;              // with --case: that case's videos and reports
  bool list = false;               // print the cases and their state, run nothing
  bool slurm = false;              // write DIR/submit.sh, run nothing
  bool k8s = false;                // write DIR/job.yaml, run nothing
  std::optional<int> tasks;        // shards of --slurm / --k8s (default: one per case, at most 1000)
};
int study_command(const StudyArguments& args);

// elbowsim merge DIR... [--out OUT]: one table and report of a study's cases.
struct MergeArguments {
  std::vector<std::string> folders;
  std::optional<std::string> out;  // default: the first folder
};
int merge_command(const MergeArguments& args);

// elbowsim accuracy SCENARIO [--methods M1,M2] [--points N] [--repeats R] [--variant V]
//                            [--no-alternatives] [--out DIR] [--set ...]
struct AccuracyArguments {
  std::string scenario;
  std::optional<std::string> out;  // default: output.folder + "/accuracy"
  std::vector<std::string> sets;
  std::string methods;   // comma-separated integrators; "": all
  int points = 6;        // settings per method
  int repeats = 10;      // timings per setting, at least (study::kMinTimedForInterval)
  std::string variant;   // "": every variant
  bool alternatives = true;
};
int accuracy_command(const AccuracyArguments& args);

int report_command(const ReportArguments& args);
int compare_command(const CompareArguments& args);

// The comparison's verdict sentences (report/comparison.hpp), one a line on
// stdout: compare, and run with variants, print them.
void print_verdict(const report::Comparison& comparison);

// Writes report.html and plots/ into a run folder from its files. Used by run and report.
int report_outputs(const std::filesystem::path& folder);

// --expect (report/expect.hpp): prints each malformed expression with its
// column; false if any.
bool expectations_well_formed(const std::vector<std::string>& expressions);
// What summary.json (or, with variants, variant -> summary.json) a run of
// `scenario` with `args` writes, as placeholders: for expectations_fit.
// Throws ScenarioError when a variant does not load.
nlohmann::ordered_json expectation_shape(const RunArguments& args, const Scenario& scenario);
// Before simulating: each well formed and every metric path it names present in
// `shape` (summary_shape, or variant -> summary_shape); prints each problem with
// the nearest valid path; false if any.
bool expectations_fit(const std::vector<std::string>& expressions,
                      const nlohmann::ordered_json& shape);
// Evaluates them over `metrics`: exit_ok, exit_expectation_failed, or
// exit_bad_input (malformed, or naming a metric that is not there).
int check_expectations(const std::vector<std::string>& expressions,
                       const nlohmann::ordered_json& metrics);

// A recorded run to render into its folder as its output section asks.
struct RunToRender {
  const Scenario* scenario = nullptr;  // must outlive the call, as must recording
  const Recording* recording = nullptr;
  std::filesystem::path folder;
};
// Renders `runs` (those whose output section asks for video.mp4 or frames/)
// on `threads` drawing threads at most (0: the cores available), printing
// what was written; with `side_by_side`, also every run's frames placed side
// by side, left to right, into that folder (video.mp4 when the first run
// asks for a video, frames/ when it asks for frames; each panel is the run's
// own frame, not drawn again). Returns one code per run (exit_ok,
// exit_bad_input, exit_io, or 128 + the signal when SIGINT or SIGTERM stopped
// it before its last frame: nothing of it kept); `side_by_side_code` gets the
// side-by-side's (exit_io when it failed; exit_ok, with a warning, when the
// runs' frames differ in height or rate and none is made; 128 + the signal).
std::vector<int> render_runs(const std::vector<RunToRender>& runs,
                             const std::optional<std::filesystem::path>& side_by_side,
                             int& side_by_side_code, int threads = 0);

}  // namespace elbowsim
