// elbowsim study: a scenario run at many cases — a grid or list over its keys
// (a sweep), each optionally repeated over seeded draws of its uncertain
// plant (a Monte Carlo design). Every case writes its own folder (index and
// a short label, cases.json maps folders to keys) and case.json when
// finished, so a study can be killed and run again (finished cases are
// skipped), split into shards (--shard I/N, one per scheduler task) and run
// as local processes (--jobs N); elbowsim merge makes the table. The same
// study gives the same files whatever --jobs and sharding.
#include <charconv>
#include <fstream>
#include <iostream>
#include <set>

#include "app/commands/interrupt.hpp"
#include "app/commands/study_plan.hpp"
#include "app/output/atomic_file.hpp"
#include "app/scenario/scenario.hpp"
#include "app/study/case_record.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim {

namespace {

using Json = nlohmann::ordered_json;

int usage_error(const std::string& message) {
  std::cerr << "error: study: " << message << '\n';
  return exit_bad_input;
}

StudyDesign design_of(const StudyArguments& args) {
  StudyDesign d;
  if (is_study_file(args.study)) {
    if (!args.grid.empty())
      throw std::invalid_argument(args.study + " is a study file: its grid is in the file (no --grid)");
    d = load_study_file(args.study);
  } else {
    if (args.grid.empty())
      throw std::invalid_argument(args.study + " is not a study file (no scenario: key): give a study "
                                  "file, or a scenario with --grid KEY=V1,V2,...");
    d.name = "study";
    d.scenario = args.study;
    for (const std::string& g : args.grid) d.grid.push_back(grid_option(g));
  }
  d.sets.insert(d.sets.end(), args.sets.begin(), args.sets.end());
  if (args.draws) d.draws = *args.draws;
  if (args.seed) d.seed = args.seed;
  if (d.draws == 1 || d.draws < 0) throw std::invalid_argument("--draws must be 0 (none) or at least 2");
  return d;
}

StudyPlan plan_study(const StudyArguments& args) {
  StudyPlan plan;
  plan.design = design_of(args);
  const Scenario base = load_scenario(plan.design.scenario, plan.design.sets);
  for (const auto& [name, overrides] : base.variants) plan.variants.push_back(name);
  if (plan.variants.empty()) plan.variants.push_back("");
  if (plan.design.draws > 0 && base.uncertainty.parameters.empty())
    throw std::invalid_argument("draws: " + plan.design.scenario +
                                " has no uncertainty: parameters to draw (scenarios/README.md, uncertainty)");
  plan.seed = plan.design.seed.value_or(base.uncertainty.seed);
  plan.cases = study::enumerate_cases(plan.design);
  plan.folder = args.out.value_or(base.output.folder + "/" + plan.design.name);
  return plan;
}

// Every case's scenario loads, in every variant (a bad value writes nothing).
void check_cases(const StudyPlan& plan, const std::vector<long>& which) {
  for (const long k : which) {
    const study::CaseSpec& c = plan.cases[k];
    std::vector<std::string> sets = plan.design.sets;
    sets.insert(sets.end(), c.overrides.begin(), c.overrides.end());
    for (const std::string& v : plan.variants) {
      try {
        load_scenario_case(plan.design.scenario, {}, v, sets);
      } catch (const ScenarioError& e) {
        throw std::invalid_argument(std::string(e.what()) + " (in study case " + c.folder + ")");
      }
    }
  }
}

// "I/N" with 1 <= I <= N.
bool parse_shard(const std::string& text, int& shard, int& shards) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return false;
  const auto number = [](const std::string& s, int& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc{} && end == s.data() + s.size();
  };
  return number(text.substr(0, slash), shard) && number(text.substr(slash + 1), shards) && shards >= 1 &&
         shard >= 1 && shard <= shards;
}

// cases.json: written by the first process of the study; any later one
// (another shard, a rerun) must find the same design there.
void write_or_check_manifest(const StudyPlan& plan) {
  const Json doc = study::cases_manifest(plan.design, plan.cases, plan.variants, plan.seed);
  const std::filesystem::path path = plan.folder / "cases.json";
  std::ifstream in(path);
  if (in) {
    Json old;
    try {
      old = Json::parse(in);
    } catch (const std::exception&) {
      throw std::invalid_argument(path.string() + " is not readable JSON: remove it, or use another --out");
    }
    for (const char* key : {"set", "columns", "variants", "draws", "cases"})
      if (old.value(key, Json()) != doc[key] || old.value("seed", Json()) != doc.value("seed", Json()))
        throw std::invalid_argument(plan.folder.string() + " holds another study (its cases.json differs in \"" +
                                    key + "\"): use another --out, or remove it");
    return;
  }
  std::filesystem::create_directories(plan.folder);
  write_atomically(path, [&](std::ostream& out) { out << doc.dump(2) << '\n'; });
}

long find_case(const StudyPlan& plan, const std::string& name) {
  for (const study::CaseSpec& c : plan.cases)
    if (c.folder == name || std::to_string(c.index) == name) return c.index;
  throw std::invalid_argument("--case: no case \"" + name + "\" (an index 0-" +
                              std::to_string(plan.cases.size() - 1) + " or a folder name; --list shows them)");
}

std::string state_of(const StudyPlan& plan, const study::CaseSpec& c) {
  const auto r = study::finished_case(plan.folder / c.folder);
  return r ? r->status : "to run";
}

void list_cases(const StudyPlan& plan, const std::vector<long>& which) {
  std::cout << "study " << plan.design.name << ": "
            << counted(static_cast<long long>(plan.cases.size()), "case") << " of "
            << plan.design.scenario << " in " << plan.folder.string() << "\n";
  for (const long k : which) {
    const study::CaseSpec& c = plan.cases[k];
    std::string keys;
    for (const std::string& o : c.overrides) keys += (keys.empty() ? "" : " ") + o;
    if (c.draw >= 0) keys += (keys.empty() ? "" : " ") + std::string("draw=") + std::to_string(c.draw);
    std::cout << c.folder << "  [" << state_of(plan, c) << "]  " << keys << '\n';
  }
}

// This study's command line, to repeat it in another process or on another
// machine (`absolute`: with absolute paths, for a scheduler's nodes).
std::vector<std::string> command_of(const StudyArguments& args, const StudyPlan& plan, bool absolute) {
  const auto path = [&](const std::filesystem::path& p) {
    return absolute ? std::filesystem::absolute(p).lexically_normal().string() : p.string();
  };
  std::vector<std::string> c{absolute ? self_executable().string() : "elbowsim", "study", path(args.study),
                             "--out", path(plan.folder)};
  for (const std::string& g : args.grid) c.insert(c.end(), {"--grid", g});
  for (const std::string& s : args.sets) c.insert(c.end(), {"--set", s});
  if (args.draws) c.insert(c.end(), {"--draws", std::to_string(*args.draws)});
  if (args.seed) c.insert(c.end(), {"--seed", std::to_string(*args.seed)});
  return c;
}

int write_scheduler_file(const StudyArguments& args, const StudyPlan& plan) {
  const int tasks = std::min<int>(args.tasks.value_or(1000), static_cast<int>(plan.cases.size()));
  write_or_check_manifest(plan);
  if (args.slurm) {
    std::filesystem::create_directories(plan.folder / "slurm");  // Slurm does not make the log folder
    write_atomically(plan.folder / "submit.sh", [&](std::ostream& out) {
      out << slurm_script(plan, command_of(args, plan, true), tasks);
    });
    std::filesystem::permissions(plan.folder / "submit.sh", std::filesystem::perms::owner_exec,
                                 std::filesystem::perm_options::add);
    std::cout << "Slurm job array of " << counted(tasks, "task") << ": sbatch "
              << (plan.folder / "submit.sh").string() << '\n';
  }
  if (args.k8s) {
    write_atomically(plan.folder / "job.yaml", [&](std::ostream& out) {
      out << k8s_job(plan, command_of(args, plan, false), tasks);
    });
    std::cout << "Kubernetes Indexed Job of " << counted(tasks, "completion")
              << ": kubectl apply -f " << (plan.folder / "job.yaml").string() << '\n';
  }
  std::cout << "then: elbowsim merge " << plan.folder.string() << '\n';
  return exit_ok;
}

// The cases to run: --case, or the shard's; finished ones left out (counted).
std::vector<long> cases_to_run(const StudyArguments& args, const StudyPlan& plan, long& finished) {
  std::vector<long> out;
  finished = 0;
  if (args.only) {
    const long k = find_case(plan, *args.only);
    if (!args.video && study::finished_case(plan.folder / plan.cases[k].folder)) ++finished;
    else out.push_back(k);
    return out;
  }
  int shard = 1, shards = 1;
  if (args.shard && !parse_shard(*args.shard, shard, shards))
    throw std::invalid_argument("--shard needs I/N with 1 <= I <= N (got \"" + *args.shard + "\")");
  for (const study::CaseSpec& c : plan.cases) {
    if (!study::in_shard(c.index, shard, shards)) continue;
    if (study::finished_case(plan.folder / c.folder)) ++finished;
    else out.push_back(c.index);
  }
  return out;
}

// Runs the cases here, one after another, or as --jobs child processes.
std::vector<int> run_cases(const StudyArguments& args, const StudyPlan& plan, const std::vector<long>& todo) {
  if (args.jobs <= 1 || todo.size() <= 1) {
    std::vector<int> codes;
    for (const long k : todo) {
      if (interrupt_exit_code()) break;
      codes.push_back(run_study_case(plan, plan.cases[k], args.video));
    }
    codes.resize(todo.size(), -1);
    return codes;
  }
  std::vector<std::vector<std::string>> commands;
  for (const long k : todo) {
    std::vector<std::string> c = command_of(args, plan, false);
    c[0] = self_executable().string();
    c.insert(c.end(), {"--case", plan.cases[k].folder, "--jobs", "1"});
    commands.push_back(std::move(c));
  }
  return run_processes(commands, args.jobs);
}

}  // namespace

int study_command(const StudyArguments& args) {
  if (args.jobs < 1) return usage_error("--jobs must be at least 1");
  if (args.video && !args.only) return usage_error("--video needs --case K: videos are made for one case");
  StudyPlan plan;
  std::vector<long> todo;
  long finished = 0;
  try {
    plan = plan_study(args);
    if (args.list) {
      std::vector<long> all;
      for (const study::CaseSpec& c : plan.cases) all.push_back(c.index);
      return list_cases(plan, all), exit_ok;
    }
    // Every case is checked before any runs (a child, given one case, checks that one).
    std::vector<long> all;
    for (const study::CaseSpec& c : plan.cases)
      if (!args.only || c.folder == *args.only || std::to_string(c.index) == *args.only) all.push_back(c.index);
    check_cases(plan, all);
    if (args.slurm || args.k8s) return write_scheduler_file(args, plan);
    todo = cases_to_run(args, plan, finished);
    write_or_check_manifest(plan);
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::invalid_argument& e) {
    return usage_error(e.what());
  } catch (const std::exception& e) {
    std::cerr << "error: study: " << e.what() << '\n';
    return exit_io;
  }
  install_interrupt_handlers();
  const std::vector<int> codes = run_cases(args, plan, todo);
  long ran = 0, failed = 0, io = 0;
  for (const int c : codes) {
    ran += c == exit_ok || c == exit_run_failed;
    failed += c == exit_run_failed;
    io += c == exit_io || c == exit_bad_input || c == 127;
  }
  if (!args.only) {  // (a case alone, as --jobs runs it, says "case ...: done")
    std::cout << "study " << plan.design.name << ": " << counted(ran, "case") << " run (" << failed
              << " failed), " << finished << " already finished, of " << plan.cases.size() << " in "
              << plan.folder.string() << (args.shard ? " (shard " + *args.shard + ")" : "") << '\n';
  } else if (finished) {
    std::cout << "case " << *args.only << " is finished (--video runs it again with its videos)\n";
  }
  if (interrupt_exit_code()) {
    std::cerr << "interrupted: the cases not finished run again when the study is run again\n";
    return interrupt_exit_code();
  }
  for (const int c : codes)
    if (c > 128) {
      std::cerr << "error: a case's process was stopped by a signal (" << c - 128 << ")\n";
      return c;
    }
  if (io) return exit_io;
  if (!args.only) std::cout << "table and report: elbowsim merge " << plan.folder.string() << '\n';
  return failed ? exit_run_failed : exit_ok;
}

}  // namespace elbowsim
