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
//
// Under AddressSanitizer (the sanitizer build) the sanitizer owns malloc: memory from
// __libc_malloc handed to its free would be reported as a bad free. There the counter
// is the sanitizer's allocation hook instead, called for every allocation the program
// makes (malloc and its kin, and operator new, which goes through malloc): a superset
// of the above, and still zero where the tests demand zero.
#include <atomic>
#include <cerrno>
#include <cstddef>

#include "support/allocations.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define ELBOWSIM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ELBOWSIM_ASAN 1
#endif
#endif

#ifdef ELBOWSIM_ASAN
// From <sanitizer/allocator_interface.h>, which clang ships and GCC does not (GCC's
// libasan exports the function all the same).
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void*, std::size_t), void (*free_hook)(const volatile void*));
#endif

namespace {
std::atomic<long> g_mallocs{0};
void counted() { g_mallocs.fetch_add(1, std::memory_order_relaxed); }
}  // namespace

long elbowsim::testing::malloc_count() { return g_mallocs.load(); }

#ifdef ELBOWSIM_ASAN

namespace {
void on_malloc(const volatile void*, std::size_t) { counted(); }
void on_free(const volatile void*) {}
// Installed during static initialisation, before any test runs.
[[maybe_unused]] const int g_hooks_installed = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
}  // namespace

#else

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* block, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}

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

#endif  // ELBOWSIM_ASAN
