// elbowsim study, inside: the study as planned (its design, cases and
// variants, where it writes), the run of one case in this process, the
// process pool of --jobs, and the scheduler files of --slurm and --k8s.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "app/scenario/study_file.hpp"
#include "app/study/study_cases.hpp"

namespace elbowsim {

struct StudyPlan {
  StudyDesign design;                   // with the command line's --set in design.sets
  std::vector<study::CaseSpec> cases;
  std::vector<std::string> variants;    // the scenario's variants; {""} without
  std::uint64_t seed = 0;               // of the draws (design.seed, else uncertainty.seed)
  std::filesystem::path folder;         // where the study writes
};

// Runs case `c` here into plan.folder/<c.folder>/: every variant's run
// (video and report only with `video`), then case.json. Returns exit_ok,
// exit_run_failed (a failure recorded in case.json), exit_io, or the
// interrupt's code (nothing recorded: the case is run again next time).
int run_study_case(const StudyPlan& plan, const study::CaseSpec& c, bool video);

// Runs each command as a child process, at most `jobs` at once; on SIGINT
// or SIGTERM starts no more and passes SIGTERM to those running. A child
// dies with this process (PR_SET_PDEATHSIG). Returns each one's exit code
// (-1: not started; 128 + n: killed by signal n).
std::vector<int> run_processes(const std::vector<std::vector<std::string>>& commands, int jobs);

// The path of this program (to start copies of it: --jobs, submit.sh).
std::filesystem::path self_executable();

// DIR/submit.sh: a Slurm job array of `tasks` shards of the study
// (SLURM_ARRAY_TASK_ID picks the shard); `command` is this study's command
// line without --shard, as absolute paths.
std::string slurm_script(const StudyPlan& plan, const std::vector<std::string>& command, int tasks);

// DIR/job.yaml: a Kubernetes Indexed Job of `tasks` completions
// (JOB_COMPLETION_INDEX + 1 is the shard); `command` as run in the
// container's working folder.
std::string k8s_job(const StudyPlan& plan, const std::vector<std::string>& command, int tasks);

// A word for a POSIX shell: as it is when it has only safe characters, else in single quotes.
std::string shell_quote(const std::string& word);

}  // namespace elbowsim
