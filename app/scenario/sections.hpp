// One reader per top-level section of a scenario file. Each validates what it
// reads and fails at the offending node (see yaml_reader.hpp). The order the
// loader calls them in matters: robot first (it sets dof), effects before
// motors and inputs (which depend on the motor model), elbows after the robot
// (they name its links).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"
#include "app/scenario/yaml_reader.hpp"
#include "engine/control/experiment.hpp"
#include "engine/model.hpp"

namespace elbowsim::loader {

// The robot as read: which form, and for robot.urdf the file's text and the
// names of its links.
struct RobotInfo {
  enum class Form { planar, joints, urdf };
  Form form = Form::joints;
  ChainNames names;       // robot.urdf only
  std::string urdf_text;  // robot.urdf only: the URDF as read
  // Every link of the chain by name: on engine link `link` (-1: fixed to the
  // base), its frame's pose in that link's frame.
  struct Frame {
    int link = -1;
    Eigen::Isometry3d to_link = Eigen::Isometry3d::Identity();
  };
  std::map<std::string, Frame> frames;
};

// robot: base, planar | joints | urdf, damping, hand. Sets dof, base, joints,
// links, damping and the hand of `model`. `scenario_file` is the path URDF
// paths are relative to.
RobotInfo read_robot(const Value& robot, Model& model, const std::string& scenario_file);

// robot.planar / robot.joints: appends joints and links to `model`.
void read_planar_chain(const Value& planar, Model& model);
void read_general_chain(const Value& joints, Model& model);
// robot.urdf (+ base_link, tip_link): appends the URDF's chain to `model` and
// sets model.damping (the URDF's) and the hand (the tip link's origin).
RobotInfo read_urdf_chain(const Value& robot, Model& model, const std::string& scenario_file);
// A link named in the scenario (an elbow's or the hand's `link`): an index
// (negative counts from the end), or with robot.urdf a link name. Returns the
// engine link and the named frame's pose in it (identity for an index).
RobotInfo::Frame read_link_frame(const Value& v, const Model& model, const RobotInfo& robot);

// motors (optional): one Motor per joint. Needs model.dof and model.effects.
std::vector<Motor> read_motors(const Value& motors, const Model& model);

Effects read_effects(const Value& effects);                                // optional
Options read_simulation(const Value& simulation, const Value& task);  // required
// simulation.integrator is auto (given so, or absent): the loader chooses it
// once the model is finalized (run/integrator_choice.hpp).
bool auto_integrator(const Value& simulation);
// rtol, atol and max_step refused unless options.integrator is adaptive.
void check_error_control(const Value& simulation, const Options& options);
Model::InitialState read_initial(const Value& initial, int dof);           // optional
OpenLoopInputs read_inputs(const Value& inputs, const Model& model);       // optional
OutputSettings read_output(const Value& output, const std::string& name);  // optional
RenderSettings read_render(const Value& render);                           // optional

// elbows (optional list): spheres on the links. Needs model.dof and
// model.links; robot.planar is the only form that allows `at` (distance along
// the link), robot.urdf the only one whose links have names.
// `default_pad`: contact.pad, the pad of every elbow that gives none of its own.
std::vector<Elbow> read_elbows(const Value& elbows, const Value& default_pad, const Model& model,
                               const RobotInfo& robot);
std::vector<TableBox> read_table(const Value& table);  // optional; boxes: one or more
ContactOptions read_contact(const Value& contact);     // optional; defaults: ContactOptions
ValidityOptions read_validity(const Value& validity);  // optional; defaults: ValidityOptions
WarningOptions read_warnings(const Value& warnings);  // optional; defaults: WarningOptions
// springs: the joint springs (optional; none when absent or null).
std::vector<JointSpring> read_springs(const Value& springs, const Model& model, const RobotInfo& robot);
// joint_friction (with effects.joint_friction): one JointFriction per joint.
std::vector<JointFriction> read_joint_friction(const Value& section, const Value& effect, int dof);
// effects.contact: true needs a non-empty elbows list and a table. Call after
// model.effects and model.elbows are read.
void check_contact_scene(const Value& root, const Model& model);
// After finalize(): no elbow or link starts deeper in the table than
// allowed, at joint angles q [rad], the pose the run starts from (`pose`
// names it in the message: "the initial pose", "the task's first pose").
void check_initial_penetration(const Value& root, const Model& model, const Eigen::VectorXd& q,
                               const std::string& pose);

// task, controller, hand_load (optional): the paper's experiment. Call after
// model.elbows, model.table and model.initial are read; read_controller after
// the task. Controller gains are expanded to one per joint.
HandTask read_task(const Value& task, const Model& model);
ControllerSpec read_controller(const Value& controller, const Model& model, const HandTask& task);
HandLoad read_hand_load(const Value& hand_load);
// controller.sample_rate, delay, pwm_bits, sensors: the digital loop (default:
// continuous control). `step` is simulation.step: the period may not be shorter.
DigitalLoopSpec read_digital_loop(const Value& controller, double step);

// variants (optional): name -> overrides "key.path=value", in file order, each
// with where it was written (for errors found when the variant is loaded).
struct VariantSpec {
  struct Entry {
    std::string text;       // "key.path=yaml value", as for --set
    Source::Origin origin;  // the entry's key in the file
  };
  std::string name;
  std::vector<Entry> overrides;
};
std::vector<VariantSpec> read_variants(const Value& variants);

// study (optional): axes of named levels, each level a set of overrides like a
// variant's; a study case takes one level of every axis (elbowsim montecarlo).
struct StudyAxisSpec {
  std::string name;
  std::vector<VariantSpec> levels;
};
std::vector<StudyAxisSpec> read_study(const Value& study);

// The named override sets of a scenario: its variants and its study's levels.
struct OverrideSets {
  std::vector<VariantSpec> variants;
  std::vector<StudyAxisSpec> axes;
};

// uncertainty (optional): the plant parameters a Monte Carlo study draws,
// expanded ("[*]") and with their nominal values looked up in `root` (the
// scenario as loaded: after variants and --set).
Uncertainty read_uncertainty(const Value& uncertainty, const YAML::Node& root);

// controller.model (optional): what the controller believes where it differs
// from the plant, as overrides "key.path=value" of robot, motors, gravity,
// hand_load, elbows or table keys (the loader reads them into a second model).
std::vector<VariantSpec::Entry> read_controller_model(const Value& model);

}  // namespace elbowsim::loader
