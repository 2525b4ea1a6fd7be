// How far a long stage (simulating, rendering) has come, on stderr: on a
// terminal, one line rewritten in place once the stage has taken over a
// second; elsewhere (a log file, a pipe) nothing, so a log is not filled
// with it: such a stage says when it starts and ends instead.
#pragma once

#include <functional>
#include <string>

namespace elbowsim {

// Whether stderr is a terminal (where the progress lines go).
bool progress_on_terminal();

// Empty when stderr is not a terminal; else a function taking the share
// done (0 .. 1) that prints "\r  <label>45.0 %  (3.2 s elapsed)" and ends
// the line at 1.
std::function<void(double)> terminal_progress(const std::string& label = "");

// Ends a progress line a stage left unfinished (stopped by a signal) before
// a message follows: a line break on a terminal, else nothing.
void end_progress_line();

}  // namespace elbowsim
