#include "app/commands/progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace elbowsim {

bool progress_on_terminal() { return isatty(STDERR_FILENO); }

std::function<void(double)> terminal_progress(const std::string& label) {
  if (!progress_on_terminal()) return {};
  const auto start = std::chrono::steady_clock::now();
  return [start, label](double fraction) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed < 1.0) return;
    std::fprintf(stderr, "\r  %s%5.1f %%  (%.1f s elapsed)", label.c_str(), 100.0 * fraction,
                 elapsed);
    if (fraction >= 1.0) std::fputc('\n', stderr);
  };
}

void end_progress_line() {
  if (progress_on_terminal()) std::fputc('\n', stderr);
}

}  // namespace elbowsim
