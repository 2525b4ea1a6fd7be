// SIGINT and SIGTERM during a run: the handler only raises a flag; the
// simulation loop reads it between steps (RunOptions::stop) and stops as
// interrupted, and the command writes what was recorded, starts nothing
// more and exits with 128 + the signal (130 for Ctrl-C, 143 for SIGTERM).
#pragma once

#include <atomic>

namespace elbowsim {

// Installs the handlers (once; later calls do nothing).
void install_interrupt_handlers();

// The flag the handlers raise (for RunOptions::stop).
const std::atomic<bool>& interrupt_flag();

// 0 before any signal; else the exit code for it: 128 + the signal number.
int interrupt_exit_code();

}  // namespace elbowsim
