// Scenario files: YAML text -> a validated, finalized elbowsim::Model (with its
// initial state) plus the run settings that are not physics (outputs).
// The schema is documented key by key in scenarios/README.md.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/control/experiment.hpp"
#include "engine/model.hpp"
#include "render/render_settings.hpp"

namespace elbowsim {

// The most joints a scenario's robot may have (robot.planar.links or robot.joints):
// a run's state holds dense dof x dof matrices, and the dynamics are O(dof^3).
inline constexpr int kMaxJoints = 256;

// What a run writes, and where.
struct OutputSettings {
  std::string folder = "runs/<scenario name>";  // default: "runs/" + model.name
  bool trajectory = true;                       // write trajectory.csv
  bool summary = true;                          // write summary.json
  int every = 1;                                // record every N-th step (>= 1)
  bool video = false;                           // render video.mp4 (render: section)
  bool frames = false;                          // render frames/frame_00001.png ...
  bool lossless_video = false;                  // video.mp4 lossless (x264 quantiser 0)
};

// uncertainty: the plant parameters a Monte Carlo study draws (elbowsim
// montecarlo); a single run uses the nominal values. One entry per concrete
// key ("links[*]" in the file is expanded to every link).
struct UncertainParameter {
  enum class Law {
    uniform,  // nominal x (1 + u), u uniform in [-spread, +spread]
    normal,   // nominal x (1 + spread z), z standard normal truncated at +-3
    range,    // uniform in [low, high], absolute (a payload, a table height)
  };
  std::string key;    // concrete key path, e.g. robot.planar.links[2].mass
  std::string given;  // as written in the file (may hold [*])
  Law law = Law::uniform;
  double spread = 0;         // uniform, normal: relative
  double low = 0, high = 0;  // range
  double nominal = 0;        // its value in this scenario (NaN when absent: range only)
};
struct Uncertainty {
  std::uint64_t seed = 1;  // default of --seed
  std::vector<UncertainParameter> parameters;
};

// The robot's chain as its source names it (robot.urdf), for `validate` and
// messages; empty names for robot.planar and robot.joints.
struct ChainNames {
  std::string urdf;                              // the URDF as named in the scenario, "" if none
  std::string base_link, tip_link;               // the chain's ends (the hand is on the tip link)
  std::vector<std::string> joints;               // [dof] joint names
  std::vector<std::string> links;                // [dof] the link each joint moves
  std::vector<std::vector<std::string>> merged;  // [dof] fixed links merged into it
  Eigen::VectorXd q_min, q_max;                  // [dof] URDF <limit>s [rad] (+-inf: continuous)
  std::vector<std::string> notes;                // what the import left out (joint friction)
};

struct Scenario {
  std::string file;  // path it was loaded from
  ChainNames chain;  // robot.urdf's names (empty for the YAML forms)
  std::string description;
  Model model;            // finalized (elbowsim::finalize called); model.initial from `initial:`
  Experiment experiment;  // task: and controller: (the plant never reads them)
  // controller.model as given ("key.path=value" each): where the controller's
  // model (experiment.controller_model) differs from the plant. Empty: none.
  std::vector<std::string> controller_model_overrides;
  Uncertainty uncertainty;  // uncertainty: (empty: nothing is drawn)
  OutputSettings output;
  RenderSettings render;  // how frames look; rendered when output.video or output.frames
  // The scenario as run: the file's YAML with the overrides applied. A run
  // folder keeps it (scenario.yaml) so renders and reports can rebuild the
  // model without the original file.
  std::string resolved_yaml;
  // variants: name -> its overrides ("key.path=value", applied like --set after
  // the file, before the command line's). Each is validated by the loader.
  std::vector<std::pair<std::string, std::vector<std::string>>> variants;
  std::string variant;  // the variant this is (load_scenario_variant); "" otherwise
  // study.axes: the dimensions of a study (elbowsim montecarlo runs every
  // case: one level of each axis, applied before the variant). A case's
  // scenario has no study.
  struct StudyAxis {
    std::string name;
    std::vector<std::pair<std::string, std::vector<std::string>>> levels;  // name, overrides
  };
  std::vector<StudyAxis> study;
  std::vector<std::string> study_case;  // the level of each axis this is (load_scenario_case)
};

// An error in a scenario. what() reads "file:line:column: key.path: message";
// line and column are 1-based, 0 when unknown (then "file: key.path: message").
// For a value that came from an override, file is "command line --set <text>".
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(std::string file, int line, int column, std::string key,
                const std::string& message);
  std::string file;  // scenario file name, or "command line --set ..."
  std::string key;   // key path, e.g. "robot.planar.links[2].mass"; empty if none
  int line;          // 1-based, 0 if unknown
  int column;        // 1-based, 0 if unknown
};

// Loads the YAML file at `path`, applies `overrides` in order (each
// "key.path=yaml value", e.g. "simulation.step=1e-4", "effects.motor=none",
// "robot.planar.links[0].mass=2"), validates and finalizes. Throws ScenarioError.
Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides = {});

// Same from text; `file_name` is used only in messages and Scenario::file.
Scenario load_scenario_text(const std::string& text, const std::string& file_name,
                            const std::vector<std::string>& overrides = {});

// One variant of a scenario: the file, then the variant's overrides, then
// `overrides`. The result has no variants (nor has its resolved_yaml), so a
// run folder's scenario.yaml is that variant alone. Throws ScenarioError, also
// when the scenario has no variant `name`.
Scenario load_scenario_variant(const std::string& path, const std::string& name,
                               const std::vector<std::string>& overrides = {});

// One case of the scenario's study: the file, then the overrides of level
// `levels[a]` of each axis a, then variant `variant` ("": none), then
// `overrides`. `levels` is empty or names one level per axis. The result has
// no study and, with a variant, no variants. Throws ScenarioError, also for
// an unknown level or variant.
Scenario load_scenario_case(const std::string& path, const std::vector<std::string>& levels,
                            const std::string& variant,
                            const std::vector<std::string>& overrides = {});
Scenario load_scenario_case_text(const std::string& text, const std::string& file_name,
                                 const std::vector<std::string>& levels, const std::string& variant,
                                 const std::vector<std::string>& overrides = {});
Scenario load_scenario_variant_text(const std::string& text, const std::string& file_name,
                                    const std::string& name,
                                    const std::vector<std::string>& overrides = {});

}  // namespace elbowsim
