// The run a log line belongs to: a label of this thread's current run (a sweep's row), which
// the log patterns of the command line and the Python module print before each message
// through the flag %*, e.g. "[warn] row 17 of 41 (loading.tangential.displacement=4e-06): ...".
#pragma once

#include <spdlog/pattern_formatter.h>

#include <spdlog/logger.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mdrsim::cli {

/// Labels this thread's log lines for its lifetime, then puts the previous label back.
class ScopedRunLabel {
 public:
  explicit ScopedRunLabel(std::string label);
  ScopedRunLabel(const ScopedRunLabel&) = delete;
  ScopedRunLabel& operator=(const ScopedRunLabel&) = delete;
  ~ScopedRunLabel();

 private:
  std::string previous_;
};

/// While it lives, `logger`'s lines from a labelled thread (a sweep's runs) go at debug level:
/// shown only where the logger is at debug or below, so that a long sweep's stderr is its
/// progress and not one line per run's warning. The warnings it held back are counted by
/// kind (their text up to the first digit) for one summary line. Set up before the threads.
class QuietRuns {
 public:
  explicit QuietRuns(spdlog::logger& logger);
  QuietRuns(const QuietRuns&) = delete;
  QuietRuns& operator=(const QuietRuns&) = delete;
  ~QuietRuns();

  /// "sweep: 312 runs warned: 300 x 'rtol not met ...', 12 x '...'" (the most frequent first),
  /// or nothing when no run warned.
  std::optional<std::string> summary() const;

 private:
  class Sink;
  spdlog::logger& logger_;
  std::vector<spdlog::sink_ptr> sinks_;
  std::shared_ptr<Sink> sink_;
};

/// A formatter for `pattern` in which %* is "LABEL: " on a labelled thread, else nothing.
std::unique_ptr<spdlog::formatter> labelled_formatter(const std::string& pattern);

}  // namespace mdrsim::cli
