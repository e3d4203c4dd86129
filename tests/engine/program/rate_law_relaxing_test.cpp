// The rate law of the edge on a relaxing bulk (the program row with material.relaxation): its
// limits against the elastic row and the elastic reference, a parabola relaxed under fixed grips
// and then retracted against the front's ODE solved here, and every stage's energy balance.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
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

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"
#include "tests/support/rate_law_front.hpp"

namespace mdrsim {
namespace {

constexpr double kRelaxingPi = std::numbers::pi;
constexpr double kRelaxed = 1e6;          // E_inf [Pa] (nu = 0)
constexpr double kRelaxingRadius = 0.01;  // R [m]
constexpr double kRelaxingWork = 0.05;    // dgamma [J/m^2]
constexpr double kRelaxingFront = 1e-6;   // v* [m/s]
constexpr double kRelaxingPress = 2.0;    // the approach's duration [s]

/// One Prony term, or none (an elastic bulk).
struct RelaxingArm {
  double modulus = 0.0;  ///< E_1 [Pa]; 0: no relaxation key
  double time = 1.0;     ///< tau_1 [s]
};

/// A parabola pressed under fixed grips to `depth` in kRelaxingPress, held `hold` seconds (none
/// at 0), and retracted at `speed` until separation, on a row of `springs` springs.
std::string relaxing_scene(double relaxed, double work, double approach_work, RelaxingArm arm,
                           double exponent, double depth, double hold, double speed,
                           std::int64_t springs) {
  std::string text = fmt::format(
      "[material]\nyoungs_modulus = {:.17g}\npoisson_ratio = 0.0\nwork_of_adhesion = {:.17g}\n"
      "approach_work_of_adhesion = {:.17g}\n",
      relaxed, work, approach_work);
  if (arm.modulus > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {:.17g}, time = {:.17g} }} ]\n", arm.modulus,
                        arm.time);
  }
  text += fmt::format(
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[detachment]\nfront_speed_law = {{ speed = {}, exponent = {} }}\n"
      "[[loading.stage]]\nname = \"approach\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\nduration = {}\n",
      kRelaxingRadius, kRelaxingFront, exponent, depth, kRelaxingPress);
  if (hold > 0.0) text += fmt::format("[[loading.stage]]\nname = \"hold\"\nduration = {}\n", hold);
  text += fmt::format(
      "[[loading.stage]]\nname = \"retract\"\nnormal = {{ by = -1e-4 }}\nuntil = \"separation\"\n"
      "speed = {:.17g}\n[solver]\nmethod = \"event\"\n[discretization]\nsprings = {}\n",
      speed, springs);
  return text;
}

/// JKR's zero-force depth of modulus E [Pa]: a0^3 = 9 pi dgamma R^2 / (2 E), d0 = a0^2 / R -
/// sqrt(2 pi a0 dgamma / E).
double relaxing_zero_force_depth(double modulus) {
  const double a0 =
      std::cbrt(4.5 * kRelaxingPi * kRelaxingWork * kRelaxingRadius * kRelaxingRadius / modulus);
  return a0 * a0 / kRelaxingRadius - std::sqrt(2.0 * kRelaxingPi * a0 * kRelaxingWork / modulus);
}
/// The grips' speed [m/s] of beta = (V / v*) (E R / dgamma)^(1/3).
double relaxing_grips_speed(double beta, double modulus) {
  return beta * kRelaxingFront / std::cbrt(modulus * kRelaxingRadius / kRelaxingWork);
}

RunResult run_relaxing(const std::string& text) {
  return run_scene(test::build_scene_text(text), {});
}

/// Every stage's balance, machine work = stored + surface + bulk + jump losses (the front's
/// dissipation among them), closes to 1e-12 of the stage's largest term: each term is summed on
/// its own in closed form, so only rounding is left.
void expect_balances_close(const RunResult& r, const std::string& what) {
  for (const StageRecord& s : r.stages) {
    ASSERT_TRUE(s.energy) << what << " " << s.name;
    const EnergyBalance& e = *s.energy;
    const double scale =
        std::max({std::abs(e.machine_work), std::abs(e.stored_change), std::abs(e.surface_change),
                  std::abs(e.dissipated_by_bulk), std::abs(e.jump_losses), 1e-300});
    const double residual =
        e.machine_work - e.stored_change - e.surface_change - e.dissipated_by_bulk - e.jump_losses;
    EXPECT_LT(std::abs(residual), 1e-12 * scale) << what << " " << s.name;
    EXPECT_EQ(e.dissipated_by_bulk, s.work.bulk) << what << " " << s.name;
    EXPECT_GE(s.work.front, -1e-12 * scale) << what << " " << s.name;
  }
}

double relative_gap(double a, double b) { return std::abs(a / b - 1.0); }

// ---- The continuum front from a relaxed contact, solved here. ------------------------------
// After the contact relaxed under fixed grips (or with arms so fast that it is relaxed
// throughout), every point glued since before the retraction shares the grips' history since
// its start: q(x, t) = E_inf (d_eff(t) - x^2 / R) with
//   d_eff(t) = d0 - V t - (V / E_inf) sum_j E_j tau_j (1 - exp(-t / tau_j)),
// the hereditary integral of the withdrawal, so the front a(t) < a0 obeys
//   da/dt = -v* (G / dgamma - 1)^(1/n),  G = q(a, t)^2 / (2 pi a E_0),
// and the force is F = 2 int_0^a q dx = 2 E_inf (d_eff a - a^3 / (3 R)). The front starts at
// a0, the advancing front's radius at d0 (a0^2 / R - sqrt(2 pi a0 dgamma_a / E_0) = d0: a
// glue is glassy), pinned until G(a0, t) reaches dgamma.
struct RelaxedFront {
  double relaxed;   ///< E_inf [Pa]
  double glassy;    ///< E_0 [Pa]
  RelaxingArm arm;  ///< E_1, tau_1 (E_1 tau_1 -> 0: relaxed throughout)
  double exponent;  ///< n
  double speed;     ///< V [m/s]
  double depth;     ///< d0 [m]

  double effective_depth(double t) const {
    return depth - speed * t -
           speed / relaxed * arm.modulus * arm.time * -std::expm1(-t / arm.time);
  }
  double effective_rate(double t) const {
    return -speed - speed / relaxed * arm.modulus * std::exp(-t / arm.time);
  }
  double load(double a, double t) const {
    return relaxed * (effective_depth(t) - a * a / kRelaxingRadius);
  }
  double release_ratio(double a, double t) const {
    const double q = load(a, t);
    return q * q / (2.0 * kRelaxingPi * a * glassy * kRelaxingWork);
  }
  double front_speed(double a, double t) const {
    const double excess = release_ratio(a, t) - 1.0;
    return excess > 0.0 ? kRelaxingFront * std::pow(excess, 1.0 / exponent) : 0.0;
  }
  double force(double a, double t) const {
    return 2.0 * relaxed * (effective_depth(t) * a - a * a * a / (3.0 * kRelaxingRadius));
  }
  /// dF/dt / (2 E_inf): negative while the tension grows.
  double force_slope(double a, double t) const {
    return effective_rate(t) * a -
           front_speed(a, t) * (effective_depth(t) - a * a / kRelaxingRadius);
  }
};

/// The advancing front's radius at depth d0 with the glassy glue gap: the root of a^2 / R -
/// sqrt(2 pi a dgamma_a / E_0) - d0 above the gap's own zero (bisection to the last bits).
double glassy_advancing_radius(double depth, double approach_work, double glassy) {
  const auto f = [&](double a) {
    return a * a / kRelaxingRadius - std::sqrt(2.0 * kRelaxingPi * a * approach_work / glassy) -
           depth;
  };
  double lo = std::cbrt(2.0 * kRelaxingPi * approach_work * std::pow(kRelaxingRadius, 2) /
                        glassy);  // f < 0 there for d0 > 0
  double hi = 10.0 * lo + std::sqrt(std::abs(depth) * kRelaxingRadius);
  for (int i = 0; i < 200 && hi - lo > 1e-17 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct RelaxedPeak {
  double force;   ///< [N]
  double time;    ///< from the retraction's start [s]
  double radius;  ///< [m]
};

/// The peak tension of the front from a0: the pinned phase's end by bisection, then a(t) by
/// Runge-Kutta-Fehlberg 7(8) at relative and absolute tolerance rtol in a / a0 and t v* / a0;
/// the peak where dF/dt turns from negative, located by redoing the step that brackets it with
/// its length found by TOMS 748.
RelaxedPeak relaxed_front_peak(const RelaxedFront& p, double a0, double rtol) {
  namespace odeint = boost::numeric::odeint;
  using Vector = std::array<double, 1>;
  using Stepper = odeint::runge_kutta_fehlberg78<Vector>;
  // The onset: G(a0, t) = dgamma, the load's tension growing monotonically.
  double lo = 0.0;
  double hi = a0 / p.speed;
  while (!(p.release_ratio(a0, hi) > 1.0)) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (p.release_ratio(a0, mid) > 1.0 ? hi : lo) = mid;
  }
  const double scale = a0 / kRelaxingFront;  // [s]
  double s = hi / scale;
  Vector y{1.0};
  const auto system = [&](const Vector& z, Vector& dz, double si) {
    dz[0] = -p.front_speed(a0 * std::max(z[0], 0.0), scale * si) * scale / a0;
  };
  const auto slope = [&](const Vector& z, double si) {
    return p.force_slope(a0 * z[0], scale * si);
  };
  auto controlled = odeint::make_controlled(rtol, rtol, Stepper());
  Stepper plain;
  double step = 1e-6;
  for (int steps = 0; steps < 10'000'000; ++steps) {
    const Vector before = y;
    const double s_before = s;
    double tried = step;
    while (controlled.try_step(system, y, s, tried) == odeint::fail) {
    }
    Vector rate;
    system(y, rate, s);
    // No step past the axis.
    step = std::min(tried, 0.25 * y[0] / std::max(-rate[0], 1e-300));
    if (slope(before, s_before) < 0.0 && slope(y, s) >= 0.0) {
      const double taken = s - s_before;
      const auto redo = [&](double h) {
        Vector z = before;
        if (h != 0.0) plain.do_step(system, z, s_before, h);
        return z;
      };
      const auto slope_after = [&](double h) { return slope(redo(h), s_before + h); };
      std::uintmax_t iterations = 200;
      const auto bracket = boost::math::tools::toms748_solve(
          slope_after, 0.0, taken, slope_after(0.0), slope_after(taken),
          [taken](double a, double b) { return std::abs(b - a) <= 1e-14 * taken; }, iterations);
      const double h = 0.5 * (bracket.first + bracket.second);
      const Vector at = redo(h);
      const double t = scale * (s_before + h);
      return {p.force(a0 * at[0], t), t, a0 * at[0]};
    }
    if (!(y[0] > 0.0)) break;
  }
  throw std::runtime_error("relaxed_front_peak: no peak tension");
}

// A vanishing arm (E_1 = 1e-9 E_inf) on the JKR retraction at beta = 1: the elastic row's
// numbers to 1e-8. The arm moves E_0, the glue gap, the front's G and the forces by O(E_1 /
// E_inf) = 1e-9 relative; the rest is the two walks' integrator (its local tolerance 1e-11,
// restarted at every let-go on the relaxing bulk).
TEST(RateLawRelaxingRow, VanishingArmIsTheElasticRow) {
  const double depth = relaxing_zero_force_depth(kRelaxed);
  const double speed = relaxing_grips_speed(1.0, kRelaxed);
  for (const double n : {1.0, 0.5}) {
    const RunResult elastic = run_relaxing(
        relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork, {}, n, depth, 0.0, speed, 1000));
    const RunResult relaxing =
        run_relaxing(relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork, {1e-9 * kRelaxed, 1.0},
                                    n, depth, 0.0, speed, 1000));
    ASSERT_EQ(relaxing.status, RunStatus::instability);
    ASSERT_TRUE(elastic.peak && relaxing.peak && elastic.critical && relaxing.critical);
    const double peak = relative_gap(relaxing.peak->normal_force, elastic.peak->normal_force);
    const double lost = relative_gap(relaxing.critical->indentation, elastic.critical->indentation);
    const double time = relative_gap(relaxing.critical->time, elastic.critical->time);
    const double work = relative_gap(relaxing.stages[1].work.normal, elastic.stages[1].work.normal);
    const double front = relative_gap(relaxing.stages[1].work.front, elastic.stages[1].work.front);
    fmt::print(
        "vanishing arm n {}: peak {:.2e} d_lost {:.2e} t_lost {:.2e} work {:.2e} front "
        "{:.2e}\n",
        n, peak, lost, time, work, front);
    EXPECT_LT(peak, 1e-8);
    EXPECT_LT(lost, 1e-8);
    EXPECT_LT(time, 1e-8);
    EXPECT_LT(work, 1e-8);
    EXPECT_LT(front, 1e-8);
    expect_balances_close(relaxing, "vanishing arm");
  }
}

// tau -> infinity (1e15 s against a retraction of ~1e3 s: the arms keep all but 1e-12 of
// their stress): the elastic rate law with E* = E_0. From JKR's zero-force state of E_0
// (approach_work_of_adhesion = work_of_adhesion, the glue glassy) the retraction at beta = 1
// against tests/support/rate_law_front's reference (rtol 1e-10) at 1000 and 4000 springs:
// N |error| below 2 and the error falling as 1/N (ratio between 1/6 and 1/2, as the elastic
// row's test takes it), and the elastic row of E_0 at the same N to 1e-8.
TEST(RateLawRelaxingRow, GlassyLimitIsTheElasticRateLawOfTheGlassyModulus) {
  const double glassy = 3.0 * kRelaxed;
  const double depth = relaxing_zero_force_depth(glassy);
  const double speed = relaxing_grips_speed(1.0, glassy);
  const test::RateLawScales sc =
      test::rate_law_scales(glassy, kRelaxingRadius, kRelaxingWork, kRelaxingFront);
  for (const double n : {1.0, 0.5}) {
    const test::RateLawRetraction ref = test::rate_law_retraction(1.0, n, 1e-10);
    double coarse_error = 0.0;
    for (const std::int64_t springs : {1000, 4000}) {
      const RunResult r =
          run_relaxing(relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork,
                                      {2.0 * kRelaxed, 1e15}, n, depth, 0.0, speed, springs));
      const RunResult elastic = run_relaxing(
          relaxing_scene(glassy, kRelaxingWork, kRelaxingWork, {}, n, depth, 0.0, speed, springs));
      ASSERT_EQ(r.status, RunStatus::instability);
      ASSERT_TRUE(r.peak && elastic.peak && r.critical);
      const double error = r.peak->normal_force / (ref.peak.force * sc.force) - 1.0;
      const double lost = relative_gap(r.critical->indentation, ref.lost.delta * sc.indentation);
      const double to_elastic = relative_gap(r.peak->normal_force, elastic.peak->normal_force);
      fmt::print(
          "glassy n {} N {}: peak {:+.3e} (N err {:+.3f}) d_lost {:.2e}, against the "
          "elastic row of E_0 {:.2e}\n",
          n, springs, error, static_cast<double>(springs) * error, lost, to_elastic);
      EXPECT_LT(static_cast<double>(springs) * std::abs(error), 2.0) << n << " " << springs;
      EXPECT_LT(static_cast<double>(springs) * lost, 5.0) << n << " " << springs;
      EXPECT_LT(to_elastic, 1e-8) << n << " " << springs;
      expect_balances_close(r, "glassy");
      if (springs == 1000) {
        coarse_error = error;
      } else {
        EXPECT_GT(error / coarse_error, 1.0 / 6.0) << n;
        EXPECT_LT(error / coarse_error, 0.5) << n;
      }
    }
  }
}

// tau -> 0 (1e-12 s: relaxed within a picosecond of every glue): the elastic rate law of E_inf
// with dgamma E_0 / E_inf (G = E_inf^2 e^2 / (2 pi a E_0)); the glue is still glassy, at
// sqrt(2 pi x dgamma_a / E_0), which the elastic row takes as dgamma_a E_inf / E_0. A press to
// 5.7 um and the retraction until separation: the peak against the front's ODE solved here
// (rtol 1e-10) at 1000 and 4000 springs with the error falling as 1/N, and the elastic row at
// the same N to 1e-8.
TEST(RateLawRelaxingRow, RelaxedLimitIsTheElasticRateLawOfTheRelaxedModulus) {
  const double glassy = 3.0 * kRelaxed;
  const double depth = 5.7e-6;
  const double speed = relaxing_grips_speed(1.0, kRelaxed);
  const RelaxingArm arm{2.0 * kRelaxed, 1e-12};
  const double a0 = glassy_advancing_radius(depth, kRelaxingWork, glassy);
  for (const double n : {1.0, 0.5}) {
    const RelaxedPeak ref = relaxed_front_peak({kRelaxed, glassy, arm, n, speed, depth}, a0, 1e-10);
    double coarse_error = 0.0;
    for (const std::int64_t springs : {1000, 4000}) {
      const RunResult r = run_relaxing(relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork, arm,
                                                      n, depth, 0.0, speed, springs));
      const RunResult elastic = run_relaxing(
          relaxing_scene(kRelaxed, kRelaxingWork * glassy / kRelaxed,
                         kRelaxingWork * kRelaxed / glassy, {}, n, depth, 0.0, speed, springs));
      ASSERT_EQ(r.status, RunStatus::instability);
      ASSERT_TRUE(r.peak && elastic.peak);
      const double error = r.peak->normal_force / ref.force - 1.0;
      const double to_elastic = relative_gap(r.peak->normal_force, elastic.peak->normal_force);
      fmt::print(
          "relaxed n {} N {}: peak {:+.3e} (N err {:+.3f}), against the elastic row of "
          "E_inf {:.2e}\n",
          n, springs, error, static_cast<double>(springs) * error, to_elastic);
      EXPECT_LT(static_cast<double>(springs) * std::abs(error), 2.0) << n << " " << springs;
      EXPECT_LT(to_elastic, 1e-8) << n << " " << springs;
      expect_balances_close(r, "relaxed");
      if (springs == 1000) {
        coarse_error = error;
      } else {
        EXPECT_GT(error / coarse_error, 1.0 / 6.0) << n;
        EXPECT_LT(error / coarse_error, 0.5) << n;
      }
    }
  }
}

// A parabola pressed, relaxed fully under fixed grips (a hold of 100 tau) and retracted at
// constant speed with tau = 100 s (the arms build up a third of the relaxed load during the
// retraction): the peak tension against the front's ODE solved here with the hereditary
// d_eff(t) (rtol 1e-10), at 1000 and 4000 springs, N |error| below 2 and falling as 1/N; the
// bulk dissipates in the hold and the retraction, and every stage's balance closes.
TEST(RateLawRelaxingRow, RelaxedContactRetractedAgainstTheFrontsOde) {
  const double glassy = 3.0 * kRelaxed;
  const double depth = 5.7e-6;
  const double speed = relaxing_grips_speed(1.0, kRelaxed);
  const RelaxingArm arm{2.0 * kRelaxed, 100.0};
  const double a0 = glassy_advancing_radius(depth, kRelaxingWork, glassy);
  for (const double n : {1.0, 0.5}) {
    const RelaxedPeak ref = relaxed_front_peak({kRelaxed, glassy, arm, n, speed, depth}, a0, 1e-10);
    double coarse_error = 0.0;
    for (const std::int64_t springs : {1000, 4000}) {
      const RunResult r = run_relaxing(relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork, arm,
                                                      n, depth, 100.0 * arm.time, speed, springs));
      ASSERT_EQ(r.status, RunStatus::instability);
      ASSERT_TRUE(r.peak);
      ASSERT_EQ(r.stages.size(), 3u);
      const double error = r.peak->normal_force / ref.force - 1.0;
      const double start = kRelaxingPress + 100.0 * arm.time;
      const double time = relative_gap(r.peak->time - start, ref.time);
      fmt::print(
          "relaxed, then retracted, n {} N {}: peak {:.9e} N against {:.9e} N, {:+.3e} "
          "(N err {:+.3f}), its time {:.2e}; bulk {:.3e} J hold, {:.3e} J retract\n",
          n, springs, r.peak->normal_force, ref.force, error, static_cast<double>(springs) * error,
          time, r.stages[1].work.bulk, r.stages[2].work.bulk);
      EXPECT_LT(static_cast<double>(springs) * std::abs(error), 2.0) << n << " " << springs;
      EXPECT_GT(r.stages[1].work.bulk, 0.0);
      EXPECT_GT(r.stages[2].work.bulk, 0.0);
      EXPECT_EQ(r.stages[1].work.normal, 0.0);
      expect_balances_close(r, "relaxed then retracted");
      if (springs == 1000) {
        coarse_error = error;
      } else {
        EXPECT_GT(error / coarse_error, 1.0 / 6.0) << n;
        EXPECT_LT(error / coarse_error, 0.5) << n;
      }
    }
  }
}

// rtol on the relaxed contact's retraction (n = 1/2): the rows double until the estimates
// (the peak, each stage's end force and work, dissipated_by_bulk among them) meet it, and the
// peak is within rtol of the front's ODE; its estimate bounds the error.
TEST(RateLawRelaxingRow, RtolCoversTheRelaxingRow) {
  const double glassy = 3.0 * kRelaxed;
  const double depth = 5.7e-6;
  const double speed = relaxing_grips_speed(1.0, kRelaxed);
  const RelaxingArm arm{2.0 * kRelaxed, 100.0};
  const double a0 = glassy_advancing_radius(depth, kRelaxingWork, glassy);
  const RelaxedPeak ref = relaxed_front_peak({kRelaxed, glassy, arm, 0.5, speed, depth}, a0, 1e-10);
  for (const double rtol : {1e-3, 1e-5}) {
    std::string text = relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork, arm, 0.5, depth,
                                      100.0 * arm.time, speed, 1000);
    text.replace(text.find("springs = 1000"), 14, fmt::format("rtol = {}", rtol));
    const RunResult r = run_relaxing(text);
    ASSERT_TRUE(r.peak && r.accuracy.peak_error_estimate && r.accuracy.work_error_estimate);
    const double error = std::abs(r.peak->normal_force - ref.force);
    fmt::print(
        "rtol {:g}: {} springs, peak error {:.2e} N, estimate {:.2e} N, bulk estimate "
        "{:.2e} J of {:.3e} J\n",
        rtol, r.springs, error, *r.accuracy.peak_error_estimate,
        r.accuracy.work_error_estimate->bulk, r.work->bulk);
    EXPECT_TRUE(r.accuracy.rtol_met);
    EXPECT_LT(error, rtol * std::abs(ref.force));
    EXPECT_LT(error, *r.accuracy.peak_error_estimate);
    EXPECT_GT(r.work->bulk, 0.0);
  }
}

// A press after a stage in which springs may have let go is refused on a relaxing bulk, even
// with rebinding: a let-go spring creeps free, which the row does not follow back into contact.
TEST(RateLawRelaxingRow, RefusesAPressAfterALetGo) {
  std::string text = relaxing_scene(kRelaxed, kRelaxingWork, kRelaxingWork, {2.0 * kRelaxed, 1.0},
                                    1.0, 5.7e-6, 0.0, 1e-8, 100);
  text += "[[loading.stage]]\nname = \"again\"\nnormal = { to = 5e-6 }\nduration = 1.0\n";
  text = "[loading]\nrebinding = true\n" + text;
  const auto at = text.find("[[loading.stage]]\nname = \"retract\"");
  // A finite pull (by -1e-4 at its speed), then a press.
  text.erase(text.find("until = \"separation\"\n", at), 21);
  EXPECT_THROW_MSG(run_relaxing(text), SceneError,
                   "test.toml:13:19: detachment.front_speed_law: stage 'again' may press the "
                   "contact again after "
                   "springs let go: not yet taken with material.relaxation (docs/rate_law.md)");
}

}  // namespace
}  // namespace mdrsim
