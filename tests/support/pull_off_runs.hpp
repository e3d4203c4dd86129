// The shorthand's pull-off runs its edge-case tests share (tests/engine/pull_off/): JKR
// scenarios by normal control, a run with its stepping halvings tracked, and the sizes a
// stepping critical point is checked against.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "engine/events/observer.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"

namespace mdrsim::test {

inline double gamma_of(double nu) { return (2.0 - 2.0 * nu) / (2.0 - nu); }  // G*/E*, paper eq. 9

/// Counts halvings in a row and keeps the preload's control value; stores no events, so that
/// runs of 10^5 steps stay cheap.
class SteppingTracker final : public mdrsim::Observer {
 public:
  void on_event(const Event& e) override {
    if (e.kind == EventKind::preload_reached) preload_control_ = e.state.normal_control;
    if (e.kind == EventKind::spring_detached && !first_let_go_control_) {
      first_let_go_control_ = e.state.normal_control;
    }
    if (e.kind == EventKind::step_halved) ++in_a_row_;
    if (e.kind == EventKind::step_accepted) {
      before_last_step_ = in_a_row_;
      in_a_row_ = 0;
    }
    // Under fixed load the step that ends the run is the flight's: its halvings are reported
    // (taken back to the critical state), its accepted row is not (docs/programs.md "A fixed load
    // that loses the contact").
    if (e.kind == EventKind::finished && in_a_row_ > 0) before_last_step_ = in_a_row_;
  }
  double preload_control() const { return preload_control_; }
  /// The control value at the first detachment (the event method's first let-go).
  double first_let_go_control() const { return first_let_go_control_.value_or(0.0); }
  /// Halvings in a row before the step that ended the run.
  int halvings_before_last_step() const { return before_last_step_; }

 private:
  double preload_control_ = 0.0;
  std::optional<double> first_let_go_control_;
  int in_a_row_ = 0;
  int before_last_step_ = -1;
};

struct TrackedRun {
  RunResult result;
  SteppingTracker tracker;
};

inline TrackedRun run_tracked(const Scene& scene) {
  TrackedRun run;
  mdrsim::ObserverList observers;
  observers.add(run.tracker);
  run.result = mdrsim::run_pull_off(scene, observers);
  return run;
}

/// dF/dw of the normal axis with `springs` attached: the held value w moves the force by
/// K/(a_u + a_F K) (1 under fixed load, K under fixed grips, less than K when compliant).
inline double force_per_control(const Scene& scene, std::int64_t springs) {
  const auto c = scene.normal.controller->constraint();
  const double k = 2.0 * scene.material.effective_modulus * scene.glued_radius /
                   static_cast<double>(scene.springs) * static_cast<double>(springs);
  return k / (c.displacement_coefficient + c.force_coefficient * k);
}

inline std::string compliant_extra(const JkrScenario& s, double stiffness_in_f0_per_d0) {
  return "stiffness = " +
         std::to_string(stiffness_in_f0_per_d0 * s.scales().force / s.scales().depth);
}

/// Rounding allowance for comparing two control values near `c`.
inline double rounding(double c) {
  return 8.0 * std::numeric_limits<double>::epsilon() * std::abs(c);
}

inline JkrScenario scenario(const std::string& normal, std::int64_t springs) {
  JkrScenario s;
  s.normal = normal;
  s.springs = springs;
  if (normal == "compliant") s.normal_extra = compliant_extra(s, 1.0);
  return s;
}

}  // namespace mdrsim::test
