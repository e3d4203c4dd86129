// Stages of a rate-law program on one row: the advancing front's glues, the receding front's ODE
// between springs with its let-gos located on the dense output, and each stage's energy balance.
#include "engine/program/rate_law_row.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

// Odeint's steppers copy their scratch arrays, unset until the first step, when the controlled
// stepper is built; GCC at -O3 sees the copy of the unset std::array.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "engine/base/bracketed_root.hpp"
#include "engine/base/hess_scale.hpp"
#include "engine/model/gluing_depth.hpp"
#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_front_arms.hpp"
#include "engine/model/viscoelastic_edge.hpp"
#include "engine/program/run_program.hpp"

namespace mdrsim {
namespace {

namespace odeint = boost::numeric::odeint;
using RowFrontVector = std::array<double, 1>;
using RowFrontStepper = odeint::runge_kutta_dopri5<RowFrontVector>;
/// The walk's local tolerance in its scaled variables (a over the row's radius, t over the time
/// the front takes at v* to cross it): far below the row's O(1/N), so that the row's numbers
/// are the row's and not the integrator's.
constexpr double kRowFrontTolerance = 1e-11;
constexpr long long kMostRowFrontSteps = 10'000'000;
/// A relaxing bulk's front load within this fraction of its threshold stands on it: the sums of
/// arm stresses it is read from round far above the load's own ulp.
constexpr double kThresholdRounding = 1e-12;

/// What a stage does to the held depth: d(t) = start + rate (t - t0) until `end_time`.
struct RowStageDrive {
  double rate = 0.0;       ///< dd/dt [m/s]
  double end_time = 0.0;   ///< [s]; infinite until separation
  double end_depth = 0.0;  ///< d at end_time [m] (not until separation)
};

/// How one walk of the front ended: at its target, with the contact lost, or at a let-go after
/// which the front's load is read from the new boundary spring (a relaxing bulk).
enum class RowWalkEnd { reached, lost, restart };

/// A spring of a relaxing bulk that let go: it creeps free from its release.
struct ReleasedRowSpring {
  FreeSpringCreep creep;
  double released_at = 0.0;  ///< [s]
};

/// The row, its glued springs 1..m, the front's radius a (x_m <= a, and a < x_(m+1)), the held
/// depth d and the clock, and the energy each stage's events move.
class RateLawRow {
 public:
  RateLawRow(const Scene& scene, const ProgramRowSpec& spec, const ObserverList& observers)
      : scene_(scene),
        law_(*scene.front_speed_law),
        observers_(observers),
        n_(spec.reference_springs),
        dx_(spec.reference_radius / static_cast<double>(spec.reference_springs)),
        modulus_(scene.material.effective_modulus),
        work_of_adhesion_(scene.material.work_of_adhesion),
        hess_(hess_scale(scene.material.work_of_adhesion, scene.material.effective_modulus)),
        length_(spec.reference_radius),
        time_scale_(spec.reference_radius / law_.speed),
        glue_material_(scene.material.relaxes() ? glassy_material(scene.material) : scene.material),
        glue_modulus_(scene.material.relaxes() ? scene.material.glassy_modulus()
                                               : scene.material.effective_modulus),
        glassy_hess_(hess_scale(scene.material.work_of_adhesion, glue_modulus_)) {
    if (scene.material.relaxes()) {
      terms_ = scene.material.relaxation;
      arms_.emplace(terms_);
      modes_ = std::make_shared<const RetardationModes>(modulus_, terms_);
    }
    images_.reserve(static_cast<std::size_t>(n_));
    image_sums_.reserve(static_cast<std::size_t>(n_) + 1);
    image_sums_.push_back(0.0);
    for (std::int64_t i = 1; i <= n_; ++i) {
      const double g = i < n_ ? program_image(scene, x(i)) : spec.reference_image;
      images_.push_back(g);
      image_sums_.push_back(image_sums_.back() + g);
    }
  }

  double x(std::int64_t i) const { return dx_ * static_cast<double>(i); }
  double g(std::int64_t i) const { return images_[static_cast<std::size_t>(i - 1)]; }
  std::int64_t glued() const { return m_; }
  double time() const { return t_; }
  double depth() const { return d_; }

  /// F [N]: 2 E* dx sum_{i <= m} (d - g_i), and on a relaxing bulk the arms' 2 sum_ij dx
  /// sigma_ij.
  double force() const {
    const double relaxed = 2.0 * modulus_ * dx_ * (static_cast<double>(m_) * d_ - image_sums_[m_]);
    if (!arms_) return relaxed;
    return relaxed + 2.0 * arms_->arm_force();
  }
  /// The glued springs' elastic energy, both halves: E* dx sum (d - g_i)^2 [J]; on a relaxing
  /// bulk with their arms' and the let-go springs' (creeping free) energy.
  double stored() const {
    double sum = 0.0;
    for (std::int64_t i = 1; i <= m_; ++i) sum += (d_ - g(i)) * (d_ - g(i));
    if (!arms_) return modulus_ * dx_ * sum;
    return modulus_ * dx_ * sum + 2.0 * arms_->stored() + released_energy_at(t_);
  }
  /// What the dashpots dissipated so far [J]: the glued arms' and the let-go springs' creep
  /// (a free spring carries no load, so it dissipates what it stores less).
  double bulk() const {
    if (!arms_) return 0.0;
    return glued_bulk_ + released_energy_ - released_energy_at(t_);
  }

  ContactSnapshot snapshot() const {
    ContactSnapshot c;
    c.normal_control = d_;
    c.indentation = d_;
    c.normal_force = force();
    c.contact_radius = m_ > 0 ? x(m_) : 0.0;
    c.springs_in_contact = m_;
    c.glued_radius = c.contact_radius;
    c.edge_normal_force = m_ > 0 ? 2.0 * modulus_ * dx_ * (d_ - g(m_)) : 0.0;
    c.time = t_;
    return c;
  }

  /// Moves the clock to t and the grips to d with the glued springs held: the machine's work
  /// int F dd in closed form, 2 E* dx (d1 - d0) (m (d0 + d1) / 2 - sum g_i).
  /// On a relaxing bulk the arms advance exactly along the stage's drive, their force's work
  /// and their dashpots' dissipation in closed form.
  void move_to(double t, double d) {
    machine_work_ += 2.0 * modulus_ * dx_ * (d - d_) *
                     (static_cast<double>(m_) * 0.5 * (d_ + d) - image_sums_[m_]);
    if (arms_ && t > t_) {
      const DrivenArmPiece piece = arms_->advance(drive_.rate, t - t_);
      machine_work_ += 2.0 * drive_.rate * piece.force_time;
      glued_bulk_ += 2.0 * piece.dissipated;
    }
    t_ = t;
    d_ = d;
  }

  /// Runs a stage from the present state; true where the last glued spring let go in it.
  bool run_stage(const Stage& stage, const RowStageDrive& drive) {
    stage_ = stage.name;
    stage_start_ = t_;
    stage_depth_ = d_;
    drive_ = drive;
    const bool until_separation = !std::isfinite(drive.end_time);
    for (;;) {
      double next_glue = std::numeric_limits<double>::infinity();
      if (drive.rate > 0.0 && m_ < n_) {
        next_glue = t_ + std::max(gluing_depth_of(m_ + 1) - d_, 0.0) / drive.rate;
      }
      if (next_glue < drive.end_time) {
        // The grips reach spring m + 1's gluing depth exactly, whatever the rounding of the time.
        if (walk_front(next_glue, std::max(gluing_depth_of(m_ + 1), d_))) return true;
        glue_due();
        continue;
      }
      const bool lost = walk_front(drive.end_time, drive.end_depth);
      if (lost) return true;
      if (until_separation) {
        throw std::runtime_error("rate-law row: a stage until separation ended in contact");
      }
      glue_due();
      return false;
    }
  }

  double machine_work() const { return machine_work_; }
  double surface() const { return surface_; }
  double front_losses() const { return front_losses_; }
  bool relaxing() const { return arms_.has_value(); }
  double glue_losses() const { return glue_losses_; }
  long long steps() const { return steps_; }
  long long root_iterations() const { return root_iterations_; }
  std::int64_t let_gos() const { return let_gos_; }
  const std::optional<ContactSnapshot>& peak() const { return peak_; }
  const std::vector<JumpRecord>& jumps() const { return jumps_; }
  /// Keeps `s` as the peak where it is the most tensile state so far.
  void note(const ContactSnapshot& s) {
    if (s.normal_force < 0.0 && (!peak_ || s.normal_force < peak_->normal_force)) peak_ = s;
  }
  /// The state where the last glued spring let go.
  const ContactSnapshot& lost_at() const { return lost_at_; }

 private:
  double depth_at(double t) const { return stage_depth_ + drive_.rate * (t - stage_start_); }
  double gluing_depth_of(std::int64_t i) const {
    return g(i) - advancing_limit(glue_material_, true, x(i));
  }

  /// Glues every spring the advancing limit takes at d (a cascade at touch), then places the
  /// front on the continuum's advancing front between the outermost glued spring and the next.
  void glue_due() {
    const ContactSnapshot before = snapshot();
    std::int64_t glued_now = 0;
    while (m_ < n_ && d_ >= gluing_depth_of(m_ + 1)) {
      ++m_;
      ++glued_now;
      const double e = g(m_) - d_;
      const double surface = 2.0 * std::numbers::pi * x(m_) * work_of_adhesion_ * dx_;
      surface_ -= surface;
      // A glue is instantaneous: the spring answers with E_0, each arm taking E_j of the step.
      glue_losses_ += surface - glue_modulus_ * dx_ * e * e;
      if (arms_) glue_arms(-e);
      const ContactSnapshot s = snapshot();
      note(s);
      Event glued{.kind = EventKind::spring_glued, .state = s, .stage = stage_};
      glued.in_cascade = glued_now > 1;
      observers_.emit(glued);
    }
    if (glued_now > 1) {
      // Several springs at one depth (the jump-in at touch): a jump, as the program row has it.
      const ContactSnapshot after = snapshot();
      jumps_.push_back({.stage = std::string(stage_),
                        .inward = true,
                        .critical = before,
                        .after = after,
                        .springs = glued_now,
                        .glued_springs = glued_now});
      observers_.emit({.kind = EventKind::jump, .state = after, .stage = stage_});
    }
    if (m_ == 0) return;
    a_ = std::max(a_, x(m_));
    if (m_ < n_) {
      const auto ahead = [&](double r) {
        return scene_.profile->mdr_image(r) - advancing_limit(glue_material_, true, r) - d_;
      };
      if (ahead(x(m_)) <= 0.0 && ahead(x(m_ + 1)) > 0.0) {
        a_ = std::max(a_, bracketed_root(ahead, x(m_), x(m_ + 1)));
      }
    }
  }

  /// Spring m lets go as the front passes it: its stretch energy leaves, its surface energy is
  /// made, and the rest is the front's dissipation, (G - dgamma) 2 pi x dx at G = E* e^2 /
  /// (2 pi x) of the front at x_m.
  void let_go() {
    const ContactSnapshot before = snapshot();
    note(before);
    Event e{.kind = EventKind::spring_detached, .state = before, .stage = stage_};
    e.spring = m_;
    observers_.emit(e);
    const double stretch = g(m_) - d_;
    const double surface = 2.0 * std::numbers::pi * x(m_) * work_of_adhesion_ * dx_;
    surface_ += surface;
    if (arms_) {
      front_losses_ += release_arms() - surface;
    } else {
      front_losses_ += modulus_ * dx_ * stretch * stretch - surface;
    }
    --m_;
    ++let_gos_;
    if (m_ == 0) {
      a_ = 0.0;
      lost_at_ = snapshot();
    }
  }

  // The front's equations in the scaled variables: a = l x, t = t_w + T s, T = l / v*.
  /// v / v* at radius a [m] and depth d [m].
  double speed(double a, double d) const {
    const double e = std::max(scene_.profile->mdr_image(a) - d, 0.0);
    if (!(a > 0.0)) return e > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return law_.front_speed(e * e / (hess_ * a)) / law_.speed;
  }
  /// The front runs to the axis: fast, the grips not pressing, and G growing as a falls at
  /// fixed d (2 a g'(a) < e): a walk in the radius, where dt/da -> 0.
  bool runs_to_axis(double a, double d) const {
    return drive_.rate <= 0.0 && speed(a, d) >= 1.0 &&
           2.0 * a * scene_.profile->mdr_image_slope(a) < scene_.profile->mdr_image(a) - d;
  }

  /// The front from now to `target` [s], where the grips reach `target_depth`: pinned while
  /// G <= dgamma, else the ODE, letting springs go as it passes them. True where the last
  /// glued spring let go (the clock then stands there).
  bool walk_front(double target, double target_depth) {
    for (;;) {
      const RowWalkEnd end = walk_front_once(target, target_depth);
      if (end != RowWalkEnd::restart) return end == RowWalkEnd::lost;
    }
  }

  RowWalkEnd walk_front_once(double target, double target_depth) {
    if (m_ == 0 || !(target > t_)) {
      if (std::isfinite(target)) move_to(target, target_depth);
      return RowWalkEnd::reached;
    }
    if (arms_) {
      if (!relaxing_onset(target, target_depth)) return RowWalkEnd::reached;
      return walk_in_time(target, target_depth);
    }
    // Pinned until e reaches Hess's stretch sqrt(2 pi a dgamma / E*): G = dgamma.
    if (!(speed(a_, d_) > 0.0)) {
      const double onset = scene_.profile->mdr_image(a_) - std::sqrt(hess_ * a_);
      if (!(drive_.rate < 0.0)) {
        move_to(target, target_depth);
        return RowWalkEnd::reached;
      }
      const double t_on = t_ + std::max(d_ - onset, 0.0) / -drive_.rate;
      if (t_on >= target) {
        move_to(target, target_depth);
        return RowWalkEnd::reached;
      }
      move_to(t_on, depth_at(t_on));
    }
    return walk_in_time(target, target_depth);
  }

  // A relaxing bulk: the front's load from the boundary spring's (engine/model/prony_front_arms).
  /// The load at the front's radius as the boundary spring m stands now.
  FrontLineLoad front_load_now() const {
    FrontLineLoad load;
    const DrivenArmMember& member = members_.back();
    load.stresses.resize(terms_.size());
    for (std::size_t j = 0; j < terms_.size(); ++j) load.stresses[j] = arms_->stress(member, j);
    load.stretch = d_ - g(m_);
    load.rate = drive_.rate;
    load.boundary_age = t_ - glue_times_.back();
    load.boundary_image = g(m_);
    load.relaxed_modulus = modulus_;
    load.terms = terms_;
    return load;
  }
  /// v / v* at radius a [m], `seconds` after front_load_ was taken: G = q^2 / (2 pi a E_0).
  double relaxing_speed(double a, double seconds) const {
    const double q = front_load_.at(scene_.profile->mdr_image(a), seconds);
    const double e = std::max(-q, 0.0) / glue_modulus_;
    if (!(a > 0.0)) return e > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return law_.front_speed(e * e / (glassy_hess_ * a)) / law_.speed;
  }
  /// As runs_to_axis: G grows as a falls at fixed time where 2 a g'(a) E(t - t_m) < -q.
  bool relaxing_runs_to_axis(double a, double seconds) const {
    if (!(drive_.rate <= 0.0) || !(relaxing_speed(a, seconds) >= 1.0)) return false;
    const double q = front_load_.at(scene_.profile->mdr_image(a), seconds);
    const double modulus = relaxation_modulus(modulus_, terms_, front_load_.boundary_age + seconds);
    return 2.0 * a * scene_.profile->mdr_image_slope(a) * modulus < -q;
  }
  /// Pinned while G <= dgamma: the clock to the onset, the first time the front's load (an
  /// exponential sum in time) reaches -sqrt(2 pi a dgamma E_0); false where it does not come
  /// before `target` (the clock is then there).
  bool relaxing_onset(double target, double target_depth) {
    front_load_ = front_load_now();
    const double image = scene_.profile->mdr_image(a_);
    const double level = -glue_modulus_ * std::sqrt(glassy_hess_ * a_);
    const double now = front_load_.at(image, 0.0);
    double from = level;
    if (!(now > level)) {
      // A spring glued this instant sits on its threshold to the rounding of the arms' sums:
      // where its tension eases it stays, until the load comes back to where it is now.
      if (!(now >= level - kThresholdRounding * std::abs(level) &&
            front_load_.slope(image).at(0.0) > 0.0)) {
        return true;
      }
      from = now;
    }
    double span = target - t_;
    if (!std::isfinite(span)) {
      // Until separation the grips withdraw, so the load falls without bound: a span that
      // reaches the level.
      span = time_scale_;
      for (int doubling = 0; !(front_load_.at(image, span) < from); ++doubling) {
        if (doubling > 200) {
          throw std::runtime_error("rate-law row: the front's load never reaches its threshold");
        }
        span *= 2.0;
      }
    }
    const std::optional<double> onset = front_load_.first_reach(image, from, span);
    if (!onset || !(t_ + *onset < target)) {
      move_to(target, target_depth);
      return false;
    }
    move_to(t_ + *onset, depth_at(t_ + *onset));
    return true;
  }
  /// Spring m glues at stretch w [m] (< 0: pulled up to the indenter): its arms take E_j w.
  void glue_arms(double stretch) {
    FewValues<double> stresses(terms_.size());
    for (std::size_t j = 0; j < terms_.size(); ++j) stresses[j] = terms_[j].modulus * stretch;
    members_.push_back(arms_->enter(stresses, dx_));
    glue_times_.push_back(t_);
  }
  /// Spring m lets go: its load q steps to zero at E_0 (each arm by E_j of the step) and it
  /// creeps free from there. Returns the glassy energy released, dx q^2 / E_0 over both halves.
  double release_arms() {
    FewValues<double> stresses = arms_->leave(members_.back());
    double q = modulus_ * (d_ - g(m_));
    for (const double sigma : stresses) q += sigma;
    glassy_step(stresses, terms_, -q / glue_modulus_);
    ReleasedRowSpring spring{FreeSpringCreep(modes_, stresses), t_};
    released_energy_ += released_energy(spring, t_);
    released_.push_back(std::move(spring));
    members_.pop_back();
    glue_times_.pop_back();
    return dx_ * q * q / glue_modulus_;
  }
  /// A free spring's energy at t [s], both halves: dx (E* w^2 + sum_j sigma_j^2 / E_j).
  double released_energy(const ReleasedRowSpring& spring, double t) const {
    const double w = spring.creep.stretch(t - spring.released_at);
    const FewValues<double> stresses = spring.creep.stresses(t - spring.released_at);
    double sum = modulus_ * w * w;
    for (std::size_t j = 0; j < terms_.size(); ++j) {
      sum += stresses[j] * stresses[j] / terms_[j].modulus;
    }
    return dx_ * sum;
  }
  double released_energy_at(double t) const {
    double sum = 0.0;
    for (const ReleasedRowSpring& spring : released_) sum += released_energy(spring, t);
    return sum;
  }

  /// The time walk: x(s) by dense-output steps, a let-go where x crosses x_m / l (TOMS 748 on
  /// the step's dense output), the target where s reaches it.
  RowWalkEnd walk_in_time(double target, double target_depth) {
    const double t_w = t_;
    const double s_target = (target - t_w) / time_scale_;
    const auto d_of = [&](double s) { return depth_at(t_w + time_scale_ * s); };
    if (arms_) front_load_ = front_load_now();
    const auto speed_at = [&](double a, double s) {
      return arms_ ? relaxing_speed(a, time_scale_ * s) : speed(a, d_of(s));
    };
    const auto system = [&](const RowFrontVector& y, RowFrontVector& dy, double s) {
      dy[0] = -speed_at(length_ * std::max(y[0], 0.0), s);
    };
    auto dense =
        odeint::make_dense_output(kRowFrontTolerance, kRowFrontTolerance, RowFrontStepper());
    const auto bounded = [&](double xs, double s, double h) {
      // Never a step past the axis or far past the target.
      const double q = speed_at(length_ * xs, s);
      if (q > 0.0) h = std::min(h, 0.5 * xs / q);
      if (std::isfinite(s_target)) h = std::min(h, std::max(s_target - s, 1e-300));
      return h;
    };
    dense.initialize(RowFrontVector{a_ / length_}, 0.0, bounded(a_ / length_, 0.0, 1e-3));
    for (;;) {
      if (++steps_ > kMostRowFrontSteps) {
        throw std::runtime_error("rate-law row: the front took ten million steps");
      }
      const RowFrontVector before = dense.current_state();
      const double s_before = dense.current_time();
      const double h_before = dense.current_time_step();
      dense.do_step(system);
      const double s1 = dense.current_time();
      const double x1 = dense.current_state()[0];
      if (!std::isfinite(x1) || !(x1 >= 0.0) || !std::isfinite(s1)) {
        // A step that leaves the domain is taken again at half its length.
        const double half = 0.5 * std::min(h_before, s1 - s_before);
        if (!(half > 0.0) || !std::isfinite(half)) {
          throw std::runtime_error("rate-law row: the front's step fell to zero at the axis");
        }
        dense.initialize(before, s_before, half);
        continue;
      }
      const auto x_at = [&](double s) {
        RowFrontVector y;
        dense.calc_state(s, y);
        return y[0];
      };
      double from = s_before;
      for (;;) {
        const double spring = x(m_) / length_;
        const bool ends = s1 >= s_target;
        const double last = ends ? s_target : s1;
        if (x_at(last) < spring) {
          const double s_l = crossing([&](double s) { return x_at(s) - spring; }, from, last);
          move_to(t_w + time_scale_ * s_l, d_of(s_l));
          a_ = x(m_);
          let_go();
          if (m_ == 0) return RowWalkEnd::lost;
          if (arms_) return RowWalkEnd::restart;
          from = s_l;
          continue;
        }
        if (ends) {
          a_ = length_ * x_at(s_target);
          move_to(target, target_depth);
          return RowWalkEnd::reached;
        }
        break;
      }
      a_ = length_ * x1;
      if (arms_ ? relaxing_runs_to_axis(a_, time_scale_ * s1) : runs_to_axis(a_, d_of(s1))) {
        move_to(t_w + time_scale_ * s1, d_of(s1));
        return walk_in_radius(target, target_depth);
      }
      const double h = bounded(x1, s1, dense.current_time_step());
      if (h < dense.current_time_step()) dense.initialize(dense.current_state(), s1, h);
    }
  }

  /// The radius walk, r = -a / l rising to the axis with s(r): a let-go where r reaches
  /// -x_m / l, the target where s reaches it (TOMS 748 on the dense output).
  RowWalkEnd walk_in_radius(double target, double target_depth) {
    const double t_w = t_;
    const double s_target = (target - t_w) / time_scale_;
    const auto d_of = [&](double s) { return depth_at(t_w + time_scale_ * s); };
    if (arms_) front_load_ = front_load_now();
    const auto system = [&](const RowFrontVector& y, RowFrontVector& dy, double r) {
      const double a = length_ * std::max(-r, 0.0);
      const double q = arms_ ? relaxing_speed(a, time_scale_ * y[0]) : speed(a, d_of(y[0]));
      if (!(q > 0.0)) {
        throw std::runtime_error("rate-law row: the front stopped on its way to the axis");
      }
      dy[0] = 1.0 / q;
    };
    auto dense =
        odeint::make_dense_output(kRowFrontTolerance, kRowFrontTolerance, RowFrontStepper());
    const double r0 = -a_ / length_;
    dense.initialize(RowFrontVector{0.0}, r0, 1e-3 * a_ / length_);
    for (;;) {
      if (++steps_ > kMostRowFrontSteps) {
        throw std::runtime_error("rate-law row: the front took ten million steps");
      }
      const double r_before = dense.current_time();
      dense.do_step(system);
      const double r1 = dense.current_time();
      const auto s_at = [&](double r) {
        RowFrontVector y;
        dense.calc_state(r, y);
        return y[0];
      };
      double from = r_before;
      for (;;) {
        const double r_spring = -x(m_) / length_;
        const double last = std::min(r1, r_spring);
        if (s_at(last) >= s_target) {
          const double r_e = crossing([&](double r) { return s_at(r) - s_target; }, from, last);
          a_ = -length_ * r_e;
          move_to(target, target_depth);
          return RowWalkEnd::reached;
        }
        if (r1 < r_spring) break;
        const double s_l = s_at(r_spring);
        move_to(t_w + time_scale_ * s_l, d_of(s_l));
        a_ = x(m_);
        let_go();
        if (m_ == 0) return RowWalkEnd::lost;
        if (arms_) return RowWalkEnd::restart;
        from = r_spring;
      }
    }
  }

  /// The root in [lo, hi] of f, whose signs differ there (lo or hi where f is zero at it or
  /// rounding left no change of sign).
  template <class F>
  double crossing(const F& f, double lo, double hi) {
    const double f_lo = f(lo);
    const double f_hi = f(hi);
    if (f_lo == 0.0) return lo;
    if (f_hi == 0.0 || (f_lo > 0.0) == (f_hi > 0.0)) return hi;
    std::uintmax_t iterations = 200;
    const double width = hi - lo;
    const auto root = boost::math::tools::toms748_solve(
        f, lo, hi, f_lo, f_hi,
        [width](double a, double b) { return std::abs(b - a) <= 1e-14 * width; }, iterations);
    root_iterations_ += static_cast<long long>(iterations);
    return 0.5 * (root.first + root.second);
  }

  const Scene& scene_;
  FrontSpeedLaw law_;
  const ObserverList& observers_;
  std::int64_t n_;
  double dx_;
  double modulus_;
  double work_of_adhesion_;
  double hess_;             ///< 2 pi dgamma / E* [m]
  double length_;           ///< l: the row's radius [m]
  double time_scale_;       ///< l / v* [s]
  Material glue_material_;  ///< the material a glue sees: the glassy one on a relaxing bulk
  double glue_modulus_;     ///< E_0 [Pa] (E* on an elastic bulk)
  double glassy_hess_;      ///< 2 pi dgamma / E_0 [m]
  std::vector<double> images_;
  std::vector<double> image_sums_;  ///< sum of g_1..g_m [m], m = 0..N

  std::int64_t m_ = 0;
  double a_ = 0.0;
  double t_ = 0.0;
  double d_ = 0.0;
  std::string_view stage_;
  double stage_start_ = 0.0;
  double stage_depth_ = 0.0;
  RowStageDrive drive_;

  double machine_work_ = 0.0;
  double surface_ = 0.0;
  double front_losses_ = 0.0;
  double glue_losses_ = 0.0;
  long long steps_ = 0;
  long long root_iterations_ = 0;
  std::int64_t let_gos_ = 0;
  std::optional<ContactSnapshot> peak_;
  std::vector<JumpRecord> jumps_;
  ContactSnapshot lost_at_;

  // A relaxing bulk (material.relaxation): the glued springs' arms, 1..m in order.
  std::vector<PronyTerm> terms_;
  std::optional<DrivenArmSums> arms_;
  std::vector<DrivenArmMember> members_;
  std::vector<double> glue_times_;  ///< [s] per glued spring
  std::shared_ptr<const RetardationModes> modes_;
  std::vector<ReleasedRowSpring> released_;
  double released_energy_ = 0.0;  ///< the let-go springs' energy at their release [J]
  double glued_bulk_ = 0.0;       ///< the glued arms' dashpots' dissipation [J]
  FrontLineLoad front_load_;
};

/// The stage's drive from depth d at time t: `to` and `by` under fixed grips, a hold without a
/// normal axis; until separation a `by` per unit of its parameter, without end.
RowStageDrive rate_law_stage_drive(const Stage& stage, double t, double d) {
  double change = 0.0;
  if (stage.normal && stage.normal->motion == StageAxis::Motion::to) {
    change = stage.normal->value - d;
  } else if (stage.normal && stage.normal->motion == StageAxis::Motion::by) {
    change = stage.normal->value;
  }
  const double seconds = seconds_per_parameter(stage, change);
  RowStageDrive drive;
  drive.rate = seconds > 0.0 ? change / seconds : 0.0;
  if (stage.until_separation) {
    drive.end_time = std::numeric_limits<double>::infinity();
  } else {
    drive.end_time = t + seconds;
    drive.end_depth = stage.normal && stage.normal->motion == StageAxis::Motion::to
                          ? stage.normal->value
                          : d + change;
  }
  return drive;
}

}  // namespace

RunResult run_rate_law_row(const Scene& scene, const ObserverList& observers) {
  RunResult result;
  ProgramRowSpec spec = program_row(scene, program_row_frame(scene), scene.springs);
  if (scene.material.relaxes() && !scene.material.glues_on_touch()) {
    // The front glues at the glassy gap: spring N where it glues at the deepest depth, as the
    // viscoelastic row places it.
    Scene glassy = scene;
    glassy.material = glassy_material(scene.material);
    const ProgramRowSpec at_glassy_gap =
        program_row(glassy, program_row_frame(glassy), spec.reference_springs);
    spec.reference_radius = at_glassy_gap.reference_radius;
    spec.reference_image = at_glassy_gap.reference_image;
  }
  result.springs = spec.reference_springs;
  result.accuracy.rows = {spec.reference_springs};
  result.accuracy.outer_radius = spec.reference_radius;
  RateLawRow row(scene, spec, observers);

  AxisWork total;
  EnergyBalance total_energy;
  bool lost = false;
  for (const Stage& stage : scene.program->stages) {
    const double stored_before = row.stored();
    const double work_before = row.machine_work();
    const double surface_before = row.surface();
    const double front_before = row.front_losses();
    const double glue_before = row.glue_losses();
    const double bulk_before = row.bulk();
    StageRecord record;
    record.name = stage.name;
    if (stage.until_separation && row.glued() == 0) {
      result.warnings.push_back(fmt::format(
          "stage '{}' runs until separation but starts with no spring in contact: it ends at "
          "once",
          stage.name));
    } else {
      const RowStageDrive drive = rate_law_stage_drive(stage, row.time(), row.depth());
      if (stage.until_separation && !(drive.rate < 0.0)) {
        stop_at_limit(result, StopReason::no_end);
        result.warnings.push_back(fmt::format(
            "stage '{}' runs until separation, but nothing on its path can part the contact: "
            "the program stops here",
            stage.name));
      } else if (row.run_stage(stage, drive)) {
        lost = true;
        result.critical = row.lost_at();
        result.critical_stage = stage.name;
        if (!stage.until_separation) {
          // Nothing glued: the grips go on to the stage's end.
          row.move_to(drive.end_time, drive.end_depth);
        }
      }
    }
    record.end = row.snapshot();
    row.note(record.end);
    record.work.normal = row.machine_work() - work_before;
    record.work.front = row.front_losses() - front_before;
    EnergyBalance e;
    e.machine_work = record.work.normal;
    e.stored_change = row.stored() - stored_before;
    e.surface_change = row.surface() - surface_before;
    // The let-gos' losses are the front's dissipation, the glues' the advancing front's.
    e.jump_losses = record.work.front + (row.glue_losses() - glue_before);
    e.residual = e.machine_work - e.stored_change - e.surface_change - e.jump_losses;
    if (row.relaxing()) {
      record.work.bulk = row.bulk() - bulk_before;
      e.dissipated_by_bulk = record.work.bulk;
      e.residual -= e.dissipated_by_bulk;
    }
    record.energy = e;
    total += record.work;
    total_energy += e;
    result.stages.push_back(record);
    Event end{.kind = EventKind::stage_end, .state = record.end};
    end.stage = result.stages.back().name;
    observers.emit(end);
    if (result.stop_reason) break;
  }
  result.work = total;
  result.energy = total_energy;
  result.peak = row.peak();
  result.jumps = row.jumps();
  result.counts.events = row.let_gos();
  result.counts.steps = row.steps();
  result.counts.root_iterations = row.root_iterations();
  if (!result.stop_reason) result.status = lost ? RunStatus::instability : RunStatus::completed;
  return result;
}

}  // namespace mdrsim
