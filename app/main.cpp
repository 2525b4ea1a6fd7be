// elbowsim: headless simulator for robot arms resting their elbows on a table.
// --set values are YAML and may hold commas: do not split them.
#define CXXOPTS_VECTOR_DELIMITER '\0'
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cxxopts.hpp>
#include <iostream>
#include <sstream>
#include <thread>

#include "app/command_line.hpp"
#include "app/commands/commands.hpp"
#include "report/provenance.hpp"

namespace {

using elbowsim::cli::CommandSpec;

// This command's parser: its options only (cli::commands()), its operands as "positional".
// Unknown options are collected (unmatched()) so that the error can name them.
cxxopts::Options make_options(const CommandSpec& command) {
  cxxopts::Options options(std::string("elbowsim ") + command.name);
  auto add = options.add_options();
  for (const elbowsim::cli::OptionSpec& o : command.options) {
    if (!o.value)
      add(o.names, o.meaning);
    else if (o.repeatable)
      add(o.names, o.meaning, cxxopts::value<std::vector<std::string>>());
    else
      add(o.names, o.meaning, cxxopts::value<std::string>());
  }
  add("positional", "", cxxopts::value<std::vector<std::string>>());
  options.parse_positional({"positional"});
  options.allow_unrecognised_options();
  return options;
}

// A usage error: its reason on one line, then where the command's help is (exit 2).
int usage_error(const std::string& reason, const std::string& command) {
  std::cerr << "error: " << reason << "\nsee 'elbowsim " << (command.empty() ? "" : command + " ")
            << "--help'\n";
  return elbowsim::exit_bad_input;
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
  usage_error(std::string(command) + ": --" + key +
                  " needs a whole number >= " + std::to_string(low) + " (got \"" + text + "\")",
              command);
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

// Why a command's operands are wrong (words: the command, then its operands).
std::string usage_problem(const std::vector<std::string>& words) {
  const std::string& command = words[0];
  const std::string given = std::to_string(words.size() - 1);
  std::string listed;
  for (std::size_t i = 1; i < words.size(); ++i) listed += " '" + words[i] + "'";
  for (const char* one :
       {"run", "validate", "render", "report", "montecarlo", "sensitivity", "accuracy", "sweep", "study"}) {
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
  return command + ": unexpected operands";  // (every command is handled above)
}

// "run has no option --samples (montecarlo and study have it)", for an
// unrecognised argument ("--samples", "--samples=5", "-x").
std::string unknown_option(const CommandSpec& command, const std::string& argument) {
  std::string name = argument.substr(argument.find_first_not_of('-'));
  name = name.substr(0, name.find('='));
  const std::string others = elbowsim::cli::commands_with_option(name, command.name);
  const bool one = others.find(' ') == std::string::npos;
  return std::string(command.name) + " has no option " + argument.substr(0, argument.find('=')) +
         (others.empty() ? "" : " (" + others + (one ? " has it)" : " have it)"));
}

int dispatch(const CommandSpec& spec, const cxxopts::ParseResult& parsed) {
  using namespace elbowsim;
  const std::string command = spec.name;
  std::vector<std::string> words{command};
  for (const std::string& w : strings(parsed, "positional")) words.push_back(w);
  const auto sets = strings(parsed, "set");
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
  if ((command == "montecarlo" || command == "sensitivity") && words.size() == 2) {
    MonteCarloArguments args;
    if (command == "sensitivity") args.samples = 20;
    args.scenario = words[1];
    args.sets = sets;
    if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
    // Whole numbers parsed here (cxxopts' integer parser trips GCC 12's -Wrestrict).
    long number = 0;
    for (const char* key : {"samples", "seed", "jobs"}) {
      if (!parsed.count(key)) continue;
      const std::string text = parsed[key].as<std::string>();
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
      if (ec != std::errc{} || end != text.data() + text.size() || number < 0)
        return usage_error(command + ": --" + key + " needs a whole number >= 0 (got \"" + text + "\")",
                           command);
      if (std::string(key) == "samples") args.samples = number;
      if (std::string(key) == "seed") args.seed = static_cast<std::uint64_t>(number);
      if (std::string(key) == "jobs") args.jobs = static_cast<int>(std::min(number, 256L));
    }
    if (!parsed.count("jobs"))
      args.jobs = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    args.report = !parsed.count("no-report");
    if (parsed.count("case")) args.cases = parsed["case"].as<std::string>();
    if (parsed.count("variants")) {
      std::stringstream list(parsed["variants"].as<std::string>());
      for (std::string name; std::getline(list, name, ',');) args.variants.push_back(name);
    }
    return command == "sensitivity" ? sensitivity_command(args) : montecarlo_command(args);
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
      if (ec != std::errc{} || end != text.data() + text.size() || number < 1 || number > 1000)
        return usage_error(
            std::string("accuracy: --") + key + " needs a whole number >= 1 (got \"" + text + "\")",
            "accuracy");
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
  return usage_error(usage_problem(words), command);
}

}  // namespace

int main(int argc, char** argv) {
  // Line by line even into a file or pipe (a batch job's log), so that stdout's
  // lines and stderr's appear in the order they happened (std::cout writes
  // through stdout: synced with stdio).
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  // --version first and alone: no parser built, nothing loaded (it stays about 3 ms).
  const std::string first = argc > 1 ? argv[1] : "";
  if (first == "--version") return std::cout << elbowsim::report::provenance_line() << '\n', 0;
  if (first == "-h" || first == "--help") return std::cout << elbowsim::cli::overview(), 0;
  if (argc < 2)
    return usage_error(
        "no command given (run, validate, sweep, render, report, compare, montecarlo, sensitivity, "
        "study, merge, accuracy)",
        "");
  if (first.starts_with('-'))
    return usage_error("the command comes first: elbowsim COMMAND ... (got '" + first + "' first)",
                       "");
  const CommandSpec* command = elbowsim::cli::find_command(first);
  if (!command) return usage_error("unknown command '" + first + "'", "");
  try {
    // The command's own arguments: cxxopts skips argv[0], here the command's name.
    const cxxopts::ParseResult parsed = make_options(*command).parse(argc - 1, argv + 1);
    if (parsed.count("help")) return std::cout << elbowsim::cli::help(*command), 0;
    if (!parsed.unmatched().empty())
      return usage_error(unknown_option(*command, parsed.unmatched().front()), command->name);
    return dispatch(*command, parsed);
  } catch (const cxxopts::exceptions::exception& e) {
    return usage_error(std::string(command->name) + ": " + e.what(), command->name);
  }
}
