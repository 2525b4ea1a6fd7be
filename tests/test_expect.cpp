// report/expect: the --expect language. Parsing (with the column of a
// malformed token), evaluation over summary.json, and the CLI exit codes
// (0 met, 4 failed, 2 malformed or unknown metric).
#include <doctest/doctest.h>

#include <sstream>

#include "report/expect.hpp"
#include "report_test_helpers.hpp"

using elbowsim::report::check_expectations;
using elbowsim::report::Expectation;
using elbowsim::report::ExpectError;
using elbowsim::report::ExpectStatus;
using Json = nlohmann::ordered_json;
namespace t = elbowsim::testing;

namespace {

const Json kSummary = Json::parse(R"({
  "scenario": "elbow_rest", "effects": ["gravity", "contact"], "completed": true,
  "steps": 2000, "final_time": 2.0, "warnings": [],
  "settings": {"integrator": "rk4", "step": 0.001},
  "energy_final": {"electrical_in": 7.37, "joule": 7.5, "friction": null}
})");

bool holds(const std::string& text, const Json& metrics = kSummary) {
  return Expectation(text).evaluate(metrics).passed;
}

// The column a malformed expression is reported at.
std::size_t error_column(const std::string& text, const Json& metrics = kSummary) {
  try {
    Expectation(text).evaluate(metrics);
  } catch (const ExpectError& e) {
    return e.column;
  }
  FAIL("no error for: " << text);
  return 0;
}

std::string error_message(const std::string& text, const Json& metrics = kSummary) {
  try {
    Expectation(text).evaluate(metrics);
  } catch (const ExpectError& e) {
    return e.message;
  }
  FAIL("no error for: " << text);
  return "";
}

}  // namespace

TEST_CASE("expect: comparisons of metrics hold or not") {
  CHECK(holds("energy_final.electrical_in < 120"));
  CHECK_FALSE(holds("energy_final.electrical_in > 120"));
  CHECK(holds("energy_final.electrical_in <= 7.37"));
  CHECK(holds("energy_final.electrical_in >= 7.37"));
  CHECK(holds("steps == 2000"));
  CHECK_FALSE(holds("steps != 2000"));
  CHECK(holds("energy_final.electrical_in < energy_final.joule"));
  CHECK(holds("1e-3 == settings.step"));
}

TEST_CASE("expect: arithmetic with precedence, unary minus, parentheses") {
  CHECK(holds("1 + 2 * 3 == 7"));
  CHECK(holds("(1 + 2) * 3 == 9"));
  CHECK(holds("10 / 4 == 2.5"));
  CHECK(holds("8 - 2 - 1 == 5"));  // left to right
  CHECK(holds("-2 < -1"));
  CHECK(holds("--2 == 2"));
  CHECK(holds("energy_final.joule - energy_final.electrical_in < 0.2"));
}

TEST_CASE("expect: and/&&, or/||, not/!, booleans") {
  CHECK(holds("completed and steps > 10"));
  CHECK_FALSE(holds("completed and steps < 10"));
  CHECK_FALSE(holds("true && false"));
  CHECK_FALSE(holds("false or false"));
  CHECK(holds("completed && !(steps < 10)"));
  CHECK(holds("false or true"));
  CHECK(holds("false || completed"));
  CHECK_FALSE(holds("not completed"));
  CHECK(holds("completed == true"));
  CHECK(holds("steps > 1 and steps < 3000 or false"));  // and binds tighter than or
  CHECK(holds("true or false and false"));              // true or (false and false)
  CHECK_FALSE(holds("(true or false) and false"));
}

TEST_CASE("expect: strings, list indices, functions") {
  CHECK(holds("scenario == 'elbow_rest'"));
  CHECK(holds("settings.integrator != \"euler\""));
  CHECK(holds("effects.1 == 'contact'"));
  CHECK(holds("len(warnings) == 0"));
  CHECK(holds("len(effects) == 2"));
  CHECK(holds("abs(-3) == 3"));
  CHECK(holds("min(energy_final.joule, 5, 9) == 5"));
  CHECK(holds("max(1, steps) == 2000"));
}

TEST_CASE("expect: a NaN metric (null) fails every comparison but !=") {
  CHECK_FALSE(holds("energy_final.friction < 1"));
  CHECK_FALSE(holds("energy_final.friction >= 1"));
  CHECK_FALSE(holds("energy_final.friction == energy_final.friction"));
  CHECK(holds("energy_final.friction != 1"));
}

TEST_CASE("expect: compare paths start with a run label; odd labels are quoted") {
  const Json runs = {{"elbow-on", kSummary},
                     {"elbow_off", Json::parse(R"({"energy_final": {"electrical_in": 10.5}})")}};
  CHECK(
      holds("'elbow-on'.energy_final.electrical_in < elbow_off.energy_final.electrical_in", runs));
  CHECK_FALSE(holds(
      "\"elbow-on\".energy_final.electrical_in > elbow_off.energy_final.electrical_in", runs));
  // Unquoted, the label reads as elbow minus on: there is no run "elbow".
  CHECK(error_message("elbow-on.steps > 0", runs).find("elbow-on, elbow_off") != std::string::npos);
}

TEST_CASE("expect: the outcome lists every metric read, with its value") {
  const auto outcome = Expectation("energy_final.electrical_in < energy_final.joule and steps > 1")
                           .evaluate(kSummary);
  CHECK(outcome.passed);
  REQUIRE(outcome.values.size() == 3);
  CHECK(outcome.values[0] ==
        std::pair<std::string, std::string>{"energy_final.electrical_in", "7.37"});
  CHECK(outcome.values[2] == std::pair<std::string, std::string>{"steps", "2000"});
}

TEST_CASE("expect: malformed expressions name the column") {
  CHECK(error_column("energy_final.electrical_in < < 120") == 30);
  CHECK(error_column("steps <") == 8);  // the end
  CHECK(error_column("(steps < 1") == 11);
  CHECK(error_column("steps < 1 < 2") == 11);
  CHECK(error_column("steps $ 2") == 7);
  CHECK(error_column("frobnicate(steps) > 1") == 1);
  CHECK(error_column("scenario == 'elbow") == 13);
  CHECK(error_column("") == 1);
  CHECK(error_column("steps > 1 steps") == 11);
  CHECK(error_column("energy_final. < 1") == 15);
  CHECK(error_column("abs(1, 2) > 0") == 1);
  CHECK(error_message("steps < 1 < 2").find("do not chain") != std::string::npos);
  CHECK(error_message("frobnicate(1)").find("unknown function") != std::string::npos);
}

TEST_CASE("expect: unknown metrics and type errors name what is there") {
  const std::string unknown = error_message("energy_final.electrical < 1");
  CHECK(unknown.find("energy_final.electrical") != std::string::npos);
  CHECK(unknown.find("electrical_in, joule") != std::string::npos);
  CHECK(error_column("steps > 1 and energy_final.nope < 1") == 15);
  CHECK(error_message("completed + 1 > 0").find("needs numbers") != std::string::npos);
  CHECK(error_message("steps and completed").find("needs true/false") != std::string::npos);
  CHECK(error_message("steps + 1").find("not true/false") != std::string::npos);
  CHECK(error_message("scenario == 1").find("cannot compare") != std::string::npos);
  CHECK(error_message("effects.7 == 'x'").find("list of 2") != std::string::npos);
}

TEST_CASE("expect: describe() puts a caret under the column") {
  try {
    Expectation("steps < < 1");
    FAIL("no error");
  } catch (const ExpectError& e) {
    const std::string text = elbowsim::report::describe(e);
    CHECK(text.find("column 9") != std::string::npos);
    CHECK(text.find("\n  steps < < 1\n          ^\n") != std::string::npos);
  }
}

TEST_CASE("expect: check_expectations reports met, failed (with values) and invalid") {
  std::vector<Expectation> list;
  list.emplace_back("steps == 2000");
  list.emplace_back("energy_final.electrical_in < 5");
  std::ostringstream out, err;
  CHECK(check_expectations(list, kSummary, out, err) == ExpectStatus::failed);
  CHECK(out.str().find("expect: ok     steps == 2000") != std::string::npos);
  CHECK(err.str().find("expect: FAILED energy_final.electrical_in < 5") != std::string::npos);
  CHECK(err.str().find("energy_final.electrical_in = 7.37") != std::string::npos);
  list.emplace_back("nope > 1");
  std::ostringstream out2, err2;
  CHECK(check_expectations(list, kSummary, out2, err2) == ExpectStatus::invalid);
  CHECK(err2.str().find("no metric \"nope\"") != std::string::npos);
  std::vector<Expectation> good;
  good.emplace_back("completed");
  std::ostringstream out3, err3;
  CHECK(check_expectations(good, kSummary, out3, err3) == ExpectStatus::met);
  CHECK(err3.str().empty());
}

// ---- the command line ------------------------------------------------------

namespace {
const std::string kScene = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_rest.yaml";
const std::string kShort = " --no-render --no-report --set simulation.duration=0.2";
}  // namespace

TEST_CASE("cli --expect: run exits 0 when met, 4 when not (naming it), 2 when malformed") {
  const auto dir = t::scratch("report", "expect_run");
  const auto ok = t::run_elbowsim("run " + kScene + " --out " + (dir / "a").string() + kShort +
                                  " --expect \"energy_final.electrical_in < 120\"" +
                                  " --expect \"completed and contact.landings >= 1\"");
  CHECK(ok.exit_code == 0);
  CHECK(ok.output.find("expect: ok     energy_final.electrical_in < 120") != std::string::npos);

  const auto failed =
      t::run_elbowsim("run " + kScene + " --out " + (dir / "b").string() + kShort +
                      " --expect \"steps > 0\" --expect \"energy_final.electrical_in < 1e-9\"");
  CHECK(failed.exit_code == 4);
  CHECK(failed.output.find("expect: FAILED energy_final.electrical_in < 1e-9") !=
        std::string::npos);
  CHECK(failed.output.find("energy_final.electrical_in = ") != std::string::npos);

  // Malformed: exit 2 before simulating (nothing written), naming the column.
  const auto bad = t::run_elbowsim("run " + kScene + " --out " + (dir / "c").string() + kShort +
                                   " --expect \"steps >> 1\"");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("column 8") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "c"));

  // Unknown metric: exit 2, listing what is there.
  const auto unknown = t::run_elbowsim("run " + kScene + " --out " + (dir / "d").string() + kShort +
                                       " --expect \"energy_final.electrical < 1\"");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.output.find("electrical_in") != std::string::npos);
}

TEST_CASE("cli --expect: compare addresses runs by folder name") {
  const auto dir = t::scratch("report", "expect_compare");
  REQUIRE(t::run_elbowsim("run " + kScene + " --out " + (dir / "on").string() + kShort).exit_code ==
          0);
  REQUIRE(t::run_elbowsim("run " + kScene + " --out " + (dir / "off").string() + kShort +
                          " --set 'inputs.voltage[0].offset=4.86'")
              .exit_code == 0);
  const std::string runs =
      (dir / "on").string() + " " + (dir / "off").string() + " --out " + (dir / "cmp").string();
  const auto met = t::run_elbowsim(
      "compare " + runs +
      " --expect \"on.energy_final.electrical_in < off.energy_final.electrical_in\"");
  CHECK(met.exit_code == 0);
  const auto failed = t::run_elbowsim(
      "compare " + runs +
      " --expect \"on.energy_final.electrical_in > off.energy_final.electrical_in\"");
  CHECK(failed.exit_code == 4);
  CHECK(failed.output.find("on.energy_final.electrical_in = ") != std::string::npos);
  CHECK(failed.output.find("off.energy_final.electrical_in = ") != std::string::npos);
  const auto unknown = t::run_elbowsim("compare " + runs + " --expect \"elbow.steps > 1\"");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.output.find("on, off") != std::string::npos);
}

TEST_CASE("cli --expect: report checks a recorded run") {
  const auto dir = t::scratch("report", "expect_report");
  REQUIRE(t::run_elbowsim("run " + kScene + " --out " + (dir / "r").string() + kShort).exit_code ==
          0);
  CHECK(
      t::run_elbowsim("report " + (dir / "r").string() + " --expect \"steps == 200\"").exit_code ==
      0);
  CHECK(
      t::run_elbowsim("report " + (dir / "r").string() + " --expect \"steps == 201\"").exit_code ==
      4);
  CHECK(t::run_elbowsim("report " + (dir / "r").string() + " --expect \"steps ==\"").exit_code ==
        2);
}
