// The counters the allocation tests rely on (test_main.cpp, support/malloc_count.cpp)
// do count: a test that demands "no allocation" with a counter that never moves could
// not fail. Checked in every build, the sanitizer build's hook included.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "support/allocations.hpp"

using elbowsim::testing::allocation_count;
using elbowsim::testing::malloc_count;

namespace {
struct alignas(64) Wide {
  double x[8];
};
// Opaque to the optimiser: a new/delete pair it can see through may be elided.
void* volatile g_sink;
}  // namespace

TEST_CASE("allocation_count counts every form of operator new") {
  const long before = allocation_count();
  auto* one = new int(1);
  g_sink = one;
  delete one;
  auto* many = new int[4];
  g_sink = many;
  delete[] many;
  auto* quiet = new (std::nothrow) int(2);
  g_sink = quiet;
  delete quiet;
  auto* wide = new Wide;  // aligned new (alignment 64 > the default 16)
  g_sink = wide;
  CHECK(reinterpret_cast<std::uintptr_t>(wide) % 64 == 0);
  delete wide;
  auto* wides = new Wide[3];
  g_sink = wides;
  delete[] wides;
  CHECK(allocation_count() - before == 5);
}

TEST_CASE("malloc_count counts the C allocator and Eigen's heap allocations") {
  long before = malloc_count();
  void* p = std::malloc(24);
  g_sink = p;
  std::free(p);
  CHECK(malloc_count() - before >= 1);
  before = malloc_count();
  Eigen::MatrixXd m(7, 9);  // Eigen's aligned_malloc, not operator new
  g_sink = m.data();
  CHECK(malloc_count() - before >= 1);
}
