// When a long run should say how far it is: at most once per interval, checked on every
// 65536th call so that a loop can ask at each iteration for the cost of an increment. There
// too a caller's interrupt check runs (Python's Ctrl-C).
#pragma once

#include <chrono>
#include <cstdint>

#include "engine/base/interrupt_check.hpp"

namespace mdrsim {

class ProgressLog {
 public:
  static constexpr std::chrono::seconds kInterval{2};

  /// True when kInterval has passed since the start or the last true; reads the clock on
  /// every 65536th call only.
  bool due() { return (++calls_ & 0xFFFF) == 0 && interval_passed(); }

  /// The same, reading the clock at each call: for a caller that asks seldom. Runs the
  /// interrupt check first.
  bool interval_passed() {
    poll_interrupt();
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < kInterval) return false;
    last_ = now;
    return true;
  }

 private:
  std::uint64_t calls_ = 0;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace mdrsim
