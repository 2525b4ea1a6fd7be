// The elbowsim command line, run as a process: exit codes, messages, outputs.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/output/folder_lock.hpp"
#include "report/provenance.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;

namespace {

using elbowsim::testing::Outcome;
using elbowsim::testing::scratch;
using elbowsim::testing::slurp;

Outcome run(const std::string& arguments) { return elbowsim::testing::run_elbowsim(arguments); }

const std::string kPendulum = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/two_link_pendulum.yaml";

}  // namespace

namespace {

// The lines of `text` (without their '\n').
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// What the elbowsim binary says it is: its --version line, e.g. "elbowsim 0.1.0 (commit
// 0ae1fb498ed1, Release build, GNU 12.2.0)", and that as the "provenance" object of the
// JSON files it writes (null when the line is not of that form). Taken from the binary,
// not from this test program: after a commit, a build of elbowsim alone has the new
// commit and this program the old one.
struct BinaryProvenance {
  std::string line;
  nlohmann::ordered_json json;
};

BinaryProvenance binary_provenance() {
  BinaryProvenance b{run("--version").output, nullptr};
  if (b.line.empty() || b.line.back() != '\n') return b;
  b.line.pop_back();
  const std::string text = b.line;
  const std::size_t commit = text.find(" (commit "), build = text.find(" build, ", commit),
                    comma = text.rfind(", ", build);
  if (text.rfind("elbowsim ", 0) != 0 || commit == std::string::npos ||
      build == std::string::npos || comma == std::string::npos || comma < commit ||
      text.back() != ')')
    return b;
  b.json = {{"program", "elbowsim"},
            {"version", text.substr(9, commit - 9)},
            {"commit", text.substr(commit + 9, comma - commit - 9)},
            {"build_type", text.substr(comma + 2, build - comma - 2)},
            {"compiler", text.substr(build + 8, text.size() - build - 9)}};
  return b;
}

const char* const kCommands[] = {"run",     "validate",   "sweep", "render", "report",
                                 "compare", "montecarlo", "study", "merge",  "accuracy"};

}  // namespace

TEST_CASE(
    "cli: --help lists the commands; --version prints version and commit; bad command exits 2") {
  const Outcome help = run("--help");
  CHECK(help.exit_code == 0);
  for (const char* command : kCommands) {  // one line each
    CAPTURE(command);
    CHECK(help.output.find(std::string("\n  ") + command + " ") != std::string::npos);
  }
  CHECK(help.output.find("elbowsim COMMAND --help") != std::string::npos);
  CHECK(help.output.find("--no-render") == std::string::npos);  // no command's options
  // --version: version, commit, build type and compiler, one line.
  CHECK(run("--version").exit_code == 0);
  const BinaryProvenance binary = binary_provenance();
  INFO(binary.line);
  REQUIRE(binary.json.is_object());
  const elbowsim::report::Provenance& p = elbowsim::report::provenance();  // this build's
  CHECK(binary.json["version"] == p.version);
  CHECK(binary.json["build_type"] == p.build_type);
  CHECK(binary.json["compiler"] == p.compiler);
  // The commit: 12 hex digits (and -dirty), or unknown; one of the source's history when
  // the source is a git checkout.
  const std::string commit = binary.json["commit"].get<std::string>();
  const std::string hex = commit.substr(0, commit.find('-'));
  CHECK((commit == "unknown" ||
         (hex.size() == 12 && hex.find_first_not_of("0123456789abcdef") == std::string::npos &&
          (commit == hex || commit == hex + "-dirty"))));
  const std::string git = "git -C " + std::string(ELBOWSIM_SOURCE_DIR);
  if (elbowsim::testing::shell(git + " rev-parse --show-toplevel").output ==
      fs::canonical(ELBOWSIM_SOURCE_DIR).string() + "\n") {
    CHECK(commit != "unknown");
    CHECK(elbowsim::testing::shell(git + " cat-file -e " + hex + "^{commit}").exit_code == 0);
  }
  const Outcome bad = run("frobnicate x");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output == "error: unknown command 'frobnicate'\nsee 'elbowsim --help'\n");
}

TEST_CASE("cli: each command's --help shows its own options only; run's and montecarlo's differ") {
  std::map<std::string, std::string> helps;
  for (const char* command : kCommands) {
    CAPTURE(command);
    const Outcome r = run(std::string(command) + " --help");
    CHECK(r.exit_code == 0);
    CHECK(r.output.find(std::string("usage: elbowsim ") + command + " ") != std::string::npos);
    CHECK(r.output.find("Exit") != std::string::npos);  // its exit codes, or the notes end early
    for (const std::string& line : lines_of(r.output)) CHECK(line.size() <= 100);
    helps[command] = r.output;
  }
  const std::string &run_help = helps["run"], &montecarlo_help = helps["montecarlo"];
  CHECK(run_help != montecarlo_help);
  for (const char* own : {"--no-render", "--no-check-step", "--expect EXPR", "--jobs N"})
    CHECK(run_help.find(own) != std::string::npos);
  for (const char* other : {"--samples", "--seed", "--case", "--grid", "--camera", "--label"})
    CHECK(run_help.find(other) == std::string::npos);
  for (const char* own : {"--samples N", "--seed S", "--case", "--no-report"})
    CHECK(montecarlo_help.find(own) != std::string::npos);
  for (const char* other : {"--no-render", "--expect", "--check-step", "--grid", "--methods"})
    CHECK(montecarlo_help.find(other) == std::string::npos);
  // What help says the command takes, its parser takes, and no other option.
  CHECK(run("montecarlo x.yaml --no-render")
            .output.find("error: montecarlo has no option --no-render (run and sweep have it)\n") ==
        0);
  CHECK(run("validate " + kPendulum + " --set simulation.duration=0.1").exit_code == 0);
}

TEST_CASE("cli: a usage error says why in one line, then where the help is (exit 2)") {
  const std::pair<const char*, const char*> cases[] = {
      {"", "error: no command given"},
      {"frobnicate x", "error: unknown command 'frobnicate'"},
      {"--out x run y.yaml", "error: the command comes first"},
      {"run", "error: run takes exactly one SCENARIO (got 0)"},
      {"run a.yaml b.yaml", "error: run takes exactly one SCENARIO (got 2: 'a.yaml' 'b.yaml')"},
      {"run a.yaml --samples 3", "error: run has no option --samples (montecarlo and sensitivity have it)"},
      {"run a.yaml --out", "error: run: "},
      {"report", "error: report takes exactly one RUN_DIR (got 0)"},
      {"report d --key k", "error: report has no option --key (sweep has it)"},
      {"sweep s.yaml --key task.duration", "error: sweep needs both --key KEY and --values"},
      {"compare runs/a", "error: compare needs at least two run folders (got 1: 'runs/a')"},
      {"montecarlo s.yaml --samples x", "error: montecarlo: --samples needs a whole number"},
      {"study s.yaml --jobs 0", "error: study: --jobs needs a whole number >= 1"},
  };
  for (const auto& [arguments, reason] : cases) {
    CAPTURE(arguments);
    const Outcome r = run(arguments);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(reason) == 0);
    const std::vector<std::string> lines = lines_of(r.output);
    CHECK(lines.size() <= 3);
    REQUIRE(lines.size() >= 2);
    const std::string command = std::string(arguments).substr(0, std::string(arguments).find(' '));
    const bool known =
        std::find(std::begin(kCommands), std::end(kCommands), command) != std::end(kCommands);
    CHECK(lines.back() == "see 'elbowsim " + (known ? command + " " : std::string()) + "--help'");
  }
}

TEST_CASE("cli: summary.json, montecarlo.json and the reports name the program that wrote them") {
  const fs::path dir = scratch("cli", "provenance");
  const BinaryProvenance binary = binary_provenance();  // --version: tested above
  const nlohmann::ordered_json& expected = binary.json;
  REQUIRE(expected.is_object());

  const Outcome r = run("run " + kPendulum + " --out " + (dir / "run").string() +
                        " --no-render --no-check-step --set simulation.duration=0.1");
  REQUIRE(r.exit_code == 0);
  const auto summary = nlohmann::ordered_json::parse(slurp(dir / "run" / "summary.json"));
  CHECK(summary.begin().key() == "provenance");  // first: tests/golden/golden.sh drops it
  CHECK(summary["provenance"] == expected);
  const std::string footer =
      "<footer class=\"provenance\">This page was written by " + binary.line + ".</footer>";
  CHECK(slurp(dir / "run" / "report.html").find(footer) != std::string::npos);

  const Outcome mc =
      run("montecarlo " + kPendulum + " --samples 2 --jobs 1 --out " + (dir / "mc").string() +
          " --set simulation.duration=0.2 --set 'uncertainty={parameters: "
          "{\"robot.planar.links[*].mass\": {uniform: 0.1}}}'");
  INFO(mc.output);
  REQUIRE(mc.exit_code == 0);
  const auto doc = nlohmann::ordered_json::parse(slurp(dir / "mc" / "montecarlo.json"));
  CHECK(doc["provenance"] == expected);
  CHECK(slurp(dir / "mc" / "report.html").find(footer) != std::string::npos);
}

TEST_CASE("cli: --expect naming a metric that is not there fails before simulating, with the nearest path") {
  const fs::path dir = scratch("cli", "expect_early");
  // The experiment takes seconds to simulate: refused in far less, nothing written.
  const std::string experiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const auto start = std::chrono::steady_clock::now();
  const Outcome r = run("run " + experiment + " --out " + dir.string() +
                        " --no-render --expect 'elbow_on.metrics.energy_inn < 3'");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("no metric \"elbow_on.metrics.energy_inn\"") != std::string::npos);
  CHECK(r.output.find("did you mean elbow_on.metrics.energy_in?") != std::string::npos);
  CHECK(fs::is_empty(dir));
  CHECK(seconds < 1);  // (loading alone: 0.08-0.11 s measured under load 5; the runs take seconds)
  // Without the variant's prefix: the same path under each variant is suggested.
  const Outcome bare = run("run " + experiment + " --out " + dir.string() +
                           " --no-render --expect 'metrics.energy_in < 3'");
  CHECK(bare.exit_code == 2);
  CHECK(bare.output.find("did you mean elbow_on.metrics.energy_in, elbow_off.metrics.energy_in or "
                         "elbow_off_balanced.metrics.energy_in?") != std::string::npos);
  CHECK(fs::is_empty(dir));
  // A scene without variants; lists (warnings) hold any index before the run.
  const Outcome single = run("run " + kPendulum + " --out " + dir.string() +
                             " --expect 'energy_final.jolue >= 0' --expect 'len(warnings) == 0'");
  CHECK(single.exit_code == 2);
  CHECK(single.output.find("did you mean energy_final.joule?") != std::string::npos);
  CHECK(single.output.find("len(warnings)") == std::string::npos);  // the valid one is not blamed
  const Outcome fine = run("run " + kPendulum + " --out " + dir.string() +
                           " --expect 'energy_final.joule >= 0' --expect 'len(warnings) == 0'");
  CHECK(fine.exit_code == 0);
}

TEST_CASE("cli: run writes trajectory.csv and summary.json, byte-identical on a second run") {
  const fs::path dir = scratch("cli", "determinism");
  const Outcome first = run("run " + kPendulum + " --out " + (dir / "a").string());
  const Outcome second = run("run " + kPendulum + " --out " + (dir / "b").string());
  REQUIRE(first.exit_code == 0);
  REQUIRE(second.exit_code == 0);
  const std::string csv = slurp(dir / "a" / "trajectory.csv");
  CHECK(csv.rfind("time [s],q0 [rad],q1 [rad]", 0) == 0);
  CHECK(csv == slurp(dir / "b" / "trajectory.csv"));
  const auto summary = nlohmann::json::parse(slurp(dir / "a" / "summary.json"));
  CHECK(summary["completed"] == true);
  CHECK(summary["scenario"] == "two_link_pendulum");
  CHECK(summary["effects"] == nlohmann::json::array({"gravity"}));
  CHECK(summary["steps"].get<long>() > 0);
  for (const auto& entry : fs::directory_iterator(dir / "a"))
    CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("cli: --set overrides a key; a bad --set names itself and writes nothing") {
  const fs::path dir = scratch("cli", "set");
  const Outcome ok = run("run " + kPendulum + " --out " + (dir / "ok").string() +
                         " --set simulation.duration=0.1 --set effects.gravity=false");
  REQUIRE(ok.exit_code == 0);
  const auto summary = nlohmann::json::parse(slurp(dir / "ok" / "summary.json"));
  CHECK(summary["settings"]["duration"] == 0.1);
  CHECK(summary["effects"].empty());
  const Outcome bad = run("run " + kPendulum + " --out " + (dir / "bad").string() +
                          " --set simulation.step=abc");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("simulation.step") != std::string::npos);
  CHECK(bad.output.find("--set") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "bad"));
}

TEST_CASE("cli: a run whose recording would not fit in memory is refused before simulating (exit 2, nothing written)") {
  const fs::path dir = scratch("cli", "too_large");
  // 1e-300 s steps: t + h == t, and 1e299 rows; refused by the size estimate.
  const Outcome tiny_step = run("run " + kPendulum + " --out " + (dir / "tiny").string() + " --set simulation.step=1e-300");
  CHECK(tiny_step.exit_code == 2);
  CHECK(tiny_step.output.find("the recording would hold") != std::string::npos);
  CHECK(tiny_step.output.find("raise output.every") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "tiny"));
  // Long and fine enough to need more than this machine has (1e12 rows).
  const Outcome long_run = run("run " + kPendulum + " --out " + (dir / "long").string() +
                               " --set simulation.duration=1e9 --set simulation.step=1e-3 --set output.every=1");
  CHECK(long_run.exit_code == 2);
  CHECK_FALSE(fs::exists(dir / "long"));
}

TEST_CASE("cli: a physically invalid scenario exits 2 naming file, line and key; writes nothing") {
  const fs::path dir = scratch("cli", "invalid");
  std::string text = slurp(kPendulum);
  const std::string needle = "mass: 1.3";
  REQUIRE(text.find(needle) != std::string::npos);
  text.replace(text.find(needle), needle.size(), "mass: -1.3");
  const fs::path file = dir / "bad.yaml";
  std::ofstream(file) << text;
  const Outcome bad = run("run " + file.string() + " --out " + (dir / "out").string());
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("bad.yaml:") != std::string::npos);
  CHECK(bad.output.find("robot.planar.links[0].mass") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "out"));
  CHECK(run("validate " + file.string()).exit_code == 2);
  CHECK(run("validate " + kPendulum).exit_code == 0);
  CHECK(run("run " + (dir / "missing.yaml").string()).exit_code == 2);
}

TEST_CASE("cli: a diverging run exits 3 with a clear message and keeps what it recorded") {
  const fs::path dir = scratch("cli", "diverge");
  const Outcome r = run("run " + kPendulum + " --out " + dir.string() +
                        " --set simulation.integrator=euler --set simulation.step=0.05"
                        " --set simulation.duration=200" +
                        " --set 'inputs={torque: [{type: constant, value: 1e4}, {type: constant, value: 1e4}]}'");
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("diverged at t = ") != std::string::npos);
  CHECK(fs::exists(dir / "trajectory.csv"));
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
  CHECK(summary["completed"] == false);
  CHECK(summary["failure"].get<std::string>().find("diverged") != std::string::npos);
}

TEST_CASE("cli: a folder another run is writing is refused (exit 1, nothing written); free, it is used") {
  const fs::path dir = scratch("cli", "locked");
  const std::string out = (dir / "busy").string();
  {
    const elbowsim::FolderLock held(dir / "busy");  // as another run would hold it
    for (const std::string& command : {"run " + kPendulum + " --out " + out,
                                      "sweep " + kPendulum + " --key simulation.duration --values 0.1 --out " + out}) {
      const Outcome busy = run(command);
      INFO(busy.output);
      CHECK(busy.exit_code == 1);
      CHECK(busy.output.find("is in use by another elbowsim run") != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir / "busy" / "summary.json"));
  }
  const Outcome free = run("run " + kPendulum + " --out " + out);
  CHECK(free.exit_code == 0);
  CHECK(fs::exists(dir / "busy" / "summary.json"));
}

TEST_CASE("cli: SIGINT or SIGTERM during a run: what was recorded is written, marked interrupted, exit 128 + signal") {
  const fs::path dir = scratch("cli", "interrupt");
  // A pendulum for 2000 s at 0.1 ms (2e7 steps, far longer than the second
  // the shell waits before the signal).
  for (const auto& [signal, code] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const fs::path out = dir / signal;
    const Outcome r = elbowsim::testing::shell(
        '(' + std::string(ELBOWSIM_BINARY) + " run " + kPendulum + " --out " + out.string() +
        " --set simulation.duration=2000 --set simulation.step=1e-4 --set output.every=1000"
        " --no-render & pid=$!; sleep 1; kill -" + signal + " $pid; wait $pid; echo \"exit=$?\")");
    INFO(r.output);
    CHECK(r.output.find("exit=" + std::to_string(code)) != std::string::npos);
    CHECK(r.output.find("interrupted") != std::string::npos);
    REQUIRE(fs::exists(out / "summary.json"));
    const auto summary = nlohmann::json::parse(slurp(out / "summary.json"));
    CHECK(summary["interrupted"] == true);
    CHECK(summary["completed"] == false);
    CHECK(summary["valid"] == false);
    CHECK(summary["final_time"].get<double>() > 0.0);
    CHECK(summary["final_time"].get<double>() < 2000.0);
    const std::string csv = slurp(out / "trajectory.csv");
    CHECK(std::count(csv.begin(), csv.end(), '\n') > 2);  // header and rows
    CHECK_FALSE(fs::exists(out / "report.html"));         // nothing more started
    for (const auto& entry : fs::directory_iterator(out))
      CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
  }
}

namespace {

// Every file under `dir` (recursively) whose name holds "tmp": what a write cut short would leave.
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().filename().string().find("tmp") != std::string::npos)
      found.push_back(entry.path().string());
  return found;
}

// Starts `command` in the background (stdout and stderr into `log`), sends
// it `signal` once `started` exists (polled every 50 ms, 30 s at most), and
// returns its exit code ("exit=N") followed by what it printed.
Outcome signal_once(const std::string& command, const fs::path& started, const std::string& signal,
                    const fs::path& log) {
  return elbowsim::testing::shell(
      "(" + command + " > " + log.string() + " 2>&1 & pid=$!; for i in $(seq 600); do [ -e " +
      started.string() + " ] && break; sleep 0.05; done; kill -" + signal +
      " $pid; wait $pid; echo \"exit=$?\"; cat " + log.string() + ")");
}

}  // namespace

TEST_CASE(
    "cli: SIGTERM during rendering: exit 143, nothing more started, no partial video, summary.json "
    "says interrupted at rendering") {
  const fs::path dir = scratch("cli", "interrupt_render");
  const fs::path out = dir / "out";
  // The pendulum for 20 s in two variants, each with a 30 fps video, and
  // their side-by-side: 2 x 601 frames, seconds of drawing after a
  // simulation of a fraction of a second. The signal goes once the first
  // video's temporary file exists: rendering has begun.
  const std::string command =
      std::string(ELBOWSIM_BINARY) + " run " + kPendulum + " --out " + out.string() +
      " --set simulation.duration=20 --set output.every=10 --set output.video=true"
      " --set 'render.size=[320, 240]'"
      " --set 'variants={heavy: {}, light: {\"robot.planar.links[1].mass\": 0.5}}'";
  const Outcome r = signal_once(command, out / "heavy" / "video.tmp.mp4", "TERM", dir / "run.log");
  INFO(r.output);
  CHECK(r.output.find("exit=143") == 0);
  CHECK(r.output.find("rendering 1202 frames of 2 runs, and their side-by-side\n") !=
        std::string::npos);
  CHECK(r.output.find("interrupted (rendering): " + (out / "heavy").string() + " keeps ") !=
        std::string::npos);
  CHECK(r.output.find("interrupted: no comparison in " + out.string()) != std::string::npos);
  // Nothing started after the signal: no report, no comparison.
  CHECK_FALSE(
      fs::exists(out / "compare"));  // no report, no side-by-side video, not even its folder
  CHECK_FALSE(fs::exists(out / "comparison.csv"));
  CHECK_FALSE(fs::exists(out / "comparison.json"));
  for (const char* variant : {"heavy", "light"}) {
    CAPTURE(variant);
    const fs::path folder = out / variant;
    CHECK_FALSE(fs::exists(folder / "video.mp4"));  // not half a video
    CHECK_FALSE(fs::exists(folder / "report.html"));
    CHECK_FALSE(fs::exists(folder / ".elbowsim.lock"));
    REQUIRE(fs::exists(folder / "summary.json"));
    const auto summary = nlohmann::json::parse(slurp(folder / "summary.json"));
    CHECK(summary["interrupted"] == true);
    CHECK(summary["interrupted_stage"] == "rendering");
    CHECK(summary["completed"] == true);  // the simulation itself ran to its end
    CHECK(fs::exists(folder / "trajectory.csv"));
  }
  CHECK(temporaries(out).empty());
  CHECK_FALSE(fs::exists(out / ".elbowsim.lock"));

  SUBCASE("SIGINT during `render` of a run folder: exit 130, the folder as it was") {
    const fs::path folder = out / "heavy";
    const std::string manifest = slurp(folder / "manifest.json");
    const Outcome again = signal_once(std::string(ELBOWSIM_BINARY) + " render " + folder.string(),
                                      folder / "video.tmp.mp4", "INT", dir / "render.log");
    INFO(again.output);
    CHECK(again.output.find("exit=130") == 0);
    CHECK(again.output.find("interrupted: no video or frames made") != std::string::npos);
    CHECK_FALSE(fs::exists(folder / "video.mp4"));
    CHECK(slurp(folder / "manifest.json") == manifest);
    CHECK(temporaries(out).empty());
  }
}

TEST_CASE(
    "cli: stdout into a file is written line by line; SIGTERM in the second variant's simulation") {
  // The first variant's line is in the file while the second still
  // simulates (2000 s at 0.1 ms, far longer than the test waits), as a batch
  // job's log shows it; block-buffered, it came at the exit. Then SIGTERM.
  const fs::path dir = scratch("cli", "line_buffered");
  const fs::path out = dir / "out", log = dir / "run.log";
  const Outcome r = elbowsim::testing::shell(
      '(' + std::string(ELBOWSIM_BINARY) + " run " + kPendulum + " --out " + out.string() +
      " --no-render --no-report --set 'variants={quick: {simulation.duration: 0.5}, long:"
      " {simulation.duration: 2000, simulation.step: 1.0e-4, output.every: 1000}}' > " +
      log.string() + " 2>&1 & pid=$!; for i in $(seq 200); do grep -q 'steps to t' " +
      log.string() + " && break; sleep 0.05; done; kill -0 $pid && grep -q 'steps to t' " +
      log.string() +
      " && echo 'seen while running'; kill -TERM $pid; wait $pid; echo \"exit=$?\"; cat " +
      log.string() + ")");
  INFO(r.output);
  CHECK(r.output.find("seen while running") == 0);
  CHECK(r.output.find("exit=143") != std::string::npos);
  // The first variant ran whole; the second stopped in its simulation; no comparison.
  const auto quick = nlohmann::json::parse(slurp(out / "quick" / "summary.json"));
  CHECK(quick["completed"] == true);
  CHECK(quick["interrupted"] == true);
  CHECK(quick["interrupted_stage"] == "comparison");
  const auto slow = nlohmann::json::parse(slurp(out / "long" / "summary.json"));
  CHECK(slow["completed"] == false);
  CHECK(slow["interrupted_stage"] == "simulation");
  CHECK_FALSE(fs::exists(out / "comparison.csv"));
  CHECK(r.output.find("interrupted (simulation): " + (out / "long").string() + " keeps ") !=
        std::string::npos);
}

TEST_CASE("cli: run with variants prints the comparison's verdict sentences, as compare does") {
  const fs::path dir = scratch("cli", "run_verdict");
  const std::string variants =
      " --set simulation.duration=0.5 --no-render"
      " --set 'variants={heavy: {}, light: {\"robot.planar.links[1].mass\": 0.5}}'";
  for (const std::string report : {"", " --no-report"}) {
    CAPTURE(report);
    const fs::path out = dir / (report.empty() ? "report" : "tables");
    const Outcome r = run("run " + kPendulum + " --out " + out.string() + variants + report);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto verdict = nlohmann::json::parse(slurp(out / "comparison.json"))["verdict"];
    REQUIRE_FALSE(verdict.empty());
    for (const auto& sentence : verdict)
      CHECK(r.output.find(sentence.get<std::string>() + "\n") != std::string::npos);
    // The same sentences as compare prints of the same folders.
    const Outcome c = run("compare " + (out / "heavy").string() + " " + (out / "light").string() +
                          " --out " + (out / "cmp").string());
    REQUIRE(c.exit_code == 0);
    for (const auto& sentence : verdict)
      CHECK(c.output.find(sentence.get<std::string>() + "\n") != std::string::npos);
  }
}

TEST_CASE("cli: the folder's lock file is gone when run and sweep end, also after an error") {
  const fs::path dir = scratch("cli", "lock_removed");
  REQUIRE(run("run " + kPendulum + " --out " + (dir / "run").string() + " --no-render --no-report")
              .exit_code == 0);
  CHECK(fs::exists(dir / "run" / "summary.json"));
  CHECK_FALSE(fs::exists(dir / "run" / ".elbowsim.lock"));
  REQUIRE(run("sweep " + kPendulum +
              " --key simulation.duration --values 0.1,0.2 --no-render --no-report --out " +
              (dir / "sweep").string())
              .exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "sweep" / ".elbowsim.lock"));
  // A run that fails (exit 3) ends the same way.
  CHECK(run("run " + kPendulum + " --out " + (dir / "failed").string() +
            " --no-render --no-report --set simulation.integrator=euler --set simulation.step=0.05"
            " --set simulation.duration=200 --set 'inputs={torque: [{type: constant, value: 1e4},"
            " {type: constant, value: 1e4}]}'")
            .exit_code == 3);
  CHECK_FALSE(fs::exists(dir / "failed" / ".elbowsim.lock"));
}

TEST_CASE("cli: report and compare refuse a cut or mismatched run folder (exit 2, the reason)") {
  const fs::path dir = scratch("cli", "inconsistent");
  REQUIRE(run("run " + kPendulum + " --out " + (dir / "good").string() + " --no-report").exit_code == 0);
  const std::string csv = slurp(dir / "good" / "trajectory.csv");
  // Cut inside a row: a damaged file.
  fs::copy(dir / "good", dir / "cut", fs::copy_options::recursive);
  std::ofstream(dir / "cut" / "trajectory.csv", std::ios::binary | std::ios::trunc)
      << csv.substr(0, csv.size() / 2 + 7);
  const Outcome cut = run("report " + (dir / "cut").string());
  CHECK(cut.exit_code == 2);
  CHECK(cut.output.find("trajectory.csv") != std::string::npos);
  // Cut at a row's end: readable, but it stops before the summary's end.
  fs::copy(dir / "good", dir / "short", fs::copy_options::recursive);
  const std::size_t half = csv.find('\n', csv.size() / 2);
  std::ofstream(dir / "short" / "trajectory.csv", std::ios::binary | std::ios::trunc) << csv.substr(0, half + 1);
  const Outcome mismatch = run("compare " + (dir / "short").string() + " " + (dir / "good").string() +
                               " --out " + (dir / "cmp").string());
  CHECK(mismatch.exit_code == 2);
  CHECK(mismatch.output.find("but summary.json says the run completed at") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "cmp"));
  const Outcome render = run("render " + (dir / "short").string());
  CHECK(render.exit_code == 2);
  CHECK(render.output.find("but summary.json says the run completed at") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "short" / "video.mp4"));
  // A damaged summary.
  fs::copy(dir / "good", dir / "summary", fs::copy_options::recursive);
  std::ofstream(dir / "summary" / "summary.json", std::ios::trunc) << "{\"completed\": tr";
  CHECK(run("report " + (dir / "summary").string()).exit_code == 2);
  CHECK(run("report " + (dir / "good").string()).exit_code == 0);
}

TEST_CASE("cli: validate prints where each elbow is against the table, per variant") {
  const std::string experiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const Outcome r = run("validate " + experiment);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // The task's first pose: the elbow rests (elbow_on) or is lifted 2 cm (elbow_off).
  CHECK(r.output.find("elbow      elbow_on: elbow (link 1, r 0.03 m) at the task's first pose: "
                      "centre (") != std::string::npos);
  CHECK(r.output.find("elbow_on: elbow (link 1, r 0.03 m) at the task's first pose") != std::string::npos);
  const std::size_t on = r.output.find("elbow_on: elbow");
  const std::size_t off = r.output.find("elbow_off: elbow");
  REQUIRE(on != std::string::npos);
  REQUIRE(off != std::string::npos);
  CHECK(r.output.find("on the table (box 0", on) < off);
  CHECK(r.output.find("20 mm above box 0", off) != std::string::npos);
}

TEST_CASE("cli: render of a variant's folder draws what run drew (the title names the variant)") {
  // scenario.yaml is the variant as run, without its name; summary.json keeps
  // it. Without it the re-rendered title lost ": elbow_off" and the frames differed.
  const std::string experiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const fs::path dir = scratch("cli", "variant_render");
  const Outcome first = run("run " + experiment + " --out " + dir.string() +
                            " --no-report --set simulation.duration=0.1 --set 'render.size=[160,96]'"
                            " --set render.fps=10 --set output.video=false --set output.frames=true"
                            " --set 'variants={elbow_off: {task.elbow_clearance: 0.02}}'");
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  const fs::path frames = dir / "elbow_off" / "frames";
  const std::string drawn = slurp(frames / "frame_00001.png");
  const auto summary = nlohmann::json::parse(slurp(dir / "elbow_off" / "summary.json"));
  CHECK(summary["variant"] == "elbow_off");
  fs::remove_all(frames);
  const Outcome again = run("render " + (dir / "elbow_off").string());
  INFO(again.output);
  REQUIRE(again.exit_code == 0);
  CHECK(slurp(frames / "frame_00001.png") == drawn);
}

TEST_CASE("cli: every JSON file a command writes starts with the provenance") {
  const fs::path dir = scratch("cli", "provenance_json");
  const nlohmann::ordered_json expected = binary_provenance().json;
  REQUIRE(expected.is_object());
  const std::string quick = " --set simulation.duration=0.1";
  const std::string uncertain =
      " --set 'uncertainty={parameters: {\"robot.planar.links[*].mass\": {uniform: 0.1}}}'";
  const std::string commands[] = {
      // summary.json, manifest.json per variant; comparison.json
      "run " + kPendulum + " --no-render --no-check-step --out " + (dir / "run").string() + quick +
          " --set 'variants={a: {}, b: {\"robot.planar.links[1].mass\": 0.5}}'",
      // cases.json; case.json, summary.json, manifest.json per case
      "study " + kPendulum + " --grid simulation.duration=0.1,0.2 --jobs 1 --out " +
          (dir / "study").string(),
      // montecarlo.json per case; study.json
      "montecarlo " + kPendulum + " --samples 2 --jobs 1 --no-report --out " +
          (dir / "mc").string() + quick + uncertain +
          " --set 'study={axes: {d: {short: {simulation.duration: 0.1}, long: {}}}}'",
      // accuracy.json
      "accuracy " + kPendulum + " --points 2 --repeats 1 --no-alternatives --out " +
          (dir / "accuracy").string() + quick,
  };
  for (const std::string& command : commands) {
    const Outcome r = run(command);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
  }
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    CAPTURE(entry.path().string());
    names.insert(entry.path().filename().string());
    const auto doc = nlohmann::ordered_json::parse(slurp(entry.path()));
    REQUIRE(doc.is_object());
    CHECK(doc.begin().key() == "provenance");
    CHECK(doc["provenance"] == expected);
  }
  CHECK(names == std::set<std::string>{"summary.json", "manifest.json", "comparison.json",
                                       "cases.json", "case.json", "montecarlo.json", "study.json",
                                       "accuracy.json"});
}

namespace {

// Every number of a JSON document by its dotted path; a list of numbers once, by the list's.
void numbers_of(const nlohmann::ordered_json& node, const std::string& path,
                std::vector<std::string>& out) {
  const bool number_list = node.is_array() && !node.empty() &&
                           std::all_of(node.begin(), node.end(), [](const auto& v) { return v.is_number(); });
  if (node.is_number() || number_list) return out.push_back(path);
  if (node.is_object() || node.is_array())
    for (const auto& [key, value] : node.items())
      numbers_of(value, path.empty() ? key : path + "." + key, out);
}

}  // namespace

TEST_CASE("cli: summary.json names its program and gives every number its unit") {
  const fs::path dir = scratch("cli", "summary_units");
  const std::string experiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const std::string runs[] = {
      // a pendulum without motors; the step check on
      "run " + kPendulum + " --no-render --no-report --out " + (dir / "pendulum").string() +
          " --set simulation.duration=0.2",
      // motors, contact bodies with friction, stick and slip, a sampled loop, two variants;
      // an adaptive integrator (rtol, atol, max_step)
      "run " + experiment + " --no-render --no-report --out " + (dir / "pd").string() +
          " --set controller.type=pd --set simulation.duration=0.3",
      "run " + kPendulum + " --no-render --no-report --no-check-step --out " +
          (dir / "adaptive").string() + " --set simulation.duration=0.2 --set simulation.integrator=dopri5",
  };
  for (const std::string& command : runs) {
    const Outcome r = run(command);
    INFO(command << "\n" << r.output);
    REQUIRE(r.exit_code == 0);
  }
  const nlohmann::ordered_json expected = binary_provenance().json;
  const std::set<std::string> units{"1", "state", "s", "m", "m/s", "kg", "J", "N", "A", "W", "Hz", "rad", "V/rad", "V s/rad", "V/(rad s)", "kg m^2"};
  std::set<std::string> seen_keys;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().filename() != "summary.json") continue;
    ++files;
    CAPTURE(entry.path().string());
    const auto doc = nlohmann::ordered_json::parse(slurp(entry.path()));
    REQUIRE(doc.is_object());
    CHECK(doc["provenance"] == expected);
    CHECK(std::next(doc.begin()).key() == "units");
    const nlohmann::ordered_json& map = doc["units"];
    REQUIRE(map.is_object());
    std::vector<std::string> paths;
    for (const auto& [key, value] : doc.items())
      if (key != "units") numbers_of(value, key, paths);
    for (const std::string& path : paths) {
      CAPTURE(path);
      REQUIRE(map.contains(path));
      CHECK(units.count(map[path].get<std::string>()) == 1);
      seen_keys.insert(path);
    }
    CHECK(map.size() == paths.size());  // no unit for a number the file lacks
    // Spot checks against the quantities' dimensions.
    CHECK(map["final_time"] == "s");
    CHECK(map["energy_final.joule"] == "J");
    if (map.contains("metrics.hand_error_rms")) CHECK(map["metrics.hand_error_rms"] == "m");
    if (map.contains("metrics.current_peak")) CHECK(map["metrics.current_peak"] == "A");
  }
  CHECK(files == 5);  // pendulum, pd's three variants, adaptive
  for (const char* key : {"contact.bodies.link3.force_mean", "contact.bodies.link3.slips",
                          "step_check.metrics.hand_error_rms.floor", "control_loop.sample_rate",
                          "settings.atol", "metrics.rest_fraction.elbow"})
    CHECK_MESSAGE(seen_keys.count(key) == 1, key);
}
