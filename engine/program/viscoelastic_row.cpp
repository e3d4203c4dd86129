// The viscoelastic row's event loop: a queue of each spring's next touch or release.
#include "engine/program/viscoelastic_row.hpp"

#include <functional>
#include <memory>
#include <queue>
#include <set>

#include "engine/model/compensated_sum.hpp"
#include "engine/model/prony_arms.hpp"
#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_shared_drive.hpp"

namespace mdrsim {
namespace {

enum class ViscoelasticSpringPhase { untouched, pressed, free };

struct ViscoelasticSpringState {
  ViscoelasticSpringPhase phase = ViscoelasticSpringPhase::untouched;
  SharedDriveMember member;              ///< while pressed
  std::optional<FreeSpringCreep> creep;  ///< while free
  double released_at = 0.0;              ///< [s]
  std::uint32_t version = 0;             ///< bumped at each change: older queue entries are stale
};

struct ViscoelasticRowEvent {
  double time;
  std::size_t spring;
  std::uint32_t version;
  bool operator>(const ViscoelasticRowEvent& other) const {
    return time != other.time ? time > other.time : spring > other.spring;
  }
};

class ViscoelasticRow {
 public:
  explicit ViscoelasticRow(const ViscoelasticRowSprings& springs)
      : springs_(springs),
        arms_(springs.terms),
        modes_(std::make_shared<const RetardationModes>(springs.relaxed_modulus, springs.terms)),
        state_(springs.images.size()) {}

  /// A new segment from the present time: every spring's next event within it is queued.
  void begin_segment(const DriveSegment& segment) {
    segment_start_ = time_;
    segment_depth_ = depth_;
    rate_ = segment.rate;
    end_ = time_ + segment.duration;
    queue_ = {};
    for (std::size_t k = 0; k < state_.size(); ++k) schedule(k);
  }

  double end() const { return end_; }
  std::optional<ViscoelasticRowEvent> next_event() {
    while (!queue_.empty() && queue_.top().version != state_[queue_.top().spring].version) {
      queue_.pop();
    }
    if (queue_.empty()) return std::nullopt;
    return queue_.top();
  }

  void advance_to(double t) {
    arms_.advance(rate_, t - time_);
    time_ = t;
    depth_ = segment_depth_ + rate_ * (t - segment_start_);
  }

  /// The queued event of spring k at the present time: a touch or a release.
  void apply(std::size_t k, ViscoelasticRowRun& run) {
    queue_.pop();
    ViscoelasticSpringState& s = state_[k];
    if (s.phase == ViscoelasticSpringPhase::pressed) {
      const std::vector<double> stresses = arms_.leave(s.member);
      s.creep.emplace(modes_, stresses);
      s.released_at = time_;
      s.phase = ViscoelasticSpringPhase::free;
      pressed_.erase(k);
      pressed_images_.add(-springs_.images[k]);
      ++run.releases;
      if (pressed_.empty()) run.separation_time = time_;
    } else {
      const std::vector<double> stresses = s.phase == ViscoelasticSpringPhase::free
                                               ? s.creep->stresses(time_ - s.released_at)
                                               : std::vector<double>(springs_.terms.size(), 0.0);
      s.member = arms_.enter(stresses, 1.0);
      s.creep.reset();
      s.phase = ViscoelasticSpringPhase::pressed;
      pressed_.insert(k);
      pressed_images_.add(springs_.images[k]);
      ++run.touches;
      run.separation_time.reset();
    }
    ++s.version;
    schedule(k);
  }

  ViscoelasticRowSample sample() const {
    const auto n = static_cast<double>(pressed_.size());
    const double line_loads =
        springs_.relaxed_modulus * (n * depth_ - pressed_images_.value()) + arms_.arm_force();
    const double radius =
        pressed_.empty() ? 0.0 : springs_.spacing * static_cast<double>(*pressed_.rbegin() + 1);
    return {time_, depth_, 2.0 * springs_.spacing * line_loads, radius,
            static_cast<std::int64_t>(pressed_.size())};
  }

 private:
  /// Spring k's next event from now within the segment, queued; none beyond its end.
  void schedule(std::size_t k) {
    if (const auto delay = next_event_delay(k)) {
      queue_.push({time_ + *delay, k, state_[k].version});
    }
  }

  std::optional<double> next_event_delay(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    const double span = end_ - time_;
    const double stretch = depth_ - springs_.images[k];
    if (s.phase == ViscoelasticSpringPhase::untouched) {
      if (stretch >= 0.0) return 0.0;
      if (rate_ <= 0.0) return std::nullopt;
      const double delay = -stretch / rate_;
      return delay <= span ? std::optional<double>(delay) : std::nullopt;
    }
    // A touch or a release leaves the spring at zero overlap or zero load up to rounding: it
    // acts at once only when the sign says so and the motion leads on (no back-and-forth at
    // one time), and a spring within rounding of the level on the wrong side starts on it.
    if (s.phase == ViscoelasticSpringPhase::free) {
      const ExponentialSum free_surface = s.creep->stretch_from(time_ - s.released_at);
      const double overlap = stretch - free_surface.at(0.0);
      if (overlap >= 0.0 && rate_ - free_surface.slope_at(0.0) > 0.0) return 0.0;
      return touch_time(*s.creep, time_ - s.released_at,
                        overlap > 0.0 ? stretch - overlap : stretch, rate_, span);
    }
    std::vector<double> stresses(springs_.terms.size());
    for (std::size_t j = 0; j < stresses.size(); ++j) stresses[j] = arms_.stress(s.member, j);
    ExponentialSum load =
        line_load_over(springs_.relaxed_modulus, springs_.terms, stretch, stresses, rate_);
    const double now = load.at(0.0);
    if (now <= 0.0 && load.slope_at(0.0) <= 0.0) return 0.0;
    if (now < 0.0) load.constant -= now;
    return first_crossing(load, 0.0, span);
  }

  const ViscoelasticRowSprings& springs_;
  SharedDriveArms arms_;
  std::shared_ptr<const RetardationModes> modes_;
  std::vector<ViscoelasticSpringState> state_;
  std::set<std::size_t> pressed_;
  CompensatedSum pressed_images_;
  std::priority_queue<ViscoelasticRowEvent, std::vector<ViscoelasticRowEvent>, std::greater<>>
      queue_;
  double time_ = 0.0;
  double depth_ = 0.0;
  double segment_start_ = 0.0;
  double segment_depth_ = 0.0;
  double rate_ = 0.0;
  double end_ = 0.0;
};

}  // namespace

ViscoelasticRowRun run_viscoelastic_row(const ViscoelasticRowSprings& springs,
                                        std::span<const DriveSegment> segments,
                                        std::span<const double> sample_times) {
  ViscoelasticRowRun run;
  ViscoelasticRow row(springs);
  std::size_t next_sample = 0;
  for (const DriveSegment& segment : segments) {
    row.begin_segment(segment);
    for (;;) {
      const auto event = row.next_event();
      const double event_time = event ? event->time : row.end();
      // Samples at or before the next event see the state before it.
      while (next_sample < sample_times.size() && sample_times[next_sample] <= event_time &&
             sample_times[next_sample] <= row.end()) {
        row.advance_to(sample_times[next_sample++]);
        run.samples.push_back(row.sample());
      }
      if (!event) break;
      row.advance_to(event->time);
      row.apply(event->spring, run);
    }
    row.advance_to(row.end());
  }
  return run;
}

}  // namespace mdrsim
