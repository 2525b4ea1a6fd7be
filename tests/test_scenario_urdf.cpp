// robot.urdf: a URDF arm against the same arm in the YAML general form, fixed
// links merged against the same links on a joint held at zero, the run
// folder's standalone scenario.yaml, and bad URDFs (exit 2 naming the file and
// the element).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/run/simulator.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

const std::string kSource = ELBOWSIM_SOURCE_DIR;

// |a - b| <= 1e-12 max(1, |a|), entry by entry: the largest violation (0: none).
double worst(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  REQUIRE(a.rows() == b.rows());
  REQUIRE(a.cols() == b.cols());
  double out = 0;
  for (Eigen::Index k = 0; k < a.size(); ++k)
    out = std::max(out, std::abs(a.data()[k] - b.data()[k]) / std::max(1.0, std::abs(a.data()[k])));
  return out;
}

// M(q) and the RNEA torques at a state, on `model`.
struct Dynamics {
  Eigen::MatrixXd M;
  Eigen::VectorXd tau;
};
Dynamics dynamics(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                  const Eigen::VectorXd& qdd) {
  Data data(model);
  forward_kinematics(model, data, q);
  mass_matrix_crba(model, data);
  Dynamics out{data.mass_matrix, Eigen::VectorXd(model.dof)};
  inverse_dynamics(model, data, qd, qdd, {}, out.tau);
  return out;
}

// panda_writes.yaml with its robot: block replaced by tests/urdf/panda_joints.yaml's
// and its elbow on link 3 by index.
std::string panda_twin_text() {
  std::string text = slurp(kSource + "/scenarios/arms/panda_writes.yaml");
  const std::string robot = slurp(kSource + "/tests/urdf/panda_joints.yaml");
  const std::size_t from = text.find("\nrobot:\n"), to = text.find("\nmotors:\n");
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  text.replace(from, to - from, '\n' + robot.substr(robot.find("robot:\n")));
  const std::string named = "link: panda_link4";
  REQUIRE(text.find(named) != std::string::npos);
  text.replace(text.find(named), named.size(), "link: 3");
  return text;
}

}  // namespace

TEST_CASE("urdf: the Panda-like URDF and the same arm in the general form give the same M, RNEA "
          "and 1 s trajectory (1e-12)") {
  const std::string file = kSource + "/scenarios/arms/panda_writes.yaml";
  const Scenario urdf = load_scenario(file, {"simulation.duration=1"});
  const Scenario typed = load_scenario_text(panda_twin_text(), file, {"simulation.duration=1"});
  REQUIRE(urdf.model.dof == 7);
  REQUIRE(typed.model.dof == 7);
  CHECK(urdf.chain.links[6] == "panda_link7");
  CHECK(urdf.chain.merged[6] == std::vector<std::string>{"panda_link8", "pen", "pen_tip"});
  CHECK(worst(urdf.model.hand_point, typed.model.hand_point) <= 1e-12);
  CHECK(worst(urdf.model.elbows[0].point, typed.model.elbows[0].point) <= 1e-12);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  double M = 0, tau = 0;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q(7), qd(7), qdd(7);
    for (int j = 0; j < 7; ++j) q[j] = u(rng), qd[j] = u(rng), qdd[j] = u(rng);
    const Dynamics a = dynamics(urdf.model, q, qd, qdd), b = dynamics(typed.model, q, qd, qdd);
    M = std::max(M, worst(a.M, b.M));
    tau = std::max(tau, worst(a.tau, b.tau));
  }
  MESSAGE("largest relative differences: M " << M << ", RNEA " << tau);
  CHECK(M <= 1e-12);
  CHECK(tau <= 1e-12);

  const RunResult ra = simulate(urdf.model, urdf.experiment, RunOptions{1, {}});
  const RunResult rb = simulate(typed.model, typed.experiment, RunOptions{1, {}});
  REQUIRE(ra.valid);
  REQUIRE(rb.valid);
  REQUIRE(ra.trajectory.columns().size() == rb.trajectory.columns().size());
  for (std::size_t c = 0; c < ra.trajectory.columns().size(); ++c)
    CHECK(ra.trajectory.columns()[c].name == rb.trajectory.columns()[c].name);
  REQUIRE(ra.trajectory.rows() == rb.trajectory.rows());
  CHECK(ra.trajectory.rows() == 1001);
  double trajectory = 0;
  std::string where;
  for (std::size_t c = 0; c < ra.trajectory.columns().size(); ++c)
    for (std::size_t r = 0; r < ra.trajectory.rows(); ++r) {
      const double x = ra.trajectory.at(r, c), y = rb.trajectory.at(r, c);
      const double d = std::abs(x - y) / std::max(1.0, std::abs(x));
      if (d > trajectory)
        trajectory = d, where = ra.trajectory.columns()[c].name + " at row " + std::to_string(r);
    }
  MESSAGE("largest relative difference over the 1 s trajectory: " << trajectory << " (" << where
                                                                    << ")");
  CHECK(trajectory <= 1e-12);
}

namespace {

// Two revolute joints (about y) with a rigid body between them made of two
// links; `middle` is the joint that holds them together ("fixed", or
// "revolute" held at q = 0).
std::string two_bodies(const std::string& middle) {
  return R"(<robot name="merge">
  <link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/>
    <axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <link name="a"><inertial><origin xyz="0.1 0 0.01" rpy="0.2 0 0"/><mass value="1.0"/>
    <inertia ixx="0.001" ixy="0.0001" ixz="0" iyy="0.004" iyz="0" izz="0.0045"/></inertial></link>
  <joint name="jm" type=")" + middle + R"("><parent link="a"/><child link="b"/>
    <origin xyz="0.2 0.01 0" rpy="0.1 -0.2 0.3"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <link name="b"><inertial><origin xyz="0.05 0.01 0.02" rpy="0 0.4 0"/><mass value="0.5"/>
    <inertia ixx="0.0005" ixy="0" ixz="0.00005" iyy="0.001" iyz="0" izz="0.0012"/></inertial></link>
  <joint name="j2" type="revolute"><parent link="b"/><child link="c"/>
    <origin xyz="0.15 0 0"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <link name="c"><inertial><origin xyz="0.1 0 0"/><mass value="0.3"/>
    <inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
</robot>)";
}

// A scenario whose robot.urdf is the URDF text itself.
Scenario inline_urdf(const std::string& xml) {
  std::string indented;
  for (const char c : xml) indented += c == '\n' ? std::string("\n    ") : std::string(1, c);
  return load_scenario_text("name: merge\nrobot:\n  urdf: |\n    " + indented +
                                "\neffects: {motor: none}\nsimulation: {duration: 0.01}\n",
                            "merge.yaml");
}

}  // namespace

TEST_CASE("urdf: links on a fixed joint are merged: M and G equal the same links on a joint held "
          "at zero") {
  const Scenario merged = inline_urdf(two_bodies("fixed"));
  const Scenario jointed = inline_urdf(two_bodies("revolute"));
  REQUIRE(merged.model.dof == 2);
  REQUIRE(jointed.model.dof == 3);
  CHECK(merged.model.links[0].mass == doctest::Approx(1.5).epsilon(1e-15));
  CHECK(merged.chain.merged[0] == std::vector<std::string>{"b"});
  const std::vector<int> outer{0, 2};  // j1 and j2 of the jointed arm
  double M = 0, G = 0;
  for (const double q1 : {-0.7, 0.0, 1.1})
    for (const double q2 : {-1.3, 0.4}) {
      const Eigen::Vector2d q(q1, q2);
      const Eigen::Vector3d q3(q1, 0.0, q2), zero3 = Eigen::Vector3d::Zero();
      const Dynamics a = dynamics(merged.model, q, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero());
      const Dynamics b = dynamics(jointed.model, q3, zero3, zero3);
      Eigen::Matrix2d Mb;
      Eigen::Vector2d Gb;
      for (int r = 0; r < 2; ++r) {
        Gb[r] = b.tau[outer[r]];
        for (int c = 0; c < 2; ++c) Mb(r, c) = b.M(outer[r], outer[c]);
      }
      M = std::max(M, worst(a.M, Mb));
      G = std::max(G, worst(a.tau, Gb));
    }
  CHECK(M <= 1e-12);
  CHECK(G <= 1e-12);
}

TEST_CASE("urdf: a scenario's resolved YAML carries the URDF and rebuilds the same model "
          "anywhere") {
  const Scenario s = load_scenario(kSource + "/scenarios/arms/open_manipulator_x_writes.yaml");
  CHECK(s.resolved_yaml.find("urdf: open_manipulator_x.urdf") == std::string::npos);
  CHECK(s.resolved_yaml.find("<robot name=") != std::string::npos);
  const Scenario again = load_scenario_text(s.resolved_yaml, "/nonexistent/folder/scenario.yaml");
  CHECK(again.chain.urdf == "the inline URDF");
  REQUIRE(again.model.dof == 4);
  const Eigen::VectorXd q = Eigen::Vector4d(0.1, 0.9, -1.2, 0.8);
  const Eigen::VectorXd qd = Eigen::Vector4d(0.3, -0.2, 0.5, 1.0);
  const Dynamics a = dynamics(s.model, q, qd, qd), b = dynamics(again.model, q, qd, qd);
  CHECK(worst(a.M, b.M) == 0);
  CHECK(worst(a.tau, b.tau) == 0);
  CHECK(s.model.elbows[0].link == 2);  // elbow on link4, the third moving link
  CHECK(s.experiment.task.q_min.size() == 4);  // the URDF's limits bound the plan
  CHECK(s.experiment.task.q_max[2] == 1.4);
}

namespace {

// A 2-joint arm; elbows name its links.
const std::string kArm = R"(<robot name="arm">
  <link name="base"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="upper"><inertial><origin xyz="0.1 0 0"/><mass value="1.0"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.004" iyz="0" izz="0.004"/></inertial>
    <collision><origin xyz="0.1 0 0" rpy="0 1.5707963267948966 0"/>
      <geometry><cylinder radius="0.02" length="0.2"/></geometry></collision></link>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="forearm"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="forearm"><inertial><origin xyz="0.1 0 0"/><mass value="0.5"/>
    <inertia ixx="0.0005" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/></inertial></link>
  <joint name="hand_joint" type="fixed"><parent link="forearm"/><child link="hand"/>
    <origin xyz="0.2 0 0"/></joint>
  <link name="hand"/>
</robot>
)";

const std::string kScenario = R"(name: urdf_arm
robot: {urdf: arm.urdf, base_link: base, tip_link: hand}
elbows: [{name: e, link: upper, point: [0.2, 0, 0]}]
simulation: {duration: 0.01}
)";

// `elbowsim validate` on kScenario with `urdf` as arm.urdf (and `scenario` as the scenario).
Outcome validate(const std::string& name, const std::string& urdf,
                 const std::string& scenario = kScenario) {
  const auto dir = scratch("urdf", name);
  write_file(dir / "arm.urdf", urdf);
  write_file(dir / "arm.yaml", scenario);
  return run_elbowsim("validate " + (dir / "arm.yaml").string());
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("urdf: validate prints the chain of a good URDF") {
  const Outcome r = validate("good", kArm);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("chain      arm.urdf: base link base, tip link hand") != std::string::npos);
  CHECK(r.output.find("shoulder, axis (0, 1, 0), moves upper, 1 kg, limits [-2, 2] rad") !=
        std::string::npos);
  CHECK(r.output.find("elbow, axis (0, 1, 0), moves forearm (with hand), 0.5 kg") !=
        std::string::npos);
  CHECK(r.output.find("elbow      e (link 0 upper") != std::string::npos);
}

TEST_CASE("urdf: a joint spring names its joint by the URDF's name or by index") {
  const std::string file = kSource + "/scenarios/arms/open_manipulator_x_writes.yaml";
  const Scenario named = load_scenario(file, {"springs=[{joint: joint2, torque: 0.5}]"});
  REQUIRE(named.model.springs.size() == 1);
  CHECK(named.model.springs[0].joint == 1);
  CHECK(load_scenario(file, {"springs=[{joint: 1, torque: 0.5}]"}).model.springs[0].joint == 1);
  try {
    load_scenario(file, {"springs=[{joint: joint9, torque: 0.5}]"});
    FAIL("joint9 loaded");
  } catch (const ScenarioError& e) {
    CHECK(std::string(e.what()).find("springs[0].joint: names no joint of the arm (its joints: joint1, joint2") !=
          std::string::npos);
  }
}

TEST_CASE("urdf: bad URDFs exit 2 naming the URDF file and the element") {
  struct Case {
    std::string name;
    std::string urdf, scenario;
    std::vector<std::string> expected;
  };
  const std::string no_inertial = R"(<link name="forearm"><inertial><origin xyz="0.1 0 0"/><mass value="0.5"/>
    <inertia ixx="0.0005" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/></inertial></link>)";
  const std::vector<Case> cases{
      {"missing_inertial", replaced(kArm, no_inertial, R"(<link name="forearm"/>)"), kScenario,
       {"link \"forearm\": no <inertial>"}},
      {"zero_mass", replaced(kArm, R"(<mass value="1.0"/>)", R"(<mass value="0"/>)"), kScenario,
       {"link \"upper\": <inertial><mass value=\"0\"/> must be > 0"}},
      {"branching",
       replaced(kArm, "</robot>", R"(<joint name="thumb_joint" type="continuous">
    <parent link="upper"/><child link="thumb"/><axis xyz="0 0 1"/></joint>
  <link name="thumb"/></robot>)"),
       kScenario, {"branches at link \"upper\"", "\"elbow\"", "\"thumb_joint\""}},
      {"unknown_link", kArm, replaced(kScenario, "link: upper", "link: uper_arm"),
       {"elbows[0].link", "no link named \"uper_arm\" on the chain of arm.urdf"}},
      {"prismatic", replaced(kArm, R"(name="elbow" type="revolute")", R"(name="elbow" type="prismatic")"),
       kScenario, {"joint \"elbow\" is prismatic"}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const Outcome r = validate(c.name, c.urdf, c.scenario);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("arm.yaml:") != std::string::npos);  // the scenario, at its key
    CHECK(r.output.find("arm.urdf") != std::string::npos);   // the URDF file
    for (const std::string& e : c.expected) CHECK(r.output.find(e) != std::string::npos);
  }
}
