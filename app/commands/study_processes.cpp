// The process pool of elbowsim study --jobs N: each case a child process (a
// copy of this program running that case alone), at most N at once. Cases
// are processes, not threads, so that one case's crash, memory or renderer
// never touches another, and a case run by a scheduler is the same program
// doing the same thing.
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <map>

#include "app/commands/interrupt.hpp"
#include "app/commands/study_plan.hpp"

namespace elbowsim {

namespace {

// Starts `command` (argv[0] the program) as a child that gets SIGTERM when
// this process dies, however it dies (a killed study leaves no orphan
// writing into its folder). Returns its pid, or -1.
pid_t spawn(const std::vector<std::string>& command) {
  std::vector<char*> argv;
  for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid != 0) return pid;
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(128 + SIGTERM);  // the parent died before prctl
  execv(argv[0], argv.data());
  std::cerr << "error: cannot start " << command[0] << ": " << std::strerror(errno) << '\n';
  _exit(127);
}

int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace

std::filesystem::path self_executable() { return std::filesystem::read_symlink("/proc/self/exe"); }

std::vector<int> run_processes(const std::vector<std::vector<std::string>>& commands, int jobs) {
  std::vector<int> codes(commands.size(), -1);
  std::map<pid_t, std::size_t> running;  // pid -> command
  std::size_t next = 0;
  bool passed_on = false;  // SIGTERM sent to the children after an interrupt
  while (next < commands.size() || !running.empty()) {
    while (!interrupt_exit_code() && next < commands.size() && static_cast<int>(running.size()) < jobs) {
      const pid_t pid = spawn(commands[next]);
      if (pid < 0) {
        std::cerr << "error: fork: " << std::strerror(errno) << '\n';
        codes[next++] = exit_io;
        continue;
      }
      running[pid] = next++;
    }
    if (running.empty()) break;
    if (interrupt_exit_code() && !passed_on) {
      for (const auto& [pid, k] : running) kill(pid, SIGTERM);
      passed_on = true;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);  // a signal interrupts it (EINTR): loop
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;  // ECHILD: nothing left to wait for
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    codes[it->second] = exit_code_of(status);
    running.erase(it);
  }
  return codes;
}

}  // namespace elbowsim
