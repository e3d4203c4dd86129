// What rebinding's last look along the run of sticking springs from the glue's front found, kept
// while nothing in that stretch changes at that time: a cascade of glues from the front, or of
// sticks beyond the run's end, then looks at each spring once instead of once a change.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>

namespace mdrsim {

class RebindingRunMemo {
 public:
  /// Where a look from the front `front` at `time` [s] resumes: the springs from `front` to
  /// the returned one (excluded) stick and do not hold; `holds`: the returned one sticks and holds
  /// (so the front glues now). None: the look starts at the front.
  struct Resume {
    std::size_t from;
    bool holds;
  };
  std::optional<Resume> resume(double time, std::size_t front) const {
    if (time != time_ || front < front_ || front > reached_) return std::nullopt;
    return Resume{reached_, holder_};
  }
  /// The look from `front` at `time` [s] stopped at spring `reached`: a holding spring
  /// (`holder`) or the first that does not stick.
  void record(double time, std::size_t front, std::size_t reached, bool holder) {
    time_ = time;
    front_ = front;
    reached_ = reached;
    holder_ = holder;
  }
  /// Spring `spring` changes now: what was seen of it is stale, unless it is the front gluing
  /// (the look from the next spring finds the same) or the spring that ended the run (the look
  /// resumes at it).
  void change(std::size_t spring, bool front_glues) {
    if (spring < front_ || spring > reached_ || (spring == reached_ && !holder_)) return;
    if (front_glues && spring == front_ && spring < reached_) {
      ++front_;
      return;
    }
    forget();
  }
  void forget() { time_ = NAN; }

 private:
  double time_ = NAN;
  std::size_t front_ = 0;
  std::size_t reached_ = 0;
  bool holder_ = false;
};

}  // namespace mdrsim
