// The run a log line belongs to: a label of this thread's current run (a sweep's row), which
// the log patterns of the command line and the Python module print before each message
// through the flag %*, e.g. "[warn] row 17 of 41 (loading.tangential.displacement=4e-06): ...".
#pragma once

#include <spdlog/pattern_formatter.h>

#include <memory>
#include <string>

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

/// A formatter for `pattern` in which %* is "LABEL: " on a labelled thread, else nothing.
std::unique_ptr<spdlog::formatter> labelled_formatter(const std::string& pattern);

}  // namespace mdrsim::cli
