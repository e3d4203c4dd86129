// Tangential fixed-grips stages on the viscoelastic row with an adhesive edge (parabola, one
// Prony term), run by `mdrsim run`'s path (run_scene), against derivations written here from
// the row's definition (SPEC "Time and viscoelastic media", "Loading programs"; no engine code)
// and against the elastic program row in the limits where the two must agree.
//
// The derivations. A spring glued at u_x = u_g carries the tangential stretch w = u_x - u_g
// through G_inf dx in parallel with a Maxwell arm G_1 dx (G_1 = E_1 G*/E*, time tau): its line
// load is q_x = G_inf w + s, s' = G_1 w' - s / tau. Springs glued before the shear (u_g = 0)
// all carry w = u_x. A ramp u_x = V t over [0, T] then a hold at u_0 = V T gives
//   s(T + h) = G_1 V tau (1 - exp(-T / tau)) exp(-h / tau),
// so the n glued springs, spaced dx with the outermost at a = n dx, carry
//   F_x(T + h) = 2 a [G_inf u_0 + G_1 V tau (1 - exp(-T / tau)) exp(-h / tau)]
// (both halves, 2 dx a spring): a step (T -> 0) relaxes as u_0 G(h), G(h) = G_inf + G_1
// exp(-h / tau). The let-go is the glassy criterion's (E_0, G_0 = E_0 G*/E*) on (q_z, q_x); with
// the mode-mixed criterion q_z^2 / E_0 + q_x^2 / G_0 >= 2 pi a dgamma. Relaxed (q_z = E_inf w_z +
// S, q_x = G_inf u_x, S an arm stress common to the glued springs) this is E_inf w_z'^2 + G_inf
// u_x^2 >= 2 pi a dgamma E_0 / E_inf with w_z' = q_z / E_inf: the elastic program of (E_inf,
// G_inf) with dgamma E_0 / E_inf, and S drops out of the force at each let-go as in the normal
// case (F_k = 2 dx sum_{i <= k} (q_k + E_inf (g_k - g_i))). Glassy (every arm unrelaxed) it is
// the elastic program of (E_0, G_0) with dgamma.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kShearRadius = 0.01;    // R [m]
constexpr double kShearRelaxed = 1.0e6;  // E*_inf = G*_inf [Pa] (G* = E*)
constexpr double kShearArm = 9.0e6;      // E*_1 [Pa]
constexpr double kShearTau = 0.1;        // [s]
constexpr double kShearDgamma = 0.05;    // [J/m^2]

/// Press to `preload`, shear to `shear_to`, hold `hold` [s], pull until separation.
struct ShearPull {
  double preload;      // [m]
  double press_speed;  // [m/s]
  double shear_to;     // u_x [m]
  double shear_speed;  // [m/s]
  double hold;         // [s]; 0: none
  double pull_speed;   // [m/s]
  std::int64_t springs;
};

/// The scene: with `arm` > 0 a standard linear solid of relaxed modulus `modulus`; without, the
/// elastic material of `modulus` (G* = E*) and work of adhesion `dgamma`.
std::string shear_pull_text(const ShearPull& c, double modulus, double arm, double dgamma) {
  std::string text =
      fmt::format("[material]\neffective_modulus = {}\nwork_of_adhesion = {}\n", modulus, dgamma);
  if (arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", arm, kShearTau);
  }
  text += fmt::format(
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
      "speed = {}\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to = {} "
      "}}\nspeed = {}\n",
      kShearRadius, c.preload, c.press_speed, c.shear_to, c.shear_speed);
  if (c.hold > 0.0) {
    text += fmt::format("[[loading.stage]]\nname = \"hold\"\nduration = {}\n", c.hold);
  }
  text += fmt::format(
      "[[loading.stage]]\nname = \"pull\"\nnormal = {{ by = -1.0 }}\nuntil = \"separation\"\n"
      "speed = {}\n[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n",
      c.pull_speed, c.springs);
  return text;
}

RunResult run_text(const std::string& text) {
  return run_scene(SceneDocument::from_text(text, "shear.toml").build(Registries::builtin()), {});
}

TEST(ViscoelasticTangential, AVanishingArmIsTheElasticProgramWithATangentialStage) {
  // E_1 = 1e-9 E_inf: the elastic program of E_inf must give the same critical point, status
  // and jumps; the arm shifts every spring's load by ~1e-9 of itself, so the forces agree to
  // 1e-8 of the press's force (a critical force near zero is a difference of such loads). The
  // shears span a let-go under tension (3e-6) to a glue broken by shear at rest (2e-5).
  for (const double ux : {3.0e-6, 8.0e-6, 1.5e-5, 2.0e-5}) {
    const ShearPull c{2.25e-4, 1.0e-3, ux, 1.0e-4, 0.5, 1.0e-3, 200};
    const RunResult v = run_text(shear_pull_text(c, kShearRelaxed, 1.0e-3, kShearDgamma));
    const RunResult e = run_text(shear_pull_text(c, kShearRelaxed, 0.0, kShearDgamma));
    ASSERT_TRUE(v.critical && e.critical) << ux;
    std::printf(
        "vanishing arm, u_x = %g: critical F %.12e (elastic %.12e), F_x %.12e (%.12e), %lld "
        "springs (%lld), status %d (%d), %zu jumps (%zu)\n",
        ux, v.critical->normal_force, e.critical->normal_force, v.critical->tangential_force,
        e.critical->tangential_force, static_cast<long long>(v.critical->springs_in_contact),
        static_cast<long long>(e.critical->springs_in_contact), static_cast<int>(v.status),
        static_cast<int>(e.status), v.jumps.size(), e.jumps.size());
    const double press_force = e.stages.front().end.normal_force;
    EXPECT_NEAR(v.critical->normal_force, e.critical->normal_force, 1e-8 * press_force);
    EXPECT_NEAR(v.critical->tangential_force, e.critical->tangential_force,
                1e-8 * std::abs(e.critical->tangential_force));
    EXPECT_EQ(v.critical->springs_in_contact, e.critical->springs_in_contact);
    EXPECT_EQ(v.status, e.status);
    ASSERT_EQ(v.jumps.size(), e.jumps.size());
    for (std::size_t i = 0; i < v.jumps.size(); ++i) {
      EXPECT_EQ(v.jumps[i].inward, e.jumps[i].inward) << i;
      EXPECT_EQ(v.jumps[i].springs, e.jumps[i].springs) << i;
    }
  }
}

TEST(ViscoelasticTangential, AHeldShearRelaxesAsTheTangentialModulus) {
  // Pressed glued on touch (dgamma_a = 0), sheared by u_0 = 1e-6 m over T = tau, then held in
  // stages: F_x at each stage's end against the ramp-and-hold closed form (header). Nothing
  // lets go: q_x^2 / G_0 <= (G_0 u_0)^2 / G_0 = 1e-5 J/m^2 << 2 pi a dgamma = 4.7e-4.
  const double u0 = 1.0e-6;
  const double speed = u0 / kShearTau;
  std::string text = fmt::format(
      "[material]\neffective_modulus = {}\nwork_of_adhesion = {}\n"
      "relaxation = [ {{ modulus = {}, time = {} }} ]\n"
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = 2.25e-4 "
      "}}\nspeed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to = {} "
      "}}\nspeed = {}\n",
      kShearRelaxed, kShearDgamma, kShearArm, kShearTau, kShearRadius, u0, speed);
  const std::vector<double> holds = {0.05, 0.05, 0.1, 0.3, 0.5};
  for (std::size_t i = 0; i < holds.size(); ++i) {
    text += fmt::format("[[loading.stage]]\nname = \"hold-{}\"\nduration = {}\n", i + 1, holds[i]);
  }
  text += "[discretization]\nsprings = 200\n[solver]\nmethod = \"event\"\n";
  const RunResult r = run_text(text);
  ASSERT_EQ(r.stages.size(), 2 + holds.size());
  const double g1 = kShearArm;  // G_1 = E_1 G*/E*, G* = E*
  const double glassy_part = g1 * speed * kShearTau * (-std::expm1(-1.0));
  double held = 0.0;
  std::printf("held shear: h [s], F_x [N], closed form, rel. error\n");
  for (std::size_t i = 1; i < r.stages.size(); ++i) {
    const ContactSnapshot& end = r.stages[i].end;
    const double a = end.contact_radius;  // n dx: every spring in contact is glued
    const double expected =
        2.0 * a * (kShearRelaxed * u0 + glassy_part * std::exp(-held / kShearTau));
    std::printf("  %5.2f %.15e %.15e %.1e\n", held, end.tangential_force, expected,
                std::abs(end.tangential_force / expected - 1.0));
    // The sums over 200 springs and the per-term updates round at a few 1e-16.
    EXPECT_NEAR(end.tangential_force, expected, 1e-12 * expected) << i;
    EXPECT_EQ(end.springs_in_contact, r.stages[1].end.springs_in_contact);
    if (i + 1 < r.stages.size()) held += holds[i - 1];
  }
}

/// The time of every let-go, in order.
class LetGoTimes : public Observer {
 public:
  void on_event(const Event& e) override {
    if (e.kind == EventKind::spring_detached) times.push_back(e.state.time);
  }
  std::vector<double> times;
};

TEST(ViscoelasticTangential, AShearBreaksTheRelaxedGlueWhenTheGlassyCriterionSaysSo) {
  // Pressed glued on touch to d0 = 2.25e-4 m at 1e-3 m/s (0.225 s), rested 2 s (20 tau: the
  // normal arms' e^-20 left, the outermost spring N at its image d0 compressed by it), then
  // sheared at V = 1e-4 m/s. Every glued spring carries q_x(t) = G_inf V t + G_1 V tau (1 -
  // exp(-t / tau)); spring N (x_N = sqrt(R d0), no elongation) lets go by the mode-mixed
  // criterion when q_x^2 / G_0 = 2 pi x_N dgamma, and every spring inside it (smaller x, the
  // same q_x) goes with it, at t* after the shear began (solved here by bisection).
  const double press = 2.25e-4 / 1.0e-3;
  const double rest = 2.0;
  const double speed = 1.0e-4;
  const double glassy = kShearRelaxed + kShearArm;  // G_0 = E_0 (G* = E*)
  const double x_n = std::sqrt(kShearRadius * 2.25e-4);
  const double threshold = std::sqrt(2.0 * std::numbers::pi * x_n * kShearDgamma * glassy);
  const auto q_x = [&](double t) {
    return kShearRelaxed * speed * t + kShearArm * speed * kShearTau * -std::expm1(-t / kShearTau);
  };
  double lo = 0.0, hi = 1.0;  // q_x(1 s) = 190 N/m > 68.6
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (q_x(mid) >= threshold ? hi : lo) = mid;
  }
  const std::string text = fmt::format(
      "[material]\neffective_modulus = {}\nwork_of_adhesion = {}\n"
      "relaxation = [ {{ modulus = {}, time = {} }} ]\n"
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = 2.25e-4 "
      "}}\nspeed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"rest\"\nduration = {}\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to = 5.0e-5 "
      "}}\nspeed = {}\n[discretization]\nsprings = 200\n[solver]\nmethod = \"event\"\n",
      kShearRelaxed, kShearDgamma, kShearArm, kShearTau, kShearRadius, rest, speed);
  LetGoTimes let_gos;
  ObserverList observers;
  observers.add(let_gos);
  const RunResult r = run_scene(
      SceneDocument::from_text(text, "shear_off.toml").build(Registries::builtin()), observers);
  ASSERT_EQ(let_gos.times.size(), 200u);
  const double t_star = hi;
  const double found = let_gos.times.front() - press - rest;
  std::printf("shear-off of the relaxed glue: t* = %.15e s (closed form %.15e, %.1e)\n", found,
              t_star, std::abs(found / t_star - 1.0));
  // The clock's rounding at t ~ 2.4 s is ~4e-16 s; the row's sums of q_x round at a few eps.
  EXPECT_NEAR(found, t_star, 1e-12 * t_star);
  EXPECT_EQ(let_gos.times.back(), let_gos.times.front());  // one cascade
  // The springs lose their glue but stay pressed, pushing only: the contact is in place at the
  // end, as the elastic program row's is after the same shear.
  EXPECT_EQ(r.status, RunStatus::completed);
  EXPECT_EQ(r.stages.back().end.springs_in_contact, 200);
  EXPECT_EQ(r.stages.back().end.tangential_force, 0.0);
}

/// Touches and lifts in order, with their times.
class TouchesAndLifts : public Observer {
 public:
  void on_event(const Event& e) override {
    if (e.kind == EventKind::spring_touched || e.kind == EventKind::spring_lifted) {
      kinds.push_back(e.kind);
      times.push_back(e.state.time);
    }
  }
  /// Lifts followed at once by a touch at the same time (a contact of no duration).
  int chatter() const {
    int n = 0;
    for (std::size_t i = 1; i < kinds.size(); ++i) {
      n += kinds[i - 1] == EventKind::spring_lifted && kinds[i] == EventKind::spring_touched &&
           times[i - 1] == times[i];
    }
    return n;
  }
  std::vector<EventKind> kinds;
  std::vector<double> times;
};

TEST(ViscoelasticTangential, ARepressAfterAShearSettlesUnderEveryCriterion) {
  // Press, shear, withdraw to separation with u_x moving back, press again while shearing (the
  // springs that let go only push without rebinding, glue again with it), pull until
  // separation while shearing; two Prony terms, dgamma_a = 0.02. A spring whose load reaches
  // zero where the rounding of the time leaves it a hair inside the indenter must not be lifted
  // and touched again at one instant (it did, until the event limit stopped the stage); every
  // stage balances to rounding.
  const std::string base =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.02\n"
      "relaxation = [ { modulus = 4.0e6, time = 0.1 }, { modulus = 5.0e6, time = 0.01 } ]\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = 2.25e-4 }\n"
      "speed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = { control = \"fixed-grips\", to = 6.0e-6 "
      "}\nspeed = 1.0e-4\n"
      "[[loading.stage]]\nname = \"back\"\nnormal = { to = 0.5e-4 }\ntangential = { to = -3.0e-6 "
      "}\nduration = 0.3\n"
      "[[loading.stage]]\nname = \"again\"\nnormal = { to = 2.0e-4 }\ntangential = { to = 4.0e-6 "
      "}\nduration = 0.2\n"
      "[[loading.stage]]\nname = \"pull\"\nnormal = { by = -1.0e-3 }\ntangential = { by = 2.0e-5 "
      "}\nuntil = \"separation\"\nduration = 1.0\n"
      "[discretization]\nsprings = 400\n[solver]\nmethod = \"event\"\n";
  for (const char* criterion :
       {"mode-mixed", "deformation", "stress", "normal-only", "mode-dependent"}) {
    for (const bool rebinding : {false, true}) {
      std::string text = base + fmt::format("[detachment]\ncriterion = \"{}\"\n", criterion);
      if (std::string(criterion) == "mode-dependent") text += "lambda = 0.3\n";
      text += fmt::format("[loading]\nrebinding = {}\n", rebinding ? "true" : "false");
      TouchesAndLifts events;
      ObserverList observers;
      observers.add(events);
      const RunResult r = run_scene(
          SceneDocument::from_text(text, "repress.toml").build(Registries::builtin()), observers);
      double worst = 0.0;
      for (const StageRecord& s : r.stages) {
        const EnergyBalance& e = *s.energy;
        const double scale = std::abs(e.machine_work) + std::abs(e.stored_change) +
                             std::abs(e.surface_change) + std::abs(e.dissipated_by_bulk) +
                             std::abs(e.jump_losses);
        worst = std::max(worst, std::abs(e.residual) / scale);
      }
      std::printf(
          "repress, %s, rebinding %d: status %d, %zu stages, %zu touches and lifts, %d "
          "at once, worst residual %.1e of its stage\n",
          criterion, rebinding, static_cast<int>(r.status), r.stages.size(), events.kinds.size(),
          events.chatter(), worst);
      EXPECT_EQ(r.status, RunStatus::instability) << criterion << rebinding;
      EXPECT_EQ(r.stages.size(), 5u) << criterion << rebinding;
      EXPECT_EQ(events.chatter(), 0) << criterion << rebinding;
      EXPECT_LE(worst, 1e-12) << criterion << rebinding;
    }
  }
}

TEST(ViscoelasticTangential, EveryStageOfAShearThenPullOffBalances) {
  // A viscous shear-then-pull-off (the arm 9 E_inf, every stage a few tau): each stage's
  // machine work (normal + tangential) = stored change + surface + dissipated + jump losses,
  // to the rounding of sums of ~1e3 terms of that size.
  for (const double ux : {4.0e-6, 1.5e-5}) {
    const ShearPull c{2.25e-4, 1.0e-3, ux, 1.0e-4, 0.2, 1.0e-3, 200};
    const RunResult r = run_text(shear_pull_text(c, kShearRelaxed, kShearArm, kShearDgamma));
    ASSERT_EQ(r.stages.size(), 4u);
    for (const StageRecord& s : r.stages) {
      ASSERT_TRUE(s.energy);
      const EnergyBalance& e = *s.energy;
      const double scale = std::abs(e.machine_work) + std::abs(e.stored_change) +
                           std::abs(e.surface_change) + std::abs(e.dissipated_by_bulk) +
                           std::abs(e.jump_losses);
      std::printf(
          "balance u_x = %g, %s: work %.6e (tangential %.6e), dissipated %.6e, jumps %.6e, "
          "residual %.1e of %.1e\n",
          ux, s.name.c_str(), e.machine_work, s.work.tangential, e.dissipated_by_bulk,
          e.jump_losses, e.residual, scale);
      EXPECT_LE(std::abs(e.residual), 1e-12 * scale) << s.name;
      EXPECT_GE(e.dissipated_by_bulk, -1e-12 * scale) << s.name;
      EXPECT_GE(e.jump_losses, -1e-12 * scale) << s.name;
    }
    // The shear stage's work is the tangential machine's.
    EXPECT_GT(r.stages[1].work.tangential, 0.0);
    EXPECT_EQ(r.stages[1].work.normal, 0.0);
  }
}

TEST(ViscoelasticTangential, SlowAndFastShearThenPullOffMeetTheElasticLimits) {
  // Slow (1e-7 m/s, every stage >> tau): the elastic program of E_inf (G_inf) with dgamma E_0 /
  // E_inf, to the rounding of the steady arm stress's approach (header). Fast (100 m/s, the
  // program ~1e-7 s = 1e-6 tau): the elastic program of E_0 (G_0) with dgamma, to the arms'
  // relaxation over it. Both at the same row (spring N at the preload's radius, gluing on
  // touch).
  const double glassy = kShearRelaxed + kShearArm;
  std::printf("shear then pull-off: pull-off [N] against the elastic limits\n");
  for (const std::int64_t n : {200, 400}) {
    const ShearPull slow{2.25e-4, 1.0e-7, 4.0e-6, 1.0e-7, 0.0, 1.0e-7, n};
    const RunResult v_slow =
        run_text(shear_pull_text(slow, kShearRelaxed, kShearArm, kShearDgamma));
    const RunResult e_slow =
        run_text(shear_pull_text(slow, kShearRelaxed, 0.0, kShearDgamma * glassy / kShearRelaxed));
    const ShearPull fast{9.0e-6, 100.0, 1.0e-6, 100.0, 0.0, 100.0, n};
    const RunResult v_fast =
        run_text(shear_pull_text(fast, kShearRelaxed, kShearArm, kShearDgamma));
    const RunResult e_fast = run_text(shear_pull_text(fast, glassy, 0.0, kShearDgamma));
    ASSERT_TRUE(v_slow.peak && e_slow.peak && v_fast.peak && e_fast.peak);
    const double slow_v = v_slow.peak->normal_force, slow_e = e_slow.peak->normal_force;
    const double fast_v = v_fast.peak->normal_force, fast_e = e_fast.peak->normal_force;
    std::printf(
        "  N = %lld slow %.14e (E_inf elastic %.14e, %.1e), fast %.14e (E_0 elastic "
        "%.14e, %.1e)\n",
        static_cast<long long>(n), slow_v, slow_e, std::abs(slow_v / slow_e - 1.0), fast_v, fast_e,
        std::abs(fast_v / fast_e - 1.0));
    EXPECT_NEAR(slow_v, slow_e, 1e-9 * std::abs(slow_e));
    // The arms relax by ~t / tau = 1e-6 of the glassy load over the fast program.
    EXPECT_NEAR(fast_v, fast_e, 1e-5 * std::abs(fast_e));
    EXPECT_EQ(v_slow.status, e_slow.status);
    EXPECT_EQ(v_fast.status, e_fast.status);
  }
}

}  // namespace
}  // namespace mdrsim
