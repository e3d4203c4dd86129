// The adhesive edge of the viscoelastic row under a machine spring (SPEC "Time and viscoelastic
// media"), run by `mdrsim run`'s path on a parabola and a standard linear solid, against
// derivations written here (no engine code): the elastic program's pull-off when the arm
// vanishes, JKR's fixed-load pull-off in the slow and fast limits when the spring is soft, and
// each stage's energy balance with the machine spring's F^2 / (2k) stored.
//
// The derivations. A let-go or a glue under a held control is instantaneous: every spring in
// contact answers with E_0, so the row's depth steps by Dd = (phi - kappa d - q) / (kappa +
// n E_0) (phi the held value, kappa the machine spring per unit length of a half, q the row's
// line load after the change), and the step loses Dd^2 (kappa + n E_0) / 2. With E_1 -> 0 the
// row is the elastic program of E_inf (whose let-go under a machine spring moves d the same way
// with E_inf). A machine spring k much softer than the contact (2 E a) is a fixed load up to
// O((k / 2 E a)^2) at the force's minimum, so the pull-off tends to JKR's fixed-load one,
// -(3/2) pi R dgamma_eff: dgamma E_0 / E_inf with E_inf when the retraction is much slower than
// tau (the arms relaxed: the let-go criterion written with E_0 gives the relaxed contact
// dgamma E_0 / E_inf), dgamma with E_0 when much faster (every arm glassy).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kHeldRadius = 0.01;                     // R [m]
constexpr double kHeldRelaxed = 1.0e6;                   // E*_inf [Pa]
constexpr double kHeldArm = 9.0e6;                       // E*_1 [Pa]
constexpr double kHeldGlassy = kHeldRelaxed + kHeldArm;  // E*_0 [Pa]
constexpr double kHeldTau = 0.1;                         // [s]
constexpr double kHeldDgamma = 0.05;                     // [J/m^2]

/// A press (fixed grips, or a machine spring with `press_under_spring`) to `preload`, a hold,
/// and a withdrawal of the machine end until separation, under a machine spring of `stiffness`.
struct HeldCycle {
  double preload;        // [m]
  double press_speed;    // [m/s]
  double hold;           // [s]
  double retract_speed;  // the machine end's [m/s]
  double stiffness;      // k [N/m]
  std::int64_t springs;
  double arm = kHeldArm;  // E*_1 [Pa]; 0: no relaxation (the elastic program)
  double approach = 0.0;  // dgamma_a [J/m^2]
  bool press_under_spring = false;
  /// > 0: the withdrawal is a fixed load lowered to -this [N] in `retract_seconds` instead.
  double tension = 0.0;
  double retract_seconds = 0.0;
};

std::string held_cycle_text(const HeldCycle& c) {
  std::string text = fmt::format(
      "[material]\neffective_modulus = {}\nwork_of_adhesion = {}\napproach_work_of_adhesion = {}\n",
      kHeldRelaxed, kHeldDgamma, c.approach);
  if (c.arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", c.arm, kHeldTau);
  }
  text += fmt::format("[profile]\ntype = \"parabolic\"\nradius = {}\n", kHeldRadius);
  if (c.press_under_spring) {
    // The machine end moved in by the preload plus what the spring takes of the force then.
    text += fmt::format(
        "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"compliant\", stiffness = "
        "{}, by = {} }}\nduration = {}\n",
        c.stiffness, c.preload, c.preload / c.press_speed);
  } else {
    text += fmt::format(
        "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
        "speed = {}\n",
        c.preload, c.press_speed);
  }
  if (c.hold > 0.0) {
    text += fmt::format("[[loading.stage]]\nname = \"hold\"\nduration = {}\n", c.hold);
  }
  if (c.tension > 0.0) {
    // A stage after it, which a lost contact leaves unrun.
    text += fmt::format(
        "[[loading.stage]]\nname = \"withdraw\"\nnormal = {{ control = \"fixed-load\", to = {} "
        "}}\nduration = {}\n[[loading.stage]]\nname = \"rest\"\nduration = 1.0\n",
        -c.tension, c.retract_seconds);
  } else {
    text += fmt::format(
        "[[loading.stage]]\nname = \"withdraw\"\nnormal = {{ control = \"compliant\", stiffness "
        "= {}, by = -1.0 }}\nuntil = \"separation\"\nduration = {}\n",
        c.stiffness, 1.0 / c.retract_speed);
  }
  text += fmt::format("[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n", c.springs);
  return text;
}

RunResult run_held_cycle(const HeldCycle& c) {
  const Scene scene =
      SceneDocument::from_text(held_cycle_text(c), "held.toml").build(Registries::builtin());
  return run_scene(scene, {});
}

/// -(3/2) pi R dgamma_eff: JKR's pull-off under a fixed load [N].
double jkr_fixed_load_pull_off(double dgamma) {
  return -1.5 * std::numbers::pi * kHeldRadius * dgamma;
}

TEST(ViscoelasticHeldAdhesion, AVanishingArmUnderAMachineSpringIsTheElasticProgram) {
  // E_1 = 1e-3 Pa = 1e-9 E_inf: every load differs from the elastic row's by that share, so the
  // pull-off, the critical point and the jumps agree to ~1e-9 (checked to 1e-8). Pressed and
  // withdrawn under the spring, so glues (dgamma_a > 0: at the glassy gap) and let-gos both
  // move the held depth.
  std::printf("vanishing arm under a machine spring: critical point against the elastic row\n");
  std::printf("%10s %8s %24s %24s %10s\n", "dgamma_a", "k [N/m]", "critical F [N]", "elastic [N]",
              "rel. diff");
  for (const double approach : {0.0, 0.02}) {
    for (const double stiffness : {20.0, 2000.0}) {
      HeldCycle c{2.25e-4, 1.0e-3, 1.0, 1.0e-3, stiffness, 200};
      c.approach = approach;
      c.press_under_spring = true;
      HeldCycle elastic = c;
      elastic.arm = 0.0;
      c.arm = 1.0e-3;
      const RunResult v = run_held_cycle(c);
      const RunResult e = run_held_cycle(elastic);
      ASSERT_TRUE(v.critical && e.critical) << approach << " " << stiffness;
      const double f = v.critical->normal_force;
      const double fe = e.critical->normal_force;
      std::printf("%10g %8g %24.16e %24.16e %10.2e\n", approach, stiffness, f, fe,
                  std::abs(f / fe - 1.0));
      EXPECT_NEAR(f, fe, 1e-8 * std::abs(fe));
      // The critical depth is a small difference of depths of the preload's size: 1e-8 of it.
      EXPECT_NEAR(v.critical->indentation, e.critical->indentation, 1e-8 * c.preload);
      EXPECT_EQ(v.critical->springs_in_contact, e.critical->springs_in_contact);
      EXPECT_EQ(v.status, e.status);
      EXPECT_EQ(v.status, RunStatus::instability);
      ASSERT_EQ(v.jumps.size(), e.jumps.size());
      for (std::size_t i = 0; i < v.jumps.size(); ++i) {
        EXPECT_EQ(v.jumps[i].inward, e.jumps[i].inward) << i;
        EXPECT_EQ(v.jumps[i].springs, e.jumps[i].springs) << i;
      }
      ASSERT_EQ(v.stages.size(), e.stages.size());
      for (std::size_t i = 0; i < v.stages.size(); ++i) {
        const double w = e.stages[i].energy->machine_work;
        EXPECT_NEAR(v.stages[i].energy->machine_work, w, 1e-8 * std::abs(w) + 1e-18) << i;
      }
    }
  }
}

TEST(ViscoelasticHeldAdhesion, AVanishingArmUnderAFixedLoadIsTheElasticProgram) {
  // As under the machine spring; the last let-go sends the indenter away (SPEC "A fixed load
  // that loses the contact"): the stage ends at the critical point, its work up to it, the jump
  // `separated`, and the stage after it unrun.
  std::printf("vanishing arm under a fixed load: critical point against the elastic row\n");
  for (const double approach : {0.0, 0.02}) {
    HeldCycle c{2.25e-4, 1.0e-3, 1.0, 0.0, 0.0, 200};
    c.approach = approach;
    c.tension = 0.01;
    c.retract_seconds = 10.0;
    HeldCycle elastic = c;
    elastic.arm = 0.0;
    c.arm = 1.0e-3;
    const RunResult v = run_held_cycle(c);
    const RunResult e = run_held_cycle(elastic);
    ASSERT_TRUE(v.critical && e.critical) << approach;
    const double f = v.critical->normal_force;
    const double fe = e.critical->normal_force;
    std::printf("dgamma_a = %g: critical F %.16e (elastic %.16e), rel. diff %.2e\n", approach, f,
                fe, std::abs(f / fe - 1.0));
    EXPECT_NEAR(f, fe, 1e-8 * std::abs(fe));
    EXPECT_NEAR(v.critical->indentation, e.critical->indentation, 1e-8 * c.preload);
    EXPECT_EQ(v.critical->springs_in_contact, e.critical->springs_in_contact);
    EXPECT_EQ(v.status, RunStatus::instability);
    EXPECT_EQ(v.status, e.status);
    ASSERT_EQ(v.jumps.size(), e.jumps.size());
    ASSERT_FALSE(v.jumps.empty());
    EXPECT_EQ(v.jumps.back().end, JumpEnd::separated);
    for (std::size_t i = 0; i < v.jumps.size(); ++i) {
      EXPECT_EQ(v.jumps[i].end, e.jumps[i].end) << i;
      EXPECT_EQ(v.jumps[i].springs, e.jumps[i].springs) << i;
    }
    // The withdrawal ends at the critical point; the rest is not run.
    ASSERT_EQ(v.stages.size(), e.stages.size());
    ASSERT_EQ(v.stages.size(), 3u);
    EXPECT_EQ(v.stages.back().end.normal_force, f);
    // The works per stage; the surface over the press and hold together (under fixed grips the
    // row meets the spring at the deepest depth's image as the hold begins, the elastic row as
    // the press ends) and over the withdrawal.
    for (std::size_t i = 0; i < v.stages.size(); ++i) {
      const double w = e.stages[i].energy->machine_work;
      EXPECT_NEAR(v.stages[i].energy->machine_work, w, 1e-8 * std::abs(w) + 1e-18) << i;
    }
    const auto glued = [](const RunResult& r) {
      return r.stages[0].energy->surface_change + r.stages[1].energy->surface_change;
    };
    EXPECT_NEAR(glued(v), glued(e), 1e-8 * std::abs(glued(e)));
    EXPECT_NEAR(v.stages[2].energy->surface_change, e.stages[2].energy->surface_change,
                1e-8 * std::abs(e.stages[2].energy->surface_change));
    EXPECT_EQ(v.warnings.size(), e.warnings.size());
  }
}

TEST(ViscoelasticHeldAdhesion, AFixedLoadsPullOffTendsToJkrsLimits) {
  std::printf("fixed load: pull-off against JKR's fixed-load limits\n");
  std::printf("%6s %8s %22s %22s %12s\n", "limit", "springs", "pull-off F [N]", "JKR [N]",
              "vs JKR");
  const double slow_jkr = jkr_fixed_load_pull_off(kHeldDgamma * kHeldGlassy / kHeldRelaxed);
  const double fast_jkr = jkr_fixed_load_pull_off(kHeldDgamma);
  for (const std::int64_t n : {200, 800}) {
    // Slow: pressed at 1e-7 m/s (22500 tau), the force lowered by 0.5 N in 5e4 s, about
    // 1e-8 m/s of depth where the contact's stiffness is 2 E_inf a*: the arms relaxed.
    HeldCycle slow{2.25e-4, 1.0e-7, 0.0, 0.0, 0.0, n};
    slow.tension = 2.0 * std::abs(slow_jkr);
    slow.retract_seconds = 5.0e4;
    // Fast: pressed at 100 m/s, the force lowered by 0.04 N in 2e-7 s = 2e-6 tau: glassy.
    HeldCycle fast{9.0e-6, 100.0, 0.0, 0.0, 0.0, n};
    fast.tension = 2.0 * std::abs(fast_jkr);
    fast.retract_seconds = 2.0e-7;
    const RunResult rs = run_held_cycle(slow);
    const RunResult rf = run_held_cycle(fast);
    ASSERT_TRUE(rs.critical && rf.critical);
    const double slow_f = rs.critical->normal_force;
    const double fast_f = rf.critical->normal_force;
    std::printf("%6s %8lld %22.14e %22.14e %12.2e\n", "slow", static_cast<long long>(n), slow_f,
                slow_jkr, std::abs(slow_f / slow_jkr - 1.0));
    std::printf("%6s %8lld %22.14e %22.14e %12.2e\n", "fast", static_cast<long long>(n), fast_f,
                fast_jkr, std::abs(fast_f / fast_jkr - 1.0));
    // The row's O(1/N) as the fixed-grips limits have it (1.0 % at 200 springs).
    const double discreteness = 300.0 / static_cast<double>(n) * 1e-2;
    EXPECT_NEAR(slow_f, slow_jkr, discreteness * std::abs(slow_jkr));
    EXPECT_NEAR(fast_f, fast_jkr, discreteness * std::abs(fast_jkr));
    EXPECT_EQ(rs.status, RunStatus::instability);
    EXPECT_EQ(rf.status, RunStatus::instability);
    // Each stage's balance, to the closed forms' rounding: 1e-12 slow; 1e-8 fast, where the
    // pieces are 1e-6 tau long and the held drive's integrals of decays lose digits to
    // cancellation (the same scene without adhesion, under a fixed load to 1 mN, closes to 1e-9).
    for (const auto& [r, tolerance] : {std::pair{&rs, 1e-12}, std::pair{&rf, 1e-8}}) {
      for (const StageRecord& st : r->stages) {
        const EnergyBalance& e = *st.energy;
        const double scale = std::max(
            {std::abs(e.machine_work), std::abs(e.stored_change), std::abs(e.dissipated_by_bulk)});
        EXPECT_LT(std::abs(e.residual), tolerance * scale) << st.name;
      }
    }
  }
}

TEST(ViscoelasticHeldAdhesion, ASoftSpringsPullOffTendsToJkrsFixedLoadLimits) {
  std::printf("soft machine spring (k = 20 N/m): pull-off against JKR's fixed-load limits\n");
  std::printf("%6s %8s %22s %22s %12s\n", "limit", "springs", "pull-off F [N]", "JKR [N]",
              "vs JKR");
  for (const std::int64_t n : {200, 800}) {
    // Slow: 1e-7 m/s, the press 2250 s = 22500 tau: the arms relaxed.
    const RunResult slow = run_held_cycle({2.25e-4, 1.0e-7, 0.0, 1.0e-7, 20.0, n});
    // Fast: 100 m/s, the cycle ~1e-6 s = 1e-5 tau: the arms glassy.
    const RunResult fast = run_held_cycle({9.0e-6, 100.0, 0.0, 100.0, 20.0, n});
    ASSERT_TRUE(slow.critical && fast.critical);
    const double slow_jkr = jkr_fixed_load_pull_off(kHeldDgamma * kHeldGlassy / kHeldRelaxed);
    const double fast_jkr = jkr_fixed_load_pull_off(kHeldDgamma);
    const double slow_f = slow.critical->normal_force;
    const double fast_f = fast.critical->normal_force;
    std::printf("%6s %8lld %22.14e %22.14e %12.2e\n", "slow", static_cast<long long>(n), slow_f,
                slow_jkr, std::abs(slow_f / slow_jkr - 1.0));
    std::printf("%6s %8lld %22.14e %22.14e %12.2e\n", "fast", static_cast<long long>(n), fast_f,
                fast_jkr, std::abs(fast_f / fast_jkr - 1.0));
    // The row's O(1/N) as the fixed-grips limits have it (1.0 % at 200 springs), the spring's
    // O((k / 2 E a*)^2) < 4e-4 below it.
    const double discreteness = 300.0 / static_cast<double>(n) * 1e-2;
    EXPECT_NEAR(slow_f, slow_jkr, discreteness * std::abs(slow_jkr));
    EXPECT_NEAR(fast_f, fast_jkr, discreteness * std::abs(fast_jkr));
    EXPECT_EQ(slow.status, RunStatus::instability);
    EXPECT_EQ(fast.status, RunStatus::instability);
  }
}

TEST(ViscoelasticHeldAdhesion, EveryStageBalancesWithTheMachineSpringStored) {
  std::printf("held cycle (press and withdraw under k = 200 N/m, dgamma_a = 0.02): energy [J]\n");
  std::printf("%8s %10s %13s %13s %13s %13s %13s %10s\n", "springs", "stage", "machine", "stored",
              "surface", "bulk", "jump_losses", "residual");
  for (const std::int64_t n : {200, 800}) {
    HeldCycle c{2.25e-4, 1.0e-3, 0.05, 1.0e-3, 200.0, n};
    c.approach = 0.02;
    c.press_under_spring = true;
    const RunResult r = run_held_cycle(c);
    ASSERT_EQ(r.stages.size(), 3u);
    double surface = 0.0;
    for (const StageRecord& s : r.stages) {
      ASSERT_TRUE(s.energy.has_value());
      const EnergyBalance& e = *s.energy;
      std::printf("%8lld %10s %13.6e %13.6e %13.6e %13.6e %13.6e %10.1e\n",
                  static_cast<long long>(n), s.name.c_str(), e.machine_work, e.stored_change,
                  e.surface_change, e.dissipated_by_bulk, e.jump_losses, e.residual);
      // Each term summed apart in closed form (the steps' losses as Dd^2 (kappa + n E_0) / 2):
      // the residual is rounding.
      const double scale = std::max(
          {std::abs(e.machine_work), std::abs(e.stored_change), std::abs(e.dissipated_by_bulk)});
      EXPECT_LT(std::abs(e.residual), 1e-12 * scale) << s.name;
      // A step loses energy, never gains it.
      EXPECT_GE(e.jump_losses, 0.0) << s.name;
      surface += e.surface_change;
    }
    // Out of contact at both ends: every ring glued was created again.
    EXPECT_NEAR(surface, 0.0, 1e-12 * std::abs(r.stages[0].energy->surface_change));
    EXPECT_EQ(r.status, RunStatus::instability);
  }
}

}  // namespace
}  // namespace mdrsim
