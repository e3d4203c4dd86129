// The viscoelastic row's event loop: a queue of each spring's next touch, release, glue or
// let-go.
#include "engine/program/viscoelastic_row.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <set>

#include "engine/model/compensated_sum.hpp"
#include "engine/model/prony_arms.hpp"
#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_shared_drive.hpp"
#include "engine/model/viscoelastic_edge.hpp"

namespace mdrsim {
namespace {

/// pressed: in contact, pushing only; glued: in contact, holding tension too.
enum class ViscoelasticSpringPhase { untouched, pressed, glued, free };

struct ViscoelasticSpringState {
  ViscoelasticSpringPhase phase = ViscoelasticSpringPhase::untouched;
  SharedDriveMember member;              ///< while pressed or glued
  std::optional<FreeSpringCreep> creep;  ///< while free
  double released_at = 0.0;              ///< [s]
  double glued_at = -1.0;                ///< [s] the last glue; < 0: never glued
  /// The energy summed up to `counted_at` [s]: while in contact, the stretch [m] and arm stresses
  /// [N/m] then; while free, the energy it stored then [J/m].
  double counted_at = 0.0;
  double counted_stretch = 0.0;
  std::vector<double> counted_stresses;
  double counted_stored = 0.0;
  std::uint32_t version = 0;  ///< bumped at each change: older queue entries are stale
};

/// The share of a let-go load within which a boundary spring's load is on it (a load summed
/// from E* w and the arms rounds at a few eps of its terms).
constexpr double kEdgeRounding = 64.0 * std::numeric_limits<double>::epsilon();

struct ViscoelasticRowEvent {
  double time;
  std::size_t spring;
  std::uint32_t version;
  bool operator>(const ViscoelasticRowEvent& other) const {
    return time != other.time ? time > other.time : spring > other.spring;
  }
};

/// The integrals of an arm's stress sigma(h) = c + (sigma_0 - c) exp(-h / tau), c = E_j w' tau,
/// over [0, h] [N s / m] and of its square [N^2 s / m^2].
struct ArmStressIntegrals {
  double stress;
  double square;
};

ArmStressIntegrals arm_stress_integrals(const PronyTerm& term, double sigma0, double rate,
                                        double h) {
  const double c = term.modulus * rate * term.time;
  const double a = sigma0 - c;
  const double once = -std::expm1(-h / term.time) * term.time;
  const double twice = -std::expm1(-2.0 * h / term.time) * term.time * 0.5;
  return {c * h + a * once, c * c * h + 2.0 * c * a * once + a * a * twice};
}

}  // namespace

class ViscoelasticRowDrive::Row {
 public:
  explicit Row(const ViscoelasticRowSprings& springs)
      : springs_(springs),
        arms_(springs.terms),
        modes_(std::make_shared<const RetardationModes>(springs.relaxed_modulus, springs.terms)),
        state_(springs.images.size()) {}

  /// A new segment from the present time: every spring's next event within it is queued (the
  /// energy summed up to now, the rate changing).
  void begin_segment(const DriveSegment& segment) {
    count_all();
    segment_start_ = time_;
    segment_depth_ = depth_;
    rate_ = segment.rate;
    end_ = time_ + segment.duration;
    end_depth_ = segment.end_depth.value_or(depth_ + rate_ * segment.duration);
    queue_ = {};
    for (std::size_t k = 0; k < state_.size(); ++k) schedule(k);
  }

  double end() const { return end_; }
  double spacing() const { return springs_.spacing; }
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
    depth_ = t == end_ ? end_depth_ : segment_depth_ + rate_ * (t - segment_start_);
  }

  /// The queued event of spring k at the present time: a touch, a release, a glue or a let-go.
  ViscoelasticRowChange apply(std::size_t k, ViscoelasticRowRun& run) {
    queue_.pop();
    if (springs_.edge) return apply_at_edge(k, run);
    ViscoelasticSpringState& s = state_[k];
    const bool release = s.phase == ViscoelasticSpringPhase::pressed;
    if (release) {
      count_pressed(s, springs_.images[k]);
      const std::vector<double> stresses = arms_.leave(s.member);
      s.counted_stored = stored_of(-sum_of(stresses) / springs_.relaxed_modulus, stresses);
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
      if (s.phase == ViscoelasticSpringPhase::free) count_free(s);
      s.member = arms_.enter(stresses, 1.0);
      s.counted_at = time_;
      s.counted_stretch = depth_ - springs_.images[k];
      s.counted_stresses = stresses;
      s.creep.reset();
      s.phase = ViscoelasticSpringPhase::pressed;
      pressed_.insert(k);
      pressed_images_.add(springs_.images[k]);
      ++run.touches;
      run.separation_time.reset();
    }
    ++s.version;
    schedule(k);
    return release ? ViscoelasticRowChange::release : ViscoelasticRowChange::touch;
  }

  bool in_contact() const { return !pressed_.empty(); }

  /// The energy up to now, per unit x of one half [J/m].
  ViscoelasticRowEnergy energy() {
    count_all();
    ViscoelasticRowEnergy e{machine_work_.value(), 0.0, dissipated_.value(), surface_.value(),
                            jump_losses_.value()};
    CompensatedSum stored;
    for (std::size_t k = 0; k < state_.size(); ++k) {
      const ViscoelasticSpringState& s = state_[k];
      if (in_contact(s)) {
        stored.add(stored_of(s.counted_stretch, s.counted_stresses));
      } else if (s.phase == ViscoelasticSpringPhase::free) {
        stored.add(s.counted_stored);
      }
    }
    e.stored = stored.value();
    return e;
  }

  ViscoelasticRowSample sample() const {
    const auto n = static_cast<double>(pressed_.size());
    const double line_loads =
        springs_.relaxed_modulus * (n * depth_ - pressed_images_.value()) + arms_.arm_force();
    const double radius =
        pressed_.empty() ? 0.0 : springs_.spacing * static_cast<double>(*pressed_.rbegin() + 1);
    const double glued_radius =
        glued_.empty() ? 0.0 : springs_.spacing * static_cast<double>(*glued_.rbegin() + 1);
    return {time_,
            depth_,
            2.0 * springs_.spacing * line_loads,
            radius,
            static_cast<std::int64_t>(pressed_.size()),
            static_cast<std::int64_t>(glued_.size()),
            glued_radius};
  }

 private:
  static bool in_contact(const ViscoelasticSpringState& s) {
    return s.phase == ViscoelasticSpringPhase::pressed || s.phase == ViscoelasticSpringPhase::glued;
  }

  /// The outermost glued spring, the one that may let go; none without glue.
  std::optional<std::size_t> boundary() const {
    if (glued_.empty()) return std::nullopt;
    return *glued_.rbegin();
  }
  /// The spring just outside the contact (the outermost spring in contact, glued or pressed),
  /// the one the advancing front may glue; none beyond the row.
  std::optional<std::size_t> outside() const {
    const std::size_t k = pressed_.empty() ? 0 : *pressed_.rbegin() + 1;
    if (k >= state_.size()) return std::nullopt;
    return k;
  }
  /// Whether spring k glues when the advancing front reaches it (else it is pressed on touch):
  /// it is the spring outside the contact, and fresh or free with rebinding.
  bool glues(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    const bool may = s.phase == ViscoelasticSpringPhase::untouched ||
                     (s.phase == ViscoelasticSpringPhase::free && springs_.edge->rebinding);
    return may && outside() == k;
  }
  /// The gap [m] at which spring k glues: the edge's, but touch for the very first spring.
  double glue_gap(std::size_t k) const {
    return pressed_.empty() ? 0.0 : springs_.edge->glue_gaps[k];
  }

  /// apply() with an adhesive edge: the spring's change, the energy of its step, and the
  /// springs whose role it changed (the boundary, the spring outside) scheduled again.
  ViscoelasticRowChange apply_at_edge(std::size_t k, ViscoelasticRowRun& run) {
    const auto boundary_before = boundary();
    const auto outside_before = outside();
    ViscoelasticSpringState& s = state_[k];
    ViscoelasticRowChange change = ViscoelasticRowChange::touch;
    if (s.phase == ViscoelasticSpringPhase::glued) {
      change = ViscoelasticRowChange::let_go;
      let_go(k, run);
    } else if (s.phase == ViscoelasticSpringPhase::pressed) {
      change = ViscoelasticRowChange::release;
      leave_contact(k, run);
    } else if (glues(k)) {
      change = ViscoelasticRowChange::glue;
      enter_contact(k, run, glue_gap(k));
    } else {
      enter_contact(k, run, std::nullopt);
    }
    for (const auto j :
         {std::optional<std::size_t>(k), boundary_before, outside_before, boundary(), outside()}) {
      if (!j) continue;
      ++state_[*j].version;
      schedule(*j);
    }
    return change;
  }

  /// The boundary spring k lets go: its stretch steps by -q / E_0 to zero load.
  void let_go(std::size_t k, ViscoelasticRowRun& run) {
    ViscoelasticSpringState& s = state_[k];
    count_pressed(s, springs_.images[k]);
    std::vector<double> stresses = arms_.leave(s.member);
    const double stretch = depth_ - springs_.images[k];
    const double load = springs_.relaxed_modulus * stretch + sum_of(stresses);
    const double before = stored_of(stretch, stresses);
    glassy_step(stresses, springs_.terms, -load / springs_.edge->glassy_modulus);
    const double after = stored_of(-sum_of(stresses) / springs_.relaxed_modulus, stresses);
    const double surface = springs_.edge->surface_energies[k];
    surface_.add(surface);
    jump_losses_.add(before - after - surface);
    s.counted_stored = after;
    s.counted_at = time_;
    s.creep.emplace(modes_, stresses);
    s.released_at = time_;
    s.phase = ViscoelasticSpringPhase::free;
    pressed_.erase(k);
    glued_.erase(k);
    pressed_images_.add(-springs_.images[k]);
    ++run.let_gos;
    if (pressed_.empty()) run.separation_time = time_;
  }

  /// A pressed spring k leaves at zero load.
  void leave_contact(std::size_t k, ViscoelasticRowRun& run) {
    ViscoelasticSpringState& s = state_[k];
    count_pressed(s, springs_.images[k]);
    const std::vector<double> stresses = arms_.leave(s.member);
    s.counted_stored = stored_of(-sum_of(stresses) / springs_.relaxed_modulus, stresses);
    s.counted_at = time_;
    s.creep.emplace(modes_, stresses);
    s.released_at = time_;
    s.phase = ViscoelasticSpringPhase::free;
    pressed_.erase(k);
    pressed_images_.add(-springs_.images[k]);
    ++run.releases;
    if (pressed_.empty()) run.separation_time = time_;
  }

  /// Spring k enters the contact: pressed on touch (`glue_gap` unset), or glued, its stretch
  /// stepping from its free surface's to the indenter's.
  void enter_contact(std::size_t k, ViscoelasticRowRun& run, std::optional<double> glue_gap) {
    ViscoelasticSpringState& s = state_[k];
    const bool free = s.phase == ViscoelasticSpringPhase::free;
    std::vector<double> stresses = free ? s.creep->stresses(time_ - s.released_at)
                                        : std::vector<double>(springs_.terms.size(), 0.0);
    double before = 0.0;
    double free_stretch = 0.0;
    if (free) {
      count_free(s);
      before = s.counted_stored;
      free_stretch = s.creep->stretch(time_ - s.released_at);
    }
    const double stretch = depth_ - springs_.images[k];
    if (glue_gap) {
      glassy_step(stresses, springs_.terms, stretch - free_stretch);
      const double surface = springs_.edge->surface_energies[k];
      surface_.add(-surface);
      jump_losses_.add(surface - (stored_of(stretch, stresses) - before));
      glued_.insert(k);
      s.glued_at = time_;
      ++run.glues;
    } else {
      ++run.touches;
    }
    s.member = arms_.enter(stresses, 1.0);
    s.counted_at = time_;
    s.counted_stretch = stretch;
    s.counted_stresses = stresses;
    s.creep.reset();
    s.phase = glue_gap ? ViscoelasticSpringPhase::glued : ViscoelasticSpringPhase::pressed;
    pressed_.insert(k);
    pressed_images_.add(springs_.images[k]);
    run.separation_time.reset();
  }
  static double sum_of(const std::vector<double>& values) {
    double sum = 0.0;
    for (const double v : values) sum += v;
    return sum;
  }

  /// What a spring of stretch w and arm stresses sigma_j stores [J/m]: E* w^2 / 2 +
  /// sum_j sigma_j^2 / (2 E_j).
  double stored_of(double stretch, const std::vector<double>& stresses) const {
    double e = 0.5 * springs_.relaxed_modulus * stretch * stretch;
    for (std::size_t j = 0; j < stresses.size(); ++j) {
      e += 0.5 * stresses[j] * stresses[j] / springs_.terms[j].modulus;
    }
    return e;
  }

  /// A pressed spring's work and dissipation from its last count to now, the drive's rate
  /// unchanged in between (every pressed spring is counted where the rate changes).
  void count_pressed(ViscoelasticSpringState& s, double image) {
    const double h = time_ - s.counted_at;
    const double w0 = s.counted_stretch;
    double load_integral = springs_.relaxed_modulus * (w0 * h + 0.5 * rate_ * h * h);
    double dissipated = 0.0;
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      const PronyTerm& term = springs_.terms[j];
      const ArmStressIntegrals i = arm_stress_integrals(term, s.counted_stresses[j], rate_, h);
      load_integral += i.stress;
      dissipated += i.square / (term.modulus * term.time);
      s.counted_stresses[j] = arms_.stress(s.member, j);
    }
    machine_work_.add(rate_ * load_integral);
    dissipated_.add(dissipated);
    s.counted_at = time_;
    s.counted_stretch = depth_ - image;
  }

  /// A free spring's dissipation from its last count to now: the energy it stores less.
  void count_free(ViscoelasticSpringState& s) {
    const double t = time_ - s.released_at;
    const double stored = stored_of(s.creep->stretch(t), s.creep->stresses(t));
    dissipated_.add(s.counted_stored - stored);
    s.counted_stored = stored;
    s.counted_at = time_;
  }

  void count_all() {
    for (const std::size_t k : pressed_) count_pressed(state_[k], springs_.images[k]);
    for (ViscoelasticSpringState& s : state_) {
      if (s.phase == ViscoelasticSpringPhase::free) count_free(s);
    }
  }

  /// Spring k's next event from now within the segment, queued; none beyond its end.
  void schedule(std::size_t k) {
    if (const auto delay = next_event_delay(k)) {
      queue_.push({time_ + *delay, k, state_[k].version});
    }
  }

  std::optional<double> next_event_delay(std::size_t k) const {
    if (springs_.edge) return next_event_delay_at_edge(k);
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
    // A spring at zero load that stays there (met at the turn of a hold) stays pressed, as an
    // elastic row counts a spring whose image the depth reaches.
    if (now <= 0.0 && load.slope_at(0.0) < 0.0) return 0.0;
    if (now < 0.0) load.constant -= now;
    return first_crossing(load, 0.0, span);
  }

  /// next_event_delay() with an adhesive edge: a glued spring lets go only as the boundary, at
  /// its load -let_go_loads; the spring outside the contact glues at its glue gap where it
  /// glues(), any other spring out of contact is pressed on touch; a pressed one leaves at zero
  /// load.
  std::optional<double> next_event_delay_at_edge(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    const double span = end_ - time_;
    const double stretch = depth_ - springs_.images[k];
    if (s.phase == ViscoelasticSpringPhase::glued) {
      if (boundary() != k) return std::nullopt;
      ExponentialSum load = load_over(s, stretch);
      const double level = -springs_.edge->let_go_loads[k];
      // Beyond the threshold it goes now (a cascade), on it only if the tension grows. A spring
      // that glued just now sits on it (at dgamma_a = dgamma, up to the rounding of loads summed
      // from stresses far larger than it): it starts on it.
      const double slack = load.at(0.0) - level;
      const double slope = load.slope_at(0.0);
      const bool on_it = s.glued_at == time_ || -slack <= kEdgeRounding * std::abs(level);
      if (slack <= 0.0 && (slope < 0.0 || !on_it)) return 0.0;
      // Within rounding below the level: the level is taken where the load stands, so that the
      // crossing is the one back down, after the load has risen.
      return first_crossing(load, slack < 0.0 ? load.at(0.0) : level, span);
    }
    if (s.phase == ViscoelasticSpringPhase::pressed) {
      ExponentialSum load = load_over(s, stretch);
      const double now = load.at(0.0);
      if (now <= 0.0 && load.slope_at(0.0) < 0.0) return 0.0;
      if (now < 0.0) load.constant -= now;
      return first_crossing(load, 0.0, span);
    }
    // Out of contact: the indenter's stretch moved by the gap at which it takes the spring.
    const double gap = glues(k) ? glue_gap(k) : 0.0;
    const double reach = stretch + gap;
    if (s.phase == ViscoelasticSpringPhase::untouched) {
      if (reach >= 0.0) return 0.0;
      if (rate_ <= 0.0) return std::nullopt;
      const double delay = -reach / rate_;
      return delay <= span ? std::optional<double>(delay) : std::nullopt;
    }
    // Within rounding of its free surface (of d and g, far larger than it) the indenter stands
    // on it (with dgamma_a = dgamma a spring that let go stands at its glue gap), and takes it
    // only as the motion leads on; a spring that glued and let go at this time is not taken
    // back at it.
    const ExponentialSum free_surface = s.creep->stretch_from(time_ - s.released_at);
    const double surface = free_surface.at(0.0);
    const double overlap = reach - surface;
    const double rounding =
        kEdgeRounding * (std::abs(depth_) + std::abs(springs_.images[k]) + std::abs(surface) + gap);
    const bool approaching = rate_ - free_surface.slope_at(0.0) > 0.0;
    const bool again_now = s.glued_at == time_;
    if (!again_now && (overlap > rounding || (overlap >= -rounding && approaching))) return 0.0;
    return reach_time(*s.creep, time_ - s.released_at, reach, rate_, span, overlap >= -rounding);
  }

  /// Spring s's line load from now over the segment's motion (its stretch `stretch` now).
  ExponentialSum load_over(const ViscoelasticSpringState& s, double stretch) const {
    std::vector<double> stresses(springs_.terms.size());
    for (std::size_t j = 0; j < stresses.size(); ++j) stresses[j] = arms_.stress(s.member, j);
    return line_load_over(springs_.relaxed_modulus, springs_.terms, stretch, stresses, rate_);
  }

  const ViscoelasticRowSprings& springs_;
  SharedDriveArms arms_;
  std::shared_ptr<const RetardationModes> modes_;
  std::vector<ViscoelasticSpringState> state_;
  std::set<std::size_t> pressed_;  ///< in contact: pressed or glued
  std::set<std::size_t> glued_;
  CompensatedSum pressed_images_;
  std::priority_queue<ViscoelasticRowEvent, std::vector<ViscoelasticRowEvent>, std::greater<>>
      queue_;
  double time_ = 0.0;
  double depth_ = 0.0;
  double segment_start_ = 0.0;
  double segment_depth_ = 0.0;
  double rate_ = 0.0;
  double end_ = 0.0;
  double end_depth_ = 0.0;
  CompensatedSum machine_work_;  ///< [J/m]
  CompensatedSum dissipated_;    ///< [J/m]
  CompensatedSum surface_;       ///< [J/m]
  CompensatedSum jump_losses_;   ///< [J/m]
};

ViscoelasticRowDrive::ViscoelasticRowDrive(const ViscoelasticRowSprings& springs)
    : row_(std::make_unique<Row>(springs)) {}

ViscoelasticRowDrive::~ViscoelasticRowDrive() = default;

bool ViscoelasticRowDrive::run(const DriveSegment& segment, bool stop_at_separation,
                               std::span<const double> sample_times,
                               std::vector<ViscoelasticRowSample>& samples,
                               const OnChange& on_change) {
  Row& row = *row_;
  row.begin_segment(segment);
  std::size_t next_sample = 0;
  for (;;) {
    const auto event = row.next_event();
    const double event_time = event ? event->time : row.end();
    // Samples at or before the next event see the state before it.
    while (next_sample < sample_times.size() && sample_times[next_sample] <= event_time &&
           sample_times[next_sample] <= row.end()) {
      row.advance_to(sample_times[next_sample++]);
      samples.push_back(row.sample());
    }
    if (!event) break;
    row.advance_to(event->time);
    // A release or a let-go is reported as the spring leaves (the state before it is removed,
    // as an elastic program's lift), a touch or a glue with the spring in contact.
    const ViscoelasticRowSample before = row.sample();
    before_last_change_ = before;
    const ViscoelasticRowChange change = row.apply(event->spring, counts_);
    const bool leaves =
        change == ViscoelasticRowChange::release || change == ViscoelasticRowChange::let_go;
    if (on_change) on_change(change, leaves ? before : row.sample());
    if (stop_at_separation && leaves && !row.in_contact()) return true;
    if (counts_.events() >= event_limit_) {
      limited_ = true;
      return false;
    }
  }
  row.advance_to(row.end());
  return false;
}

ViscoelasticRowSample ViscoelasticRowDrive::sample() const { return row_->sample(); }

ViscoelasticRowEnergy ViscoelasticRowDrive::energy() {
  ViscoelasticRowEnergy e = row_->energy();
  // Both halves: each spring of the row stands for 2 dx of the foundation.
  const double both_halves = 2.0 * row_->spacing();
  return {e.machine_work * both_halves, e.stored * both_halves, e.dissipated_by_bulk * both_halves,
          e.surface * both_halves, e.jump_losses * both_halves};
}

ViscoelasticRowRun run_viscoelastic_row(const ViscoelasticRowSprings& springs,
                                        std::span<const DriveSegment> segments,
                                        std::span<const double> sample_times) {
  ViscoelasticRowDrive drive(springs);
  std::vector<ViscoelasticRowSample> samples;
  std::size_t first = 0;
  double start = 0.0;
  for (const DriveSegment& segment : segments) {
    // Each segment takes the samples up to its end; the last takes the rest within it.
    std::size_t last = first;
    while (last < sample_times.size() && sample_times[last] <= start + segment.duration) ++last;
    drive.run(segment, false, sample_times.subspan(first, last - first), samples);
    first = last;
    start += segment.duration;
  }
  ViscoelasticRowRun run = drive.counts();
  run.samples = std::move(samples);
  return run;
}

}  // namespace mdrsim
