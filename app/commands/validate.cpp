#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/commands/commands.hpp"
#include "app/scenario/scenario.hpp"
#include "app/study/cases.hpp"
#include "engine/contact/geometry.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/dynamics/springs.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/step.hpp"
#include "engine/run/step_log.hpp"
#include "engine/run/warnings.hpp"

namespace elbowsim {

namespace {

void print_model(const Scenario& s) {
  const Model& m = s.model;
  double total = 0;
  for (const Link& link : m.links) total += link.mass;
  std::cout << "scenario   " << m.name << " (" << s.file << ")\n";
  if (!s.description.empty()) std::cout << "           " << s.description << '\n';
  std::cout << "dof        " << m.dof << '\n' << "masses     ";
  for (const Link& link : m.links) std::cout << link.mass << ' ';
  std::cout << "kg (total " << total << " kg)\n" << "effects    ";
  for (const std::string& e : m.active_effects()) std::cout << e << ' ';
  if (m.active_effects().empty()) std::cout << "(none)";
  std::cout << '\n';
  if (m.has_motor()) {
    std::cout << "motors     Km ";
    for (int j = 0; j < m.dof; ++j) std::cout << m.km[j] << ' ';
    std::cout << "N m/A, Jm ";
    for (int j = 0; j < m.dof; ++j) std::cout << m.armature[j] << ' ';
    std::cout << "kg m^2\n";
  }
  std::cout << "simulation " << m.options.duration << " s, step " << m.options.step << " s, "
            << to_string(m.options.integrator) << ", " << to_string(m.options.dynamics) << '\n'
            << "output     " << s.output.folder << '\n';
  const ControllerSpec gains = gains_before_run(m, s.experiment);  // a rule's, as the run has them
  for (const std::string& w : model_warnings(m, &gains))
    std::cout << "note       " << w << '\n';
}

// "0, 1 and 3".
std::string joint_list(const std::vector<int>& joints) {
  std::string out;
  for (std::size_t k = 0; k < joints.size(); ++k)
    out += (k == 0 ? "" : k + 1 == joints.size() ? " and " : ", ") + std::to_string(joints[k]);
  return out;
}

// What the scenario left to defaults that a newcomer should know: the
// integrator auto chose, the built-in motors and the motors without a rating.
void print_defaults(const Scenario& s) {
  const Model& m = s.model;
  if (!m.options.integrator_reason.empty())
    std::cout << "integrator auto chose " << to_string(m.options.integrator) << ": "
              << m.options.integrator_reason << '\n';
  if (!m.has_motor()) return;
  std::vector<int> builtin, unrated;
  for (int j = 0; j < m.dof; ++j) {
    const Motor& motor = m.motors[static_cast<std::size_t>(j)];
    if (motor.builtin) builtin.push_back(j);
    if (!std::isfinite(motor.rated_current)) unrated.push_back(j);
  }
  if (!builtin.empty())
    std::cout << "note       joint" << (builtin.size() > 1 ? "s " : " ") << joint_list(builtin)
              << " run the built-in motor (motors: none of resistance, inductance, "
                 "torque_constant, gear_ratio, rotor_inertia given): a 24 V brushed DC motor of "
                 "the 20 W class behind 100:1, rated "
              << kBuiltinRatedCurrent
              << " A (scenarios/README.md, motors); give motors: for the arm's own\n";
  if (!unrated.empty())
    std::cout << "note       motor" << (unrated.size() > 1 ? "s " : " ") << joint_list(unrated)
              << (unrated.size() > 1 ? " have" : " has")
              << " no rated_current: a run cannot warn when "
              << (unrated.size() > 1 ? "they" : "it") << " would overheat\n";
}

// The chain, joint by joint: name (a URDF's), axis (its link's frame), the
// link it moves and that link's mass (with the fixed links merged into it),
// and the URDF's limits.
void print_chain(const Scenario& s) {
  const Model& m = s.model;
  const ChainNames& c = s.chain;
  if (!c.urdf.empty())
    std::cout << "chain      " << c.urdf << ": base link " << c.base_link << ", tip link "
              << c.tip_link << " (the hand)\n";
  for (int j = 0; j < m.dof; ++j) {
    const std::size_t i = static_cast<std::size_t>(j);
    const Eigen::Vector3d& a = m.joints[i].axis;
    char line[160];
    std::snprintf(line, sizeof line, "joint %-4d %s axis (%.3g, %.3g, %.3g), moves ", j,
                  c.joints.empty() ? "" : (c.joints[i] + ",").c_str(), a.x(), a.y(), a.z());
    std::cout << line << (c.links.empty() ? "link " + std::to_string(j) : c.links[i]);
    if (!c.merged.empty() && !c.merged[i].empty()) {
      std::cout << " (with";
      for (const std::string& name : c.merged[i]) std::cout << ' ' << name;
      std::cout << ')';
    }
    std::cout << ", " << m.links[i].mass << " kg";
    if (c.q_min.size() == m.dof && std::isfinite(c.q_min[j]))
      std::cout << ", limits [" << c.q_min[j] << ", " << c.q_max[j] << "] rad";
    std::cout << '\n';
  }
  for (const std::string& note : c.notes) std::cout << "note       " << note << '\n';
}

// Where an elbow sphere of `radius` centred at `centre` is against the table:
// on it, above, into it (mm) or beside it, naming the nearest box.
std::string place_against_table(const Eigen::Vector3d& centre, double radius,
                                const std::vector<TableBox>& table) {
  if (table.empty()) return "no table";
  int nearest = 0;
  BoxContact best = sphere_box(centre, radius, table[0]);
  for (std::size_t b = 1; b < table.size(); ++b) {
    const BoxContact c = sphere_box(centre, radius, table[b]);
    if (c.distance < best.distance) best = c, nearest = int(b);
  }
  const std::string box = "box " + std::to_string(nearest);
  const bool over = best.feature == BoxFeature::face && best.normal.z() > 0.5;
  char text[160];
  if (std::abs(best.distance) <= 1e-6)
    std::snprintf(text, sizeof text, "on the table (%s, gap %.2g m)", box.c_str(), best.distance);
  else if (best.distance < 0)
    std::snprintf(text, sizeof text, "%.3g mm into %s", -1e3 * best.distance, box.c_str());
  else
    std::snprintf(text, sizeof text, "%.3g mm %s %s", 1e3 * best.distance,
                  over ? "above" : "from", box.c_str());
  return text;
}

// The pose the run starts from, the task's first pose (solved as the run
// solves it) or initial.q, and its name; false (after printing why under
// `heading`) when the task's first pose cannot be solved.
bool pose_of_start(const Scenario& s, const char* heading, const std::string& label,
                   Eigen::VectorXd& q, std::string& pose) {
  const Model& m = s.model;
  q = m.initial.q.size() == m.dof ? m.initial.q : Eigen::VectorXd::Zero(m.dof);
  pose = "initial.q";
  if (!s.experiment.needs_plan()) return true;
  try {
    q = start_pose(m, s.experiment);
    pose = "the task's first pose";
    return true;
  } catch (const PlanError& e) {
    std::cout << heading << label << "the task's first pose: " << e.what() << '\n';
    return false;
  }
}

// Each elbow at the pose the run starts from.
void print_elbows(const Scenario& s, const std::string& label) {
  const Model& m = s.model;
  if (m.elbows.empty()) return;
  Eigen::VectorXd q;
  std::string pose;
  if (!pose_of_start(s, "elbows     ", label, q, pose)) return;
  Data data(m);
  forward_kinematics(m, data, q);
  for (const Elbow& e : m.elbows) {
    const Eigen::Vector3d c = point_position(data, e.link, e.point);
    char centre[96];
    std::snprintf(centre, sizeof centre, "(%.4g, %.4g, %.4g) m", c.x(), c.y(), c.z());
    const std::string link_name =
        s.chain.links.empty() ? "" : " " + s.chain.links[static_cast<std::size_t>(e.link)];
    std::cout << "elbow      " << label << e.name << " (link " << e.link << link_name << ", r "
              << e.radius << " m";
    if (e.pad.on())
      std::cout << ", pad k " << e.pad.stiffness << " N/m, c " << e.pad.damping << " N s/m, "
                << e.pad.thickness << " m thick";
    std::cout << ") at " << pose << ": centre " << centre << ", "
              << place_against_table(c, e.radius, m.table) << '\n';
  }
}

// Each joint spring at the pose the run starts from, beside the torque the
// joint needs there to hold the arm against gravity (what a counterbalance
// would take over; the hand load included).
void print_springs(const Scenario& s, const std::string& label) {
  const Model& m = s.model;
  if (!m.has_springs()) return;
  Eigen::VectorXd q;
  std::string pose;
  if (!pose_of_start(s, "springs    ", label, q, pose)) return;
  Data data(m);
  forward_kinematics(m, data, q);
  Eigen::VectorXd holding(m.dof);
  inverse_dynamics(m, data, data.zero, data.zero, {false, true, false, false}, holding);
  for (const JointSpring& spring : m.springs)
    std::cout << "spring     " << label << "joint " << spring.joint << ": "
              << significant(spring_torque(spring, q[spring.joint])) << " N m at " << pose
              << " (stiffness " << significant(spring.stiffness)
              << " N m/rad); gravity asks " << significant(holding[spring.joint])
              << " N m of the joint there\n";
}

// What the run does before its first step, done here: the plan (inverse
// kinematics over the whole task, and its feed-forward) and reset() at t = 0
// (the start state, the active set of resting elbows and its forces: a
// Painleve configuration or no contact solution stops a run there). Empty
// when all pass, else why the run would stop before it starts.
std::string start_of_run(const Scenario& s, std::shared_ptr<const Controller>& controller) {
  try {
    Data data(s.model);
    data.controller = controller = make_controller(s.model, s.experiment);
    reset(s.model, data);
    if (data.failure) return describe(s.model, data.failure);
  } catch (const PlanError& e) {
    return std::string("the hand task cannot be followed: ") + e.what();
  }
  return "";
}

// "(50, 50, 2.5)"
std::string vector_text(const Eigen::VectorXd& v) {
  std::string out = "(";
  for (int j = 0; j < v.size(); ++j) out += (j ? ", " : "") + significant(v[j], 4);
  return out + ")";
}

// The gains a tracking controller will run with, as given or as its tuning
// rule placed them (engine/control/tuning.hpp), and the rule's warnings.
void print_gains(const std::string& label, const Controller& c) {
  const ControllerSpec& spec = c.spec;
  if (spec.kind == ControllerSpec::Kind::open_loop) return;
  std::cout << "gains      " << label;
  if (spec.tuning.given())
    std::cout << "tuned at " << significant(spec.tuning.bandwidth) << " Hz, damping "
              << significant(spec.tuning.damping) << ", integral pole "
              << significant(spec.tuning.integral) << " x bandwidth, on I "
              << vector_text(c.tuning_inertia) << " kg m^2: ";
  std::cout << "Kp " << vector_text(spec.kp) << " V/rad, Kd " << vector_text(spec.kd) << " V s/rad";
  if (spec.integral()) std::cout << ", Ki " << vector_text(spec.ki) << " V/(rad s)";
  std::cout << (spec.tuning.given() ? "\n" : " (as given)\n");
  if (!c.integral_held.empty()) {
    std::cout << "gains      " << label << "no integral on joint" << (c.integral_held.size() > 1 ? "s" : "");
    for (std::size_t k = 0; k < c.integral_held.size(); ++k)
      std::cout << (k ? ", " : " ") << c.integral_held[k];
    std::cout << ": the resting elbows hold " << (c.integral_held.size() > 1 ? "them" : "it") << '\n';
  }
  for (const std::string& w : c.warnings) std::cout << "note       " << label << w << '\n';
}

// One line per run the scenario makes (each variant): its start passed, or the
// reason it would stop; false if any would.
bool check_starts(const std::string& file, const Scenario& s, const std::vector<std::string>& sets) {
  std::vector<std::pair<std::string, Scenario>> runs;
  if (s.variants.empty()) runs.emplace_back("", s);
  for (const auto& [variant, overrides] : s.variants)
    runs.emplace_back(variant + ": ", load_scenario_variant(file, variant, sets));
  bool ok = true;
  for (const auto& [label, run] : runs) {
    std::shared_ptr<const Controller> controller;
    const std::string why = start_of_run(run, controller);
    if (why.empty()) {
      if (controller) print_gains(label, *controller);
      std::cout << "start      " << label << "planned and reset at t = 0 as the run does: passes\n";
      continue;
    }
    std::cerr << "error: " << file << ": " << label << "the run would stop before its first step: "
              << why << '\n';
    ok = false;
  }
  return ok;
}

}  // namespace

int validate_command(const std::string& scenario, const std::vector<std::string>& sets) {
  try {
    const Scenario s = load_scenario(scenario, sets);
    print_model(s);
    print_defaults(s);
    print_chain(s);
    if (s.variants.empty()) print_elbows(s, ""), print_springs(s, "");
    for (const auto& [variant, overrides] : s.variants) {  // (the file alone is not run)
      const Scenario v = load_scenario_variant(scenario, variant, sets);
      print_elbows(v, variant + ": ");
      print_springs(v, variant + ": ");
    }
    if (!check_starts(scenario, s, sets)) return exit_bad_input;
    // Every case of the study, with every variant, as montecarlo loads them.
    const auto cases = study::study_cases(s);
    if (!s.study.empty()) {
      for (const study::StudyCase& c : cases) {
        load_scenario_case(scenario, c.levels, "", sets);
        for (const auto& [variant, overrides] : s.variants) load_scenario_case(scenario, c.levels, variant, sets);
      }
      std::cout << "study      " << counted(static_cast<long long>(cases.size()), "case") << " (";
      for (std::size_t a = 0; a < s.study.size(); ++a)
        std::cout << (a ? " x " : "") << s.study[a].levels.size() << " " << s.study[a].name;
      std::cout << "), each loaded\n";
    }
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace elbowsim
