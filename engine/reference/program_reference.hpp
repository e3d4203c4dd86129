// Continuum (N -> infinity) references for the loading programs of scenes/programs/ on the
// parabola, derived apart from the engine: closed forms, TOMS 748 roots and Gauss-Kronrod
// quadrature.
#pragma once

#include <array>

namespace mdrsim::program_reference {

// Units: the paper's scales (eqs. 16-17), a/a0, d/d0, u_x/d0, F/F0, F_x/F0 and work/(F0 d0);
// gamma = G*/E* (eq. 9). In them the MDR image of the parabola is g(x) = 3 x^2 (a0^2/(R d0)
// = 3), the Hess limit (eq. 12) is dl(x) = 4 sqrt(x), springs glued over [0, a] at depth d
// carry F = (1/2) int_0^a (d - 3 x^2) dx = (a/2)(d - a^2) (eq. 26, 2 E* a0 d0 = F0/2) and
// F_x = (gamma/2) a u (eq. 27), and the mode-mixed law (eq. 20) lets the boundary spring go
// when e^2 + gamma u^2 >= 16 a, e = max(3 a^2 - d, 0) its elongation. A machine's work is
// int F dd (+ int F_x du), fixed grips: nothing during a jump.

/// One equilibrium (or the state after a jump).
struct State {
  double contact_radius = 0.0;  ///< the glued radius a; 0 once nothing is in contact
  double indentation = 0.0;     ///< d
  double normal_force = 0.0;    ///< F_z
  double tangential_displacement = 0.0;
  double tangential_force = 0.0;
};

// ---- The JKR branch without tangential load (eqs. 18-19) ----

/// The fixed-grips fold dd/da = 0: a_c^3 = 1/9, d_c = -3^(2/3), F_c = -5/9.
State jkr_fold();
/// The root a >= a_c of eq. 18, 3 a^2 - 4 sqrt(a) = d (needs d >= d_c).
double jkr_radius_at_indentation(double indentation);
/// The root a >= 1 of eq. 19, a^3 - 2 a^(3/2) = F: a^(3/2) = 1 + sqrt(1 + F) (needs F >= -1).
double jkr_radius_at_force(double normal_force);
/// The state on eqs. 18-19 at radius a.
State jkr_state(double contact_radius);
/// int F dd along eqs. 18-19 from radius a_from to a_to, in closed form.
double jkr_branch_work(double from_radius, double to_radius);

// ---- (a) Reversible JKR cycle under fixed grips (dgamma_a = dgamma) ----

struct ReversibleCycle {
  State jump_in_after;     ///< d = 0: a = (16/9)^(1/3), F = -8/9
  State approach_end;      ///< on the JKR branch at d_max
  State retract_critical;  ///< the fold: d_c, F_c = -5/9
  double dissipated_work;  ///< the machine's work over the cycle, whatever d_max > 0
};
ReversibleCycle reversible_jkr_cycle(double max_indentation);
/// The dissipated work over F0 |d_c|, exactly 4 (6 2^(2/3) + 1)/45 = 0.935503...
double reversible_cycle_work_per_fold_depth();

// ---- (b) The same cycle with glue on touch (dgamma_a = 0) ----

struct GlueOnTouchCycle {
  double max_radius = 0.0;  ///< a_m = sqrt(d_max/3) (Hertz)
  State load_end;           ///< F = a_m^3
  State let_go_onset;       ///< the boundary at a_m reaches the Hess limit: d = d_JKR(a_m)
  /// The last equilibrium before the jump out: the fold when a_m > a_c, else let_go_onset.
  State retract_critical;
  bool jumps_at_first_let_go = false;  ///< a_m <= a_c
  double loading_work = 0.0;           ///< (6/5) a_m^5
  double dissipated_work = 0.0;        ///< 2 a_m^2 + (4/5) a_c^2 if a_m >= a_c
};
GlueOnTouchCycle glue_on_touch_cycle(double max_indentation);
/// F on the retract at depth d (0 once the contact is lost).
double glue_on_touch_retract_force(double max_indentation, double indentation);
/// The estimate (2/3) d_max + (4/45) |d_c|: equal to the dissipated work iff a_m >= a_c.
double claimed_glue_on_touch_dissipation(double max_indentation);

// ---- (c) Tangential ramp to failure from a contact glued at preload radius a_p ----

/// The fixed-load critical point (eq. 29 with eqs. 25-27) whose normal force is F: eq. 29's
/// F_c(u) inverted for u (needs F >= -1).
State fixed_load_critical_at_force(double normal_force, double gamma = 1.0);
/// The fixed-grips critical point (eq. 31, eqs. 25-27) whose indentation is d (d >= d_c).
State fixed_grips_critical_at_indentation(double indentation, double gamma = 1.0);

struct ShearRamp {
  State start;                         ///< after the normal unload, u = 0
  State first_let_go;                  ///< the boundary spring at start's radius reaches eq. 20
  State critical;                      ///< the last equilibrium before the jump
  bool jumps_at_first_let_go = false;  ///< start's radius is already below the fold's
};
/// Glued on touch to radius a_p, unloaded to normal force F (held, fixed load), u ramped.
ShearRamp shear_ramp_at_held_force(double preload_radius, double normal_force, double gamma = 1.0);
/// Glued on touch to radius a_p, unloaded to depth d (held, fixed grips), u ramped.
ShearRamp shear_ramp_at_held_indentation(double preload_radius, double indentation,
                                         double gamma = 1.0);

// ---- (d) A straight pull from a glued preload: d = d_p - s, u = k s (k = 1: 45 degrees) ----

struct InclinedPull {
  enum class End {
    fold,          ///< ds/da = 0 on the peeling branch
    shear_off,     ///< the boundary reaches zero elongation first: the glue shears off
    first_let_go,  ///< the preload radius is already past the fold
  };
  End end = End::fold;
  State first_let_go;
  State critical;     ///< the last equilibrium before the jump
  double path = 0.0;  ///< s at the critical point
  /// No equilibrium with contact after the jump: d < 0 there and s(a) < s_c below a_c.
  bool contact_lost = false;
};
InclinedPull inclined_pull(double preload_indentation, double tangential_per_normal = 1.0,
                           double gamma = 1.0);

// ---- (e) Load, partial unload, reload, unload, pull-off: fixed grips, glue on touch ----

struct ReloadProgram {
  double glued_radius = 0.0;   ///< a1 = sqrt(d1/3)
  double peeled_radius = 0.0;  ///< a2: d_JKR(a2) = d2
  /// F at the end of load (d1), unload (d2), reload (d1), second unload (d3).
  std::array<double, 4> stage_end_force{};
  /// The machine's work in each of the five stages (the pull-off until separation).
  std::array<double, 5> stage_work{};
  State pull_off_critical;  ///< the fold of the JKR branch for both rebinding values
  double work = 0.0;        ///< over the whole program, which starts and ends out of contact
};
/// d1 > d2, d2 < d_JKR(a1) (the contact peels), d2 <= d3 <= d1.
ReloadProgram reload_program(double d1, double d2, double d3, bool rebinding);
/// F at depth d during the second unload (from d1 down to d3), for either rebinding value.
double second_unload_force(double d1, double d2, double indentation, bool rebinding);

}  // namespace mdrsim::program_reference
