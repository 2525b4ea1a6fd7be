#include "app/commands/interrupt.hpp"

#include <csignal>

namespace elbowsim {

namespace {

std::atomic<bool> raised{false};  // lock-free: safe to store from a handler
volatile std::sig_atomic_t signal_number = 0;

extern "C" void on_signal(int number) {
  signal_number = number;
  raised.store(true, std::memory_order_relaxed);
}

}  // namespace

void install_interrupt_handlers() {
  static_assert(std::atomic<bool>::is_always_lock_free);
  static const bool installed = [] {
    struct sigaction action = {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    return true;
  }();
  (void)installed;
}

const std::atomic<bool>& interrupt_flag() { return raised; }

int interrupt_exit_code() { return raised.load() ? 128 + static_cast<int>(signal_number) : 0; }

}  // namespace elbowsim
