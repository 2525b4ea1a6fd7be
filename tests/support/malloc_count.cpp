// Counts every call of the C allocator in this process (linked into engine_tests only).
//
// Why: Eigen allocates with std::malloc, not operator new, and its malloc guard
// (EIGEN_RUNTIME_NO_MALLOC + set_is_malloc_allowed(false)) reports through eigen_assert,
// which -DNDEBUG (Release) turns off. In a Release build a heap allocation inside Eigen is
// therefore invisible to both the guard and allocation_count(); this counter sees it.
//
// malloc, calloc, realloc and the aligned allocators are replaced by counting forwarders
// to glibc's own implementations (__libc_*), so memory still comes from, and goes back to,
// one allocator (free is not replaced).
#include <atomic>
#include <cerrno>
#include <cstddef>

#include "support/allocations.hpp"

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* block, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}

namespace {
std::atomic<long> g_mallocs{0};
void counted() { g_mallocs.fetch_add(1, std::memory_order_relaxed); }
}  // namespace

long elbowsim::testing::malloc_count() { return g_mallocs.load(); }

extern "C" {

void* malloc(std::size_t size) noexcept {
  counted();
  return __libc_malloc(size);
}

void* calloc(std::size_t count, std::size_t size) noexcept {
  counted();
  return __libc_calloc(count, size);
}

void* realloc(void* block, std::size_t size) noexcept {
  counted();
  return __libc_realloc(block, size);
}

void* memalign(std::size_t alignment, std::size_t size) noexcept {
  counted();
  return __libc_memalign(alignment, size);
}

void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  counted();
  return __libc_memalign(alignment, size);
}

int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  counted();
  void* block = __libc_memalign(alignment, size);
  if (!block) return ENOMEM;
  *out = block;
  return 0;
}

}  // extern "C"
