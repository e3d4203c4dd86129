// The handler may only call async-signal-safe functions: the paths wait in fixed buffers,
// flagged by lock-free atomics, and the handler calls unlink(2), write(2) and _exit(2) alone.
#include "apps/interrupt_cleanup.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstddef>
#include <cstring>

namespace mdrsim::cli {
namespace {

static_assert(std::atomic<bool>::is_always_lock_free);

struct Slot {
  std::atomic<bool> used{false};
  std::array<char, 4096> path{};
};

/// `run` writes at most two files (--json, --trajectory).
std::array<Slot, 8> slots;

void say(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

extern "C" void on_interrupt(int signal_number) {
  for (Slot& slot : slots) {
    if (slot.used.load(std::memory_order_acquire)) ::unlink(slot.path.data());
  }
  say(signal_number == SIGINT ? "mdrsim: stopped by SIGINT; unfinished output files removed\n"
                              : "mdrsim: stopped by SIGTERM; unfinished output files removed\n");
  ::_exit(128 + signal_number);
}

}  // namespace

void install_interrupt_cleanup() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // Both signals blocked while the handler runs: one cleanup, one exit code.
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  for (const int signal_number : {SIGINT, SIGTERM}) {
    // A signal ignored on entry (nohup, a script's background job) stays ignored.
    struct sigaction previous {};
    if (sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) {
      continue;
    }
    sigaction(signal_number, &action, nullptr);
  }
}

int remove_on_interrupt(const std::string& path) {
  for (std::size_t i = 0; i < slots.size(); ++i) {
    Slot& slot = slots[i];
    if (slot.used.load(std::memory_order_relaxed) || path.size() >= slot.path.size()) continue;
    std::memcpy(slot.path.data(), path.c_str(), path.size() + 1);
    slot.used.store(true, std::memory_order_release);
    return static_cast<int>(i);
  }
  return -1;
}

void forget_on_interrupt(int slot) {
  if (slot >= 0 && static_cast<std::size_t>(slot) < slots.size()) {
    slots[static_cast<std::size_t>(slot)].used.store(false, std::memory_order_release);
  }
}

}  // namespace mdrsim::cli
