// When a long run should say how far it is: at most once per interval, checked on every
// 65536th call so that a loop can ask at each iteration for the cost of an increment.
#pragma once

#include <chrono>
#include <cstdint>

namespace mdrsim {

class ProgressLog {
 public:
  static constexpr std::chrono::seconds kInterval{2};

  /// True when kInterval has passed since the start or the last true; reads the clock on
  /// every 65536th call only.
  bool due() { return (++calls_ & 0xFFFF) == 0 && interval_passed(); }

  /// The same, reading the clock at each call: for a caller that asks seldom.
  bool interval_passed() {
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
