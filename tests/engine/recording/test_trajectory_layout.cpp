// engine/recording/trajectory_layout.cpp: every column's name, unit and index; readers
// rebuild the layout from a header with from_columns, which refuses anything else.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "engine/recording/trajectory_layout.hpp"

using namespace elbowsim;

namespace {

using Groups = TrajectoryLayout::Groups;

// 2 joints, motors, a desired hand, one elbow called "elbow".
Groups full_groups() { return Groups{2, true, true, true, {"elbow"}}; }

// The message of the invalid_argument from_columns throws, or "" if it accepts.
std::string refusal(const std::vector<Column>& columns) {
  try {
    TrajectoryLayout::from_columns(columns);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool same_groups(const Groups& a, const Groups& b) {
  return a.dof == b.dof && a.motors == b.motors && a.desired_hand == b.desired_hand &&
         a.contact == b.contact && a.elbows == b.elbows && a.friction == b.friction;
}

}  // namespace

TEST_CASE("trajectory layout: the exact columns (golden) of 2 joints, motors, a desired hand, an elbow") {
  // Renaming a column breaks every trajectory.csv already written and the readers: this
  // list changes only on purpose (docs/conventions.md lists the same columns).
  const std::vector<std::pair<std::string, std::string>> golden = {
      {"time", "s"},        {"q0", "rad"},         {"q1", "rad"},         {"qd0", "rad/s"},
      {"qd1", "rad/s"},     {"qdd0", "rad/s^2"},   {"qdd1", "rad/s^2"},   {"i0", "A"},
      {"i1", "A"},          {"v0", "V"},           {"v1", "V"},           {"tau0", "N m"},
      {"tau1", "N m"},      {"hand_x", "m"},       {"hand_y", "m"},       {"hand_z", "m"},
      {"hand_d_x", "m"},    {"hand_d_y", "m"},     {"hand_d_z", "m"},     {"hand_error", "m"},
      {"fn_elbow", "N"},    {"d_elbow", "m"},      {"rest_elbow", "1"},   {"fn_link0", "N"},
      {"d_link0", "m"},     {"rest_link0", "1"},   {"fn_link1", "N"},     {"d_link1", "m"},
      {"rest_link1", "1"},  {"E_in", "J"},
      {"E_joule", "J"},     {"E_viscous", "J"},    {"KE_links", "J"},     {"KE_rotors", "J"},
      {"PE", "J"},          {"E_magnetic", "J"},   {"E_friction", "J"},   {"E_normal", "J"},
      {"E_impact", "J"},    {"E_projection", "J"}, {"E_drawn", "J"},      {"E_regenerated", "J"},
      {"balance_residual", "J"}};
  const TrajectoryLayout L(full_groups());
  REQUIRE(L.columns().size() == golden.size());
  for (std::size_t k = 0; k < golden.size(); ++k) {
    CAPTURE(k);
    CHECK(L.columns()[k].name == golden[k].first);
    CHECK(L.columns()[k].unit == golden[k].second);
  }
}

TEST_CASE("trajectory layout: the index accessors point at their columns, -1 where absent") {
  const TrajectoryLayout L(full_groups());
  const auto name = [&](int index) { return L.columns()[std::size_t(index)].name; };
  CHECK(name(L.time()) == "time");
  CHECK(name(L.q(1)) == "q1");
  CHECK(name(L.qd(0)) == "qd0");
  CHECK(name(L.qdd(1)) == "qdd1");
  CHECK(name(L.current(1)) == "i1");
  CHECK(name(L.voltage(0)) == "v0");
  CHECK(name(L.torque(1)) == "tau1");
  CHECK(name(L.hand(2)) == "hand_z");
  CHECK(name(L.hand_desired(0)) == "hand_d_x");
  CHECK(name(L.hand_error()) == "hand_error");
  CHECK(name(L.elbow_force(0)) == "fn_elbow");
  CHECK(name(L.elbow_distance(0)) == "d_elbow");
  CHECK(name(L.elbow_resting(0)) == "rest_elbow");
  CHECK(name(L.energy(Energy::electrical_in)) == "E_in");
  CHECK(name(L.energy(Energy::magnetic)) == "E_magnetic");
  CHECK(name(L.energy(Energy::projection)) == "E_projection");
  CHECK(name(L.energy(Energy::drawn)) == "E_drawn");
  CHECK(name(L.energy(Energy::regenerated)) == "E_regenerated");
  CHECK(name(L.balance_residual()) == "balance_residual");
  CHECK(name(L.link_force(1)) == "fn_link1");
  CHECK(name(L.link_distance(1)) == "d_link1");
  CHECK(name(L.link_resting(1)) == "rest_link1");
  CHECK(L.elbow_friction(0) == -1);  // no friction
  CHECK(L.elbow("elbow") == 0);
  CHECK(L.elbow("knee") == -1);
  Groups with_friction = full_groups();
  with_friction.friction = true;
  const TrajectoryLayout F(with_friction);
  const auto fname = [&](int index) { return F.columns()[std::size_t(index)].name; };
  CHECK(fname(F.elbow_friction(0)) == "E_friction_elbow");
  CHECK(fname(F.link_friction(0)) == "E_friction_link0");
  CHECK(fname(F.link_friction(1)) == "E_friction_link1");
  CHECK(F.columns()[std::size_t(F.link_friction(1))].unit == "J");
  CHECK(F.link_friction(1) + 1 == F.energy(Energy::electrical_in));
  const TrajectoryLayout bare(Groups{1, false, false, false, {}});
  CHECK(bare.size() == 1 + 3 + 1 + 3 + 7 + 1);
  CHECK(bare.current(0) == -1);
  CHECK(bare.voltage(0) == -1);
  CHECK(bare.hand_desired(0) == -1);
  CHECK(bare.hand_error() == -1);
  CHECK(bare.elbow_force(0) == -1);
  CHECK(bare.energy(Energy::friction) == -1);
  CHECK(bare.energy(Energy::projection) == -1);
  CHECK(bare.energy(Energy::drawn) == -1);  // no motors
  CHECK(bare.energy(Energy::regenerated) == -1);
  // Motors without contact: the split follows the seven always-there terms.
  const TrajectoryLayout motors(Groups{1, true, false, false, {}});
  CHECK(motors.columns()[std::size_t(motors.energy(Energy::drawn))].name == "E_drawn");
  CHECK(motors.energy(Energy::drawn) == motors.energy(Energy::magnetic) + 1);
  CHECK(motors.energy(Energy::friction) == -1);
  CHECK(bare.columns()[std::size_t(bare.energy(Energy::magnetic))].name == "E_magnetic");
}

TEST_CASE("from_columns(columns()) round-trips the groups of every kind of layout") {
  int layouts = 0;
  for (int dof = 1; dof <= 3; ++dof)
    for (bool motors : {false, true})
      for (bool desired : {false, true})
        for (const std::vector<std::string>& elbows :
             {std::vector<std::string>{}, {"elbow"}, {"left", "right"}})
          for (int contact = 0; contact < 3; ++contact) {  // off, on, on with friction
            if (!contact && !elbows.empty()) continue;  // elbows are recorded with contact only
            const Groups g{dof, motors, desired, contact > 0, elbows, contact == 2};
            const TrajectoryLayout L(g);
            const TrajectoryLayout back = TrajectoryLayout::from_columns(L.columns());
            CAPTURE(dof);
            CAPTURE(motors);
            CAPTURE(desired);
            CAPTURE(contact);
            CAPTURE(elbows.size());
            CHECK(same_groups(back.groups(), g));
            CHECK(back.size() == L.size());
            ++layouts;
          }
  CHECK(layouts == 3 * 2 * 2 * 7);
}

TEST_CASE("from_columns refuses a renamed column, naming its position and the expected name") {
  // Columns whose names the groups are not inferred from (see the next test for those).
  const TrajectoryLayout L(full_groups());
  for (const char* renamed : {"time", "qd1", "qdd0", "v1", "tau0", "hand_y", "hand_d_z", "d_elbow",
                              "rest_elbow", "E_in", "KE_links", "E_magnetic", "E_normal",
                              "balance_residual"}) {
    std::vector<Column> columns = L.columns();
    std::size_t k = 0;
    while (columns[k].name != renamed) ++k;
    columns[k].name += "_old";
    const std::string message = refusal(columns);
    CAPTURE(message);
    CHECK(message.find("trajectory column " + std::to_string(k + 1) + " ") != std::string::npos);
    CHECK(message.find("expected '" + std::string(renamed) + " [") != std::string::npos);
  }
  // A changed unit is refused the same way.
  std::vector<Column> columns = L.columns();
  columns[1].unit = "deg";
  CHECK(refusal(columns) == "trajectory column 2 is 'q0 [deg]', expected 'q0 [rad]'");
}

TEST_CASE("from_columns names a renamed marker column (q1, i0, hand_error, fn_elbow) and its position") {
  const TrajectoryLayout L(full_groups());
  for (const char* renamed : {"q1", "i0", "hand_error", "fn_elbow"}) {
    std::vector<Column> columns = L.columns();
    std::size_t k = 0;
    while (columns[k].name != renamed) ++k;
    columns[k].name += "_old";
    const std::string message = refusal(columns);
    CAPTURE(message);
    CHECK_FALSE(message.empty());
    CHECK(message.find("trajectory column " + std::to_string(k + 1) + " ") != std::string::npos);
    CHECK(message.find("expected '" + std::string(renamed) + " [") != std::string::npos);
  }
}

TEST_CASE("from_columns refuses a missing or an extra column, naming the position") {
  const TrajectoryLayout L(full_groups());
  std::vector<Column> missing = L.columns();
  missing.pop_back();
  CHECK(refusal(missing) == "trajectory column 43 is missing: expected 'balance_residual [J]'");
  std::vector<Column> middle = L.columns();
  middle.erase(middle.begin() + 30);  // E_joule
  CHECK(refusal(middle).find("trajectory column 31 is 'E_viscous [J]', expected 'E_joule [J]'") == 0);
  std::vector<Column> extra = L.columns();
  extra.push_back({"temperature", "K"});
  CHECK(refusal(extra) == "trajectory column 44 'temperature [K]' is not a trajectory column");
}
