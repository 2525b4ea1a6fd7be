#pragma once
namespace elbowsim::testing {
// Number of global operator new calls so far in this process.
long allocation_count();
// Number of C allocator calls (malloc, calloc, realloc, aligned) so far in this process:
// Eigen's heap allocations go there, unseen by operator new, and its malloc guard is off
// in Release builds (support/malloc_count.cpp; defined in engine_tests only).
long malloc_count();
}  // namespace elbowsim::testing
