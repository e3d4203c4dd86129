// Progress lines of a sweep.
#include "engine/sweep/sweep_progress.hpp"

#include <fmt/format.h>

#include <utility>

namespace mdrsim::cli {

SweepProgress::SweepProgress(std::uint64_t done, std::uint64_t rows, Clock::time_point started,
                             Clock::duration interval, std::string command, std::string unit)
    : done_(done),
      rows_(rows),
      started_(started),
      last_(started),
      interval_(interval),
      command_(std::move(command)),
      unit_(std::move(unit)) {}

std::optional<std::string> SweepProgress::line(std::uint64_t written, Clock::time_point now) {
  if (now - last_ < interval_ || written >= rows_) return std::nullopt;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - started_).count();
  std::string line = fmt::format("{}: {} of {} {} in {}", command_, written, rows_, unit_,
                                 rough_duration(elapsed));
  if (written > done_) {
    const double per_row = elapsed / static_cast<double>(written - done_);
    line += ", about " + rough_duration(per_row * static_cast<double>(rows_ - written)) + " to go";
  }
  return line;
}

std::string rough_duration(double seconds) {
  if (seconds < 99.5) return fmt::format("{:.0f} s", seconds);
  if (seconds < 99.5 * 60) return fmt::format("{:.0f} min", seconds / 60);
  return fmt::format("{:.2g} h", seconds / 3600);
}

}  // namespace mdrsim::cli
