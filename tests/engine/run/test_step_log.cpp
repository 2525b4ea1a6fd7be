// engine/run/step_log.cpp: the messages written from a step's records (describe()):
// each Warning and Failure kind names its time and its quantity.
#include <doctest/doctest.h>

#include <string>

#include "engine/model.hpp"
#include "engine/run/step_log.hpp"

using namespace elbowsim;

namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("describe(Warning): dependent rows name t, the elbow count, the rank and the threshold") {
  Model model;
  model.contact.rank_tolerance = 1e-9;
  Warning w;
  w.kind = Warning::Kind::dependent_rows;
  w.t = 0.25;
  w.count = 3;
  w.rank = 2;
  const std::string text = describe(model, w);
  MESSAGE(text);
  CHECK(has(text, "dependent"));
  CHECK(has(text, "t = 0.25 s"));
  CHECK(has(text, "3 touching elbows"));
  CHECK(has(text, "rank 2"));
  CHECK(has(text, "threshold"));
}

TEST_CASE("describe(Warning): a link in the table names the link, the box, t and the depth") {
  const Model model;
  Warning w;
  w.kind = Warning::Kind::link_in_table;
  w.t = 1.5;
  w.index = 1;
  w.box = 2;
  w.value = 0.012;
  const std::string text = describe(model, w);
  MESSAGE(text);
  CHECK(has(text, "link 1"));
  CHECK(has(text, "table box 2"));
  CHECK(has(text, "t = 1.5 s"));
  CHECK(has(text, "depth 0.012 m"));
}

TEST_CASE("describe(Failure): each kind names its time and quantity; none says nothing") {
  Model model;
  model.contact.friction = 0.75;
  model.options.step = 2e-3;
  Failure f;
  CHECK(describe(model, f).empty());
  f.t = 0.125;
  f.step = 62;

  f.kind = Failure::Kind::painleve;
  std::string text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "Painleve"));
  CHECK(has(text, "t = 0.125 s"));
  CHECK(has(text, "mu = 0.75"));

  f.kind = Failure::Kind::no_contact_solution;
  text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "contact failure"));
  CHECK(has(text, "t = 0.125 s"));
  model.effects.friction = true;
  CHECK(has(describe(model, f), "Painleve paradox"));  // with friction, it is one

  f.kind = Failure::Kind::diverged;
  text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "diverged"));
  CHECK(has(text, "t = 0.125 s"));
  CHECK(has(text, "step 62"));
  CHECK(has(text, "0.002 s"));  // the step it ran with
}

TEST_CASE("StepLog::clear empties the lists and keeps their capacity") {
  StepLog log;
  log.events.reserve(8);
  log.warnings.reserve(4);
  log.events.push_back({});
  log.warnings.push_back({});
  log.clear();
  CHECK(log.events.empty());
  CHECK(log.warnings.empty());
  CHECK(log.events.capacity() >= 8);
  CHECK(log.warnings.capacity() >= 4);
}

// may_fail: KNOWN BUG in engine/run/step_log.cpp (not fixed here, tests only). The
// dependent-rows message prints contact.rank_tolerance with std::to_string, which has
// six fixed decimals: the default 1e-9 reads "threshold 0.000000 relative".
TEST_CASE("describe(Warning): the dependent-rows threshold is readable (1e-09, not 0.000000)" *
          doctest::may_fail()) {
  Model model;
  model.contact.rank_tolerance = 1e-9;
  Warning w;
  w.kind = Warning::Kind::dependent_rows;
  w.t = 0.25;
  w.count = 3;
  w.rank = 2;
  const std::string text = describe(model, w);
  CHECK_FALSE(has(text, "threshold 0.000000"));
  CHECK(has(text, "1e-09"));
}
