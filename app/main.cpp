// elbowsim: headless simulator for robot arms resting their elbows on a table.
// --set values are YAML and may hold commas: do not split them.
#define CXXOPTS_VECTOR_DELIMITER '\0'
#include <cxxopts.hpp>
#include <iostream>

#include "app/commands/commands.hpp"

namespace {

constexpr const char* kVersion = "0.1.0";

constexpr const char* kUsage = R"(usage:
  elbowsim run SCENARIO [--out DIR] [--set key=value ...]   simulate, write outputs
  elbowsim validate SCENARIO [--set key=value ...]          load, check, print the model
  elbowsim --help | --version

Outputs of run (in output.folder, or DIR): scenario.yaml (as run), trajectory.csv,
summary.json, events.csv (with contacts).
Exit codes: 0 ok, 1 I/O error, 2 bad input, 3 run stopped early (outputs kept).
Scenario keys: scenarios/README.md)";

cxxopts::Options make_options() {
  cxxopts::Options options("elbowsim", "Robot arms resting their elbows on a table");
  options.add_options()("h,help", "show help")("version", "show version")(
      "o,out", "output folder (overrides output.folder)", cxxopts::value<std::string>())(
      "s,set", "override a scenario key: key.path=value (repeatable)",
      cxxopts::value<std::vector<std::string>>())(
      "positional", "", cxxopts::value<std::vector<std::string>>());
  options.parse_positional({"positional"});
  return options;
}

std::vector<std::string> strings(const cxxopts::ParseResult& parsed, const char* key) {
  return parsed.count(key) ? parsed[key].as<std::vector<std::string>>()
                           : std::vector<std::string>{};
}

int dispatch(const cxxopts::ParseResult& parsed) {
  using namespace elbowsim;
  if (parsed.count("help")) return std::cout << kUsage << '\n', exit_ok;
  if (parsed.count("version")) return std::cout << "elbowsim " << kVersion << '\n', exit_ok;
  const auto words = strings(parsed, "positional");
  const auto sets = strings(parsed, "set");
  const std::string command = words.empty() ? "" : words[0];
  if (command == "run" && words.size() == 2) {
    RunArguments args{words[1], std::nullopt, sets};
    if (parsed.count("out")) args.out = parsed["out"].as<std::string>();
    return run_command(args);
  }
  if (command == "validate" && words.size() == 2) return validate_command(words[1], sets);
  std::cerr << kUsage << '\n';
  return exit_bad_input;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return dispatch(make_options().parse(argc, argv));
  } catch (const cxxopts::exceptions::exception& e) {
    std::cerr << "error: " << e.what() << "\n" << kUsage << '\n';
    return elbowsim::exit_bad_input;
  }
}
