// engine/recording/recording.cpp: a recorded table, its columns looked up by name and
// read as series.
#include <doctest/doctest.h>

#include "engine/recording/recording.hpp"
#include "support/recordings.hpp"

using namespace elbowsim;
using elbowsim::testing::set;
using elbowsim::testing::zero_recording;

TEST_CASE("Recording: column(name) is the layout's index, -1 for an unknown name") {
  const Recording rec(TrajectoryLayout({2, true, false, true, {"elbow"}}));
  for (std::size_t k = 0; k < rec.columns().size(); ++k) CHECK(rec.column(rec.columns()[k].name) == int(k));
  CHECK(rec.column("q1") == rec.layout.q(1));
  CHECK(rec.column("fn_elbow") == rec.layout.elbow_force(0));
  CHECK(rec.column("hand_error") == -1);  // not recorded: no desired hand
  CHECK(rec.column("nonsense") == -1);
  CHECK(rec.rows() == 0);
}

TEST_CASE("Recording: rows, at(row, column) and series(index) read the row-major table") {
  Recording rec = zero_recording({1, false, false, false, {}}, 3);
  REQUIRE(rec.rows() == 3);
  const int q = rec.column("q0"), t = rec.column("time");
  for (std::size_t row = 0; row < 3; ++row) {
    set(rec, row, t, 0.5 * double(row));
    set(rec, row, q, 10.0 + double(row));
  }
  CHECK(rec.at(2, std::size_t(q)) == 12.0);
  CHECK(rec.values[2 * rec.columns().size() + std::size_t(q)] == 12.0);  // row-major
  CHECK(rec.series(t) == std::vector<double>{0.0, 0.5, 1.0});
  CHECK(rec.series(q) == std::vector<double>{10.0, 11.0, 12.0});
  CHECK(rec.series(-1).empty());
  CHECK(Recording().rows() == 0);  // no layout, no rows
}
