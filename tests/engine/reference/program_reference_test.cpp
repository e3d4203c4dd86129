// The loading-program references (engine/reference/program_reference) against hand values, the
// paper's closed forms and independent trapezoid integrations; all quantities dimensionless
// (a/a0, d/d0, u/d0, F/F0, work/(F0 d0)). Tolerances: 1e-12..1e-14 where both sides are
// closed forms or full-precision roots; 1e-6 against trapezoids with 1e5 intervals (their
// error is O(h^2) ~ 1e-10 on smooth integrands, O(h^1.5) at a fold's square root).
#include "engine/reference/program_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "engine/reference/parabolic_reference.hpp"

namespace pr = mdrsim::program_reference;
namespace paper = mdrsim::parabolic_reference;

namespace {

constexpr double kGammaNu03 = 1.4 / 1.7;  ///< G*/E* at nu = 0.3 (paper eq. 9)

double jkr_force(double a) { return a * a * a - 2.0 * std::pow(a, 1.5); }  // eq. 19
double jkr_depth(double a) { return 3.0 * a * a - 4.0 * std::sqrt(a); }    // eq. 18
double jkr_depth_slope(double a) { return 6.0 * a - 2.0 / std::sqrt(a); }

double trapezoid(const std::function<double(double)>& f, double lo, double hi, int n = 100000) {
  const double h = (hi - lo) / n;
  double sum = 0.5 * (f(lo) + f(hi));
  for (int i = 1; i < n; ++i) sum += f(lo + i * h);
  return sum * h;
}

/// x in [lo, hi] where the increasing fn crosses 0, by plain bisection.
double bisect(const std::function<double(double)>& fn, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fn(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The maximiser of f on [lo, hi]: the best of 2000 grid points, then golden section.
double argmax(const std::function<double(double)>& f, double lo, double hi) {
  double best = lo;
  const int n = 2000;
  for (int i = 0; i <= n; ++i) {
    const double x = lo + (hi - lo) * i / n;
    if (f(x) > f(best)) best = x;
  }
  double a = std::max(lo, best - (hi - lo) / n);
  double b = std::min(hi, best + (hi - lo) / n);
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  while (b - a > 1e-13) {
    const double left = b - r * (b - a);
    const double right = a + r * (b - a);
    if (f(left) > f(right)) {
      b = right;
    } else {
      a = left;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

// ---- (a) reversible JKR cycle ----

TEST(ProgramReference, ReversibleJumpInLandsAtMinusEightNinthsAndLeavesAtMinusFiveNinths) {
  const auto c = pr::reversible_jkr_cycle(3.0);
  EXPECT_NEAR(c.jump_in_after.normal_force, -8.0 / 9.0, 1e-14);
  EXPECT_NEAR(c.jump_in_after.contact_radius, std::cbrt(16.0 / 9.0), 1e-14);
  EXPECT_EQ(c.jump_in_after.indentation, 0.0);
  EXPECT_NEAR(jkr_depth(c.jump_in_after.contact_radius), 0.0, 1e-14);  // it lands on eq. 18
  EXPECT_NEAR(c.retract_critical.normal_force, -5.0 / 9.0, 1e-14);
  EXPECT_NEAR(c.retract_critical.indentation, -std::cbrt(9.0), 1e-14);
  EXPECT_NEAR(c.retract_critical.contact_radius, std::cbrt(1.0 / 9.0), 1e-14);
  EXPECT_NEAR(jkr_depth(c.approach_end.contact_radius), 3.0, 1e-12);
}

// W = -int_{d_c}^{0} F dd along eqs. 18-19, as a trapezoid over the radius.
TEST(ProgramReference, ReversibleCycleWorkMatchesTrapezoidAndTheIssuesFigure) {
  const double a_star = std::cbrt(16.0 / 9.0);
  const double ac = std::cbrt(1.0 / 9.0);
  const double integral =
      -trapezoid([](double a) { return jkr_force(a) * jkr_depth_slope(a); }, ac, a_star);
  for (const double dmax : {0.5, 3.0, 12.0}) {
    EXPECT_NEAR(pr::reversible_jkr_cycle(dmax).dissipated_work, integral, 1e-6) << dmax;
    EXPECT_NEAR(pr::reversible_jkr_cycle(dmax).dissipated_work,
                pr::reversible_jkr_cycle(3.0).dissipated_work, 1e-12)
        << "the work must not depend on d_max = " << dmax;
  }
  const double ratio = pr::reversible_jkr_cycle(3.0).dissipated_work / std::cbrt(9.0);
  EXPECT_NEAR(ratio, pr::reversible_cycle_work_per_fold_depth(), 1e-14);
  EXPECT_NEAR(ratio, 0.9355, 5e-5) << "the issue's 0.9355 F0 |d_c|";
}

// ---- (b) glue-on-touch cycle ----

// Loading over the radius (d = 3 a^2, F = a^3), the fixed-radius retract over the depth,
// the peel over the radius again.
TEST(ProgramReference, GlueOnTouchCycleWorkMatchesTrapezoid) {
  const double ac = std::cbrt(1.0 / 9.0);
  for (const double dmax : {0.3, 0.5, 1.0, 3.0, 12.0}) {
    const double am = std::sqrt(dmax / 3.0);
    const double load = trapezoid([](double a) { return a * a * a * 6.0 * a; }, 0.0, am);
    const double d1 = jkr_depth(am);
    const double fixed = -trapezoid([am](double d) { return 0.5 * am * (d - am * am); }, d1, dmax);
    const double peel =
        am > ac ? -trapezoid([](double a) { return jkr_force(a) * jkr_depth_slope(a); }, ac, am)
                : 0.0;
    const auto c = pr::glue_on_touch_cycle(dmax);
    EXPECT_NEAR(c.loading_work, load, 1e-6) << dmax;
    EXPECT_NEAR(c.dissipated_work, load + fixed + peel, 1e-6) << dmax;
    EXPECT_EQ(c.jumps_at_first_let_go, am <= ac) << dmax;
  }
}

// The claim (2/3) d_max + (4/45)|d_c| holds exactly once a_max >= a_c (d_max >= 3^(-1/3));
// below it overstates the work by P(a_c) - P(a_m) = int_{a_m}^{a_c} F dd/da da > 0.
TEST(ProgramReference, GlueOnTouchClaimHoldsOnlyAboveTheFoldRadius) {
  const double ac = std::cbrt(1.0 / 9.0);
  for (const double dmax : {3.0 * ac * ac, 1.0, 3.0, 12.0}) {
    EXPECT_NEAR(pr::glue_on_touch_cycle(dmax).dissipated_work,
                pr::claimed_glue_on_touch_dissipation(dmax), 1e-12)
        << dmax;
  }
  for (const double dmax : {0.1, 0.3, 0.5}) {
    const double am = std::sqrt(dmax / 3.0);
    const double excess =
        trapezoid([](double a) { return jkr_force(a) * jkr_depth_slope(a); }, am, ac);
    EXPECT_GT(excess, 0.0);
    EXPECT_NEAR(
        pr::claimed_glue_on_touch_dissipation(dmax) - pr::glue_on_touch_cycle(dmax).dissipated_work,
        excess, 1e-6)
        << dmax;
  }
}

// d_max = 3: a_m = 1, F = (1/2)(d - 1) until d_JKR(1) = -1 (F = -1, the fixed-load point),
// then eq. 19 up to the fold, then 0.
TEST(ProgramReference, GlueOnTouchRetractForceByHand) {
  EXPECT_NEAR(pr::glue_on_touch_retract_force(3.0, 3.0), 1.0, 1e-13);
  EXPECT_NEAR(pr::glue_on_touch_retract_force(3.0, 0.0), -0.5, 1e-13);
  EXPECT_NEAR(pr::glue_on_touch_retract_force(3.0, -1.0), -1.0, 1e-13);
  const double a = bisect([](double x) { return jkr_depth(x) + 2.0; }, std::cbrt(1.0 / 9.0), 1.0);
  EXPECT_NEAR(pr::glue_on_touch_retract_force(3.0, -2.0), jkr_force(a), 1e-12);
  EXPECT_EQ(pr::glue_on_touch_retract_force(3.0, -2.1), 0.0);
  const auto c = pr::glue_on_touch_cycle(3.0);
  EXPECT_NEAR(c.let_go_onset.indentation, -1.0, 1e-14);
  EXPECT_NEAR(c.let_go_onset.normal_force, -1.0, 1e-14);
  EXPECT_NEAR(c.retract_critical.normal_force, -5.0 / 9.0, 1e-14);
}

// ---- (c) tangential ramps ----

// Held F: eq. 26 with eq. 25 gives S = 2 (a^3 - F)/a and gamma u^2 = 16 a - S^2. The ramp's
// last equilibrium is the largest u on that curve; it must be eq. 29's point (the fold of F
// at fixed u), and, setting d(u^2)/da = 0, t = a^3 solves 2 t^2 - (F + 2) t - F^2 = 0.
TEST(ProgramReference, HeldForceRampFoldIsTheFixedLoadEnvelope) {
  for (const double gamma : {1.0, kGammaNu03}) {
    for (const double f : {-0.9, -0.5, 0.0, 0.5, 2.0}) {
      const auto c = pr::fixed_load_critical_at_force(f, gamma);
      EXPECT_NEAR(c.normal_force, f, 1e-12);
      EXPECT_NEAR(paper::normal_force_slope(c.contact_radius, c.tangential_displacement, gamma),
                  0.0, 1e-10)
          << "not on eq. 29";
      const auto u2 = [&](double a) {
        const double s = 2.0 * (a * a * a - f) / a;
        return (16.0 * a - s * s) / gamma;
      };
      const double a_max = argmax(u2, std::cbrt(std::max(f, 0.0)) + 1e-9, 4.0);
      EXPECT_NEAR(c.contact_radius, a_max, 1e-6) << "F = " << f << ", gamma = " << gamma;
      EXPECT_NEAR(c.tangential_displacement, std::sqrt(u2(a_max)), 1e-10);
      const double t = 0.25 * ((f + 2.0) + std::sqrt((f + 2.0) * (f + 2.0) + 8.0 * f * f));
      EXPECT_NEAR(c.contact_radius, std::cbrt(t), 1e-12);
    }
  }
}

// Held d: gamma u^2 = 16 a - (3 a^2 - d)^2, largest where a (3 a^2 - d) = 4/3; it must be
// eq. 31's point with that d.
TEST(ProgramReference, HeldDepthRampFoldIsTheFixedGripsEnvelope) {
  for (const double gamma : {1.0, kGammaNu03}) {
    for (const double d : {-2.0, -1.0, 0.0, 1.0, 3.0}) {
      const auto c = pr::fixed_grips_critical_at_indentation(d, gamma);
      EXPECT_NEAR(c.indentation, d, 1e-12);
      const double a = c.contact_radius;
      const double u = c.tangential_displacement;
      EXPECT_NEAR(a * a * a - gamma / 16.0 * (u * a) * (u * a) - 1.0 / 9.0, 0.0, 1e-12)
          << "not on eq. 31";
      const auto u2 = [&](double x) {
        const double s = 3.0 * x * x - d;
        return (16.0 * x - s * s) / gamma;
      };
      const double a_max = argmax(u2, 1e-9, 4.0);
      EXPECT_NEAR(a, a_max, 1e-6) << "d = " << d << ", gamma = " << gamma;
      EXPECT_NEAR(u, std::sqrt(u2(a_max)), 1e-10);
      EXPECT_NEAR(a * (3.0 * a * a - d), 4.0 / 3.0, 1e-12);
      EXPECT_NEAR(c.normal_force, a * a * a - 2.0 / 3.0, 1e-12);  // eq. 33
    }
  }
}

// The ramps of the example scenes, glued at a_p = 2: unloaded to d = -1 the contact peels to
// a = 1 exactly (3 - 4 = -1, F = -1); unloaded to F = -0.5 to a^(3/2) = 1 + sqrt(1/2).
// Both start on eq. 18-19 (u_1 = 0) above their folds. A contact glued at 0.6 and held at
// d = 0.5 has e = 0.58 and lets go at u^2 = 9.6 - 0.58^2, below its fold (a(3a^2 - 0.5) = 4/3
// needs a > 0.6): the first let-go is the jump.
TEST(ProgramReference, ShearRampsStartWhereTheUnloadLeavesTheContact) {
  const auto held_d = pr::shear_ramp_at_held_indentation(2.0, -1.0);
  EXPECT_NEAR(held_d.start.contact_radius, 1.0, 1e-13);
  EXPECT_NEAR(held_d.start.normal_force, -1.0, 1e-13);
  EXPECT_NEAR(held_d.first_let_go.tangential_displacement, 0.0, 1e-6);
  EXPECT_FALSE(held_d.jumps_at_first_let_go);
  EXPECT_LT(held_d.critical.contact_radius, held_d.start.contact_radius);

  const auto held_f = pr::shear_ramp_at_held_force(2.0, -0.5);
  EXPECT_NEAR(held_f.start.contact_radius, std::pow(1.0 + std::sqrt(0.5), 2.0 / 3.0), 1e-13);
  EXPECT_FALSE(held_f.jumps_at_first_let_go);
  EXPECT_NEAR(held_f.critical.normal_force, -0.5, 1e-12);

  const auto early = pr::shear_ramp_at_held_indentation(0.6, 0.5);
  EXPECT_TRUE(early.jumps_at_first_let_go);
  EXPECT_NEAR(early.critical.tangential_displacement, std::sqrt(9.6 - 0.58 * 0.58), 1e-13);
  EXPECT_NEAR(early.critical.normal_force, 0.3 * (0.5 - 0.36), 1e-13);
}

// ---- (d) inclined pull ----

// The boundary equation (3 a^2 - d_p + s)^2 + gamma s^2 = 16 a solved here for s by
// bisection; the critical point must satisfy it and be a local maximum of s(a).
TEST(ProgramReference, InclinedPullEndsAtTheFoldOfTheBoundaryEquation) {
  for (const double gamma : {1.0, kGammaNu03}) {
    const double dp = 2.0;
    const double ap = std::sqrt(dp / 3.0);
    const auto s_of = [&](double a) {
      return bisect(
          [&](double s) {
            const double e = 3.0 * a * a - dp + s;
            return e * e + gamma * s * s - 16.0 * a;
          },
          dp - 3.0 * a * a, 20.0);
    };
    const auto p = pr::inclined_pull(dp, 1.0, gamma);
    ASSERT_EQ(p.end, pr::InclinedPull::End::fold) << gamma;
    EXPECT_TRUE(p.contact_lost);
    const double a = p.critical.contact_radius;
    EXPECT_LT(a, ap);
    EXPECT_NEAR(p.path, s_of(a), 1e-12);
    const double h = 1e-4;
    EXPECT_NEAR((s_of(a + h) - s_of(a - h)) / (2.0 * h), 0.0, 1e-6) << "not a fold";
    EXPECT_LT(s_of(a + 10 * h), p.path);
    EXPECT_LT(s_of(a - 10 * h), p.path);
    EXPECT_NEAR(p.critical.indentation, dp - p.path, 1e-14);
    EXPECT_NEAR(p.critical.tangential_displacement, p.path, 1e-14);
    EXPECT_NEAR(p.critical.normal_force, 0.5 * a * (p.critical.indentation - a * a), 1e-14);
    EXPECT_NEAR(p.critical.tangential_force, 0.5 * gamma * a * p.path, 1e-14);
    EXPECT_NEAR(p.first_let_go.tangential_displacement, 4.0 * std::sqrt(ap / (1.0 + gamma)), 1e-13);
  }
  // Glued at a_p^3 < (1 + gamma)/9 = 2/9 the slope at a_p is already >= 0.
  EXPECT_EQ(pr::inclined_pull(0.5).end, pr::InclinedPull::End::first_let_go);
}

// ---- (e) load, partial unload, reload, unload, pull-off ----

// d1 = 12 (a1 = 2, F = 8), d2 = 3 (eq. 18 at a2 = 1.6465), d3 = 6 < 3 a2^2 = 8.13: without
// rebinding only [0, a2] holds, F = (a2/2)(6 - a2^2); with it the contact is a1's again and
// has peeled (6 < d_JKR(2) = 12 - 4 sqrt(2)) to eq. 18 at d = 6.
TEST(ProgramReference, ReloadSecondUnloadDiffersWithRebinding) {
  const double a2 = bisect([](double a) { return jkr_depth(a) - 3.0; }, 1.0, 2.0);
  const double a3 = bisect([](double a) { return jkr_depth(a) - 6.0; }, 1.0, 2.0);
  const auto off = pr::reload_program(12.0, 3.0, 6.0, false);
  const auto on = pr::reload_program(12.0, 3.0, 6.0, true);
  for (const auto* p : {&off, &on}) {
    EXPECT_NEAR(p->peeled_radius, a2, 1e-12);
    EXPECT_NEAR(p->stage_end_force[0], 8.0, 1e-12);
    EXPECT_NEAR(p->stage_end_force[1], jkr_force(a2), 1e-12);
    EXPECT_NEAR(p->stage_end_force[2], 8.0, 1e-12);
    EXPECT_NEAR(p->pull_off_critical.normal_force, -5.0 / 9.0, 1e-13);
    EXPECT_NEAR(p->pull_off_critical.indentation, -std::cbrt(9.0), 1e-13);
    EXPECT_NEAR(p->stage_work[0], 1.2 * 32.0, 1e-10);  // (6/5) a1^5
  }
  EXPECT_NEAR(off.stage_end_force[3], 0.5 * a2 * (6.0 - a2 * a2), 1e-12);
  EXPECT_NEAR(on.stage_end_force[3], jkr_force(a3), 1e-12);
  EXPECT_GT(off.stage_end_force[3] - on.stage_end_force[3], 0.5);
  // Above 3 a2^2 the lifted band and the glued core push like Hertz: b^3 at d = 9, b = sqrt 3;
  // rebinding's fixed radius a1 = 2 gives (2/2)(9 - 4) = 5.
  EXPECT_NEAR(pr::second_unload_force(12.0, 3.0, 9.0, false), std::pow(3.0, 1.5), 1e-12);
  EXPECT_NEAR(pr::second_unload_force(12.0, 3.0, 9.0, true), 5.0, 1e-12);
  // The reload, as a trapezoid: a2 glued below 3 a2^2, Hertz above.
  const double reload = trapezoid(
      [a2](double d) {
        return d < 3.0 * a2 * a2 ? 0.5 * a2 * (d - a2 * a2) : std::pow(d / 3.0, 1.5);
      },
      3.0, 12.0, 1000000);
  EXPECT_NEAR(off.stage_work[2], reload, 1e-6);
  EXPECT_NEAR(on.stage_work[2], reload, 1e-6);
  // Without rebinding nothing glues or lets go between d2 and d1: the extra loop is elastic
  // and the program dissipates what the plain cycle to d1 does; with it, more.
  EXPECT_NEAR(off.work, pr::glue_on_touch_cycle(12.0).dissipated_work, 1e-9);
  EXPECT_GT(on.work, off.work + 1.0);
}
