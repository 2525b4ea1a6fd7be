// Running programs from tests: the elbowsim binary (ELBOWSIM_BINARY, set by
// tests/CMakeLists.txt) or any shell command, with stdout and stderr captured.
#pragma once

#include <doctest/doctest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace elbowsim::testing {

struct Outcome {
  int exit_code;       // -1 when the process did not exit normally
  std::string output;  // stdout and stderr
};

inline Outcome shell(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

#ifdef ELBOWSIM_BINARY
inline Outcome run_elbowsim(const std::string& arguments) {
  return shell(std::string(ELBOWSIM_BINARY) + " " + arguments);
}
#endif

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace elbowsim::testing
