// The subcommands of the elbowsim command line. Each returns the exit code:
// 0 success, 1 I/O failure, 2 bad input (scenario or usage), 3 the run
// stopped early (diverged); what it recorded is still written.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace elbowsim {

enum ExitCode { exit_ok = 0, exit_io = 1, exit_bad_input = 2, exit_run_failed = 3 };

struct RunArguments {
  std::string scenario;
  std::optional<std::string> out;   // overrides output.folder
  std::vector<std::string> sets;    // "key.path=value" overrides
};

int run_command(const RunArguments& args);
int validate_command(const std::string& scenario, const std::vector<std::string>& sets);

}  // namespace elbowsim
