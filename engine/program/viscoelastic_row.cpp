// The viscoelastic row's event loop: each spring's next touch, release, glue or let-go, queued
// (or, in a held segment, indexed).
#include "engine/program/viscoelastic_row.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <set>

#include "engine/base/large_pages.hpp"
#include "engine/model/compensated_sum.hpp"
#include "engine/model/decay_integrals.hpp"
#include "engine/model/exponential_sum_total.hpp"
#include "engine/model/prony_arms.hpp"
#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_held_shear.hpp"
#include "engine/model/prony_load_drive.hpp"
#include "engine/model/prony_shared_drive.hpp"
#include "engine/model/prony_shared_energy.hpp"
#include "engine/model/viscoelastic_edge.hpp"
#include "engine/program/rebinding_run.hpp"
#include "engine/program/viscoelastic_holding.hpp"
#include "engine/program/viscoelastic_slide.hpp"

namespace mdrsim {
// The row's parts, in a namespace of their own rather than an anonymous one: the Row class
// holds them as fields, which a unity build (Python's package) would flag (-Wsubobject-linkage).
namespace viscoelastic_row_parts {

/// pressed: in contact, pushing only; glued: in contact, holding tension too.
enum class ViscoelasticSpringPhase { untouched, pressed, glued, free };

/// A spring's tangential arms: while glued, the member and u_x where the spring's tangential
/// stretch is zero; otherwise the free creep of what a let-go left; the energy counted as the
/// normal arms' is.
struct ViscoelasticSpringShear {
  SharedDriveMember member;
  double origin = 0.0;  ///< [m]
  std::optional<FreeSpringCreep> creep;
  double free_since = 0.0;  ///< [s]
  double counted_stretch = 0.0;
  FewValues<double> counted_stresses;
  double counted_stored = 0.0;
  /// Whether the member is in the tangential arms' set (glued, or pressed and sticking).
  bool in_set = false;
  /// With friction: the slide of a pressed spring at its limit; none while it sticks.
  std::unique_ptr<ViscoelasticSlide> slide;
  /// With friction: the spring's queued event (next_event_delay): 0 none, +1 / -1 a slip along
  /// +x / -x, kStickEvent a stick.
  std::int8_t friction_event = 0;
  double changed_at = -1.0;  ///< [s] its last slip or stick
};

constexpr std::int8_t kStickEvent = 2;
/// With friction and rebinding: a sticking pressed spring at the glue's front glues.
constexpr std::int8_t kGlueEvent = 3;

struct ViscoelasticSpringState {
  ViscoelasticSpringPhase phase = ViscoelasticSpringPhase::untouched;
  std::uint32_t version = 0;  ///< bumped at each change: older queue entries are stale
  /// While pressed or glued: when it joined the arms [s] (its offsets in the row's store).
  double entry_time = 0.0;
  double released_at = 0.0;  ///< [s]
  double glued_at = -1.0;    ///< [s] the last glue; < 0: never glued
  double lifted_at = -1.0;   ///< [s] the last release from pressed; < 0: never
  /// The energy summed up to `counted_at` [s]: while in contact, the stretch [m] and arm stresses
  /// [N/m] (in the row's store) then; while free, the energy it stored then [J/m].
  double counted_at = 0.0;
  double counted_stretch = 0.0;
  double counted_stored = 0.0;
  /// The tangential arms, made when the spring first glues under a tangential drive (so that a
  /// row without one carries none of them, O(1) numbers a spring).
  std::unique_ptr<ViscoelasticSpringShear> shear;
};

/// A spring's key in a held segment's search (Row::index_held).
struct HeldSpringKey {
  double key;
  std::size_t spring;
  std::uint32_t version;
  double valid_until = HUGE_VAL;  ///< [s]: a free spring's key bounds it until then
  std::uint32_t generation = 0;   ///< a free spring's keys are renewed: older ones are stale
};
struct HeldKeyBelow {
  bool operator()(const HeldSpringKey& a, const HeldSpringKey& b) const { return a.key < b.key; }
};
struct HeldKeyAbove {
  bool operator()(const HeldSpringKey& a, const HeldSpringKey& b) const { return a.key > b.key; }
};
struct HeldKeyExpiresLater {
  bool operator()(const HeldSpringKey& a, const HeldSpringKey& b) const {
    return a.valid_until > b.valid_until;
  }
};
/// The share of a let-go load within which a boundary spring's load is on it (a load summed
/// from E* w and the arms rounds at a few eps of its terms).
constexpr double kEdgeRounding = 64.0 * std::numeric_limits<double>::epsilon();

/// A set of springs by index (those in contact, those glued): a flag per spring, their count and
/// the outermost. Springs mostly leave from the outside in, so the next outermost is found by a
/// short scan of the flags' words below the one that left.
class RowSpringSet {
 public:
  explicit RowSpringSet(std::size_t springs) : words_((springs + 63) / 64, 0) {}
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  /// The largest index in the set; the set must not be empty.
  std::size_t outermost() const { return outermost_; }
  void insert(std::size_t k) {
    std::uint64_t& word = words_[k / 64];
    const std::uint64_t bit = std::uint64_t{1} << (k % 64);
    if (word & bit) return;
    word |= bit;
    outermost_ = size_ == 0 ? k : std::max(outermost_, k);
    ++size_;
  }
  void erase(std::size_t k) {
    std::uint64_t& word = words_[k / 64];
    const std::uint64_t bit = std::uint64_t{1} << (k % 64);
    if (!(word & bit)) return;
    word &= ~bit;
    if (--size_ == 0) {
      outermost_ = 0;
    } else if (k == outermost_) {
      std::size_t w = k / 64;
      while (words_[w] == 0) --w;  // a member remains below k
      outermost_ = 64 * w + static_cast<std::size_t>(std::bit_width(words_[w])) - 1;
    }
  }

 private:
  std::vector<std::uint64_t> words_;
  std::size_t size_ = 0;
  std::size_t outermost_ = 0;
};

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
ArmStressIntegrals arm_stress_integrals(const PronyTerm& term, double sigma0, double rate,
                                        double h) {
  return arm_stress_integrals(decay_integrals(h, term.time), sigma0,
                              term.modulus * rate * term.time);
}

/// Whether f(s) = c + b s + sum_j a_j exp(-s / tau_j) cannot fall for s >= 0: b >= 0 and every
/// a_j <= 0 (a pressed spring's load while the drive presses and its arms stand below their
/// steady stress). Its values rounded are monotone too (each a_j exp(-s / tau_j) rounds to at
/// least a_j), so first_crossing from f(0) >= 0 to the level 0 finds nothing, and need not look.
bool loads_up(const ExponentialSum& f) {
  return f.slope >= 0.0 &&
         std::all_of(f.decays.begin(), f.decays.end(),
                     [](const ExponentialDecay& d) { return d.amplitude <= 0.0; });
}

/// f'(s) as an exponential sum.
ExponentialSum exponential_sum_slope(const ExponentialSum& f) {
  ExponentialSum slope{f.slope, 0.0, {}};
  for (const ExponentialDecay& d : f.decays)
    slope.decays.push_back({-d.amplitude / d.time, d.time});
  return slope;
}

/// The times in (0, span] [s] where f crosses zero, in order: each found by first_crossing from
/// the last (an exponential sum with K decays has at most K + 1 zeros); none where f is zero
/// throughout.
void exponential_sum_zeros(const ExponentialSum& f, double span, std::vector<double>& zeros) {
  const bool identically_zero =
      f.constant == 0.0 && f.slope == 0.0 &&
      std::all_of(f.decays.begin(), f.decays.end(),
                  [](const ExponentialDecay& d) { return d.amplitude == 0.0; });
  if (identically_zero) return;
  double from = 0.0;
  ExponentialSum shifted = f;
  for (std::size_t found = 0; found <= f.decays.size() + 1 && from < span; ++found) {
    const auto zero = first_crossing(shifted, 0.0, span - from);
    if (!zero || !(*zero > 0.0)) return;
    from += *zero;
    zeros.push_back(from);
    shifted.constant = f.constant + f.slope * from;
    for (std::size_t j = 0; j < f.decays.size(); ++j) {
      shifted.decays[j].amplitude = f.decays[j].amplitude * std::exp(-from / f.decays[j].time);
    }
  }
}

/// The terms of the tangential arms: G_j = E_j G* / E*, the same tau_j.
std::vector<PronyTerm> tangential_terms(std::span<const PronyTerm> terms, double shear_ratio) {
  std::vector<PronyTerm> scaled(terms.begin(), terms.end());
  for (PronyTerm& term : scaled) term.modulus *= shear_ratio;
  return scaled;
}

}  // namespace viscoelastic_row_parts

using namespace viscoelastic_row_parts;

class ViscoelasticRowDrive::Row {
 public:
  explicit Row(const ViscoelasticRowSprings& springs)
      : springs_(springs),
        arms_(springs.terms),
        modes_(std::make_shared<const RetardationModes>(springs.relaxed_modulus, springs.terms)),
        tangential_terms_(tangential_terms(springs.terms, springs.shear_ratio)),
        tangential_arms_(tangential_terms_),
        state_(springs.images.size()),
        store_stride_(3 * springs.terms.size() + modes_->rates().size()),
        store_(state_.size() * store_stride_, 0.0),
        pressed_(springs.images.size()),
        glued_(springs.images.size()),
        holding_loads_(springs.edge, springs.spacing, springs.images.size()) {
    for (const PronyTerm& term : springs.terms) {
      inverse_times_.push_back(1.0 / term.time);
      dissipation_factors_.push_back(1.0 / (term.modulus * term.time));
    }
  }

  /// A new segment from the present time: every spring's next event within it is queued (the
  /// energy summed up to now, the rate changing).
  void begin_segment(const DriveSegment& segment) {
    count_all();
    segment_start_ = time_;
    segment_depth_ = depth_;
    rate_ = segment.rate;
    end_ = time_ + segment.duration;
    end_depth_ = segment.end_depth.value_or(depth_ + rate_ * segment.duration);
    segment_tangential_ = tangential_;
    tangential_rate_ = segment.tangential_rate;
    end_tangential_ =
        segment.end_tangential.value_or(tangential_ + tangential_rate_ * segment.duration);
    if (tangential_rate_ != 0.0 && !tangential_on_ && (springs_.edge || springs_.friction) &&
        springs_.shear_ratio > 0.0) {
      start_tangential();
    }
    if (springs_.friction) restart_slides();
    begin_held_shear(segment);
    run_memo_.forget();
    queue_ = {};
    first_events_.clear();
    next_first_event_ = 0;
    held_.reset();
    if (!segment.held && !own_squares_current_) rebuild_own_squares();
    own_squares_current_ = !segment.held;
    if (segment.held) {
      // Per unit length of one half: kappa d + q_total = phi (prony_load_drive.hpp).
      const AffineConstraint& c = segment.held->constraint;
      const double per_half = 2.0 * springs_.spacing * c.force_coefficient;
      held_ = RowHeldAxis{c.displacement_coefficient / per_half, segment.held->start / per_half,
                          segment.held->rate / per_half};
      index_held();
      rebuild_motion();
      return;
    }
    // At most one a spring: room for all at once, not grown by copies.
    first_events_.reserve(state_.size());
    // The hint: the last two neighbours' delays carried on in a line (their spacing changes
    // slowly along the row), so that Newton starts a second difference from the root, not a
    // first.
    // Plain numbers, kNoHint for none: an optional written to a member in two parts and read
    // whole stalls on store forwarding at every spring.
    double last = kNoHint, before_last = kNoHint;
    for (std::size_t k = 0; k < state_.size(); ++k) {
      release_hint_ = last;
      if (last > 0.0 && before_last > 0.0 && 2.0 * last - before_last > 0.0) {
        release_hint_ = 2.0 * last - before_last;
      }
      if (const double delay = event_delay(k); delay < kNoDelay) {
        first_events_.push_back({time_ + delay, k, state_[k].version});
        before_last = last;
        last = delay;
      }
    }
    release_hint_ = kNoHint;
    sort_first_events();
  }

  /// first_events_ in their order. A linear drive meets the springs from the inside out and
  /// Ting's releases go from the outside in, so they mostly come in order or in reverse (no two
  /// entries are equal: one a spring), found in one pass each before sorting.
  void sort_first_events() {
    const auto earlier = [](const ViscoelasticRowEvent& a, const ViscoelasticRowEvent& b) {
      return b > a;
    };
    if (std::is_sorted(first_events_.begin(), first_events_.end(), earlier)) return;
    if (std::is_sorted(first_events_.rbegin(), first_events_.rend(), earlier)) {
      std::reverse(first_events_.begin(), first_events_.end());
      return;
    }
    std::sort(first_events_.begin(), first_events_.end(), earlier);
  }

  double end() const { return end_; }
  double spacing() const { return springs_.spacing; }
  std::optional<ViscoelasticRowEvent> next_event() {
    if (held_) return held_next_event();
    while (!queue_.empty() && queue_.top().version != state_[queue_.top().spring].version) {
      queue_.pop();
    }
    while (next_first_event_ < first_events_.size() &&
           first_events_[next_first_event_].version !=
               state_[first_events_[next_first_event_].spring].version) {
      ++next_first_event_;
    }
    const bool queued = !queue_.empty();
    const bool first = next_first_event_ < first_events_.size();
    if (!queued && !first) return std::nullopt;
    next_is_first_ = first && (!queued || queue_.top() > first_events_[next_first_event_]);
    return next_is_first_ ? first_events_[next_first_event_] : queue_.top();
  }

  void advance_to(double t) {
    if (held_) {
      held_advance_to(t);
      return;
    }
    if (t > time_ && arms_.weight() > 0.0) {
      // The contact's piece and the arms' advance share 1 - exp(-h / tau_j).
      count_contact_piece(t - time_);
      arms_.advance(rate_, t - time_, relaxed_parts_);
    } else {
      arms_.advance(rate_, t - time_);
    }
    if (shear_held_) {
      advance_held_shear(t - time_);
    } else if (tangential_on_) {
      tangential_arms_.advance(tangential_rate_, t - time_);
    }
    time_ = t;
    depth_ = t == end_ ? end_depth_ : segment_depth_ + rate_ * (t - segment_start_);
    if (shear_held_) return;
    tangential_ =
        t == end_ ? end_tangential_ : segment_tangential_ + tangential_rate_ * (t - segment_start_);
  }

  /// The queued event of spring k at the present time: a touch, a release, a glue or a let-go.
  ViscoelasticRowChange apply(std::size_t k, ViscoelasticRowRun& run) {
    if (!held_) {
      if (next_is_first_) {
        ++next_first_event_;
      } else {
        queue_.pop();
      }
    }
    run_memo_.change(k, state_[k].shear && state_[k].shear->friction_event == kGlueEvent);
    if (state_[k].shear && state_[k].shear->friction_event) return apply_friction(k, run);
    if (springs_.edge) return apply_at_edge(k, run);
    ViscoelasticSpringState& s = state_[k];
    const bool release = s.phase == ViscoelasticSpringPhase::pressed;
    if (release) {
      count_pressed(s, springs_.images[k]);
      if (s.shear) lift_tangentially(k);
      const FewValues<double> stresses = leave_arms_counted(s);
      s.counted_stored = stored_of(-sum_of(stresses) / springs_.relaxed_modulus, stresses);
      start_creep(s, stresses);
      s.released_at = time_;
      s.phase = ViscoelasticSpringPhase::free;
      pressed_.erase(k);
      pressed_images_.add(-springs_.images[k]);
      pressed_image_squares_.add(-springs_.images[k] * springs_.images[k]);
      ++run.releases;
      if (pressed_.empty()) run.separation_time = time_;
    } else {
      const FewValues<double> stresses = s.phase == ViscoelasticSpringPhase::free
                                             ? creep(s).stresses(time_ - s.released_at)
                                             : FewValues<double>(springs_.terms.size(), 0.0);
      if (s.phase == ViscoelasticSpringPhase::free) count_free(s);
      enter_arms(s, stresses);
      s.counted_at = time_;
      s.counted_stretch = depth_ - springs_.images[k];
      copy_counted_stresses(s, stresses);
      s.phase = ViscoelasticSpringPhase::pressed;
      pressed_.insert(k);
      pressed_images_.add(springs_.images[k]);
      pressed_image_squares_.add(springs_.images[k] * springs_.images[k]);
      if (springs_.friction && tangential_on_) glue_tangentially(s);
      ++run.touches;
      run.separation_time.reset();
    }
    ++s.version;
    if (held_) {
      index_change(k, release);
      rebuild_motion();
    } else {
      schedule(k);
    }
    return release ? ViscoelasticRowChange::release : ViscoelasticRowChange::touch;
  }

  bool in_contact() const { return !pressed_.empty(); }
  bool last_let_go_by_shear() const { return last_let_go_by_shear_; }
  bool shear_unheld() const { return shear_unheld_; }

  /// The energy up to now, per unit x of one half [J/m].
  ViscoelasticRowEnergy energy() {
    count_all();
    ViscoelasticRowEnergy e{machine_work_.value(), tangential_work_.value(), 0.0,
                            dissipated_.value(),   surface_.value(),         jump_losses_.value(),
                            friction_.value()};
    CompensatedSum stored;
    const std::optional<double> contact = contact_stored_by_sums();
    if (contact) stored.add(*contact);
    for (std::size_t k = 0; k < state_.size(); ++k) {
      const ViscoelasticSpringState& s = state_[k];
      if (in_contact(s) && !contact) {
        // stored_of(w, its stresses now), term by term as it sums them.
        const double w = depth_ - springs_.images[k];
        double e = 0.5 * springs_.relaxed_modulus * w * w;
        for (std::size_t j = 0; j < terms(); ++j) {
          const double sigma = arms_.stress(member(s), j);
          e += 0.5 * sigma * sigma / springs_.terms[j].modulus;
        }
        stored.add(e);
      } else if (s.phase == ViscoelasticSpringPhase::free) {
        stored.add(s.counted_stored);
      }
      if (!tangential_on_) continue;
      if (s.shear && s.shear->in_set) {
        stored.add(tangential_stored_of(s.shear->counted_stretch, s.shear->counted_stresses));
      } else if (s.shear && s.shear->slide) {
        stored.add(
            tangential_stored_of(s.shear->slide->stretch(time_), s.shear->slide->stresses(time_)));
      } else if (s.shear && s.shear->creep) {
        stored.add(s.shear->counted_stored);
      }
    }
    e.stored = stored.value();
    return e;
  }

  /// What the springs in contact store [J/m] from the row's sums, O(terms): E* / 2 sum_i w_i^2
  /// with sum_i w_i^2 = n d^2 - 2 d sum g_i + sum g_i^2, and per term sum_i sigma_ij^2 / (2 E_j)
  /// with sum_i sigma_ij^2 = W H_j^2 + 2 H_j C_j + sum_i delta_ij^2 (count_contact_piece's
  /// split). None where the sums are not kept (a held segment's) or where they cancel beyond
  /// 2^10 of the result (then at most ten bits are lost to them): the springs are summed instead.
  std::optional<double> contact_stored_by_sums() const {
    if (held_ || !own_squares_current_) return std::nullopt;
    const double n = static_cast<double>(pressed_.size());
    if (n == 0.0) return 0.0;
    const double images = pressed_images_.value();
    const double squares = pressed_image_squares_.value();
    const double stretches = n * depth_ * depth_ - 2.0 * depth_ * images + squares;
    double stored = 0.5 * springs_.relaxed_modulus * stretches;
    double gross = 0.5 * springs_.relaxed_modulus *
                   (n * depth_ * depth_ + 2.0 * std::abs(depth_ * images) + squares);
    if (!(stretches > 0.0)) return std::nullopt;
    for (std::size_t j = 0; j < terms(); ++j) {
      const double history = arms_.history(j);
      const double decaying = arms_.arm_force(j) - n * history;
      const double half_compliance = 0.5 / springs_.terms[j].modulus;
      const double own = own_squares_[j];
      if (!(own >= 0.0) || own_squares_gross_[j] > 0x1p10 * own) return std::nullopt;
      stored += (n * history * history + 2.0 * history * decaying + own) * half_compliance;
      gross += (n * history * history + 2.0 * std::abs(history * decaying) + own) * half_compliance;
    }
    if (!(stored > 0.0) || gross > 0x1p10 * stored) return std::nullopt;
    return stored;
  }

  ViscoelasticRowSample sample() const {
    const auto n = static_cast<double>(pressed_.size());
    const double line_loads =
        springs_.relaxed_modulus * (n * depth_ - pressed_images_.value()) + arms_.arm_force();
    const double radius =
        pressed_.empty() ? 0.0 : springs_.spacing * static_cast<double>(pressed_.outermost() + 1);
    const double glued_radius =
        glued_.empty() ? 0.0 : springs_.spacing * static_cast<double>(glued_.outermost() + 1);
    double tangential_loads = 0.0;
    if (tangential_on_) {
      tangential_loads =
          tangential_relaxed() *
              (static_cast<double>(tangential_members_) * tangential_ - glued_origins_.value()) +
          tangential_arms_.arm_force();
      if (!sliding_.empty()) tangential_loads += sliding_loads_.at(time_);
    }
    const bool carries = tangential_members_ > 0 || !sliding_.empty();
    return {time_,
            depth_,
            2.0 * springs_.spacing * line_loads,
            radius,
            static_cast<std::int64_t>(pressed_.size()),
            static_cast<std::int64_t>(glued_.size()),
            glued_radius,
            tangential_,
            carries ? 2.0 * springs_.spacing * tangential_loads : 0.0,
            static_cast<std::int64_t>(sliding_.size()),
            !springs_.friction || sliding_.empty()
                ? (springs_.friction ? radius : 0.0)
                : springs_.spacing * static_cast<double>(*sliding_.begin())};
  }

 private:
  // A spring's per-term numbers sit in the row's flat store, a block a spring: its arms'
  // offsets while in contact, its counted stresses, its free creep's mode amplitudes and its
  // terms' residuals (a spring's state stays small: the row's passes stream it).
  std::size_t terms() const { return springs_.terms.size(); }
  const double* block(const ViscoelasticSpringState& s) const {
    return store_.data() + static_cast<std::size_t>(&s - state_.data()) * store_stride_;
  }
  double* block(const ViscoelasticSpringState& s) {
    return store_.data() + static_cast<std::size_t>(&s - state_.data()) * store_stride_;
  }
  SharedDriveMemberRef member(const ViscoelasticSpringState& s) const {
    return {s.entry_time, {block(s), terms()}};
  }
  std::span<double> counted_stresses(const ViscoelasticSpringState& s) {
    return {block(s) + terms(), terms()};
  }
  std::span<const double> counted_stresses(const ViscoelasticSpringState& s) const {
    return {block(s) + terms(), terms()};
  }
  void copy_counted_stresses(const ViscoelasticSpringState& s, std::span<const double> stresses) {
    std::copy(stresses.begin(), stresses.end(), counted_stresses(s).begin());
  }
  FreeSpringCreepRef creep(const ViscoelasticSpringState& s) const {
    const std::size_t modes = modes_->rates().size();
    return {*modes_, {block(s) + 2 * terms(), modes}, {block(s) + 2 * terms() + modes, terms()}};
  }
  /// Spring s is free from now with arm stresses `stresses` [N/m].
  void start_creep(const ViscoelasticSpringState& s, std::span<const double> stresses) {
    const std::size_t modes = modes_->rates().size();
    double* numbers = block(s) + 2 * terms();
    free_spring_numbers(*modes_, stresses, {numbers, modes}, {numbers + modes, terms()});
  }
  /// Spring s joins the arms now with arm stresses `stresses` [N/m].
  void enter_arms(ViscoelasticSpringState& s, std::span<const double> stresses) {
    s.entry_time = arms_.enter(stresses, 1.0, {block(s), terms()});
    if (held_) return;
    // Its own part sigma_j - H_j is its offset, now.
    for (std::size_t j = 0; j < terms(); ++j) {
      own_squares_[j] += block(s)[j] * block(s)[j];
      own_squares_gross_[j] += block(s)[j] * block(s)[j];
    }
  }
  /// Spring s leaves the arms now, just after count_pressed(s), which read its arm stresses
  /// [N/m] into counted_stresses; they are returned.
  FewValues<double> leave_arms_counted(const ViscoelasticSpringState& s) {
    const std::span<const double> counted = counted_stresses(s);
    FewValues<double> stresses(counted.begin(), counted.end());
    if (!held_) {
      for (std::size_t j = 0; j < terms(); ++j) {
        const double own = stresses[j] - arms_.history(j);
        own_squares_[j] -= own * own;
        own_squares_gross_[j] += own * own;
      }
    }
    arms_.leave_read(stresses, 1.0);
    // An empty set's sums are zero exactly, not the roundoff of their additions and removals.
    if (!held_ && arms_.weight() == 0.0) {
      std::fill(own_squares_.begin(), own_squares_.end(), 0.0);
      std::fill(own_squares_gross_.begin(), own_squares_gross_.end(), 0.0);
    }
    return stresses;
  }

  static bool in_contact(const ViscoelasticSpringState& s) {
    return s.phase == ViscoelasticSpringPhase::pressed || s.phase == ViscoelasticSpringPhase::glued;
  }

  /// The outermost glued spring, the one that may let go; none without glue.
  std::optional<std::size_t> boundary() const {
    if (glued_.empty()) return std::nullopt;
    return glued_.outermost();
  }
  /// The spring just outside the contact (the outermost spring in contact, glued or pressed),
  /// the one the advancing front may glue; none beyond the row.
  std::optional<std::size_t> outside() const {
    const std::size_t k = pressed_.empty() ? 0 : pressed_.outermost() + 1;
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
    // Under a held control the constraint is met before the change (the row's load then).
    const double held_load_before = held_ ? line_loads() : 0.0;
    const double machine_before = machine_work_.value();
    const double surface_before = surface_.value();
    const double losses_before = jump_losses_.value();
    const double tangential_before = tangential_work_.value();
    const double spring_before = spring_work_.value();
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
    if (held_) {
      // The held search finds every spring's event afresh; only k's indexes change.
      ++s.version;
      if (change == ViscoelasticRowChange::let_go && s.phase == ViscoelasticSpringPhase::pressed) {
        // Its glue broken by its tangential load alone, it stays pressed: its normal arms stay.
        pressed_keys_.push({pressed_key(k), k, s.version});
      } else {
        const bool left =
            change == ViscoelasticRowChange::release || change == ViscoelasticRowChange::let_go;
        index_change(k, left);
      }
      held_glassy_step(held_load_before);
      if (shear_held_ &&
          (change == ViscoelasticRowChange::let_go || change == ViscoelasticRowChange::glue)) {
        held_shear_change(change);
      }
      rebuild_motion();
      note_let_go_run(change, machine_before, surface_before, losses_before, tangential_before,
                      spring_before);
      return change;
    }
    if (shear_held_ &&
        (change == ViscoelasticRowChange::let_go || change == ViscoelasticRowChange::glue)) {
      held_shear_change(change);
      note_let_go_run(change, machine_before, surface_before, losses_before, tangential_before,
                      spring_before);
    }
    for (const auto j :
         {std::optional<std::size_t>(k), boundary_before, outside_before, boundary(), outside()}) {
      if (!j) continue;
      ++state_[*j].version;
      schedule(*j);
    }
    reschedule_glue_front(k);
    return change;
  }

 public:
  /// What the let-gos at this time did since the last other change (their steps included),
  /// per unit x of one half [J/m]: no time passes among them, so nothing is dissipated in the
  /// bulk and what is stored changes by the work less the surface and the losses.
  ViscoelasticRowEnergy let_go_run() const { return let_go_run_; }

 private:
  void note_let_go_run(ViscoelasticRowChange change, double machine_before, double surface_before,
                       double losses_before, double tangential_before, double spring_before) {
    const bool joins = change == ViscoelasticRowChange::let_go && time_ == let_go_run_time_;
    if (!joins) let_go_run_ = {};
    let_go_run_time_ = change == ViscoelasticRowChange::let_go ? time_ : -HUGE_VAL;
    if (change != ViscoelasticRowChange::let_go) return;
    const double machine = machine_work_.value() - machine_before;
    const double surface = surface_.value() - surface_before;
    const double losses = jump_losses_.value() - losses_before;
    // A held F_x's let-gos step u_x (its work); under fixed grips u_x does not move at a let-go.
    const double tangential = tangential_work_.value() - tangential_before;
    let_go_run_.machine_work += machine;
    let_go_run_.tangential_work += tangential;
    let_go_run_.surface += surface;
    let_go_run_.jump_losses += losses;
    // What a machine spring's end gave the row in their glassy steps (its own energy is the
    // caller's).
    const double spring = spring_work_.value() - spring_before;
    let_go_run_.stored += machine + tangential + spring - surface - losses;
  }

  /// The springs' total line load per half [N/m]: E* (n d - sum g) + sum_j S_j.
  double line_loads() const {
    const auto n = static_cast<double>(pressed_.size());
    return springs_.relaxed_modulus * (n * depth_ - pressed_images_.value()) + arms_.arm_force();
  }

  /// After a glue or a let-go under a held control, the constraint kappa d + q = phi is met
  /// again at once: the dashpots do not move, so every spring in contact answers with E_0 and
  /// (kappa + n E_0) Dd = phi - kappa d - q. `load_before` [N/m] is q before the change (the
  /// constraint held there). The machine's end stays (a machine spring) or its force does (a
  /// fixed load, the work phi Dd); the springs in contact store Dd q + n E_0 Dd^2 / 2 more, a
  /// machine spring -Dd (q_before + q_after) / 2, and the rest is lost: Dd^2 (kappa + n E_0) / 2
  /// (docs/viscoelastic.md). Under a fixed load with nothing left in contact the force is not
  /// held (the contact is lost: the row stays where it is).
  void held_glassy_step(double load_before) {
    const RowHeldAxis axis = held_now();
    const auto n = static_cast<double>(pressed_.size());
    const double stiffness = axis.stiffness + n * springs_.edge->glassy_modulus;
    if (!(stiffness > 0.0)) return;
    const double load = line_loads();
    const double step = (axis.held - axis.stiffness * depth_ - load) / stiffness;
    const double load_after = load + n * springs_.edge->glassy_modulus * step;
    const double stored = step * load + 0.5 * n * springs_.edge->glassy_modulus * step * step;
    const bool fixed_load = axis.stiffness == 0.0;
    const double machine = fixed_load ? axis.held * step : 0.5 * step * (load_before + load_after);
    if (fixed_load) machine_work_.add(machine);
    if (!fixed_load) spring_work_.add(machine);
    jump_losses_.add(machine - stored);
    arms_.glassy_step(step);
    depth_ += step;
  }

  /// The boundary spring k lets go: its stretch steps by -q / E_0 to zero load.
  void let_go(std::size_t k, ViscoelasticRowRun& run) {
    ViscoelasticSpringState& s = state_[k];
    count_pressed(s, springs_.images[k]);
    last_let_go_by_shear_ = tangential_on_ && broken_at_rest(k);
    if (tangential_on_ && load_now(s, depth_ - springs_.images[k]) >= 0.0) {
      lose_glue_pressed(k, run);
      return;
    }
    FewValues<double> stresses = leave_arms_counted(s);
    const double stretch = depth_ - springs_.images[k];
    const double load = springs_.relaxed_modulus * stretch + sum_of(stresses);
    const double before = stored_of(stretch, stresses);
    glassy_step(stresses, springs_.terms, -load / springs_.edge->glassy_modulus);
    const double after = stored_of(-sum_of(stresses) / springs_.relaxed_modulus, stresses);
    const double surface = springs_.edge->surface_energies[k];
    surface_.add(surface);
    jump_losses_.add(before - after - surface);
    if (tangential_on_) let_go_tangentially(s);
    s.counted_stored = after;
    s.counted_at = time_;
    start_creep(s, stresses);
    s.released_at = time_;
    s.phase = ViscoelasticSpringPhase::free;
    pressed_.erase(k);
    glued_.erase(k);
    pressed_images_.add(-springs_.images[k]);
    pressed_image_squares_.add(-springs_.images[k] * springs_.images[k]);
    ++run.let_gos;
    if (pressed_.empty()) run.separation_time = time_;
  }

  /// The boundary spring k, compressed, lets go by its tangential load alone: it loses its glue
  /// and its tangential load (q_x^2 / (2 G_0) released) and stays pressed, pushing only.
  void lose_glue_pressed(std::size_t k, ViscoelasticRowRun& run) {
    ViscoelasticSpringState& s = state_[k];
    if (springs_.friction) {
      slip_to_limit(k);
    } else {
      let_go_tangentially(s);
    }
    const double surface = springs_.edge->surface_energies[k];
    surface_.add(surface);
    jump_losses_.add(-surface);
    s.phase = ViscoelasticSpringPhase::pressed;
    glued_.erase(k);
    ++run.let_gos;
  }

  /// Whether glued spring k's tangential load alone breaks it: the glassy criterion's margin
  /// at zero elongation and u_x = q_x / G_0 is <= 0 (a let-go "by shear", as an elastic
  /// program's LetGo::Kind::now).
  bool broken_at_rest(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    const ViscoelasticEdge& edge = *springs_.edge;
    if (!edge.criterion) return false;
    // A spring without tangential arms (no tangential drive yet) carries no tangential load.
    double load = 0.0;
    if (s.shear) {
      load = tangential_relaxed() * (tangential_ - s.shear->origin);
      for (std::size_t j = 0; j < tangential_terms_.size(); ++j) {
        load += tangential_arms_.stress(s.shear->member, j);
      }
    }
    const double x = springs_.spacing * static_cast<double>(k + 1);
    if (springs_.friction)
      load = released_tangential(load, load_now(s, depth_ - springs_.images[k]));
    return edge.criterion->margin({0.0, load / edge.glassy_shear_modulus, x}) <= 0.0;
  }

  /// Spring s's normal line load now [N/m] (in contact, its stretch `stretch`).
  double load_now(const ViscoelasticSpringState& s, double stretch) const {
    double load = springs_.relaxed_modulus * stretch;
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) load += arms_.stress(member(s), j);
    return load;
  }

  /// A pressed spring k leaves at zero load.
  void leave_contact(std::size_t k, ViscoelasticRowRun& run) {
    ViscoelasticSpringState& s = state_[k];
    count_pressed(s, springs_.images[k]);
    if (s.shear) lift_tangentially(k);
    const FewValues<double> stresses = leave_arms_counted(s);
    s.counted_stored = stored_of(-sum_of(stresses) / springs_.relaxed_modulus, stresses);
    s.counted_at = time_;
    start_creep(s, stresses);
    s.released_at = time_;
    s.lifted_at = time_;
    s.phase = ViscoelasticSpringPhase::free;
    pressed_.erase(k);
    pressed_images_.add(-springs_.images[k]);
    pressed_image_squares_.add(-springs_.images[k] * springs_.images[k]);
    ++run.releases;
    if (pressed_.empty()) run.separation_time = time_;
  }

  /// Spring k enters the contact: pressed on touch (`glue_gap` unset), or glued, its stretch
  /// stepping from its free surface's to the indenter's.
  void enter_contact(std::size_t k, ViscoelasticRowRun& run, std::optional<double> glue_gap) {
    ViscoelasticSpringState& s = state_[k];
    const bool free = s.phase == ViscoelasticSpringPhase::free;
    FewValues<double> stresses = free ? creep(s).stresses(time_ - s.released_at)
                                      : FewValues<double>(springs_.terms.size(), 0.0);
    double before = 0.0;
    double free_stretch = 0.0;
    if (free) {
      count_free(s);
      before = s.counted_stored;
      free_stretch = creep(s).stretch(time_ - s.released_at);
    }
    const double stretch = depth_ - springs_.images[k];
    if (glue_gap) {
      glassy_step(stresses, springs_.terms, stretch - free_stretch);
      const double surface = springs_.edge->surface_energies[k];
      surface_.add(-surface);
      jump_losses_.add(surface - (stored_of(stretch, stresses) - before));
      glued_.insert(k);
      s.glued_at = time_;
      if (tangential_on_) glue_tangentially(s);
      ++run.glues;
    } else {
      if (springs_.friction && tangential_on_) glue_tangentially(s);
      ++run.touches;
    }
    enter_arms(s, stresses);
    s.counted_at = time_;
    s.counted_stretch = stretch;
    copy_counted_stresses(s, stresses);
    s.phase = glue_gap ? ViscoelasticSpringPhase::glued : ViscoelasticSpringPhase::pressed;
    pressed_.insert(k);
    pressed_images_.add(springs_.images[k]);
    pressed_image_squares_.add(springs_.images[k] * springs_.images[k]);
    run.separation_time.reset();
  }
  static double sum_of(std::span<const double> values) {
    double sum = 0.0;
    for (const double v : values) sum += v;
    return sum;
  }

  /// What a spring of stretch w and arm stresses sigma_j stores [J/m]: E* w^2 / 2 +
  /// sum_j sigma_j^2 / (2 E_j).
  double stored_of(double stretch, std::span<const double> stresses) const {
    double e = 0.5 * springs_.relaxed_modulus * stretch * stretch;
    for (std::size_t j = 0; j < stresses.size(); ++j) {
      e += 0.5 * stresses[j] * stresses[j] / springs_.terms[j].modulus;
    }
    return e;
  }

  /// A spring in contact notes where it stands (its normal work and dissipation are counted for
  /// the whole contact at once: count_contact_piece, count_held_piece), and its tangential work
  /// and dissipation from its last count to now, the drive's rate unchanged in between (every
  /// spring with tangential arms is counted where the rate changes).
  void count_pressed(ViscoelasticSpringState& s, double image) {
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      counted_stresses(s)[j] = arms_.stress(member(s), j);
    }
    if (held_) {
      s.counted_at = time_;
      s.counted_stretch = depth_ - image;
      if (tangential_on_ && s.phase == ViscoelasticSpringPhase::glued) note_tangential(s);
      return;
    }
    const double h = time_ - s.counted_at;
    if (shear_held_ && s.shear && s.shear->in_set) {
      note_tangential(s);  // counted for all members at once (count_held_shear_piece)
    } else if (tangential_on_ && s.shear && s.shear->in_set) {
      count_tangential(s, h);
    }
    if (s.shear && s.shear->slide) count_sliding(s);
    s.counted_at = time_;
    s.counted_stretch = depth_ - image;
  }

  /// The springs in contact: their normal work and dissipation over the next h [s] of the drive
  /// at its rate, all at once. With sigma_ij = H_j + delta_ij (H_j the arms' common history,
  /// relaxing towards c_j = E_j w' tau_j, delta_ij a member's own part, decaying as
  /// exp(-s / tau_j)), sum_i sigma_ij = W H_j + C_j and sum_i sigma_ij^2 = W H_j^2 + 2 H_j C_j +
  /// sum_i delta_ij^2, each integrated in closed form: O(terms) a piece, where a closed form a
  /// spring at each of its counts took three exponentials a term.
  void count_contact_piece(double h) {
    const double n = arms_.weight();
    double load_integral = springs_.relaxed_modulus *
                           ((n * depth_ - pressed_images_.value()) * h + 0.5 * n * rate_ * h * h);
    double dissipated = 0.0;
    relaxed_parts_.resize(springs_.terms.size());
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      const PronyTerm& term = springs_.terms[j];
      // 1 - exp(-h / tau) (h is mostly far below tau: its series), shared with the arms' advance.
      const double x = h * inverse_times_[j];
      const double relaxed_part = mdrsim::relaxed_part(x);
      relaxed_parts_[j] = relaxed_part;
      // The common history H(s) = history E(s) + steady D(s) (E = exp(-s / tau), D = 1 - E),
      // the members' own parts decaying as E: integrals of E, D and their products taken whole
      // (decay_integrals), so that a piece far shorter than tau keeps its digits.
      const DecayIntegrals i = decay_integrals_at(x, term.time, relaxed_part);
      const double steady = term.modulus * rate_ * term.time;
      const double history = arms_.history(j);
      const double decaying = arms_.arm_force(j) - n * history;
      load_integral += n * (history * i.decay + steady * i.rise) + decaying * i.decay;
      const double history_squared = history * history * i.decay_squared +
                                     2.0 * history * steady * i.rise_decay +
                                     steady * steady * i.rise_squared;
      const double squares = n * history_squared +
                             2.0 * decaying * (history * i.decay_squared + steady * i.rise_decay) +
                             std::max(own_squares_[j], 0.0) * i.decay_squared;
      dissipated += squares * dissipation_factors_[j];
      const double remaining = 1.0 - relaxed_part;
      own_squares_[j] *= remaining * remaining;
      own_squares_gross_[j] *= remaining * remaining;
    }
    machine_work_.add(rate_ * load_integral);
    dissipated_.add(dissipated);
  }

  /// own_squares_ from the springs in contact where they stand.
  void rebuild_own_squares() {
    own_squares_.assign(terms(), 0.0);
    for (const ViscoelasticSpringState& s : state_) {
      if (!in_contact(s)) continue;
      for (std::size_t j = 0; j < terms(); ++j) {
        const double own = arms_.stress(member(s), j) - arms_.history(j);
        own_squares_[j] += own * own;
      }
    }
    own_squares_gross_ = own_squares_;
  }

  /// G_inf [Pa], the tangential arms' relaxed modulus.
  double tangential_relaxed() const { return springs_.relaxed_modulus * springs_.shear_ratio; }

  /// What a spring's tangential arms store at tangential stretch w and arm stresses s_j [J/m].
  double tangential_stored_of(double stretch, std::span<const double> stresses) const {
    double e = 0.5 * tangential_relaxed() * stretch * stretch;
    for (std::size_t j = 0; j < stresses.size(); ++j) {
      e += 0.5 * stresses[j] * stresses[j] / tangential_terms_[j].modulus;
    }
    return e;
  }

  /// The tangential drive begins: the springs glued now join the tangential arms at rest, their
  /// stretch zero at the present u_x.
  void start_tangential() {
    tangential_on_ = true;
    tangential_modes_ =
        std::make_shared<const RetardationModes>(tangential_relaxed(), tangential_terms_);
    for (ViscoelasticSpringState& s : state_) {
      const bool joins = s.phase == ViscoelasticSpringPhase::glued ||
                         (springs_.friction && s.phase == ViscoelasticSpringPhase::pressed);
      if (joins) glue_tangentially(s);
    }
  }

  /// A spring glues with no tangential step: its stretch goes on from where its free creep
  /// stands (zero for a fresh spring) as u_x moves.
  void glue_tangentially(ViscoelasticSpringState& s) {
    if (!s.shear) s.shear = std::make_unique<ViscoelasticSpringShear>();
    FewValues<double> stresses(tangential_terms_.size(), 0.0);
    double stretch = 0.0;
    if (s.shear->creep) {
      count_tangential_free(s);
      const double t = time_ - s.shear->free_since;
      stresses = s.shear->creep->stresses(t);
      stretch = s.shear->creep->stretch(t);
      s.shear->creep.reset();
    }
    s.shear->origin = tangential_ - stretch;
    if (held_ || shear_held_) tangential_own_squares_.change(tangential_arms_, stresses, 1.0);
    s.shear->member = tangential_arms_.enter(stresses, 1.0);
    s.shear->counted_stretch = stretch;
    s.shear->counted_stresses = stresses;
    s.shear->in_set = true;
    ++tangential_members_;
    glued_origins_.add(s.shear->origin);
  }

  /// The glued spring s lets go (counted up to now): its tangential stretch steps by -q_x / G_0
  /// to zero load, releasing q_x^2 / (2 G_0), and it creeps free from there.
  void let_go_tangentially(ViscoelasticSpringState& s) {
    FewValues<double> stresses = tangential_arms_.leave(s.shear->member);
    if (held_ || shear_held_) tangential_own_squares_.change(tangential_arms_, stresses, -1.0);
    const double stretch = tangential_ - s.shear->origin;
    const double load = tangential_relaxed() * stretch + sum_of(stresses);
    const double before = tangential_stored_of(stretch, stresses);
    glassy_step(stresses, tangential_terms_, -load / glassy_shear_modulus());
    const double after = tangential_stored_of(-sum_of(stresses) / tangential_relaxed(), stresses);
    jump_losses_.add(before - after);
    glued_origins_.add(-s.shear->origin);
    s.shear->in_set = false;
    --tangential_members_;
    s.shear->creep.emplace(tangential_modes_, stresses);
    s.shear->free_since = time_;
    s.shear->counted_stored = after;
  }

  /// A glued spring's tangential work and dissipation over the last `h` [s], u_x' unchanged.
  void count_tangential(ViscoelasticSpringState& s, double h) {
    const double w0 = s.shear->counted_stretch;
    const double rate = tangential_rate_;
    double load_integral = tangential_relaxed() * (w0 * h + 0.5 * rate * h * h);
    double dissipated = 0.0;
    for (std::size_t j = 0; j < tangential_terms_.size(); ++j) {
      const PronyTerm& term = tangential_terms_[j];
      const ArmStressIntegrals i =
          arm_stress_integrals(term, s.shear->counted_stresses[j], rate, h);
      load_integral += i.stress;
      dissipated += i.square / (term.modulus * term.time);
      s.shear->counted_stresses[j] = tangential_arms_.stress(s.shear->member, j);
    }
    tangential_work_.add(rate * load_integral);
    dissipated_.add(dissipated);
    s.shear->counted_stretch = tangential_ - s.shear->origin;
  }

  /// A glued spring's tangential arms where they stand now, in a held segment (which counts the
  /// work and the dissipation of all glued springs together, count_held_tangential_piece).
  void note_tangential(ViscoelasticSpringState& s) {
    for (std::size_t j = 0; j < tangential_terms_.size(); ++j) {
      s.shear->counted_stresses[j] = tangential_arms_.stress(s.shear->member, j);
    }
    s.shear->counted_stretch = tangential_ - s.shear->origin;
  }

  /// The glued springs' tangential work and dissipation over the next h [s] of a held segment,
  /// all at once: u_x moves at its rate as under fixed grips, whatever the depth does.
  void count_held_tangential_piece(double h) {
    const double n = tangential_arms_.weight();
    const double stretches = n * tangential_ - glued_origins_.value();
    const SharedArmsPiece arms =
        shared_arms_linear_piece(tangential_arms_, tangential_own_squares_, tangential_rate_, h);
    const double load_integral =
        tangential_relaxed() * (stretches * h + 0.5 * n * tangential_rate_ * h * h) +
        arms.load_integral;
    tangential_work_.add(tangential_rate_ * load_integral);
    dissipated_.add(arms.dissipated);
  }

  // Friction on pressed springs (docs/friction.md, docs/viscoelastic.md "Friction"): a sticking
  // spring is a member of the tangential set as a glued one is; a sliding one leaves it and
  // follows its limit (ViscoelasticSlide) until its slip velocity turns.

  /// G_0 [Pa]: the tangential arms' glassy modulus (the edge's where there is one).
  double glassy_shear_modulus() const {
    if (springs_.edge) return springs_.edge->glassy_shear_modulus;
    double modulus = tangential_relaxed();
    for (const PronyTerm& term : tangential_terms_) modulus += term.modulus;
    return modulus;
  }

  /// A member of the tangential set leaves it; its arm stresses then [N/m].
  FewValues<double> leave_set(ViscoelasticSpringState& s) {
    FewValues<double> stresses = tangential_arms_.leave(s.shear->member);
    glued_origins_.add(-s.shear->origin);
    s.shear->in_set = false;
    --tangential_members_;
    return stresses;
  }

  /// Spring s joins the tangential set at stretch `stretch` with arm stresses `stresses`.
  void join_set(ViscoelasticSpringState& s, double stretch, std::span<const double> stresses) {
    s.shear->origin = tangential_ - stretch;
    s.shear->member = tangential_arms_.enter(stresses, 1.0);
    s.shear->counted_stretch = stretch;
    s.shear->counted_stresses = FewValues<double>(stresses.begin(), stresses.end());
    s.shear->in_set = true;
    ++tangential_members_;
    glued_origins_.add(s.shear->origin);
  }

  /// Pressed spring k slides from now along `direction` from arm stresses `stresses` and stretch
  /// `stretch` [m]; the rounding between that stretch and the slide's (its load then the limit
  /// to the last bits) is a jump loss.
  void start_slide(std::size_t k, std::span<const double> stresses, double stretch,
                   std::int8_t direction) {
    ViscoelasticSpringState& s = state_[k];
    s.shear->slide = std::make_unique<ViscoelasticSlide>(
        *tangential_modes_, stresses, load_over(s, depth_ - springs_.images[k]), *springs_.friction,
        direction, tangential_rate_, time_);
    jump_losses_.add(tangential_stored_of(stretch, stresses) -
                     tangential_stored_of(s.shear->slide->stretch(time_), stresses));
    sliding_.insert(k);
    sliding_loads_.add(s.shear->slide->load_from_start(), time_, time_, 1.0);
  }

  /// The queued slip or stick of pressed spring k, now.
  ViscoelasticRowChange apply_friction(std::size_t k, ViscoelasticRowRun& run) {
    ViscoelasticSpringState& s = state_[k];
    const std::int8_t kind = s.shear->friction_event;
    s.shear->friction_event = 0;
    s.shear->changed_at = time_;
    count_pressed(s, springs_.images[k]);
    if (kind == kGlueEvent) return glue_pressed(k, run);
    ViscoelasticRowChange change = ViscoelasticRowChange::slip;
    if (kind == kStickEvent) {
      const FewValues<double> stresses = s.shear->slide->stresses(time_);
      const double stretch = s.shear->slide->stretch(time_);
      leave_sliding_loads(*s.shear->slide);
      s.shear->slide.reset();
      sliding_.erase(k);
      join_set(s, stretch, stresses);
      change = ViscoelasticRowChange::stick;
      ++run.sticks;
    } else {
      const double stretch = tangential_ - s.shear->origin;
      const FewValues<double> stresses = leave_set(s);
      start_slide(k, stresses, stretch, kind);
      ++run.slips;
    }
    ++s.version;
    schedule(k);
    // A stick or a slip changes the run of sticking springs the glue's front may take.
    reschedule_glue_front(k);
    return change;
  }

  // Rebinding under friction (docs/friction.md "Rebinding: where the glue holds"): a pressed
  // spring that sticks glues again keeping its stretch, from the glue's front outwards, out to
  // the outermost spring of the run of sticking springs there that holds at its kept stretch
  // with no elongation.

  bool rebinds_pressed() const {
    return springs_.friction && springs_.edge && springs_.edge->rebinding && tangential_on_;
  }
  /// The spring just outside the glue (the centre's without glue).
  std::size_t glue_front() const { return glued_.empty() ? 0 : glued_.outermost() + 1; }
  bool sticks_pressed(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    return s.phase == ViscoelasticSpringPhase::pressed && s.shear && s.shear->in_set;
  }
  /// Sticking spring k's tangential line load now [N/m].
  double kept_tangential_load(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    double load = tangential_relaxed() * (tangential_ - s.shear->origin);
    for (std::size_t j = 0; j < tangential_terms_.size(); ++j) {
      load += tangential_arms_.stress(s.shear->member, j);
    }
    return load;
  }
  /// A member of the tangential set's line load q_x [N/m] from now, its stretch moving at u_x'.
  ExponentialSum tangential_load_over(const ViscoelasticSpringState& s) const {
    FewValues<double> stresses(tangential_terms_.size());
    for (std::size_t j = 0; j < stresses.size(); ++j) {
      stresses[j] = tangential_arms_.stress(s.shear->member, j);
    }
    if (shear_held_) return held_shear_load(s, stresses);
    return line_load_over(tangential_relaxed(), tangential_terms_, tangential_ - s.shear->origin,
                          stresses, tangential_rate_);
  }
  /// |q_x| [N/m] below which glued spring k holds with no elongation (HoldingTangentialLoads).
  double holding_tangential_load(std::size_t k) const { return holding_loads_.at(k); }
  /// The front spring k's glue: now where some spring of the sticking run from k outwards holds
  /// at its kept stretch, else where k's own tangential load falls within what holds.
  std::optional<double> rebinding_glue_delay(std::size_t k) const {
    if (!rebinds_pressed() || k != glue_front() || !sticks_pressed(k)) return std::nullopt;
    std::size_t j = k;
    // Under a held control a change moves every spring's load at once: no memo there.
    if (const auto resume = held_ ? std::nullopt : run_memo_.resume(time_, k)) {
      if (resume->holds) return 0.0;
      j = resume->from;
    }
    for (; j < state_.size() && sticks_pressed(j); ++j) {
      if (std::abs(kept_tangential_load(j)) < holding_tangential_load(j)) {
        run_memo_.record(time_, k, j, true);
        return 0.0;
      }
    }
    run_memo_.record(time_, k, j, false);
    const ViscoelasticSpringState& s = state_[k];
    const ExponentialSum load = tangential_load_over(s);
    const double holding = holding_tangential_load(k);
    return first_crossing(load, load.at(0.0) > 0.0 ? holding : -holding, end_ - time_);
  }
  /// Pressed sticking spring k glues keeping its stretch: no step, its ring's surface energy
  /// lost as a glue's at no gap is.
  ViscoelasticRowChange glue_pressed(std::size_t k, ViscoelasticRowRun& run) {
    const auto boundary_before = boundary();
    ViscoelasticSpringState& s = state_[k];
    const double surface = springs_.edge->surface_energies[k];
    surface_.add(-surface);
    jump_losses_.add(surface);
    s.phase = ViscoelasticSpringPhase::glued;
    s.glued_at = time_;
    glued_.insert(k);
    ++run.glues;
    for (const auto j : {std::optional<std::size_t>(k), boundary_before,
                         std::optional<std::size_t>(glue_front())}) {
      if (!j || *j >= state_.size()) continue;
      ++state_[*j].version;
      schedule(*j);
    }
    return ViscoelasticRowChange::glue;
  }
  /// After spring k's change the glue's front may glue now or later: it is looked at again.
  void reschedule_glue_front(std::size_t k) {
    if (!rebinds_pressed()) return;
    const std::size_t front = glue_front();
    if (front == k || front >= state_.size()) return;
    ++state_[front].version;
    schedule(front);
  }

  /// A slide ends now: its load leaves the sliding springs' total (which restarts from zero
  /// once none slides, so that rounding left over from the leaves does not outlive them).
  void leave_sliding_loads(const ViscoelasticSlide& slide) {
    if (sliding_.size() == 1) {
      sliding_loads_.clear(time_);
      return;
    }
    sliding_loads_.add(slide.load_from_start(), slide.since(), time_, -1.0);
  }

  /// A segment begins: each sliding spring's limit follows the new rates from its state now.
  void restart_slides() {
    const std::vector<std::size_t> sliding(sliding_.begin(), sliding_.end());
    sliding_loads_.clear(time_);
    for (const std::size_t k : sliding) {
      ViscoelasticSpringState& s = state_[k];
      const FewValues<double> stresses = s.shear->slide->stresses(time_);
      const double stretch = s.shear->slide->stretch(time_);
      const std::int8_t direction = s.shear->slide->direction();
      sliding_.erase(k);
      start_slide(k, stresses, stretch, direction);
    }
  }

  /// Pressed spring k lifts (counted up to now): its tangential load, zero at its limit to
  /// rounding, steps to zero and its arms creep free; its slip offset is forgotten.
  void lift_tangentially(std::size_t k) {
    ViscoelasticSpringState& s = state_[k];
    if (s.shear->in_set) {
      let_go_tangentially(s);
      return;
    }
    if (!s.shear->slide) return;
    FewValues<double> stresses = s.shear->slide->stresses(time_);
    const double stretch = s.shear->slide->stretch(time_);
    const double load = tangential_relaxed() * stretch + sum_of(stresses);
    const double before = tangential_stored_of(stretch, stresses);
    glassy_step(stresses, tangential_terms_, -load / glassy_shear_modulus());
    const double after = tangential_stored_of(-sum_of(stresses) / tangential_relaxed(), stresses);
    jump_losses_.add(before - after);
    leave_sliding_loads(*s.shear->slide);
    s.shear->slide.reset();
    sliding_.erase(k);
    s.shear->creep.emplace(tangential_modes_, stresses);
    s.shear->free_since = time_;
    s.shear->counted_stored = after;
  }

  /// Glued spring k, compressed, loses its glue and keeps its stretch: beyond its limit mu q_z
  /// it slips there at once (the arms' springs take the step, G_0), the limit times the slip
  /// lost to friction and the rest, G_0 step^2 / 2, a jump loss; then it slides on.
  void slip_to_limit(std::size_t k) {
    ViscoelasticSpringState& s = state_[k];
    const double stretch = tangential_ - s.shear->origin;
    double load = tangential_relaxed() * stretch;
    for (std::size_t j = 0; j < tangential_terms_.size(); ++j) {
      load += tangential_arms_.stress(s.shear->member, j);
    }
    const double limit = *springs_.friction * load_now(s, depth_ - springs_.images[k]);
    if (std::abs(load) <= limit) return;
    const std::int8_t direction = load > 0.0 ? 1 : -1;
    FewValues<double> stresses = leave_set(s);
    const double step = (direction * limit - load) / glassy_shear_modulus();
    const double before = tangential_stored_of(stretch, stresses);
    glassy_step(stresses, tangential_terms_, step);
    const double after = tangential_stored_of(stretch + step, stresses);
    const double lost = limit * std::abs(step);
    friction_.add(lost);
    jump_losses_.add(before - after - lost);
    s.shear->changed_at = time_;
    start_slide(k, stresses, stretch + step, direction);
  }

  /// A sliding spring's work and dissipation from its last count to now.
  void count_sliding(ViscoelasticSpringState& s) {
    const SlideCount c = s.shear->slide->count(tangential_terms_, s.counted_at, time_);
    tangential_work_.add(c.work);
    friction_.add(c.friction);
    dissipated_.add(c.bulk);
  }

  /// Pressed spring k's next slip (sticking: |f_x| reaching mu f_z, both exponential sums
  /// over the segment) or stick (sliding: its slip velocity turning) within the segment, and
  /// which (the slip's direction or kStickEvent). Just after its last change the level is taken
  /// where it stands, so that rounding cannot turn it back at once.
  std::pair<std::optional<double>, std::int8_t> friction_event_delay(std::size_t k) const {
    const ViscoelasticSpringState& s = state_[k];
    const double span = end_ - time_;
    const bool just_changed = s.shear->changed_at == time_;
    if (s.shear->slide)
      return {s.shear->slide->stick_delay(time_, span, just_changed), kStickEvent};
    if (!s.shear->in_set) return {std::nullopt, 0};
    const ExponentialSum normal = load_over(s, depth_ - springs_.images[k]);
    const ExponentialSum tangential = tangential_load_over(s);
    const double mu = *springs_.friction;
    std::optional<double> best;
    std::int8_t kind = 0;
    for (const std::int8_t direction : {std::int8_t{1}, std::int8_t{-1}}) {
      // direction f_x - mu f_z: negative while it sticks.
      ExponentialSum margin{direction * tangential.constant - mu * normal.constant,
                            direction * tangential.slope - mu * normal.slope,
                            {}};
      for (const ExponentialDecay& d : tangential.decays) {
        margin.decays.push_back({direction * d.amplitude, d.time});
      }
      for (const ExponentialDecay& d : normal.decays) {
        margin.decays.push_back({-mu * d.amplitude, d.time});
      }
      const double now = margin.at(0.0);
      // Just stuck on this side: on its limit to the rounding of the loads.
      const double scale = std::abs(tangential.at(0.0)) + mu * std::abs(normal.at(0.0));
      const bool on_limit = just_changed && std::abs(now) <= 1e-9 * scale;
      std::optional<double> delay;
      if (!on_limit && now >= 0.0 && margin.slope_at(0.0) > 0.0) {
        delay = 0.0;
      } else {
        delay = first_crossing(margin, on_limit ? now : std::max(now, 0.0), span);
      }
      if (delay && (!best || *delay < *best)) {
        best = delay;
        kind = direction;
      }
    }
    return {best, kind};
  }

  /// A free tangential creep's dissipation from its last count to now: what it stores less.
  void count_tangential_free(ViscoelasticSpringState& s) {
    const double t = time_ - s.shear->free_since;
    const double stored =
        tangential_stored_of(s.shear->creep->stretch(t), s.shear->creep->stresses(t));
    dissipated_.add(s.shear->counted_stored - stored);
    s.shear->counted_stored = stored;
  }

  /// A free spring's dissipation from its last count to now: the energy it stores less.
  void count_free(ViscoelasticSpringState& s) {
    const double stored = creep(s).stored(time_ - s.released_at);
    dissipated_.add(s.counted_stored - stored);
    s.counted_stored = stored;
    s.counted_at = time_;
  }

  void count_all() {
    // The springs in contact in ascending order, then the free ones.
    for (std::size_t k = 0; k < state_.size(); ++k) {
      // The normal arms are counted for the whole contact as time passes; only a spring's
      // tangential arms are counted one by one.
      ViscoelasticSpringState& s = state_[k];
      if (!in_contact(s)) continue;
      if (s.shear) {
        count_pressed(s, springs_.images[k]);
      } else {
        // Tangential arms made later count from here (glue_tangentially).
        s.counted_at = time_;
        s.counted_stretch = depth_ - springs_.images[k];
      }
    }
    for (ViscoelasticSpringState& s : state_) {
      if (s.phase == ViscoelasticSpringPhase::free) count_free(s);
    }
    if (!tangential_on_) return;
    for (ViscoelasticSpringState& s : state_) {
      if (s.phase != ViscoelasticSpringPhase::glued && s.shear && s.shear->creep) {
        count_tangential_free(s);
      }
    }
  }

  /// Spring k's next event from now within the segment, queued; none beyond its end.
  void schedule(std::size_t k) {
    if (const double delay = event_delay(k); delay < kNoDelay) {
      queue_.push({time_ + delay, k, state_[k].version});
    }
  }

  /// No event within the segment, for event_delay and contact_delay.
  static constexpr double kNoDelay = HUGE_VAL;

  /// next_event_delay() as a number, kNoDelay for none: a spring without tangential arms (the
  /// most) takes contact_delay() as it comes. An optional returned up through the stack is
  /// written in two parts and read whole: a store-forwarding stall at every call.
  double event_delay(std::size_t k) const {
    if (!state_[k].shear) return contact_delay(k);
    return next_event_delay(k).value_or(kNoDelay);
  }

  std::optional<double> next_event_delay(std::size_t k) const {
    const std::optional<double> contact = contact_event_delay(k);
    const ViscoelasticSpringState& s = state_[k];
    if (!s.shear) return contact;
    s.shear->friction_event = 0;
    if (s.phase != ViscoelasticSpringPhase::pressed || !springs_.friction) return contact;
    auto [friction, kind] = friction_event_delay(k);
    if (const auto glue = rebinding_glue_delay(k); glue && (!friction || *glue < *friction)) {
      friction = glue;
      kind = kGlueEvent;
    }
    if (!friction || (contact && !(*friction < *contact))) return contact;
    s.shear->friction_event = kind;
    return friction;
  }

  /// Spring k's next touch, release, glue or let-go from now within the segment.
  std::optional<double> contact_event_delay(std::size_t k) const {
    const double delay = contact_delay(k);
    return delay < kNoDelay ? std::optional<double>(delay) : std::nullopt;
  }

  /// contact_event_delay() as a number, kNoDelay for none.
  double contact_delay(std::size_t k) const {
    if (springs_.edge) return next_event_delay_at_edge(k).value_or(kNoDelay);
    const ViscoelasticSpringState& s = state_[k];
    const double span = end_ - time_;
    const double stretch = depth_ - springs_.images[k];
    if (s.phase == ViscoelasticSpringPhase::untouched) {
      if (stretch >= 0.0) return 0.0;
      if (rate_ <= 0.0) return kNoDelay;
      const double delay = -stretch / rate_;
      return delay <= span ? delay : kNoDelay;
    }
    // A touch or a release leaves the spring at zero overlap or zero load up to rounding: it
    // acts at once only when the sign says so and the motion leads on (no back-and-forth at
    // one time), and a spring within rounding of the level on the wrong side starts on it.
    if (s.phase == ViscoelasticSpringPhase::free) {
      // The indenter's stretch less the free surface's, negative while apart. A spring released
      // at this time is not met again at it: where its load touched zero with zero slope the
      // release's test and this one disagree by rounding, and the two would alternate forever.
      // Within rounding of the surface the level is taken where the overlap stands (shifting
      // the sum by its value at 0 need not make it 0 there), so that the crossing is a later one.
      // Its value and slope now, read as ExponentialSum::at and slope_at read the sum below (the
      // same numbers), before the sum is built: most free springs need no more.
      const FreeSpringCreepRef free_creep = creep(s);
      const double age = time_ - s.released_at;
      double now = stretch + rate_ * 0.0;
      double closing = rate_;
      bool falls = true;
      for (std::size_t m = 0; m < free_creep.rates().size(); ++m) {
        const double amplitude = -free_creep.mode_stretch(m, age);
        now += amplitude;
        closing -= amplitude / (1.0 / free_creep.rates()[m]);
        falls = falls && amplitude <= 0.0;
      }
      if (now >= 0.0 && closing > 0.0 && time_ > s.released_at) return 0.0;
      // The indenter leaving faster than the surface comes back, which comes back ever slower
      // (the overlap's decays all below zero: its slope only falls): the overlap falls from
      // where it stands, and the spring is not met again in the segment. first_crossing finds
      // none as well, at the cost of its pieces (most of a withdrawal's free springs).
      if (closing < 0.0 && falls) return kNoDelay;
      ExponentialSum& overlap = scratch_;
      free_creep.stretch_from(age, overlap);
      for (ExponentialDecay& decay : overlap.decays) decay.amplitude = -decay.amplitude;
      overlap.constant = stretch - overlap.constant;
      overlap.slope = rate_;
      return first_crossing(overlap, std::max(now, 0.0), span).value_or(kNoDelay);
    }
    FewValues<double> stresses(springs_.terms.size());
    for (std::size_t j = 0; j < stresses.size(); ++j) stresses[j] = arms_.stress(member(s), j);
    {
      // Whether the load only rises (loads_up of the sum below at a load not below zero), read
      // as line_load_over builds the sum and ExponentialSum::at reads it (the same numbers):
      // a pressed spring while the drive presses needs no more.
      double constant = springs_.relaxed_modulus * stretch;
      for (const PronyTerm& term : springs_.terms) constant += term.modulus * rate_ * term.time;
      double at_zero = constant + springs_.relaxed_modulus * rate_ * 0.0;
      bool falls = true;
      for (std::size_t j = 0; j < stresses.size(); ++j) {
        const PronyTerm& term = springs_.terms[j];
        const double amplitude = stresses[j] - term.modulus * rate_ * term.time;
        at_zero += amplitude;
        falls = falls && amplitude <= 0.0;
      }
      if (at_zero >= 0.0 && springs_.relaxed_modulus * rate_ >= 0.0 && falls) return kNoDelay;
    }
    ExponentialSum& load = scratch_;
    line_load_over(load, springs_.relaxed_modulus, springs_.terms, stretch, stresses, rate_);
    const double now = load.at(0.0);
    // A spring at zero load that stays there (met at the turn of a hold) stays pressed, as an
    // elastic row counts a spring whose image the depth reaches.
    if (now <= 0.0 && load.slope_at(0.0) < 0.0) return 0.0;
    if (now >= 0.0 && loads_up(load)) return kNoDelay;
    if (now < 0.0) load.constant -= now;
    const std::optional<double> near =
        release_hint_ > 0.0 ? std::optional<double>(release_hint_) : std::nullopt;
    return first_crossing(load, 0.0, span, near).value_or(kNoDelay);
  }

  // A held segment (fixed load, a machine spring): the depth follows motion_, rebuilt at every
  // event, and each event is the first of every spring's found against it.

  RowHeldAxis held_now() const { return held_->after(time_ - segment_start_); }

  std::vector<double> arm_sums() const {
    std::vector<double> sums(springs_.terms.size());
    for (std::size_t j = 0; j < sums.size(); ++j) sums[j] = arms_.arm_force(j);
    return sums;
  }

  /// The depth at which the indenter meets the nearest spring that is not pressed [m].
  double nearest_surface() const {
    double nearest = HUGE_VAL;
    for (std::size_t k = 0; k < state_.size(); ++k) {
      const ViscoelasticSpringState& s = state_[k];
      if (s.phase == ViscoelasticSpringPhase::pressed) continue;
      const double w =
          s.phase == ViscoelasticSpringPhase::free ? creep(s).stretch(time_ - s.released_at) : 0.0;
      nearest = std::min(nearest, springs_.images[k] + w);
    }
    return nearest;
  }

  void rebuild_motion() {
    const RowHeldAxis axis = held_now();
    if (pressed_.empty() && axis.stiffness == 0.0 && (axis.held > 0.0 || axis.rate > 0.0)) {
      // A force that nothing holds yet (at zero force, so with no work): the indenter moves in
      // to the nearest surface at once.
      const double nearest = nearest_surface();
      if (std::isfinite(nearest)) depth_ = nearest;
    }
    const std::vector<double> sums = arm_sums();
    motion_ = depth_under_held_axis(
        springs_.relaxed_modulus, springs_.terms,
        {static_cast<std::int64_t>(pressed_.size()), pressed_images_.value(), sums}, axis, depth_);
    depth_ = motion_.at(0.0);
  }

  void held_advance_to(double t) {
    const double h = t - time_;
    if (h > 0.0) {
      count_held_piece(h);
      arms_.advance_along(motion_, h);
      for (std::size_t j = 0; j < own_squares_.size(); ++j) {
        own_squares_[j] *= std::exp(-2.0 * h / springs_.terms[j].time);
      }
      depth_ = motion_.at(h);
      motion_ = shifted(motion_, h);
      if (shear_held_) {
        advance_held_shear(h);
      } else if (tangential_on_) {
        count_held_tangential_piece(h);
        tangential_arms_.advance(tangential_rate_, h);
        tangential_own_squares_.advance(tangential_terms_, h);
      }
    }
    time_ = t;
    if (shear_held_) return;
    tangential_ =
        t == end_ ? end_tangential_ : segment_tangential_ + tangential_rate_ * (t - segment_start_);
  }

  /// The machine's work and the pressed springs' dissipation over the next h [s] of motion_, all
  /// springs at once: the load per half is phi - kappa d; each pressed spring's arm is its own
  /// stress decaying plus the arms' common response R_j to the motion, so sum_i sigma_ij^2 =
  /// n R_j^2 + 2 R_j S_j(0) exp(-s/tau_j) + sum_i sigma_ij(0)^2 exp(-2 s/tau_j).
  void count_held_piece(double h) {
    machine_work_.add(held_axis_work(held_now(), motion_, h));
    if (pressed_.empty()) return;
    const auto n = static_cast<double>(pressed_.size());
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      const PronyTerm& term = springs_.terms[j];
      const ExponentialSum common = arm_stress_under(0.0, term, motion_);
      const ExponentialSum own{0.0, 0.0, {{1.0, term.time}}};
      const ExponentialSum own_squared{0.0, 0.0, {{1.0, 0.5 * term.time}}};
      // sum_i sigma_ij^2 = n H_j^2 + 2 H_j C_j + sum_i delta_ij^2, sigma_ij = H_j + delta_ij.
      const double history = arms_.history(j);
      const double own_sum = arms_.arm_force(j) - n * history;
      const double squares =
          n * history * history + 2.0 * history * own_sum + std::max(own_squares_[j], 0.0);
      const double integral = n * integral_of_product(common, common, h) +
                              2.0 * arms_.arm_force(j) * integral_of_product(common, own, h) +
                              squares * integral_of_product(own_squared, {1.0, 0.0, {}}, h);
      dissipated_.add(integral / (term.modulus * term.time));
    }
  }

  // The held search's indexes. Each spring's next event is looked for only where a bound allows
  // one, and the bounds are kept so that the springs that cannot act are never visited:
  // - an untouched spring's gap g - d(s) reaches 0 only where g <= max d (its image, in order);
  // - a pressed spring's load is q_i(s) = Q(s) - E* g_i + sum_j delta_ij exp(-s / tau_j), with
  //   Q = E* d + sum_j (the arms' history H_j driven on) shared and delta_ij = sigma_ij - H_j its
  //   own decaying part, so q_i >= min Q - K_i, K_i = E* g_i - sum_j min(delta_ij, 0): a key
  //   that only falls as the deltas decay, kept in a max-heap (a stale key is too high, never
  //   too low);
  // - a free spring's surface g_i + w_i(t), w_i a sum of decays, is at least g_i + sum_k
  //   min(a_ik(t), 0), a key that only rises, kept in a min-heap (a stale key is too low).

  double pressed_key(std::size_t k) const {
    double key = springs_.relaxed_modulus * springs_.images[k];
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      key -= std::min(arms_.stress(member(state_[k]), j) - arms_.history(j), 0.0);
    }
    return key;
  }

  /// A free spring's surface g + w over the next `horizon` [s] is at least this: each decay of w
  /// at its lower end.
  double free_key(std::size_t k, double horizon) const {
    const ViscoelasticSpringState& s = state_[k];
    double key = springs_.images[k];
    for (const ExponentialDecay& d : creep(s).stretch_from(time_ - s.released_at).decays) {
      key += std::min(d.amplitude, d.amplitude * std::exp(-horizon / d.time));
    }
    return key;
  }

  /// A free spring's key is kept for a quarter of the fastest retardation time (so that the
  /// part of its surface still pressed in counts), renewed when it runs out.
  double free_key_horizon() const { return 0.25 / modes_->rates().back(); }

  void push_free_key(std::size_t k, double horizon) {
    const std::uint32_t generation = ++free_generation_[k];
    const HeldSpringKey entry{free_key(k, horizon), k, state_[k].version, time_ + horizon,
                              generation};
    free_keys_.push(entry);
    free_expiry_.push(entry);
  }

  bool free_key_is_current(const HeldSpringKey& entry) const {
    return entry.version == state_[entry.spring].version &&
           entry.generation == free_generation_[entry.spring];
  }

  void index_held() {
    untouched_by_image_.clear();
    pressed_keys_ = {};
    free_keys_ = {};
    free_expiry_ = {};
    free_generation_.resize(state_.size(), 0);
    own_squares_.assign(springs_.terms.size(), 0.0);
    tangential_own_squares_.reset(tangential_terms_.size());
    for (std::size_t k = 0; k < state_.size(); ++k) {
      const ViscoelasticSpringState& s = state_[k];
      if (s.phase == ViscoelasticSpringPhase::untouched) {
        untouched_by_image_.insert({springs_.images[k], k});
      } else if (in_contact(s)) {
        // A glued spring acts only as the boundary, which the search offers first.
        if (s.phase == ViscoelasticSpringPhase::pressed) {
          pressed_keys_.push({pressed_key(k), k, s.version});
        }
        for (std::size_t j = 0; j < own_squares_.size(); ++j) {
          const double delta = arms_.stress(member(s), j) - arms_.history(j);
          own_squares_[j] += delta * delta;
        }
        if (tangential_on_ && s.phase == ViscoelasticSpringPhase::glued) {
          FewValues<double> stresses(tangential_terms_.size());
          for (std::size_t j = 0; j < stresses.size(); ++j) {
            stresses[j] = tangential_arms_.stress(s.shear->member, j);
          }
          tangential_own_squares_.change(tangential_arms_, stresses, 1.0);
        }
      } else {
        push_free_key(k, free_key_horizon());
      }
    }
  }

  /// Spring k was just touched or glued, or released or let go (its stresses then in
  /// counted_stresses).
  void index_change(std::size_t k, bool release) {
    const ViscoelasticSpringState& s = state_[k];
    for (std::size_t j = 0; j < own_squares_.size(); ++j) {
      const double delta = counted_stresses(s)[j] - arms_.history(j);
      own_squares_[j] += release ? -delta * delta : delta * delta;
    }
    if (release) {
      push_free_key(k, free_key_horizon());
    } else {
      untouched_by_image_.erase({springs_.images[k], k});
      if (s.phase == ViscoelasticSpringPhase::pressed) {
        pressed_keys_.push({pressed_key(k), k, s.version});
      }
    }
  }

  /// The pressed springs' shared load part E* d(s) + sum_j R_j(s), each spring's load being it
  /// less E* g_i plus its own arms' stresses decaying.
  ExponentialSum shared_load() const {
    ExponentialSum q{
        springs_.relaxed_modulus * motion_.constant, springs_.relaxed_modulus * motion_.slope, {}};
    for (const ExponentialDecay& d : motion_.decays) {
      q.decays.push_back({springs_.relaxed_modulus * d.amplitude, d.time});
    }
    for (const PronyTerm& term : springs_.terms) {
      const ExponentialSum r = arm_stress_under(0.0, term, motion_);
      q.constant += r.constant;
      q.decays.insert(q.decays.end(), r.decays.begin(), r.decays.end());
    }
    return q;
  }

  /// Whether spring k may have an event within `limit` [s] of now, by bounds on each part of its
  /// gap or load (never false where it has one).
  bool held_may_act(std::size_t k, double limit, const ExponentialSumBounds& depth,
                    const ExponentialSumBounds& shared) const {
    const ViscoelasticSpringState& s = state_[k];
    // With an adhesive edge the boundary may let go (looked at exactly), no other glued spring
    // acts, and the spring outside the contact is reached at its glue gap.
    if (s.phase == ViscoelasticSpringPhase::glued) return boundary() == k;
    const double g = springs_.images[k] - held_glue_gap(k);
    if (s.phase == ViscoelasticSpringPhase::untouched) return depth.hi - g >= 0.0;
    if (s.phase == ViscoelasticSpringPhase::free) {
      const ExponentialSum w = creep(s).stretch_from(time_ - s.released_at);
      return depth.hi - g - bounds_over(w, limit).lo >= 0.0;
    }
    double lo = shared.lo - springs_.relaxed_modulus * g;
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      const double sigma = arms_.stress(member(s), j);
      lo += std::min(sigma, sigma * std::exp(-limit / springs_.terms[j].time));
    }
    return lo <= 0.0;
  }

  /// Spring k's next event within `limit` [s] of now under motion_, as next_event_delay has it
  /// for a linear drive.
  std::optional<double> held_delay(std::size_t k, double limit,
                                   const ExponentialSum& shared) const {
    const ViscoelasticSpringState& s = state_[k];
    if (s.phase == ViscoelasticSpringPhase::glued) return held_let_go_delay(k, limit, shared);
    // The indenter reaches a spring it glues at the glue gap.
    const double g = springs_.images[k] - held_glue_gap(k);
    if (s.phase == ViscoelasticSpringPhase::untouched) {
      if (depth_ - g >= 0.0) return 0.0;
      ExponentialSum gap = motion_;
      gap.constant -= g;
      return first_crossing(gap, 0.0, limit);
    }
    if (s.phase == ViscoelasticSpringPhase::free) {
      ExponentialSum overlap = motion_;
      overlap.constant -= g;
      for (const ExponentialDecay& d : creep(s).stretch_from(time_ - s.released_at).decays) {
        overlap.decays.push_back({-d.amplitude, d.time});
      }
      const double now = overlap.at(0.0);
      // A spring that let go at this time is not met again at it (with dgamma_a = dgamma it
      // stands at its glue gap).
      if (now >= 0.0 && overlap.slope_at(0.0) > 0.0 && (!springs_.edge || time_ > s.released_at)) {
        return 0.0;
      }
      return first_crossing(overlap, std::max(now, 0.0), limit);
    }
    ExponentialSum load = shared;
    load.constant -= springs_.relaxed_modulus * g;
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      load.decays.push_back({arms_.stress(member(s), j), springs_.terms[j].time});
    }
    // A spring at zero load within rounding starts on its level (f - level is then exactly 0 at
    // s = 0, and first_crossing takes its side from where it moves).
    const double now = load.at(0.0);
    if (now <= 0.0 && load.slope_at(0.0) < 0.0) return 0.0;
    return first_crossing(load, std::min(now, 0.0), limit);
  }

  /// The gap [m] at which the indenter takes spring k in a held segment: its glue gap where it
  /// glues, else 0 (pressed on touch).
  double held_glue_gap(std::size_t k) const {
    return springs_.edge && glues(k) ? glue_gap(k) : 0.0;
  }

  /// Spring k's line load from now under motion_: the pressed springs' shared part less E* g_k
  /// plus its own arms' stresses decaying.
  ExponentialSum held_load(std::size_t k, const ExponentialSum& shared) const {
    ExponentialSum load = shared;
    load.constant -= springs_.relaxed_modulus * springs_.images[k];
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      load.decays.push_back({arms_.stress(member(state_[k]), j), springs_.terms[j].time});
    }
    return load;
  }

  /// The glued spring k's let-go within `limit` [s] under motion_, as the boundary: its load's
  /// first crossing down to -let_go_loads (next_event_delay_at_edge's rule at the level).
  std::optional<double> held_let_go_delay(std::size_t k, double limit,
                                          const ExponentialSum& shared) const {
    if (boundary() != k) return std::nullopt;
    const ExponentialSum load = held_load(k, shared);
    // A tangential load joins the criterion (u_x moves as under fixed grips, apart from d).
    if (tangential_on_ && springs_.edge->criterion) {
      const double limit_load = springs_.edge->let_go_loads[k];
      if (limit_load > 0.0 && std::isfinite(limit_load)) {
        return tangential_let_go_delay(k, load, limit);
      }
    }
    const double level = -springs_.edge->let_go_loads[k];
    const double slack = load.at(0.0) - level;
    const double slope = load.slope_at(0.0);
    const bool on_it = state_[k].glued_at == time_ || -slack <= kEdgeRounding * std::abs(level);
    if (slack <= 0.0 && (slope < 0.0 || !on_it)) return 0.0;
    return first_crossing(load, slack < 0.0 ? load.at(0.0) : level, limit);
  }

  /// The first event of any spring from now within the segment: the springs at the contact's
  /// edge first (their times bound the search), then the springs the indexes name as able to
  /// act before the best so far, each checked by its own bounds and then exactly.
  std::optional<ViscoelasticRowEvent> held_next_event() {
    const double span = end_ - time_;
    const ExponentialSum shared = shared_load();
    ExponentialSum history_load{
        springs_.relaxed_modulus * motion_.constant, springs_.relaxed_modulus * motion_.slope, {}};
    for (const ExponentialDecay& d : motion_.decays) {
      history_load.decays.push_back({springs_.relaxed_modulus * d.amplitude, d.time});
    }
    for (std::size_t j = 0; j < springs_.terms.size(); ++j) {
      const ExponentialSum h = arm_stress_under(arms_.history(j), springs_.terms[j], motion_);
      history_load.constant += h.constant;
      history_load.decays.insert(history_load.decays.end(), h.decays.begin(), h.decays.end());
    }
    std::optional<double> best;
    std::size_t best_k = 0;
    double bounded_limit = -1.0;
    ExponentialSumBounds depth{0.0, 0.0}, shared_bounds{0.0, 0.0}, history_bounds{0.0, 0.0};
    // A key within rounding of its bound is looked at.
    const auto slack = [](double x) { return 1e-12 * std::abs(x); };
    const auto bound = [&] {
      const double limit = best ? *best : span;
      if (limit != bounded_limit) {
        depth = bounds_over(motion_, limit);
        shared_bounds = bounds_over(shared, limit);
        history_bounds = bounds_over(history_load, limit);
        bounded_limit = limit;
      }
      return limit;
    };
    const auto offer = [&](std::size_t k) {
      const double limit = bound();
      if (!held_may_act(k, limit, depth, shared_bounds)) return;
      const auto delay = held_delay(k, limit, shared);
      if (delay && (!best || *delay < *best || (*delay == *best && k < best_k))) {
        best = delay;
        best_k = k;
      }
    };
    if (const auto k = boundary()) offer(*k);
    if (!pressed_.empty()) {
      const std::size_t edge = pressed_.outermost();
      for (const std::size_t k : {edge, edge + 1, edge + 2}) {
        if (k < state_.size()) offer(k);
      }
    }
    for (const auto& [image, k] : untouched_by_image_) {
      bound();
      if (image > depth.hi + slack(depth.hi)) break;
      offer(k);
    }
    std::vector<HeldSpringKey> looked;
    while (!pressed_keys_.empty()) {
      bound();
      const HeldSpringKey top = pressed_keys_.top();
      if (top.key < history_bounds.lo - slack(history_bounds.lo)) break;
      pressed_keys_.pop();
      if (top.version != state_[top.spring].version) continue;
      const double key = pressed_key(top.spring);
      looked.push_back({key, top.spring, top.version});
      if (key >= history_bounds.lo - slack(history_bounds.lo)) offer(top.spring);
    }
    for (const HeldSpringKey& key : looked) pressed_keys_.push(key);
    looked.clear();
    // Keys that run out before the search's end are renewed over it first.
    const double reach = bound();
    while (!free_expiry_.empty() && free_expiry_.top().valid_until < time_ + reach) {
      const HeldSpringKey top = free_expiry_.top();
      free_expiry_.pop();
      if (free_key_is_current(top)) push_free_key(top.spring, std::max(free_key_horizon(), reach));
    }
    while (!free_keys_.empty()) {
      bound();
      const HeldSpringKey top = free_keys_.top();
      if (top.key > depth.hi + slack(depth.hi)) break;
      free_keys_.pop();
      if (!free_key_is_current(top)) continue;
      looked.push_back(top);
      offer(top.spring);
    }
    for (const HeldSpringKey& key : looked) free_keys_.push(key);
    if (!best) return std::nullopt;
    return ViscoelasticRowEvent{time_ + *best, best_k, state_[best_k].version};
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
      if (tangential_on_ && springs_.edge->criterion) {
        const double limit = springs_.edge->let_go_loads[k];
        if (limit > 0.0 && std::isfinite(limit)) {
          return tangential_let_go_delay(k, load_over(s, stretch), span);
        }
      }
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
      // Within rounding below zero and rising: the level is taken where the load stands, to the
      // bit, so that its side is read from where it goes (a constant shifted by it may leave
      // f(0) a hair below and find a crossing at once).
      return first_crossing(load, std::min(now, 0.0), span);
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
    const ExponentialSum free_surface = creep(s).stretch_from(time_ - s.released_at);
    const double surface = free_surface.at(0.0);
    const double overlap = reach - surface;
    const double rounding =
        kEdgeRounding * (std::abs(depth_) + std::abs(springs_.images[k]) + std::abs(surface) + gap);
    const bool approaching = rate_ - free_surface.slope_at(0.0) > 0.0;
    const bool again_now = s.glued_at == time_;
    if (s.lifted_at == time_ && !again_now) {
      // A pressed spring lifted at this time stands on the indenter whatever the overlap (its
      // load reached zero where the rounding of the time, d' times an ulp of t, may leave it a
      // hair inside): it is taken back now only where its load, pressed, would rise, read as the
      // pressed spring's own release reads it, so the two cannot take turns at one time.
      if (overlap >= -rounding && lifted_load_rises(s, stretch)) return 0.0;
      return reach_time(creep(s), time_ - s.released_at, reach, rate_, span, true);
    }
    if (!again_now && (overlap > rounding || (overlap >= -rounding && approaching))) return 0.0;
    return reach_time(creep(s), time_ - s.released_at, reach, rate_, span, overlap >= -rounding);
  }

  /// The boundary spring k's let-go with a tangential load: the first s at which the glassy
  /// criterion's margin at elongation -q_z(s) / E_0 and u_x = q_x(s) / G_0 is <= 0, q_z and q_x
  /// exponential sums in s. A built-in criterion's holding set is convex and symmetric in u_x,
  /// so it only shrinks as |u_x| grows: the let-go comes no later than the normal one (q_z
  /// reaching -let_go_loads), and the span up to it is cut where q_z, q_x or their slopes cross
  /// zero. On a piece where the elongation and |q_x| both grow the margin falls, so its ends
  /// bracket the let-go; where both shrink it rises and holds none; where they part the margin
  /// is read on a grid, and a dip below 0 and back within one step of it is missed. The
  /// bracket is bisected to the last bit.
  /// `normal` is its normal line load from now, over the next `span` [s].
  std::optional<double> tangential_let_go_delay(std::size_t k, const ExponentialSum& normal,
                                                double span) const {
    const ViscoelasticSpringState& s = state_[k];
    const ExponentialSum tangential = tangential_load_over(s);
    const ViscoelasticEdge& edge = *springs_.edge;
    const double x = springs_.spacing * static_cast<double>(k + 1);
    const auto lets_go = [&](double at) {
      const double qx = released_tangential(tangential.at(at), normal.at(at));
      const BoundarySpring spring{std::max(-normal.at(at) / edge.glassy_modulus, 0.0),
                                  qx / edge.glassy_shear_modulus, x};
      return edge.criterion->margin(spring) <= 0.0;
    };
    if (lets_go(0.0) && s.glued_at != time_) return 0.0;
    const double level = -edge.let_go_loads[k];
    const double from = normal.at(0.0);
    const auto normal_let_go = first_crossing(normal, from < level ? from : level, span);
    const double reach = normal_let_go ? *normal_let_go : span;
    const ExponentialSum normal_slope = exponential_sum_slope(normal);
    const ExponentialSum tangential_slope = exponential_sum_slope(tangential);
    std::vector<double> cuts{0.0, reach};
    for (const ExponentialSum* f : {&normal, &tangential, &normal_slope, &tangential_slope}) {
      exponential_sum_zeros(*f, reach, cuts);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    while (cuts.back() > reach) cuts.pop_back();
    const auto bisect = [&](double below, double above) {
      for (;;) {
        const double mid = below + 0.5 * (above - below);
        if (mid <= below || mid >= above) return above;
        (lets_go(mid) ? above : below) = mid;
      }
    };
    constexpr int kGrid = 64;
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
      const double a = cuts[p];
      const double b = cuts[p + 1];
      if (lets_go(b)) return bisect(a, b);
      // Within the piece no sum or slope changes sign: read them in its middle.
      const double mid = a + 0.5 * (b - a);
      const bool opening = normal.at(mid) >= 0.0 || normal_slope.at(mid) <= 0.0;
      const bool closing = normal.at(mid) < 0.0 && normal_slope.at(mid) >= 0.0;
      const double qx = tangential.at(mid);
      const double qx_slope = tangential_slope.at(mid);
      // With friction a compressed spring releases |q_x| - mu q_z: it grows with |q_x| only
      // where q_z does not.
      const bool shearing = qx * qx_slope >= 0.0 && (!springs_.friction || normal.at(mid) <= 0.0 ||
                                                     normal_slope.at(mid) <= 0.0);
      const bool unshearing = qx * qx_slope <= 0.0;
      if ((opening && shearing) || (closing && unshearing)) continue;
      double lo = a;
      for (int i = 1; i < kGrid; ++i) {
        const double at = a + (b - a) * static_cast<double>(i) / kGrid;
        if (lets_go(at)) return bisect(lo, at);
        lo = at;
      }
    }
    return normal_let_go;
  }

  /// The tangential line load [N/m] a glued spring's let-go releases to the surface, of its
  /// tangential load q_x and normal load q_z: all of it without friction or in tension; with
  /// friction a compressed spring keeps its limit mu q_z (it slips there, dissipating), and
  /// releases sign(q_x) max(|q_x| - mu q_z, 0) (docs/friction.md "Letting go under friction").
  double released_tangential(double qx, double qz) const {
    if (!springs_.friction || !(qz > 0.0)) return qx;
    return std::copysign(std::max(std::abs(qx) - *springs_.friction * qz, 0.0), qx);
  }

  /// Whether free spring s, pressed now at stretch `stretch`, would see its load rise: the
  /// slope of load_over() with the arm stresses SharedDriveArms would give it on entering.
  bool lifted_load_rises(const ViscoelasticSpringState& s, double stretch) const {
    FewValues<double> stresses = creep(s).stresses(time_ - s.released_at);
    for (std::size_t j = 0; j < stresses.size(); ++j) {
      const double history = arms_.history(j);
      stresses[j] = history + (stresses[j] - history);
    }
    return line_load_over(springs_.relaxed_modulus, springs_.terms, stretch, stresses, rate_)
               .slope_at(0.0) >= 0.0;
  }

  /// Spring s's line load from now over the segment's motion (its stretch `stretch` now).
  ExponentialSum load_over(const ViscoelasticSpringState& s, double stretch) const {
    FewValues<double> stresses(springs_.terms.size());
    for (std::size_t j = 0; j < stresses.size(); ++j) stresses[j] = arms_.stress(member(s), j);
    return line_load_over(springs_.relaxed_modulus, springs_.terms, stretch, stresses, rate_);
  }

  // A held tangential force or machine spring (under any normal control). Between events the
  // glued set is fixed and kappa u_x + G_inf (m u_x - sum of its origins) + sum_j S_j = phi(t),
  // phi the held F_x (or k h) per unit length of one half, kappa = 0 under a fixed load, S_j the
  // set's arm forces with S_j' = G_j m u_x' - S_j / tau_j: the equation the depth obeys under a
  // held normal control, so u_x(t) is depth_under_held_axis's exponential sum with the
  // tangential arms and G_inf. The normal axis does not see it; only the boundary's let-go
  // reads its q_x, against that sum. A glue leaves the constraint met (a free spring carries no
  // load); a let-go takes its q_x away, and the members left (and a machine spring) take it at
  // once with the arms' glassy modulus G_0 (a step of u_x), which may let the next boundary go
  // at the same time. Either rebuilds the motion. With no member left a fixed load F_x != 0 is
  // not carried (shear_unheld).

  /// The tangential constraint from now: kappa, phi and phi' [N/m^2, N/m, N/(m s)].
  RowHeldAxis shear_now() const { return shear_held_->after(time_ - segment_start_); }

  void begin_held_shear(const DriveSegment& segment) {
    shear_held_.reset();
    shear_unheld_ = false;
    if (!segment.tangential_force) return;
    if (!tangential_on_ && springs_.edge && springs_.shear_ratio > 0.0) start_tangential();
    // Per unit length of one half: kappa u_x + q_total = phi (prony_load_drive.hpp).
    const AffineConstraint& c = segment.tangential_force->constraint;
    const double per_half = 2.0 * springs_.spacing * c.force_coefficient;
    shear_held_ = RowHeldAxis{c.displacement_coefficient / per_half,
                              segment.tangential_force->start / per_half,
                              segment.tangential_force->rate / per_half};
    tangential_own_squares_.reset(tangential_terms_.size());
    for (const ViscoelasticSpringState& s : state_) {
      if (!s.shear || !s.shear->in_set) continue;
      FewValues<double> stresses(tangential_terms_.size());
      for (std::size_t j = 0; j < stresses.size(); ++j) {
        stresses[j] = tangential_arms_.stress(s.shear->member, j);
      }
      tangential_own_squares_.change(tangential_arms_, stresses, 1.0);
    }
    rebuild_shear_motion();
  }

  void rebuild_shear_motion() {
    const RowHeldAxis axis = shear_now();
    std::vector<double> sums(tangential_terms_.size());
    for (std::size_t j = 0; j < sums.size(); ++j) sums[j] = tangential_arms_.arm_force(j);
    shear_motion_ = depth_under_held_axis(tangential_relaxed(), tangential_terms_,
                                          {tangential_members_, glued_origins_.value(), sums}, axis,
                                          tangential_);
    tangential_ = shear_motion_.at(0.0);
    shear_unheld_ =
        tangential_members_ == 0 && axis.stiffness == 0.0 && (axis.held != 0.0 || axis.rate != 0.0);
  }

  void advance_held_shear(double h) {
    if (!(h > 0.0)) return;
    count_held_shear_piece(h);
    tangential_arms_.advance_along(shear_motion_, h);
    tangential_own_squares_.advance(tangential_terms_, h);
    tangential_ = shear_motion_.at(h);
    shear_motion_ = shifted(shear_motion_, h);
  }

  /// The machine's tangential work and the members' dissipation over the next h [s] of
  /// shear_motion_, all members at once: int phi du_x under a fixed load, int q dh under a
  /// machine spring (its end moving at phi' / kappa, its load phi - kappa u_x).
  void count_held_shear_piece(double h) {
    tangential_work_.add(held_axis_work(shear_now(), shear_motion_, h));
    if (tangential_members_ == 0) return;
    dissipated_.add(
        shared_arms_motion_piece(tangential_arms_, tangential_own_squares_, shear_motion_, h)
            .dissipated);
  }

  /// After a glue or a let-go: the constraint met again at once, the members answering with
  /// G_0 (the dashpots do not move): (kappa + m G_0) Du = phi - kappa u - q, as the held normal
  /// axis's glassy step (held_glassy_step): a fixed load holds its force (work phi Du), a
  /// machine spring's end stays (its work on the row Du (q_before + q_after) / 2); the members
  /// store Du q + m G_0 Du^2 / 2 more, and the rest is lost.
  void held_shear_change(ViscoelasticRowChange change) {
    const RowHeldAxis axis = shear_now();
    const auto m = static_cast<double>(tangential_members_);
    const double glassy = m * glassy_shear_modulus();
    const double stiffness = axis.stiffness + glassy;
    if (change == ViscoelasticRowChange::let_go && stiffness > 0.0) {
      const double load = tangential_relaxed() * (m * tangential_ - glued_origins_.value()) +
                          tangential_arms_.arm_force();
      const double load_before = axis.held - axis.stiffness * tangential_;
      const double step = (load_before - load) / stiffness;
      const double stored = step * load + 0.5 * glassy * step * step;
      const bool fixed_load = axis.stiffness == 0.0;
      const double machine =
          fixed_load ? axis.held * step : 0.5 * step * (load_before + load + glassy * step);
      if (fixed_load) {
        tangential_work_.add(machine);
      } else {
        spring_work_.add(machine);
      }
      jump_losses_.add(machine - stored);
      if (m > 0.0) tangential_arms_.glassy_step(step);
      tangential_ += step;
    }
    rebuild_shear_motion();
  }

  /// A member's tangential line load from now under shear_motion_ (its arm stresses now).
  ExponentialSum held_shear_load(const ViscoelasticSpringState& s,
                                 std::span<const double> stresses) const {
    ExponentialSum load{tangential_relaxed() * (shear_motion_.constant - s.shear->origin),
                        tangential_relaxed() * shear_motion_.slope,
                        {}};
    for (const ExponentialDecay& d : shear_motion_.decays) {
      load.decays.push_back({tangential_relaxed() * d.amplitude, d.time});
    }
    for (std::size_t j = 0; j < tangential_terms_.size(); ++j) {
      const ExponentialSum r = arm_stress_under(stresses[j], tangential_terms_[j], shear_motion_);
      load.constant += r.constant;
      load.slope += r.slope;
      load.decays.insert(load.decays.end(), r.decays.begin(), r.decays.end());
    }
    return load;
  }

  std::optional<RowHeldAxis> shear_held_;  ///< a held F_x's constraint, per unit x of one half
  ExponentialSum shear_motion_;            ///< u_x from now under it [m]
  CompensatedSum spring_work_;  ///< a machine spring's work on the row in glassy steps [J/m]
  bool shear_unheld_ = false;

  const ViscoelasticRowSprings& springs_;
  SharedDriveArms arms_;
  std::shared_ptr<const RetardationModes> modes_;
  std::vector<PronyTerm> tangential_terms_;
  SharedDriveArms tangential_arms_;  ///< the glued springs' tangential arms
  std::shared_ptr<const RetardationModes> tangential_modes_;
  bool tangential_on_ = false;  ///< a tangential drive has moved u_x: the arms are followed
  double tangential_ = 0.0;     ///< u_x [m]
  double segment_tangential_ = 0.0;
  double tangential_rate_ = 0.0;
  double end_tangential_ = 0.0;
  CompensatedSum glued_origins_;         ///< sum of the tangential set's origins [m]
  std::int64_t tangential_members_ = 0;  ///< springs in the tangential set (glued or sticking)
  std::set<std::size_t> sliding_;        ///< with friction: pressed springs sliding
  ExponentialSumTotal sliding_loads_;    ///< their tangential line loads' sum [N/m]
  CompensatedSum friction_;              ///< dissipated by friction [J/m]
  CompensatedSum tangential_work_;       ///< [J/m]
  bool last_let_go_by_shear_ = false;
  // The per-spring arrays in large pages: 1e5 springs write some 13 MB of fresh memory a run (a
  // fault per 4 KiB otherwise, and glibc returns such blocks between runs more or less at will).
  std::vector<ViscoelasticSpringState, LargePageAllocator<ViscoelasticSpringState>> state_;
  std::size_t store_stride_;                               ///< the numbers a spring's block holds
  std::vector<double, LargePageAllocator<double>> store_;  ///< the springs' blocks, in spring order
  RowSpringSet pressed_;                                   ///< in contact: pressed or glued
  RowSpringSet glued_;
  HoldingTangentialLoads holding_loads_;
  mutable RebindingRunMemo run_memo_;  ///< rebinding's last look along the sticking run
  CompensatedSum pressed_images_;
  CompensatedSum pressed_image_squares_;  ///< sum of g_i^2 over the springs in contact [m^2]
  /// The events found as a segment begins (each spring's first in it: most of its events), in
  /// their order, read in turn; the events found later are queued. The next is the earlier head
  /// (a spring's stale entries skipped in both), as one queue of all would give it.
  std::vector<ViscoelasticRowEvent, LargePageAllocator<ViscoelasticRowEvent>> first_events_;
  std::size_t next_first_event_ = 0;
  bool next_is_first_ = false;  ///< whether next_event() took first_events_'s head
  std::priority_queue<ViscoelasticRowEvent, std::vector<ViscoelasticRowEvent>, std::greater<>>
      queue_;
  double time_ = 0.0;
  double depth_ = 0.0;
  double segment_start_ = 0.0;
  double segment_depth_ = 0.0;
  double rate_ = 0.0;
  double end_ = 0.0;
  double end_depth_ = 0.0;
  std::optional<RowHeldAxis> held_;                              ///< set in a held segment
  std::set<std::pair<double, std::size_t>> untouched_by_image_;  ///< in a held segment
  std::priority_queue<HeldSpringKey, std::vector<HeldSpringKey>, HeldKeyBelow> pressed_keys_;
  std::priority_queue<HeldSpringKey, std::vector<HeldSpringKey>, HeldKeyAbove> free_keys_;
  std::priority_queue<HeldSpringKey, std::vector<HeldSpringKey>, HeldKeyExpiresLater> free_expiry_;
  std::vector<std::uint32_t> free_generation_;
  /// sum_i delta_ij^2 over the springs in contact [N^2/m^2], delta_ij = sigma_ij - H_j.
  std::vector<double> own_squares_;
  /// The same with every removal added, decayed alike: how far own_squares_ may have cancelled.
  std::vector<double> own_squares_gross_;
  bool own_squares_current_ = false;  ///< whether own_squares_ is, outside a held segment
  /// 1 - exp(-h / tau_j) of the last piece, which count_contact_piece hands to the arms.
  std::vector<double> relaxed_parts_;
  /// Per term, 1 / tau_j and 1 / (E_j tau_j): an event's piece multiplies by them.
  std::vector<double> inverse_times_;
  std::vector<double> dissipation_factors_;
  /// The same of the glued springs' tangential arms, in a held segment.
  SharedArmOwnSquares tangential_own_squares_;
  ExponentialSum motion_;  ///< the depth from now in a held segment [m]
  /// A sum next_event_delay builds, its storage kept from event to event.
  mutable ExponentialSum scratch_;
  /// As a segment begins, where the next release's Newton starts [s]: the last two springs'
  /// first event delays carried on (neighbours release close in time).
  double release_hint_ = kNoHint;
  static constexpr double kNoHint = -1.0;  ///< no hint: a delay is never negative
  CompensatedSum machine_work_;            ///< [J/m]
  CompensatedSum dissipated_;              ///< [J/m]
  CompensatedSum surface_;                 ///< [J/m]
  CompensatedSum jump_losses_;             ///< [J/m]
  ViscoelasticRowEnergy let_go_run_;       ///< let_go_run()
  double let_go_run_time_ = -HUGE_VAL;
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
  if (row.shear_unheld()) return true;
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
    // as an elastic program's lift), a touch or a glue with the spring in contact; with no one
    // to report to, neither state is built.
    if (on_change) before_last_change_ = row.sample();
    const ViscoelasticRowChange change = row.apply(event->spring, counts_);
    const bool leaves =
        change == ViscoelasticRowChange::release || change == ViscoelasticRowChange::let_go;
    if (on_change) on_change(change, leaves ? before_last_change_ : row.sample());
    if (stop_at_separation && leaves && !row.in_contact()) return true;
    if (row.shear_unheld()) return true;
    if (counts_.events() >= event_limit_) {
      limited_ = true;
      return false;
    }
  }
  row.advance_to(row.end());
  return false;
}

ViscoelasticRowSample ViscoelasticRowDrive::sample() const { return row_->sample(); }

bool ViscoelasticRowDrive::last_let_go_by_shear() const { return row_->last_let_go_by_shear(); }
bool ViscoelasticRowDrive::shear_unheld() const { return row_->shear_unheld(); }
ViscoelasticRowEnergy ViscoelasticRowDrive::let_go_run() const {
  const ViscoelasticRowEnergy e = row_->let_go_run();
  const double both_halves = 2.0 * row_->spacing();
  return {.machine_work = e.machine_work * both_halves,
          .tangential_work = e.tangential_work * both_halves,
          .stored = e.stored * both_halves,
          .surface = e.surface * both_halves,
          .jump_losses = e.jump_losses * both_halves};
}

ViscoelasticRowEnergy ViscoelasticRowDrive::energy() {
  ViscoelasticRowEnergy e = row_->energy();
  // Both halves: each spring of the row stands for 2 dx of the foundation.
  const double both_halves = 2.0 * row_->spacing();
  return {.machine_work = e.machine_work * both_halves,
          .tangential_work = e.tangential_work * both_halves,
          .stored = e.stored * both_halves,
          .dissipated_by_bulk = e.dissipated_by_bulk * both_halves,
          .surface = e.surface * both_halves,
          .jump_losses = e.jump_losses * both_halves,
          .dissipated_by_friction = e.dissipated_by_friction * both_halves};
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
