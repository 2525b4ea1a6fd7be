// The command line's vocabulary, one table per command: its operands, its
// options (spelling, value, meaning and default) and what it writes. main.cpp
// builds each command's parser from its table (a command accepts its own
// options only) and prints its --help from the same table.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace elbowsim::cli {

struct OptionSpec {
  const char* names;    // cxxopts' spelling: "o,out" (short, long) or "no-render"
  const char* value;    // its placeholder ("DIR"); nullptr: a switch
  const char* meaning;  // one line, with its default
  bool repeatable = false;
};

struct CommandSpec {
  const char* name;
  const char* operands;  // after the name: "SCENARIO", "RUN_DIR RUN_DIR..."
  const char* synopsis;  // one line, for elbowsim --help
  std::span<const OptionSpec> options;
  const char* notes;  // what it writes and its exit codes, a few lines
};

std::span<const CommandSpec> commands();
const CommandSpec* find_command(std::string_view name);

// "o,out" -> "out".
std::string_view long_name(const OptionSpec& option);

// elbowsim --help: what the program is, the commands one a line, where to read more.
std::string overview();

// elbowsim COMMAND --help: usage, one line per option, what it writes, exit codes.
std::string help(const CommandSpec& command);

// The commands other than `except` that have option `name` (its long name),
// "montecarlo and study"; empty when none has it.
std::string commands_with_option(std::string_view name, std::string_view except);

}  // namespace elbowsim::cli
