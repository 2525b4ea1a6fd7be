// elbowsim study and merge as processes: cases and their folder names,
// identical tables whatever --jobs or sharding, a killed study resumed,
// failures recorded, Monte Carlo points with intervals, the Slurm and
// Kubernetes files (the Kubernetes command run here, index by index, as its
// pods would run it); and compare --label with the keys that differ.
#include <doctest/doctest.h>
#include <signal.h>
#include <unistd.h>

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "support/process.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace elbowsim::testing;

namespace {

const std::string kBinary = ELBOWSIM_BINARY;
const std::string kPendulum = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/two_link_pendulum.yaml";

// A study of the pendulum: `grid` lines under grid:, plus `extra` top-level lines.
fs::path study_file(const fs::path& dir, const std::string& grid, const std::string& extra = "") {
  const fs::path file = dir / "s.yaml";
  write_file(file, "scenario: " + kPendulum + "\nset: [simulation.duration=0.3, output.every=10]\ngrid:\n" +
                       grid + extra);
  return file;
}

Outcome study(const fs::path& file, const fs::path& out, const std::string& options) {
  return run_elbowsim("study " + file.string() + " --out " + out.string() + " " + options);
}

std::string merged_table(const fs::path& dir, const std::string& more = "") {
  const Outcome m = run_elbowsim("merge " + dir.string() + " " + more);
  INFO(m.output);
  CHECK(m.exit_code == 0);
  return slurp((more.empty() ? dir : fs::path(more.substr(more.rfind(' ') + 1))) / "table.csv");
}

std::size_t count_lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

long count_finished(const fs::path& dir) {
  long n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += fs::exists(e.path() / "case.json");
  return n;
}

const std::string kSixCases = "  initial.q: [[0.5, 0.3], [0.2, 0.1], [-0.4, 0.9]]\n  simulation.step: [1.0e-3, 5.0e-4]\n";

}  // namespace

TEST_CASE("study: safe folder names, cases.json maps them to keys, --list shows the state") {
  const fs::path dir = scratch("study", "names");
  const fs::path file = study_file(dir, "  simulation.duration: [0.1, 0.2]\n  initial.q: [[0.5, 0.3], [-0.2, 0.1]]\n");
  const Outcome list = study(file, dir / "out", "--list");
  INFO(list.output);
  REQUIRE(list.exit_code == 0);
  CHECK(list.output.find("000-duration_0.1-q_0.5_0.3  [to run]") != std::string::npos);
  CHECK(list.output.find("003-duration_0.2-q_-0.2_0.1  [to run]") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "out"));  // --list writes nothing
  const Outcome r = study(file, dir / "out", "--jobs 1 --case 3");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto cases = nlohmann::json::parse(slurp(dir / "out" / "cases.json"));
  CHECK(cases["columns"] == nlohmann::json({"simulation.duration", "initial.q"}));
  CHECK(cases["cases"][3]["folder"] == "003-duration_0.2-q_-0.2_0.1");
  CHECK(cases["cases"][3]["overrides"] == nlohmann::json({"simulation.duration=0.2", "initial.q=[-0.2, 0.1]"}));
  CHECK(fs::exists(dir / "out" / "003-duration_0.2-q_-0.2_0.1" / "summary.json"));
  CHECK_FALSE(fs::exists(dir / "out" / "003-duration_0.2-q_-0.2_0.1" / "video.mp4"));  // no videos in studies
  CHECK(study(file, dir / "out", "--list").output.find("003-duration_0.2-q_-0.2_0.1  [done]") != std::string::npos);
  // Videos only on request, for one case: run again with its video and report.
  CHECK(study(file, dir / "out", "--video").exit_code == 2);
  const Outcome v = study(file, dir / "out", "--case 003-duration_0.2-q_-0.2_0.1 --video --set render.size=[160,120]");
  INFO(v.output);
  CHECK(v.exit_code == 2);  // --set changes the design: refused, the folder holds another study
  const Outcome video = study(file, dir / "out", "--case 003-duration_0.2-q_-0.2_0.1 --video");
  INFO(video.output);
  REQUIRE(video.exit_code == 0);
  CHECK(fs::file_size(dir / "out" / "003-duration_0.2-q_-0.2_0.1" / "video.mp4") > 1000);
  CHECK(fs::exists(dir / "out" / "003-duration_0.2-q_-0.2_0.1" / "report.html"));
  CHECK(fs::exists(dir / "out" / "003-duration_0.2-q_-0.2_0.1" / "case.json"));
  CHECK_FALSE(fs::exists(dir / "out" / "002-duration_0.2-q_0.5_0.3" / "video.mp4"));
  // Another design into the same folder is refused.
  const fs::path other = study_file(dir, "  simulation.duration: [0.1, 0.3]\n");
  const Outcome refused = study(other, dir / "out", "--jobs 1");
  CHECK(refused.exit_code == 2);
  CHECK(refused.output.find("holds another study") != std::string::npos);
  // A bad value is found before anything runs, naming the case.
  const fs::path bad = study_file(dir, "  simulation.step: [1.0e-3, -1]\n");
  const Outcome b = study(bad, dir / "bad", "--jobs 1");
  CHECK(b.exit_code == 2);
  CHECK(b.output.find("001-step_-1") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "bad"));
}

TEST_CASE("study: --jobs 2 and --jobs 1 give identical merged tables; shards 1/3..3/3 merged equal the whole") {
  const fs::path dir = scratch("study", "jobs");
  const fs::path file = study_file(dir, kSixCases);
  const Outcome one = study(file, dir / "one", "--jobs 1");
  INFO(one.output);
  REQUIRE(one.exit_code == 0);
  const Outcome two = study(file, dir / "two", "--jobs 2");
  INFO(two.output);
  REQUIRE(two.exit_code == 0);
  CHECK(two.output.find("6 cases run (0 failed), 0 already finished") != std::string::npos);
  const std::string table = merged_table(dir / "one");
  CHECK(count_lines(table) == 1 + 6);
  CHECK(table.rfind("case,initial.q,simulation.step,variant,status,failure,", 0) == 0);
  CHECK(table.find("wall") == std::string::npos);  // timings are left out
  CHECK(merged_table(dir / "two") == table);
  // Three shards, each into its own folder, merged together.
  for (int i = 1; i <= 3; ++i) {
    const Outcome s = study(file, dir / ("shard" + std::to_string(i)), "--jobs 1 --shard " + std::to_string(i) + "/3");
    INFO(s.output);
    REQUIRE(s.exit_code == 0);
    CHECK(s.output.find("2 cases run") != std::string::npos);
    CHECK(fs::exists(dir / ("shard" + std::to_string(i)) / ("00" + std::to_string(i - 1) + "-q_0.5_0.3-step_1.0e-3") / "case.json") == (i == 1));
  }
  const Outcome m = run_elbowsim("merge " + (dir / "shard1").string() + " " + (dir / "shard2").string() + " " +
                                 (dir / "shard3").string() + " --out " + (dir / "merged").string());
  INFO(m.output);
  CHECK(m.exit_code == 0);
  CHECK(slurp(dir / "merged" / "table.csv") == table);
  // One shard alone is missing the others' cases: merge says so (exit 3).
  const Outcome partial = run_elbowsim("merge " + (dir / "shard2").string());
  CHECK(partial.exit_code == 3);
  CHECK(slurp(dir / "shard2" / "table.csv").find(",missing,") != std::string::npos);
  CHECK(study(file, dir / "one", "--shard 4/3").exit_code == 2);
}

TEST_CASE("study: killed midway, the rerun runs only the missing cases" * doctest::test_suite("long")) {
  const fs::path dir = scratch("study", "resume");
  // Twelve cases of about 0.1 s each.
  const fs::path file = study_file(dir, kSixCases + "  effects.damping: [false, true]\n",
                                   "");
  write_file(file, slurp(file) + "");
  const fs::path out = dir / "out";
  const std::string command = kBinary + " study " + file.string() + " --out " + out.string() +
                              " --jobs 2 --set simulation.duration=2 > " + (dir / "log").string() + " 2>&1";
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), nullptr);
    _exit(127);
  }
  // Kill it (SIGKILL: no clean-up of its own) once some cases are finished.
  const auto start = std::chrono::steady_clock::now();
  while ((!fs::exists(out) || count_finished(out) < 3) &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // its children see it die and stop
  const long finished = count_finished(out);
  INFO(slurp(dir / "log"));
  REQUIRE(finished >= 3);
  REQUIRE(finished < 12);
  const Outcome again = study(file, out, "--jobs 2 --set simulation.duration=2");
  INFO(again.output);
  REQUIRE(again.exit_code == 0);
  CHECK(again.output.find(std::to_string(12 - finished) + (finished == 11 ? " case" : " cases") +
                          " run (0 failed), " + std::to_string(finished) + " already finished") !=
        std::string::npos);
  const std::string resumed = merged_table(out);
  const Outcome whole = study(file, dir / "whole", "--jobs 1 --set simulation.duration=2");
  REQUIRE(whole.exit_code == 0);
  CHECK(merged_table(dir / "whole") == resumed);
  // Run again: nothing left to do.
  CHECK(study(file, out, "--jobs 2 --set simulation.duration=2").output.find("0 cases run (0 failed), 12 already finished") != std::string::npos);
}

TEST_CASE("study: a failed case is recorded with its reason and not rerun; draws give points with intervals") {
  const fs::path dir = scratch("study", "failed");
  const fs::path file = study_file(dir, "  validity.energy_residual: [1.0e-3, 1.0e-300]\n");
  const Outcome r = study(file, dir / "out", "--jobs 1");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  const auto record = nlohmann::json::parse(slurp(dir / "out" / "001-energy_residual_1.0e-300" / "case.json"));
  CHECK(record["status"] == "failed");
  CHECK(record["failures"][0]["reason"].get<std::string>().find("energy") != std::string::npos);
  CHECK(study(file, dir / "out", "--jobs 1").output.find("0 cases run (0 failed), 2 already finished") !=
        std::string::npos);
  run_elbowsim("merge " + (dir / "out").string());
  const std::string table = slurp(dir / "out" / "table.csv");
  CHECK(table.find("001-energy_residual_1.0e-300,1.0e-300,,failed,\"") != std::string::npos);
  CHECK(slurp(dir / "out" / "report.html").find("Runs that failed") != std::string::npos);

  // Monte Carlo: the links' masses drawn 4 times per point.
  const fs::path scenario = dir / "p.yaml";
  write_file(scenario, slurp(kPendulum) + "\nuncertainty:\n  seed: 7\n  parameters:\n    robot.planar.links[*].mass: {uniform: 0.2}\n");
  write_file(dir / "mc.yaml", "scenario: p.yaml\ngrid:\n  simulation.duration: [0.2, 0.3]\ndraws: 4\n");
  const Outcome mc = run_elbowsim("study " + (dir / "mc.yaml").string() + " --out " + (dir / "mc").string() + " --jobs 2");
  INFO(mc.output);
  REQUIRE(mc.exit_code == 0);
  CHECK(fs::exists(dir / "mc" / "007-duration_0.3-d3" / "summary.json"));
  const Outcome m = run_elbowsim("merge " + (dir / "mc").string());
  INFO(m.output);
  REQUIRE(m.exit_code == 0);
  const std::string points = slurp(dir / "mc" / "points.csv");
  CHECK(count_lines(points) == 3);
  CHECK(points.find("metrics.energy_in mean [J],metrics.energy_in ci95 low") != std::string::npos);
  // The draws change the plant: the four masses of a point differ.
  const std::string a = slurp(dir / "mc" / "000-duration_0.2-d0" / "scenario.yaml");
  const std::string b = slurp(dir / "mc" / "001-duration_0.2-d1" / "scenario.yaml");
  CHECK(a != b);
  CHECK(slurp(dir / "mc" / "report.html").find("95 %") != std::string::npos);
}

TEST_CASE("study: --slurm writes a job array script, --k8s an Indexed Job whose command runs the shards") {
  const fs::path dir = scratch("study", "scheduler");
  const fs::path file = study_file(dir, kSixCases);
  const Outcome s = study(file, dir / "out", "--slurm --k8s --tasks 4");
  INFO(s.output);
  REQUIRE(s.exit_code == 0);
  const std::string submit = slurp(dir / "out" / "submit.sh");
  CHECK(submit.find("#SBATCH --array=1-4\n") != std::string::npos);
  CHECK(submit.find("--shard \"${SLURM_ARRAY_TASK_ID}/4\"") != std::string::npos);
  CHECK(submit.find("exec " + fs::canonical(kBinary).string() + " study " + fs::absolute(file).string()) != std::string::npos);
  CHECK(fs::is_directory(dir / "out" / "slurm"));
  const std::string job = slurp(dir / "out" / "job.yaml");
  for (const char* line : {"kind: Job\n", "  completionMode: Indexed\n", "  completions: 4\n", "      restartPolicy: Never\n"})
    CHECK(job.find(line) != std::string::npos);
  // The container's command, run here as each of the 4 pods would (JOB_COMPLETION_INDEX 0-3).
  std::smatch args;
  REQUIRE(std::regex_search(job, args, std::regex("args: \\[\"(.*)\"\\]")));
  std::string command = std::regex_replace(args[1].str(), std::regex("\\\\\""), "\"");
  CHECK(command.find("--shard \"$((JOB_COMPLETION_INDEX + 1))/4\"") != std::string::npos);
  command = std::regex_replace(command, std::regex("^exec elbowsim "), "exec " + kBinary + " ");
  for (int index = 0; index < 4; ++index) {
    const Outcome pod = shell("JOB_COMPLETION_INDEX=" + std::to_string(index) + " sh -c '" + command + "'");
    INFO(pod.output);
    CHECK(pod.exit_code == 0);
  }
  const std::string table = merged_table(dir / "out");
  CHECK(table.find(",missing,") == std::string::npos);
  REQUIRE(study(file, dir / "local", "--jobs 2").exit_code == 0);
  CHECK(merged_table(dir / "local") == table);
}

TEST_CASE("compare --label names the runs; the keys that differ are listed") {
  const fs::path dir = scratch("study", "compare");
  for (const char* step : {"1.0e-3", "5.0e-4"})
    REQUIRE(run_elbowsim("run " + kPendulum + " --no-render --no-report --set simulation.duration=0.2 --set simulation.step=" +
                         step + " --out " + (dir / step).string())
                .exit_code == 0);
  const std::string runs = (dir / "1.0e-3").string() + " " + (dir / "5.0e-4").string();
  const Outcome c = run_elbowsim("compare " + runs + " --label coarse --label fine --out " + (dir / "cmp").string() +
                                 " --expect \"fine.steps > coarse.steps\"");
  INFO(c.output);
  CHECK(c.exit_code == 0);
  CHECK(c.output.find("differs: simulation.step: coarse 1.0e-3, fine 5.0e-4") != std::string::npos);
  const std::string html = slurp(dir / "cmp" / "report.html");
  CHECK(html.find("<th>coarse</th><th>fine</th>") != std::string::npos);
  CHECK(html.find("scenario keys that differ</th><td class=\"keys\">simulation.step = 1.0e-3</td>") != std::string::npos);
  const auto json = nlohmann::json::parse(slurp(dir / "cmp" / "comparison.json"));
  CHECK(json["differing_keys"]["simulation.step"]["fine"] == "5.0e-4");
  CHECK(run_elbowsim("compare " + runs + " --label one").exit_code == 2);
  CHECK(run_elbowsim("compare " + runs + " --label a --label a").exit_code == 2);
}

TEST_CASE("study: the shipped study files load, with the cases their comments say") {
  const fs::path dir = scratch("study", "shipped");
  const std::string studies = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/studies/";
  for (const auto& [file, cases] : {std::pair{"task_speed.yaml", 6}, {"speed_elbow_draws.yaml", 90}}) {
    const Outcome list = run_elbowsim("study " + studies + file + " --list --out " + (dir / "x").string());
    INFO(list.output);
    CHECK(list.exit_code == 0);
    CHECK(count_lines(list.output) == 1 + cases);
  }
}
