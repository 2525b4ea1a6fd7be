// elbowsim: headless simulator for robot arms resting their elbows on a table.
// --set values are YAML and may hold commas: do not split them.
#define CXXOPTS_VECTOR_DELIMITER '\0'
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cxxopts.hpp>
#include <iostream>
#include <thread>

#include "app/commands/commands.hpp"

namespace {

constexpr const char* kVersion = "0.1.0";

constexpr const char* kUsage = R"(usage:
  elbowsim run SCENARIO [--out DIR] [--set key=value ...] [--no-render] [--no-report]
                       [--expect EXPR ...] [--no-check-step] [--jobs N]
                                                            simulate, write outputs
  elbowsim validate SCENARIO [--set key=value ...]          load, check, print the model
  elbowsim sweep SCENARIO --key KEY --values V1,V2,... [--out DIR] [run options]
                                                            one run per value of KEY
  elbowsim render RUN_DIR [--camera VIEW] [--follow hand] [--size WxH] [--fps N]
                                                            re-render a saved run (no simulation)
  elbowsim report RUN_DIR [--expect EXPR ...]               rebuild report.html (no simulation)
  elbowsim compare RUN_DIR RUN_DIR ... [--label L ...] [--out DIR] [--expect EXPR ...]
                                                            compare saved runs in one report
  elbowsim montecarlo SCENARIO [--samples N] [--seed S] [--jobs J] [--out DIR] [--set ...]
                       [--case AXIS=LEVEL,...] [--no-report] draw the uncertain plant N times
  elbowsim study STUDY [--jobs N] [--shard I/N] [--list] [--case K [--video]] [--slurm] [--k8s]
                       [--tasks N] [--out DIR] [--set ...]   a study file's cases (a grid or list
                                                            over keys, optionally x Monte Carlo draws)
  elbowsim study SCENARIO --grid KEY=V1,V2,... [--grid ...] [--draws N] [--seed S] [study options]
  elbowsim merge DIR... [--out DIR]                         one table and report of a study's cases
  elbowsim accuracy SCENARIO [--methods M,...] [--points N] [--repeats R] [--variant V]
                       [--no-alternatives] [--out DIR] [--set ...]
                                                            work-precision study: error vs CPU time
  elbowsim --help | --version

Outputs of run (in output.folder, or DIR): scenario.yaml (as run), trajectory.csv,
summary.json, events.csv (with contacts), video.mp4 (output.video) and frames/
(output.frames); --no-render skips the last two. render writes RUN_DIR/video.mp4
(and frames/ if the scenario asks). VIEW: a preset (front, side, top, three_quarter),
optionally with fov=DEG ("top,fov=25"), or eye=X,Y,Z,target=X,Y,Z[,up=X,Y,Z][,fov=DEG]
in metres and degrees; --follow hand keeps the hand at the centre of the view.
run and report write RUN_DIR/report.html and plots/ (--no-report skips them);
compare writes report.html, comparison.json and plots/ into DIR (default: compare/
beside the first run). --expect "energy_final.electrical_in < 120" checks a
summary.json metric (compare: "A.energy_final.joule < B.energy_final.joule", A and B
run folder names); README "Expectations" has the language.
A scenario with variants: runs each into DIR/<variant>/, then DIR/comparison.csv and
comparison.json; their videos are drawn at once, --jobs N at most (default: the cores
available), and DIR/compare/video.mp4 shows their frames side by side. sweep writes DIR/KEY=V/ per value and DIR/sweep.csv (DIR default:
output.folder/sweep). montecarlo draws the scenario's uncertainty: parameters N times
(default 30), runs every variant on each draw under the nominal controller, and writes
DIR/samples.csv, montecarlo.json and report.html (DIR default: output.folder/montecarlo);
--jobs defaults to the machine's cores. With a study: section, the same for every case
(one level of each axis) in DIR/<case>/, plus DIR/study.csv, study.json and report.html;
--case task=loops,speed=fast runs only the cases with those levels.
study writes DIR/NNN-label/ per case (NNN its index; DIR/cases.json maps folders to keys;
DIR default: output.folder/<study name>), skips finished cases (DIR/<case>/case.json),
runs --jobs cases at once as processes, and no videos (--case K --video: that one).
--shard I/N runs cases I-1, I-1+N, ...; --slurm writes DIR/submit.sh (a job array,
SLURM_ARRAY_TASK_ID picks the shard), --k8s DIR/job.yaml (an Indexed Job). merge writes
DIR/table.csv (every run, no timings: the same bytes however the cases ran), points.csv
(means and 95 % intervals over draws) and report.html. scenarios/README.md, "Study files".
accuracy runs each method (euler, semi_implicit_euler, rk4: steps step/m, m = 1,2,3,4,6,8;
dopri5, ros34pw2: rtol 1e-3.../1e-2...) against a dopri5 rtol 1e-11 reference and writes
DIR/work_precision.csv, accuracy.json (with the verdict), report.html and plots/
(DIR default: output.folder/accuracy).
Exit codes: 0 ok, 1 I/O error, 2 bad input, 3 run stopped early (outputs kept),
4 an --expect expression does not hold, 128 + signal (130 Ctrl-C, 143 SIGTERM): interrupted
(run, sweep: what was recorded is written; montecarlo: the finished cases).
Scenario keys: scenarios/README.md)";

cxxopts::Options make_options() {
  cxxopts::Options options("elbowsim", "Robot arms resting their elbows on a table");
  options.add_options()("h,help", "show help")("version", "show version")(
      "o,out", "output folder (overrides output.folder)", cxxopts::value<std::string>())(
      "s,set", "override a scenario key: key.path=value (repeatable)",
      cxxopts::value<std::vector<std::string>>())("positional", "",
                                                  cxxopts::value<std::vector<std::string>>())(
      "no-render", "run: skip output.video and output.frames")("no-report",
                                                               "run: skip report.html and plots")(
      "check-step", "run, sweep: the step check (the default; kept for older scripts)")(
      "no-check-step",
      "run, sweep: skip the step check (each valid run again, refined: summary.json step_check)")(
      "expect", "run, report, compare: a check over summary.json metrics (repeatable)",
      cxxopts::value<std::vector<std::string>>())(
      "camera", "render: camera preset or eye=..,target=..,fov=..", cxxopts::value<std::string>())(
      "follow", "render: hand (the camera follows the hand) or none",
      cxxopts::value<std::string>())("size", "render: WIDTHxHEIGHT", cxxopts::value<std::string>())(
      "fps", "render: frames per second", cxxopts::value<std::string>())(
      "key", "sweep: the key path to vary", cxxopts::value<std::string>())(
      "values", "sweep: its values, comma-separated", cxxopts::value<std::string>())(
      "samples", "montecarlo: number of draws", cxxopts::value<std::string>())(
      "seed", "montecarlo: seed of the draws", cxxopts::value<std::string>())(
      "jobs", "montecarlo: threads; study: processes; run, sweep: variants drawn at once",
      cxxopts::value<std::string>())(
      "case", "montecarlo: the study cases to run (axis=level,...)", cxxopts::value<std::string>())(
      "methods", "accuracy: integrators, comma-separated", cxxopts::value<std::string>())(
      "points", "accuracy: settings per method", cxxopts::value<std::string>())(
      "repeats", "accuracy: timings per setting", cxxopts::value<std::string>())(
      "variant", "accuracy: the one variant to study", cxxopts::value<std::string>())(
      "no-alternatives", "accuracy: skip the dynamics/solver/event-mode timings")(
      "grid", "study: KEY=V1,V2,... over a scenario (repeatable)",
      cxxopts::value<std::vector<std::string>>())(
      "draws", "study: Monte Carlo draws per point", cxxopts::value<std::string>())(
      "shard", "study: run shard I of N (I/N)", cxxopts::value<std::string>())(
      "video", "study: with --case, that case's videos and reports")(
      "list", "study: print the cases and their state")(
      "slurm", "study: write DIR/submit.sh (a Slurm job array)")(
      "k8s", "study: write DIR/job.yaml (a Kubernetes Indexed Job)")(
      "tasks", "study: shards of --slurm / --k8s", cxxopts::value<std::string>())(
      "label", "compare: a label per run, in order (repeatable)",
      cxxopts::value<std::vector<std::string>>());
  options.parse_positional({"positional"});
  return options;
}

std::vector<std::string> strings(const cxxopts::ParseResult& parsed, const char* key) {
  return parsed.count(key) ? parsed[key].as<std::vector<std::string>>()
                           : std::vector<std::string>{};
}

// run (and sweep): the scenario, --out, --set, --no-render, --no-report, --expect;
// --jobs checked by the caller.
elbowsim::RunArguments run_arguments(const cxxopts::ParseResult& parsed, const std::string& file,
                                     int render_jobs) {
  elbowsim::RunArguments args;
  args.render_jobs = render_jobs;
  args.scenario = file;
  args.sets = strings(parsed, "set");
  if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
  args.render = !parsed.count("no-render");
  args.report = !parsed.count("no-report");
  args.check_step = !parsed.count("no-check-step");
  args.expect = strings(parsed, "expect");
  return args;
}

// A whole number >= `low` from --key; false (after saying why) if it is not one.
bool whole_number(const cxxopts::ParseResult& parsed, const char* command, const char* key, long low,
                  long& out) {
  const std::string text = parsed[key].as<std::string>();
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (ec == std::errc{} && end == text.data() + text.size() && out >= low) return true;
  std::cerr << "error: " << command << ": --" << key << " needs a whole number >= " << low << " (got \""
            << text << "\")\n";
  return false;
}

int study_arguments(const cxxopts::ParseResult& parsed, const std::string& file) {
  elbowsim::StudyArguments args;
  args.study = file;
  args.grid = strings(parsed, "grid");
  args.sets = strings(parsed, "set");
  if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
  long number = 0;
  if (parsed.count("draws")) {
    if (!whole_number(parsed, "study", "draws", 0, number)) return elbowsim::exit_bad_input;
    args.draws = number;
  }
  if (parsed.count("seed")) {
    if (!whole_number(parsed, "study", "seed", 0, number)) return elbowsim::exit_bad_input;
    args.seed = static_cast<std::uint64_t>(number);
  }
  args.jobs = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (parsed.count("jobs")) {
    if (!whole_number(parsed, "study", "jobs", 1, number)) return elbowsim::exit_bad_input;
    args.jobs = static_cast<int>(std::min(number, 256L));
  }
  if (parsed.count("tasks")) {
    if (!whole_number(parsed, "study", "tasks", 1, number)) return elbowsim::exit_bad_input;
    args.tasks = static_cast<int>(std::min(number, 100000L));
  }
  if (parsed.count("shard")) args.shard = parsed["shard"].as<std::string>();
  if (parsed.count("case")) args.only = parsed["case"].as<std::string>();
  args.video = parsed.count("video") > 0;
  args.list = parsed.count("list") > 0;
  args.slurm = parsed.count("slurm") > 0;
  args.k8s = parsed.count("k8s") > 0;
  return elbowsim::study_command(args);
}

// Why a command line matched no command: the first thing wrong with it.
std::string usage_problem(const std::vector<std::string>& words) {
  if (words.empty()) return "no command given (run, validate, sweep, render, report, compare, montecarlo, study, merge, accuracy)";
  const std::string& command = words[0];
  const std::string given = std::to_string(words.size() - 1);
  std::string listed;
  for (std::size_t i = 1; i < words.size(); ++i) listed += " '" + words[i] + "'";
  for (const char* one : {"run", "validate", "render", "report", "montecarlo", "accuracy", "sweep", "study"}) {
    if (command != one) continue;
    const bool folder = command == "render" || command == "report";
    if (words.size() != 2)
      return command + " takes exactly one " + (folder ? "RUN_DIR" : "SCENARIO") + " (got " + given +
             (listed.empty() ? "" : ":" + listed) + ")";
    if (command == "sweep") return "sweep needs both --key KEY and --values V1,V2,...";
  }
  if (command == "merge") return "merge needs one or more study folders (elbowsim study writes them)";
  if (command == "compare")
    return "compare needs at least two run folders (got " + given + (listed.empty() ? "" : ":" + listed) +
           "); a scenario with variants: compares them itself (elbowsim run)";
  return "unknown command '" + command + "'";
}

int dispatch(const cxxopts::ParseResult& parsed) {
  using namespace elbowsim;
  if (parsed.count("help")) return std::cout << kUsage << '\n', exit_ok;
  if (parsed.count("version")) return std::cout << "elbowsim " << kVersion << '\n', exit_ok;
  const auto words = strings(parsed, "positional");
  const auto sets = strings(parsed, "set");
  const std::string command = words.empty() ? "" : words[0];
  // run, sweep: --jobs bounds the variants drawn at once (0: the cores available).
  long render_jobs = 0;
  if ((command == "run" || command == "sweep") && parsed.count("jobs") &&
      !whole_number(parsed, command.c_str(), "jobs", 1, render_jobs))
    return elbowsim::exit_bad_input;
  if (command == "run" && words.size() == 2)
    return run_command(run_arguments(parsed, words[1], int(std::min(render_jobs, 256L))));
  if (command == "sweep" && words.size() == 2 && parsed.count("key") && parsed.count("values"))
    return sweep_command({run_arguments(parsed, words[1], int(std::min(render_jobs, 256L))),
                          parsed["key"].as<std::string>(), parsed["values"].as<std::string>()});
  if (command == "render" && words.size() == 2) {
    RenderArguments args{words[1], {}, {}, {}, {}};
    for (auto [key, value] : {std::pair{"camera", &args.camera},
                              {"follow", &args.follow},
                              {"size", &args.size},
                              {"fps", &args.fps}})
      if (parsed.count(key)) *value = parsed[key].as<std::string>();
    return render_command(args);
  }
  if (command == "validate" && words.size() == 2) return validate_command(words[1], sets);
  if (command == "montecarlo" && words.size() == 2) {
    MonteCarloArguments args;
    args.scenario = words[1];
    args.sets = sets;
    if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
    // Whole numbers parsed here (cxxopts' integer parser trips GCC 12's -Wrestrict).
    long number = 0;
    for (const char* key : {"samples", "seed", "jobs"}) {
      if (!parsed.count(key)) continue;
      const std::string text = parsed[key].as<std::string>();
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
      if (ec != std::errc{} || end != text.data() + text.size() || number < 0) {
        std::cerr << "error: montecarlo: --" << key << " needs a whole number >= 0 (got \"" << text
                  << "\")\n";
        return exit_bad_input;
      }
      if (std::string(key) == "samples") args.samples = number;
      if (std::string(key) == "seed") args.seed = static_cast<std::uint64_t>(number);
      if (std::string(key) == "jobs") args.jobs = static_cast<int>(std::min(number, 256L));
    }
    if (!parsed.count("jobs"))
      args.jobs = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    args.report = !parsed.count("no-report");
    if (parsed.count("case")) args.cases = parsed["case"].as<std::string>();
    return montecarlo_command(args);
  }
  if (command == "accuracy" && words.size() == 2) {
    AccuracyArguments args;
    args.scenario = words[1];
    args.sets = sets;
    if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
    if (parsed.count("methods")) args.methods = parsed["methods"].as<std::string>();
    if (parsed.count("variant")) args.variant = parsed["variant"].as<std::string>();
    args.alternatives = !parsed.count("no-alternatives");
    for (auto [key, target] : {std::pair{"points", &args.points}, {"repeats", &args.repeats}}) {
      if (!parsed.count(key)) continue;
      const std::string text = parsed[key].as<std::string>();
      long number = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
      if (ec != std::errc{} || end != text.data() + text.size() || number < 1 || number > 1000) {
        std::cerr << "error: accuracy: --" << key << " needs a whole number >= 1 (got \"" << text
                  << "\")\n";
        return exit_bad_input;
      }
      *target = static_cast<int>(number);
    }
    return accuracy_command(args);
  }
  if (command == "study" && words.size() == 2) return study_arguments(parsed, words[1]);
  if (command == "merge" && words.size() >= 2) {
    MergeArguments args{{words.begin() + 1, words.end()}, std::nullopt};
    if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
    return merge_command(args);
  }
  if (command == "report" && words.size() == 2)
    return report_command({words[1], strings(parsed, "expect")});
  if (command == "compare" && words.size() >= 3) {
    CompareArguments args{
        {words.begin() + 1, words.end()}, std::nullopt, strings(parsed, "expect"), strings(parsed, "label")};
    if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
    return compare_command(args);
  }
  std::cerr << "error: " << usage_problem(words) << "\n\n" << kUsage << '\n';
  return exit_bad_input;
}

}  // namespace

int main(int argc, char** argv) {
  // Line by line even into a file or pipe (a batch job's log), so that stdout's
  // lines and stderr's appear in the order they happened (std::cout writes
  // through stdout: synced with stdio).
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  try {
    return dispatch(make_options().parse(argc, argv));
  } catch (const cxxopts::exceptions::exception& e) {
    std::cerr << "error: " << e.what() << "\n" << kUsage << '\n';
    return elbowsim::exit_bad_input;
  }
}
