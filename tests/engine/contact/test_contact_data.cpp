// engine/contact/contact_data.cpp: ContactData holds the rows of M* for every number of
// resting slots up to its capacity, and use_rows(p) swaps the pre-sized set in without allocating.
#include <doctest/doctest.h>

#include <limits>

#include "engine/contact/contact_data.hpp"
#include "support/allocations.hpp"

using namespace elbowsim;
using elbowsim::testing::allocation_count;
using elbowsim::testing::malloc_count;

namespace {

// Every p-sized member of the flat rows has its size for p rows and n joints.
void check_sizes(const ContactData& c, int p, int n) {
  CAPTURE(p);
  CHECK(c.rows() == p);
  CHECK((c.Jc.rows() == p && c.Jc.cols() == n));
  CHECK((c.Jf.rows() == p && c.Jf.cols() == n));
  CHECK((c.Y.rows() == n && c.Y.cols() == p));
  CHECK((c.Z.rows() == n && c.Z.cols() == p));
  CHECK((c.A.rows() == p && c.A.cols() == p));
  for (const Eigen::VectorXd* v : {&c.gamma, &c.C, &c.Cd, &c.fn, &c.slide, &c.Jf_qd, &c.rhs,
                                   &c.lcp_b, &c.lcp_f, &c.lcp_w})
    CHECK(v->size() == p);
}

}  // namespace

// 3 elbow balls on 2 boxes: 6 slots, rows for 3 at once.
ContactData three_elbows_two_boxes() {
  ContactGeometry g;
  for (int k = 0; k < 3; ++k) {
    Primitive p;
    p.link = k;
    p.elbow = k;
    g.primitives.push_back(p);
    for (int b = 0; b < 2; ++b) {
      g.first_slot.push_back(static_cast<int>(g.slots.size()));
      g.slots.push_back({k, b, ContactSlot::Part::ball});
    }
  }
  g.first_slot.push_back(static_cast<int>(g.slots.size()));
  g.boxes = 2;
  return ContactData(g, 2, 5, 3);
}

TEST_CASE("ContactData: sized for 6 slots, rows for 3, 5 joints; use_rows(0) at start") {
  const ContactData c = three_elbows_two_boxes();
  check_sizes(c, 0, 5);
  CHECK(c.slots() == 6);
  CHECK(c.resting.size() == 6);
  CHECK(c.detected.size() == 6);
  CHECK(c.normal.size() == 6);
  CHECK(c.surface.size() == 6);
  CHECK(c.capacity() == 3);
  CHECK(c.active.capacity() >= 3);
  CHECK(c.candidates.capacity() >= 6);
  for (const SlotContact& d : c.detected) CHECK(d.distance == std::numeric_limits<double>::infinity());
  REQUIRE(c.solvers.size() == 4);  // one workspace per m = 0..3
  for (int m = 0; m <= 3; ++m) {
    CAPTURE(m);
    const SolverWorkspace& ws = c.solvers[std::size_t(m)];
    CHECK((ws.block.rows() == m && ws.block.cols() == m));
    CHECK((ws.Jc.rows() == m && ws.Jc.cols() == 5));
    CHECK((ws.MinvJt.rows() == 5 && ws.MinvJt.cols() == m));
    CHECK(ws.dx.size() == 5);
    CHECK(ws.rhs.size() == m);
  }
}

TEST_CASE("use_rows swaps in the set for p = 0..capacity and back, allocating nothing") {
  ContactData c = three_elbows_two_boxes();
  const int order[] = {1, 2, 3, 2, 0, 3, 1, 1, 0};
  const long news = allocation_count(), mallocs = malloc_count();
  Eigen::internal::set_is_malloc_allowed(false);
  int sizes_ok = 0;
  for (const int p : order) {
    c.use_rows(p);
    // Checked without doctest's macros inside the guarded loop (they may allocate).
    sizes_ok += c.rows() == p && c.Jc.rows() == p && c.Jc.cols() == 5 && c.Y.cols() == p &&
                c.A.rows() == p && c.A.cols() == p && c.gamma.size() == p && c.lcp_w.size() == p &&
                c.fn.size() == p;
  }
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(allocation_count() == news);
  CHECK(malloc_count() == mallocs);
  CHECK(sizes_ok == int(std::size(order)));
  for (int p = 0; p <= 3; ++p) {
    c.use_rows(p);
    check_sizes(c, p, 5);
  }
}
