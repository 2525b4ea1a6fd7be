// engine/run/step_log.cpp: the messages written from a step's records (describe()):
// each Warning and Failure kind names its time and its quantity.
#include <doctest/doctest.h>

#include <cmath>
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
  CHECK(has(text, "3 rows of M*"));
  CHECK(has(text, "rank 2"));
  CHECK(has(text, "threshold"));
}

TEST_CASE("describe(Failure): each kind names its time and quantity; none says nothing") {
  Model model;
  model.contact.friction.mu = 0.75;
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

TEST_CASE("describe(Failure): the validity checks name the part, the quantity, its bound, the cause") {
  Model model;
  model.elbows = {Elbow{"elbow", 0, Eigen::Vector3d::Zero(), 0.03}};
  model.options.step = 1.75e-3;
  Failure f;
  f.t = 0.5;
  f.kind = Failure::Kind::penetration;
  f.part = Failure::Part::link;
  f.index = 2;
  f.box = 1;
  f.value = 0.004;
  f.limit = 0.001;
  std::string text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "link 2 is 0.004 m inside table box 1 at t = 0.5 s"));
  CHECK(has(text, "contact.penetration_tolerance 0.001 m"));
  CHECK(has(text, "effects.contact is false"));  // the likely cause with contact off
  model.effects.contact = true;
  model.contact.events = EventTiming::step;
  CHECK(has(describe(model, f), "contact.events: locate"));  // with events: step
  model.contact.events = EventTiming::locate;
  model.links.resize(3);
  model.links[2].collision.kind = LinkCollision::Kind::capsule;
  CHECK(has(describe(model, f), "its contact rows did not hold it"));  // located, with a solid
  const double later = f.t;
  f.t = 0.5 * model.options.step;
  CHECK(has(describe(model, f), "the pose the run starts from puts it there"));
  f.t = later;
  CHECK(has(describe(model, f), "try a smaller simulation.step"));
  model.links[2].collision.kind = LinkCollision::Kind::none;
  CHECK(has(describe(model, f), "the link has no solid (collision: none)"));

  f = Failure{Failure::Kind::energy_balance, 0.5, 100};
  f.value = 2.0, f.limit = 0.1, f.flow = 100.0;
  f.stable_step = 1.5e-3;  // the step 1.75 ms is beyond it
  text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "invalid run: the energy balance is off by 2 J at t = 0.5 s, 2 % of the 100 J"));
  CHECK(has(text, "the step 0.00175 s is too large"));
  CHECK(has(text, "try simulation.step <= 0.00075 s"));

  f = Failure{Failure::Kind::current_bound, 0.25, 10};
  f.part = Failure::Part::joint, f.index = 1, f.value = 250, f.limit = 120;
  text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "simulation diverged at t = 0.25 s: motor 1's current reached 250 A"));
  CHECK(has(text, "beyond 120 A"));

  f = Failure{Failure::Kind::elbow_not_resting, 4.8, 4800};
  f.part = Failure::Part::elbow, f.index = 0, f.value = 0.4, f.limit = 0.9;
  text = describe(model, f);
  MESSAGE(text);
  CHECK(has(text, "elbow 'elbow' rested 40 % of the run"));
  CHECK(has(text, "validity.rest_share 90 %"));

  f = Failure{Failure::Kind::too_many_contacts, 0.1, 100};
  f.value = 30, f.limit = 24;
  CHECK(has(describe(model, f), "30 contact points touch the table at once, more than the 24"));
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

// The threshold is printed as a number, not with std::to_string's six fixed decimals
// (which made the default 1e-9 read "threshold 0.000000 relative").
TEST_CASE("describe(Warning): the dependent-rows threshold is readable (1e-09, not 0.000000)") {
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

TEST_CASE("describe(Failure, causes): a failure leads with the first cause that explains it") {
  Model model;
  Failure f;
  f.kind = Failure::Kind::energy_balance;
  f.t = 2.7;
  f.since = 1.2;
  f.value = 0.06;
  f.limit = 0.03;
  f.flow = 26;
  const std::string own = describe(model, f);
  REQUIRE(own.starts_with("invalid run: the energy balance is off"));
  const FailureCause saturation{"motor 1 is at its limit", 0.0, {Failure::Kind::elbow_not_resting}};
  const FailureCause singular{"the hand task passes near a singular pose at t = 1.2 s",
                              1.15,
                              {Failure::Kind::diverged, Failure::Kind::energy_balance}};
  const FailureCause later{"something after it", 1.3, {Failure::Kind::energy_balance}};
  // The cause of another kind is passed over; the one that explains it leads,
  // the failure's own message (without its label) follows.
  const std::string led = describe(model, f, {saturation, singular});
  MESSAGE(led);
  CHECK(led == singular.clause + "; likely as a result, " +
                   own.substr(std::string("invalid run: ").size()));
  // A condition that began after the balance went off explains nothing
  // (energy balance: from `since`; other kinds: from t).
  CHECK(describe(model, f, {later}) == own);
  CHECK(describe(model, f, {later, singular}).starts_with(singular.clause));
  f.since = std::nan("");
  CHECK(describe(model, f, {later}).starts_with(later.clause));
  // Nothing to explain: no failure, no cause.
  CHECK(describe(model, Failure{}, {singular}).empty());
  CHECK(describe(model, f, {}) == describe(model, f));
}
