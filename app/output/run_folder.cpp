#include "app/output/run_folder.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "app/output/run_manifest.hpp"
#include "app/output/trajectory_csv.hpp"
#include "app/scenario/scenario.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/step_grid.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim {

namespace {

namespace fs = std::filesystem;
using Rows = std::vector<std::pair<std::string, std::string>>;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// events.csv rows: time, contact (elbow), kind, speed, impulse, energy_lost.
std::vector<report::EventRow> read_events(const fs::path& path) {
  std::ifstream in(path);
  std::vector<report::EventRow> rows;
  std::string line;
  std::getline(in, line);  // header
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::stringstream cells(line);
    std::string t, elbow, kind, speed, impulse, lost;
    std::getline(cells, t, ','), std::getline(cells, elbow, ','), std::getline(cells, kind, ',');
    std::getline(cells, speed, ','), std::getline(cells, impulse, ','), std::getline(cells, lost);
    try {
      rows.push_back(
          {std::stod(t), elbow, kind, std::stod(speed), std::stod(impulse), std::stod(lost)});
    } catch (const std::exception&) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) +
                               ": malformed event row");
    }
  }
  return rows;
}

std::string links_text(const Model& m) {
  std::string text;
  for (const Link& link : m.links)
    text += (text.empty() ? "" : "; ") + significant(link.tip.norm(), 4) + " m, " +
            significant(link.mass, 4) + " kg";
  return text;
}

std::string motor_text(const Motor& motor) {
  return "R " + significant(motor.resistance, 4) + " ohm, L " + significant(motor.inductance, 4) +
         " H, K " + significant(motor.torque_constant, 4) + " N m/A, gear " +
         significant(motor.gear_ratio, 4) + ":1, limit " + significant(motor.voltage_limit, 4) +
         " V";
}

std::string motors_text(const Model& m) {
  bool same = true;
  for (const Motor& motor : m.motors) same = same && motor_text(motor) == motor_text(m.motors[0]);
  if (same && !m.motors.empty()) return "each joint: " + motor_text(m.motors[0]);
  std::string text;
  for (std::size_t j = 0; j < m.motors.size(); ++j)
    text += (j ? "; " : "") + std::string("joint ") + std::to_string(j) + ": " +
            motor_text(m.motors[j]);
  return text;
}

std::string contact_text(const Model& m) {
  std::string text;
  for (const Elbow& e : m.elbows)
    text += (text.empty() ? "" : "; ") + e.name + " on link " + std::to_string(e.link) +
            ", radius " + significant(e.radius, 4) + " m";
  text += "; table of " + std::to_string(m.table.size()) + " box(es); restitution " +
          significant(m.contact.restitution, 4);
  if (m.effects.friction)
    text += std::string(", ") + to_string(m.contact.friction.law) + " friction mu " +
            significant(m.contact.friction.mu, 4);
  else
    text += ", no friction";
  if (m.effects.stabilization == Stabilization::baumgarte)
    text += ", Baumgarte time " + significant(m.contact.baumgarte_time, 4) + " s";
  return text;
}

// The model in a few rows, rebuilt from the scenario as run.
Rows model_rows(const Model& m) {
  Rows rows{{"links (length, mass)", links_text(m)}};
  if (m.has_motor()) rows.push_back({"motors", motors_text(m)});
  rows.push_back(
      {"gravity", '(' + listed({m.gravity.x(), m.gravity.y(), m.gravity.z()}, 4) + ") m/s^2"});
  if (m.effects.contact)
    rows.push_back({"elbows and table", contact_text(m)});
  else if (!m.table.empty())
    rows.push_back({"table", "ignored: effects.contact is off, so links pass through it (an "
                             "approximation; a run with a link inside a box is not valid)"});
  return rows;
}

void read_scenario(const fs::path& file, report::RunData& run) {
  run.scenario_yaml = slurp(file);
  try {
    run.model_rows = model_rows(load_scenario_text(run.scenario_yaml, file.string()).model);
  } catch (const std::exception& e) {
    run.problems.push_back("scenario.yaml: the model could not be rebuilt: " +
                           std::string(e.what()));
  }
}

}  // namespace

report::RunData load_run_folder(const fs::path& folder) {
  if (!fs::is_directory(folder)) throw NotARunFolder(folder.string() + ": no such folder");
  report::RunData run;
  run.folder = folder;
  run.label = fs::weakly_canonical(fs::absolute(folder)).filename().string();
  const fs::path summary = folder / "summary.json", trajectory = folder / "trajectory.csv";
  if (!fs::exists(summary) && !fs::exists(trajectory))
    throw NotARunFolder(folder.string() +
                        ": not a run folder (no summary.json, no trajectory.csv)");
  // Each file on its own: one that cannot be read is a problem shown in the report.
  const auto attempt = [&](const fs::path& file, auto&& read) {
    if (!fs::exists(file))
      return run.problems.push_back(file.filename().string() + ": not in the run folder");
    try {
      read();
    } catch (const std::exception& e) {
      run.problems.push_back(file.filename().string() + ": " + e.what());
    }
  };
  attempt(summary, [&] { run.summary = nlohmann::ordered_json::parse(slurp(summary)); });
  attempt(trajectory, [&] {
    std::ifstream in(trajectory);
    run.trajectory = read_trajectory_csv(in, trajectory.string());
  });
  if (fs::exists(folder / "events.csv"))
    attempt(folder / "events.csv", [&] { run.events = read_events(folder / "events.csv"); });
  attempt(folder / "scenario.yaml", [&] { read_scenario(folder / "scenario.yaml", run); });
  // Only what the run that wrote the folder made: a video left by an earlier
  // run (or put there by hand) is not this run's (run_manifest.hpp).
  std::optional<std::vector<std::string>> manifest;
  try {
    manifest = read_manifest(folder);
  } catch (const std::exception& e) {
    run.problems.push_back(std::string(kManifestFile) + ": " + e.what());
    manifest = std::vector<std::string>{};
  }
  for (const char* name :
       {"trajectory.csv", "summary.json", "events.csv", "scenario.yaml", "video.mp4"})
    if (written_by_run(manifest, folder, name)) run.files.push_back(name);
  if (manifest) run.files.push_back(kManifestFile);
  run.has_video = written_by_run(manifest, folder, "video.mp4");
  if (const std::string why = inconsistency(run); !why.empty())
    throw InconsistentRunFolder(folder.string() + ": " + why);
  return run;
}

std::string inconsistency(const report::RunData& run) {
  // A file that is there but cannot be read was cut or damaged.
  for (const std::string& problem : run.problems)
    for (const char* file : {"summary.json: ", "trajectory.csv: ", "events.csv: "})
      if (problem.starts_with(file) && problem.find("not in the run folder") == std::string::npos)
        return problem;
  if (!run.has_summary() || !run.has_trajectory()) return "";
  // The same run wrote both: the last recorded row is the run's last state
  // (or, for a run that stopped early, no later than it).
  const double final_time = run.summary.value(summary_key::final_time.name(), 0.0);
  const double last = run.trajectory.at(run.trajectory.rows() - 1, 0);
  const double tolerance = step_grid::recorded_time_tolerance(final_time);
  const bool completed = run.summary.value(summary_key::completed.name(), false);
  if (last > final_time + tolerance || (completed && last < final_time - tolerance))
    return "trajectory.csv ends at t = " + significant(last, 4) +
           " s but summary.json says the run " + (completed ? "completed at" : "stopped at") +
           " t = " + significant(final_time, 4) +
           " s: the files are from different runs, or one of them was cut";
  return "";
}

}  // namespace elbowsim
