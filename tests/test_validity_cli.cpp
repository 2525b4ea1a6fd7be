// Runs that cannot be trusted say so (engine/run/validity.hpp), run as a user
// runs them: exit 3, a message naming the check, the time, the quantity and the
// likely cause; summary.json says valid: false; a comparison gives no verdict.
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/process.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
namespace t = elbowsim::testing;

namespace {

const std::string kExperiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("the experiment at a 1.75 ms step: invalid (energy balance), exit 3, no verdict") {
  const fs::path dir = t::scratch("validity", "step_175");
  const t::Outcome r = t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                                       " --no-render --set simulation.step=1.75e-3");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(has(r.output, "invalid run: the energy balance is off by"));
  CHECK(has(r.output, "simulation.step"));  // what to change
  for (const char* variant : {"elbow_on", "elbow_off"}) {
    const auto summary = nlohmann::json::parse(t::slurp(dir / variant / "summary.json"));
    CHECK(summary["completed"] == true);  // it ran to the end...
    CHECK(summary["valid"] == false);     // ...but its numbers cannot be used
  }
  const auto comparison = nlohmann::json::parse(t::slurp(dir / "comparison.json"));
  CHECK(comparison["valid"]["elbow_on"] == false);
  bool refused = false, compared = false;
  for (const auto& sentence : comparison["verdict"]) {
    refused = refused || has(sentence.get<std::string>(), "No verdict");
    compared = compared || has(sentence.get<std::string>(), "less electrical energy");
  }
  CHECK(refused);
  CHECK_FALSE(compared);
}

TEST_CASE("an elbow planned to rest beyond the box's edge: exit 3 naming the elbow and the box") {
  const fs::path dir = t::scratch("validity", "beyond_edge");
  // The table moved 12 cm away: the elbow's resting point is past its edge.
  const t::Outcome r =
      t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                      " --no-render --no-report --set 'table.boxes[0].center=[0.77,0,-0.0998938]'");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(has(r.output, "elbow 'elbow' on table box 0"));
  CHECK(has(r.output, "beyond the box's top face"));
}

TEST_CASE("contact off with a table: the physics ignores it, a link that goes in makes the run invalid") {
  const fs::path dir = t::scratch("validity", "contact_off");
  const t::Outcome r = t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                                       " --no-render --no-report --set effects.contact=false"
                                       " --set controller.type=pd --set variants.elbow_off=null");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(has(r.output, "inside table box 0"));
  CHECK(has(r.output, "effects.contact is false"));
}
