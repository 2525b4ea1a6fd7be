#pragma once
namespace elbowsim::testing {
// Number of global operator new calls so far in this process.
long allocation_count();
}  // namespace elbowsim::testing
