#include "app/command_line.hpp"

#include <algorithm>
#include <vector>

#include "report/provenance.hpp"

namespace elbowsim::cli {

namespace {

// Options several commands share.
constexpr OptionSpec kSet{"s,set", "KEY=VALUE",
                          "override a scenario key (a YAML value), e.g. simulation.step=1e-4",
                          true};
constexpr OptionSpec kNoRender{"no-render", nullptr,
                               "skip video.mp4 and frames/ (output.video, output.frames)"};
constexpr OptionSpec kNoReport{"no-report", nullptr, "skip report.html and plots/"};
constexpr OptionSpec kNoCheckStep{
    "no-check-step", nullptr,
    "skip the step check (the run again, refined: summary.json step_check)"};
constexpr OptionSpec kCheckStep{"check-step", nullptr,
                                "the step check (the default; kept for older scripts)"};
constexpr OptionSpec kExpect{"expect", "EXPR",
                             "a check over summary.json, e.g. \"energy_final.joule < 120\"", true};
constexpr OptionSpec kRenderJobs{"jobs", "N",
                                 "variants drawn at once (default: the cores available)"};
constexpr OptionSpec kHelp{"h,help", nullptr, "show this help"};

constexpr OptionSpec kRun[] = {
    {"o,out", "DIR", "output folder (default: the scenario's output.folder)"},
    kSet,
    kNoRender,
    kNoReport,
    kNoCheckStep,
    kCheckStep,
    kExpect,
    kRenderJobs,
    kHelp};

constexpr OptionSpec kValidate[] = {kSet, kHelp};

constexpr OptionSpec kSweep[] = {
    {"key", "KEY", "the scenario key to vary, e.g. task.duration (required)"},
    {"values", "V1,V2,...", "its values, comma-separated YAML (required)"},
    {"o,out", "DIR", "output folder (default: the scenario's output.folder/sweep)"},
    kSet,
    kNoRender,
    kNoReport,
    kNoCheckStep,
    kCheckStep,
    kExpect,
    kRenderJobs,
    kHelp};

constexpr OptionSpec kRender[] = {
    {"camera", "VIEW", "the camera, a preset or eye=..,target=.. (default: render.camera)"},
    {"follow", "hand|none", "hand: the view follows the hand (default: render.camera.follow)"},
    {"size", "WxH", "frame size in pixels (default: render.size)"},
    {"fps", "N", "frames per second (default: render.fps)"},
    kHelp};

constexpr OptionSpec kReport[] = {kExpect, kHelp};

constexpr OptionSpec kCompare[] = {
    {"o,out", "DIR", "output folder (default: compare/ beside the first run folder)"},
    {"label", "L", "a label per run, in order (default: the folders' names)", true},
    {"expect", "EXPR", "a check, e.g. \"A.energy_final.joule < B.energy_final.joule\"", true},
    kHelp};

constexpr OptionSpec kMonteCarlo[] = {
    {"samples", "N", "number of draws (default: 30)"},
    {"seed", "S", "seed of the draws (default: the scenario's uncertainty.seed)"},
    {"jobs", "J", "threads (default: the cores available)"},
    {"o,out", "DIR", "output folder (default: the scenario's output.folder/montecarlo)"},
    kSet,
    {"case", "AXIS=LEVEL,...", "only the study: cases at these levels (default: all)"},
    {"variants", "A,B,...", "only these variants, in this order (default: all)"},
    {"no-report", nullptr, "skip report.html"},
    kHelp};

constexpr OptionSpec kSensitivity[] = {
    {"samples", "N", "draws per point (default: 20)"},
    {"seed", "S", "seed of the draws (default: the scenario's uncertainty.seed)"},
    {"jobs", "J", "threads (default: the cores available)"},
    {"o,out", "DIR", "output folder (default: the scenario's output.folder/sensitivity)"},
    kSet,
    {"case", "AXIS=LEVEL,...", "with a study: the one case to analyse"},
    {"variants", "A,B", "the two variants to compare, A over B (default: the first two)"},
    {"no-report", nullptr, "skip report.html (the tornado charts are still drawn)"},
    kHelp};

constexpr OptionSpec kStudy[] = {
    {"grid", "KEY=V1,V2,...", "with a SCENARIO: an axis of the grid (repeatable)", true},
    {"draws", "N", "Monte Carlo draws per point, 0 or >= 2 (default: the file's; --grid: 0)"},
    {"seed", "S", "seed of the draws (default: the file's, else uncertainty.seed)"},
    {"o,out", "DIR", "output folder (default: output.folder/<study name>)"},
    {"s,set", "KEY=VALUE", "override a scenario key in every case (YAML value)", true},
    {"jobs", "N", "cases at once, each a process (default: the cores available)"},
    {"shard", "I/N", "run only shard I of N: cases I-1, I-1+N, ... (default: all)"},
    {"case", "K", "run only case K, by index or folder name (default: all)"},
    {"video", nullptr, "with --case: that case's videos and reports too"},
    {"list", nullptr, "print the cases and their state; run nothing"},
    {"slurm", nullptr, "write DIR/submit.sh, a Slurm job array; run nothing"},
    {"k8s", nullptr, "write DIR/job.yaml, a Kubernetes Indexed Job; run nothing"},
    {"tasks", "N", "shards of --slurm / --k8s (default: one per case, at most 1000)"},
    kHelp};

constexpr OptionSpec kMerge[] = {{"o,out", "DIR", "output folder (default: the first DIR)"}, kHelp};

constexpr OptionSpec kAccuracy[] = {
    {"methods", "M,...", "the integrators to study, comma-separated (default: all five, below)"},
    {"points", "N", "settings per method, 2-12 (default: 6)"},
    {"repeats", "R", "timings per setting at least, 1-100 (default: 10; from 6 on, to +-5 %)"},
    {"variant", "V", "the one variant to study (default: every variant)"},
    {"no-alternatives", nullptr, "skip the timings of the dynamics, solver and event modes"},
    {"o,out", "DIR", "output folder (default: the scenario's output.folder/accuracy)"},
    kSet,
    kHelp};

constexpr const char* kRunNotes =
    R"(Writes into DIR: scenario.yaml (as run), trajectory.csv, summary.json, events.csv (with
contact), manifest.json; video.mp4 and frames/ as output.video and output.frames ask;
report.html and plots/. A scenario with variants: each into DIR/<variant>/, then
DIR/comparison.csv, comparison.json and DIR/compare/ (their report and their videos side by
side); prints the comparison's verdict. With variants, --expect paths start with the variant:
"elbow_on.energy_final.joule < elbow_off.energy_final.joule".
Exit: 3 a run stopped early (what it recorded is written), 4 an --expect does not hold,
128 + signal when interrupted (what was recorded is written, marked interrupted).)";

constexpr const char* kValidateNotes =
    R"(Loads and checks SCENARIO (and each variant) and prints the model: masses, effects, motors,
where each elbow is against the table at the task's first pose. Writes nothing.
Exit: 2 the scenario is not valid (the message names file, line and key).)";

constexpr const char* kSweepNotes =
    R"(Writes DIR/KEY=V/ per value (each as elbowsim run writes it) and DIR/sweep.csv.
Exit: as run's, of the first run that did not end with 0; 128 + signal when interrupted (the
runs done are kept, no sweep.csv).)";

constexpr const char* kRenderNotes =
    R"(Draws a saved run again (no simulation): writes RUN_DIR/video.mp4 (and frames/ if the
scenario asks). VIEW: a preset (front, side, top, three_quarter), optionally with fov=DEG
("top,fov=25"), or eye=X,Y,Z,target=X,Y,Z[,up=X,Y,Z][,fov=DEG] in metres and degrees.
Exit: 128 + signal when interrupted (the folder as it was: no partial video).)";

constexpr const char* kReportNotes =
    R"(Writes RUN_DIR/report.html and plots/ from the saved files (no simulation).
Exit: 4 an --expect does not hold.)";

constexpr const char* kCompareNotes =
    R"(Writes report.html, comparison.json, comparison.csv and plots/ into DIR and prints the
verdict. --expect paths start with a run's label.
Exit: 4 an --expect does not hold.)";

constexpr const char* kMonteCarloNotes =
    R"(Draws the scenario's uncertainty: parameters N times and runs every variant on each draw
under the nominal controller. Writes DIR/samples.csv, montecarlo.json and report.html. With a
study: section, the same for every case (one level of each axis) in DIR/<case>/, plus
DIR/study.csv, study.json and report.html.
Exit: 128 + signal when interrupted (the finished cases are kept).)";

constexpr const char* kSensitivityNotes =
    R"(Runs montecarlo with every uncertain parameter drawn, then with each parameter (as the
file gives it: a [*] entry moves together) held at either end of its range, the others drawn
on the same draws: uniform at +-spread, normal at +-2 sigma, range at its bounds. The scenario
needs two variants (with more, the first two or --variants A,B; only those run). Writes DIR/points/<point>/ (each a montecarlo folder), sensitivity.json,
sensitivity.csv, plots/tornado_<metric>.png and report.html; prints which parameter changes
each verdict and where the paired ratio crosses 1.
Exit: 128 + signal when interrupted (the finished points are kept).)";

constexpr const char* kStudyNotes =
    R"(STUDY is a study file (scenarios/README.md, "Study files"), or a scenario with --grid.
Writes DIR/NNN-label/ per case (NNN its index) and DIR/cases.json (folders to keys); skips
the finished cases (DIR/<case>/case.json); draws no videos (--case K --video: that case's).
--slurm: SLURM_ARRAY_TASK_ID picks the shard. Then: elbowsim merge DIR.
Exit: 3 a case failed; 128 + signal when interrupted (the rest run when it is run again).)";

constexpr const char* kMergeNotes =
    R"(Writes into DIR: table.csv (every run, no timings: the same bytes however the cases ran),
points.csv (with draws: means and 95 % intervals over them) and report.html. Several DIRs:
the shards of one study, each case taken from the first folder that finished it.
Exit: 3 runs are missing (run the study again to finish them).)";

constexpr const char* kAccuracyNotes =
    R"(Runs each method against a dopri5 reference at rtol 1e-11: euler, semi_implicit_euler
and rk4 at steps step/m (m = 1, 2, 3, 4, 6, 8, ...), dopri5 at rtol 1e-3, 1e-4, ..., ros34pw2
at rtol 1e-2, 1e-3, ... Each setting is timed at least R times; from 6 on, again until the
median's 95 % interval is within 5 % of it (at most 100 timings or 30 s of CPU).
Writes DIR/work_precision.csv, accuracy.json (with the verdict), report.html and plots/.
Exit: 3 the reference run is not valid; 128 + signal when interrupted (no report).)";

constexpr CommandSpec kCommands[] = {
    {"run", "SCENARIO", "simulate a scenario; write its data, video and report", kRun, kRunNotes},
    {"validate", "SCENARIO", "load and check a scenario, print the model (no simulation)",
     kValidate, kValidateNotes},
    {"sweep", "SCENARIO --key KEY --values V1,V2,...", "one run per value of a scenario key",
     kSweep, kSweepNotes},
    {"render", "RUN_DIR", "draw a saved run's video again (no simulation)", kRender, kRenderNotes},
    {"report", "RUN_DIR", "write a saved run's report.html again (no simulation)", kReport,
     kReportNotes},
    {"compare", "RUN_DIR RUN_DIR...", "compare saved runs in one report", kCompare, kCompareNotes},
    {"montecarlo", "SCENARIO", "draw the uncertain plant N times: distributions and verdicts",
     kMonteCarlo, kMonteCarloNotes},
    {"sensitivity", "SCENARIO", "each uncertain parameter at its ends: what flips a verdict",
     kSensitivity, kSensitivityNotes},
    {"study", "STUDY", "a study's cases (a grid or list over keys, x Monte Carlo draws)", kStudy,
     kStudyNotes},
    {"merge", "DIR...", "one table and report of a study's cases", kMerge, kMergeNotes},
    {"accuracy", "SCENARIO", "work-precision study: error against CPU time per integrator",
     kAccuracy, kAccuracyNotes},
};

// "-o, --out DIR", "    --no-render", "    --set KEY=VALUE ..." (repeatable).
std::string spelling(const OptionSpec& o) {
  const std::string_view names = o.names;
  const std::size_t comma = names.find(',');
  // Appended piece by piece: GCC 12 warns -Wrestrict on "-" + std::string&& (bug 105329).
  std::string out;
  if (comma == std::string_view::npos) {
    out = "    --";
    out += names;
  } else {
    out = '-';
    out += names.substr(0, comma);
    out += ", --";
    out += names.substr(comma + 1);
  }
  if (o.value) out += std::string(" ") + o.value;
  if (o.repeatable && !out.ends_with("...")) out += " ...";  // (--grid's meaning says it)
  return out;
}

}  // namespace

std::span<const CommandSpec> commands() { return kCommands; }

const CommandSpec* find_command(std::string_view name) {
  for (const CommandSpec& c : kCommands)
    if (name == c.name) return &c;
  return nullptr;
}

std::string_view long_name(const OptionSpec& option) {
  const std::string_view names = option.names;
  const std::size_t comma = names.find(',');
  return comma == std::string_view::npos ? names : names.substr(comma + 1);
}

std::string overview() {
  std::string out = std::string("elbowsim ") + report::provenance().version +
                    ": robot arms resting their elbows on a table, simulated headless\n\n"
                    "usage: elbowsim COMMAND ARGUMENTS [OPTIONS]\n"
                    "       elbowsim COMMAND --help   the command's options, outputs, exit codes\n"
                    "       elbowsim --version        version, git commit, build type, compiler\n"
                    "\ncommands:\n";
  for (const CommandSpec& c : kCommands) {
    std::string name = c.name;
    name.resize(12, ' ');
    out += "  " + name + c.synopsis + "\n";
  }
  return out +
         "\nExit codes: 0 ok, 1 I/O error, 2 bad input, 3 a run failed (each command's --help "
         "says\n"
         "how), 4 an --expect does not hold, 128 + signal when interrupted (130 Ctrl-C, 143 "
         "SIGTERM).\n"
         "Scenario keys: scenarios/README.md. Commands, reports and --expect: docs/cli.md.\n";
}

std::string help(const CommandSpec& c) {
  std::string out = std::string("elbowsim ") + c.name + ": " + c.synopsis + "\n\nusage: elbowsim " +
                    c.name + " " + c.operands + " [options]\n\noptions:\n";
  std::size_t width = 0;
  for (const OptionSpec& o : c.options) width = std::max(width, spelling(o).size());
  for (const OptionSpec& o : c.options) {
    std::string left = spelling(o);
    left.resize(width + 2, ' ');
    out += "  " + left + o.meaning + "\n";
  }
  return out + "\n" + c.notes + "\n";
}

std::string commands_with_option(std::string_view name, std::string_view except) {
  std::vector<std::string_view> having;
  for (const CommandSpec& c : kCommands)
    for (const OptionSpec& o : c.options)
      if (c.name != except && name != "help" && long_name(o) == name) having.push_back(c.name);
  std::string out;
  for (std::size_t k = 0; k < having.size(); ++k)
    out += std::string(k == 0                   ? ""
                       : k + 1 == having.size() ? " and "
                                                : ", ") +
           std::string(having[k]);
  return out;
}

}  // namespace elbowsim::cli
