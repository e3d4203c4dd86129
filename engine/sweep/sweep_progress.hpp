// The progress lines of a long sweep (or fit of many curves): rows written and the time to go
// at the rate so far.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace mdrsim::cli {

class SweepProgress {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::seconds kInterval{10};

  /// A sweep of `rows` rows started at `started` with `done` of them in the CSV already,
  /// saying how far it is every `interval`; `command` and `unit` name the run and what it
  /// counts ("fit", "curves").
  SweepProgress(std::uint64_t done, std::uint64_t rows, Clock::time_point started,
                Clock::duration interval = kInterval, std::string command = "sweep",
                std::string unit = "rows");

  /// Called as rows are written (`written` in all): the line to log when the interval has
  /// passed since the start or the last line, e.g.
  /// "sweep: 120 of 2000 rows in 31 s, about 8 min to go"; else nothing.
  std::optional<std::string> line(std::uint64_t written, Clock::time_point now);

 private:
  std::uint64_t done_;
  std::uint64_t rows_;
  Clock::time_point started_;
  Clock::time_point last_;
  Clock::duration interval_;
  std::string command_;
  std::string unit_;
};

/// A duration for people: "40 s", "8 min", "2.5 h".
std::string rough_duration(double seconds);

}  // namespace mdrsim::cli
