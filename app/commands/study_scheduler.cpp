// The files that hand a study's shards to a scheduler: a Slurm job array
// (submit.sh, one array task per shard, SLURM_ARRAY_TASK_ID picks it) and a
// Kubernetes Indexed Job (job.yaml, one completion per shard,
// JOB_COMPLETION_INDEX + 1 picks it). Each task is `elbowsim study ...
// --shard i/N` into the same folder, which must be shared by every node;
// `elbowsim merge DIR` then makes the table.
#include <algorithm>
#include <cctype>

#include "app/commands/study_plan.hpp"

namespace elbowsim {

namespace {

std::string join_quoted(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) {
    if (!out.empty()) out += ' ';
    out += shell_quote(w);
  }
  return out;
}

// A Kubernetes object name: lower case letters, digits and '-', at most 63.
std::string k8s_name(const std::string& text) {
  std::string out = "elbowsim-";
  for (const char c : text) {
    const char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    out += std::isalnum(static_cast<unsigned char>(l)) ? l : '-';
  }
  out.resize(std::min<std::size_t>(out.size(), 52));
  while (out.back() == '-') out.pop_back();
  return out;
}

// A string as a YAML double-quoted scalar.
std::string yaml_quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string shell_quote(const std::string& word) {
  const bool safe = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string("/._-+=:,").find(c) != std::string::npos;
  });
  if (safe) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string slurm_script(const StudyPlan& plan, const std::vector<std::string>& command, int tasks) {
  const std::string n = std::to_string(tasks);
  const std::string log = (plan.folder / "slurm" / "%A_%a.out").string();
  std::string s;
  s += "#!/bin/bash\n";
  s += "# elbowsim study " + plan.design.name + ": " + std::to_string(plan.cases.size()) + " cases in " + n +
       " shards, one Slurm array task each.\n";
  s += "# Submit: sbatch " + (plan.folder / "submit.sh").string() + "\n";
  s += "# Then, when every task has ended: elbowsim merge " + plan.folder.string() + "\n";
  s += "# Every node must see the study's folder and files at these paths. A task\n";
  s += "# skips the cases already finished, so a resubmission redoes only the rest.\n";
  s += "#SBATCH --job-name=" + k8s_name(plan.design.name) + "\n";
  s += "#SBATCH --array=1-" + n + "\n";
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --cpus-per-task=1\n";
  s += "#SBATCH --output=" + log + "\n";
  s += "set -eu\n";
  s += "exec " + join_quoted(command) + " --shard \"${SLURM_ARRAY_TASK_ID}/" + n + "\"\n";
  return s;
}

std::string k8s_job(const StudyPlan& plan, const std::vector<std::string>& command, int tasks) {
  const std::string n = std::to_string(tasks);
  const std::string shell =
      "exec " + join_quoted(command) + " --shard \"$((JOB_COMPLETION_INDEX + 1))/" + n + "\"";
  std::string y;
  y += "# elbowsim study " + plan.design.name + ": " + std::to_string(plan.cases.size()) + " cases in " + n +
       " shards, one completion of an Indexed Job each.\n";
  y += "# Apply: kubectl apply -f job.yaml; then elbowsim merge " + plan.folder.string() + "\n";
  y += "# The image must hold elbowsim; the volume the working folder with the study's\n";
  y += "# files (paths below are relative to it), shared by every pod (ReadWriteMany).\n";
  y += "apiVersion: batch/v1\n";
  y += "kind: Job\n";
  y += "metadata:\n";
  y += "  name: " + k8s_name(plan.design.name) + "\n";
  y += "spec:\n";
  y += "  completionMode: Indexed\n";
  y += "  completions: " + n + "\n";
  y += "  parallelism: " + n + "\n";
  y += "  backoffLimitPerIndex: 1\n";
  y += "  maxFailedIndexes: " + n + "\n";
  y += "  template:\n";
  y += "    spec:\n";
  y += "      restartPolicy: Never\n";
  y += "      containers:\n";
  y += "        - name: study\n";
  y += "          image: elbowsim:latest\n";
  y += "          workingDir: /work\n";
  y += "          command: [\"/bin/sh\", \"-c\"]\n";
  y += "          args: [" + yaml_quoted(shell) + "]\n";
  y += "          resources:\n";
  y += "            requests: {cpu: \"1\", memory: 1Gi}\n";
  y += "          volumeMounts:\n";
  y += "            - {name: work, mountPath: /work}\n";
  y += "      volumes:\n";
  y += "        - name: work\n";
  y += "          persistentVolumeClaim: {claimName: elbowsim-work}\n";
  return y;
}

}  // namespace elbowsim
