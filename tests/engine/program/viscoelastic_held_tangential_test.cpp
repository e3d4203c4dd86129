// Tangential fixed-grips stages of the viscoelastic row under a held normal control (a fixed
// load, a machine spring), and held controls after a shear, run by `mdrsim run`'s path on a
// parabola and a standard linear solid, against derivations written here (no engine code).
//
// The derivations. In the MDR every spring is independent, so u_x moves the glued springs'
// tangential arms as under fixed grips whatever the depth does: a spring glued at u_x = u_g
// carries q_x = G_inf (u_x - u_g) + s, s' = G_1 u_x' - s / tau. The depth's equation under a held
// control (kappa d + q_z = phi per unit length of a half) does not see q_x; only the let-go does,
// through the glassy criterion on (q_z, q_x). So:
// - with E_1 -> 0 the row is the elastic program of E_inf (G_inf), tangential stages and all;
// - with n springs glued and none changing, a ramp of u_x by u_0 over T then a hold gives
//   F_x(T + h) = 2 a [G_inf u_0 + G_1 (u_0 / T) tau (1 - exp(-T / tau)) exp(-h / tau)], a = n dx,
//   while the fixed load F(t) makes the n springs creep as one flat punch: with y = n d - sum g,
//   F = 2 dx (E_inf y + S), S' = n E_1 d' - S / tau, so y = int J(t - u) dF(u) / (2 dx) with the
//   standard linear solid's creep compliance J(t) = 1/E_inf - (1/E_inf - 1/E_0) exp(-t / tau_c),
//   tau_c = tau E_0 / E_inf; from a relaxed state at depth d_r and a ramp of F by -DF over T,
//   d(T + h) = d_r - (DF / (2 a T)) [T / E_inf - (1/E_inf - 1/E_0) tau_c (exp(-h / tau_c) -
//   exp(-(T + h) / tau_c))];
// - much slower than tau every arm relaxes (q_x = G_inf u_x, q_z = E_inf w + S with S common):
//   the elastic program of (E_inf, G_inf) with dgamma E_0 / E_inf; much faster, every arm is
//   glassy: the elastic program of (E_0, G_0) with dgamma.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kHtRadius = 0.01;                    // R [m]
constexpr double kHtRelaxed = 1.0e6;                  // E*_inf = G*_inf [Pa] (G* = E*)
constexpr double kHtArm = 9.0e6;                      // E*_1 [Pa]
constexpr double kHtGlassy = kHtRelaxed + kHtArm;     // E*_0 [Pa]
constexpr double kHtTau = 0.1;                        // [s]
constexpr double kHtDgamma = 0.05;                    // [J/m^2]
constexpr double kHtVanishing = 1.0e-9 * kHtRelaxed;  // E*_1 [Pa] that is nearly none

/// A scene of material (`modulus`, one arm `arm` unless 0, `dgamma`), the parabola, `stages`
/// (TOML of [[loading.stage]] tables) and `springs` springs.
std::string held_tangential_text(double modulus, double arm, double dgamma,
                                 const std::string& stages, std::int64_t springs) {
  std::string text =
      fmt::format("[material]\neffective_modulus = {}\nwork_of_adhesion = {}\n", modulus, dgamma);
  if (arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", arm, kHtTau);
  }
  text += fmt::format("[profile]\ntype = \"parabolic\"\nradius = {}\n", kHtRadius);
  text += stages;
  text += fmt::format("[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n", springs);
  return text;
}

RunResult run_held_tangential(const std::string& text) {
  return run_scene(SceneDocument::from_text(text, "ht.toml").build(Registries::builtin()), {});
}

std::string held_stage(const std::string& name, const std::string& body) {
  return fmt::format("[[loading.stage]]\nname = \"{}\"\n{}", name, body);
}

/// The press, shear and pull-off programs of the vanishing-arm comparison.
struct HeldProgram {
  std::string name;
  std::string stages;
  bool press_at_spring = false;  ///< the press ends under fixed grips at spring N's image
};

std::string held_shear(double ux) {
  return held_stage("shear", fmt::format("tangential = {{ control = \"fixed-grips\", to = {} }}\n"
                                         "duration = 0.5\n",
                                         ux));
}

std::vector<HeldProgram> held_programs() {
  const std::string load_pull =
      held_stage("pull",
                 "normal = { control = \"fixed-load\", by = -1.0 }\nuntil = \"separation\"\n"
                 "duration = 10.0\n");
  const std::string load_press =
      held_stage("press", "normal = { control = \"fixed-load\", to = 0.2 }\nduration = 0.5\n");
  std::vector<HeldProgram> programs;
  // The shears span a let-go in tension (3 um) to one near the glue's shear strength (8 um).
  for (const double ux : {3.0e-6, 8.0e-6}) {
    programs.push_back(
        {fmt::format("fixed load, u_x = {}", ux), load_press + held_shear(ux) + load_pull});
    programs.push_back(
        {fmt::format("machine spring, u_x = {}", ux),
         held_stage("press",
                    "normal = { control = \"compliant\", stiffness = 2000.0, by = 3.0e-4 "
                    "}\nduration = 0.3\n") +
             held_shear(ux) +
             held_stage("pull",
                        "normal = { control = \"compliant\", stiffness = 2000.0, by = -1.0 "
                        "}\nuntil = \"separation\"\nduration = 1000.0\n")});
    programs.push_back(
        {fmt::format("fixed grips, then a fixed load, u_x = {}", ux),
         held_stage("press",
                    "normal = { control = \"fixed-grips\", to = 2.25e-4 }\nspeed = 1.0e-3\n") +
             held_shear(ux) + load_pull,
         true});
  }
  // The glue broken during the shear under a held force: by shear at rest (0.05 N, 20 um, the
  // springs left pressed: shear-off), and in a cascade in tension (0.01 N, 12 um).
  for (const auto& [force, ux] : {std::pair{0.05, 2.0e-5}, std::pair{0.01, 1.2e-5}}) {
    programs.push_back(
        {fmt::format("sheared off under {} N, u_x = {}", force, ux),
         load_press +
             held_stage("lower", fmt::format("normal = {{ control = \"fixed-load\", to = {} }}\n"
                                             "duration = 0.5\n",
                                             force)) +
             held_shear(ux) + load_pull});
  }
  return programs;
}

double held_relative_gap(double a, double b, double scale) { return std::abs(a - b) / scale; }

TEST(ViscoelasticHeldTangential, AVanishingArmIsTheElasticProgramUnderAHeldControl) {
  // E_1 = 1e-9 E_inf: every load differs from the elastic row's by that share, so every state
  // the two report agrees to 1e-9 of the path's largest force (a force near zero is a
  // difference of such loads); counts, statuses and jumps equal.
  std::printf("vanishing arm under a held control: largest gap to the elastic program / F_max\n");
  for (const HeldProgram& p : held_programs()) {
    const RunResult v = run_held_tangential(
        held_tangential_text(kHtRelaxed, kHtVanishing, kHtDgamma, p.stages, 200));
    const RunResult e =
        run_held_tangential(held_tangential_text(kHtRelaxed, 0.0, kHtDgamma, p.stages, 200));
    SCOPED_TRACE(p.name);
    ASSERT_TRUE(v.critical && e.critical);
    ASSERT_EQ(v.peak.has_value(), e.peak.has_value());
    ASSERT_EQ(v.stages.size(), e.stages.size());
    double scale = 0.0;
    for (const StageRecord& s : e.stages) scale = std::max(scale, std::abs(s.end.normal_force));
    double gap = 0.0;
    double depth_gap = 0.0;  // [m]
    const auto compare = [&](const ContactSnapshot& a, const ContactSnapshot& b,
                             const std::string& what, bool count = true) {
      SCOPED_TRACE(what);
      gap = std::max({gap, held_relative_gap(a.normal_force, b.normal_force, scale),
                      held_relative_gap(a.tangential_force, b.tangential_force, scale)});
      depth_gap = std::max(depth_gap, std::abs(a.indentation - b.indentation));
      EXPECT_NEAR(a.normal_force, b.normal_force, 1e-9 * scale);
      EXPECT_NEAR(a.tangential_force, b.tangential_force, 1e-9 * scale);
      // Depths are differences of the images' size: 1e-9 of the deepest (3e-4 m).
      EXPECT_NEAR(a.indentation, b.indentation, 1e-9 * 3.0e-4);
      if (count) {
        EXPECT_EQ(a.springs_in_contact, b.springs_in_contact);
      }
    };
    compare(*v.critical, *e.critical, "critical");
    if (v.peak) {
      // Under a fixed load the pull-off is the held force at the let-go that loses the contact,
      // and every state of its cascade stands at it: the peak is the cascade's first, as the
      // elastic row's.
      compare(*v.peak, *e.peak, "peak");
    }
    for (std::size_t i = 0; i < v.stages.size(); ++i) {
      // A press under fixed grips ends at the row's spring N, whose image is its depth: the
      // elastic row counts it, the viscoelastic row's touch falls a rounding of the time
      // beyond the stage's end (as without a shear).
      // A contact lost at zero force (the glue broken by shear, the springs left pressed then
      // lifted as the load falls to 0): the elastic row keeps its last spring at zero load,
      // the viscoelastic row has released it.
      const bool lost_at_zero = e.stages[i].end.normal_force == 0.0;
      compare(v.stages[i].end, e.stages[i].end, v.stages[i].name,
              (i > 0 || !p.press_at_spring) && !lost_at_zero);
    }
    EXPECT_EQ(v.status, e.status);
    ASSERT_EQ(v.jumps.size(), e.jumps.size());
    for (std::size_t i = 0; i < v.jumps.size(); ++i) {
      EXPECT_EQ(v.jumps[i].inward, e.jumps[i].inward) << i;
      EXPECT_EQ(v.jumps[i].springs, e.jumps[i].springs) << i;
      compare(v.jumps[i].critical, e.jumps[i].critical, "jump");
    }
    std::printf(
        "  %-46s %.2e, depth %.1e m (critical F %.10e, elastic %.10e; status %d, %zu "
        "jumps)\n",
        p.name.c_str(), gap, depth_gap, v.critical->normal_force, e.critical->normal_force,
        static_cast<int>(v.status), v.jumps.size());
  }
}

TEST(ViscoelasticHeldTangential, AShearHeldUnderAFixedLoadRelaxesWhileTheDepthCreeps) {
  // Pressed glued on touch to d_r, relaxed 100 tau under fixed grips, then in T = 0.05 s the
  // force lowered by DF = 0.01 N under a fixed load while u_x moves to u_0 = 1 um, then held.
  // Nothing glues (d falls) and nothing lets go: the boundary's tension grows by at most
  // E_0 DF / (2 a E_0) ~ 5 N/m against sqrt(2 pi a dgamma E_0) ~ 56 N/m, and q_x^2 / G_0 <=
  // G_0 u_0^2 = 1e-5 J/m^2 against 2 pi a dgamma ~ 3e-4. So the n springs carry the header's
  // closed forms for d and F_x at each hold's end.
  const double depth = 2.25e-5;
  const double force_step = 0.01;
  const double ramp = 0.05;
  const double u0 = 1.0e-6;
  const std::vector<double> holds{0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0};
  std::string stages =
      held_stage("press", fmt::format("normal = {{ control = \"fixed-grips\", to = {} }}\nspeed = "
                                      "1.0e-3\n",
                                      depth)) +
      held_stage("relax", "duration = 10.0\n") +
      held_stage("shear",
                 fmt::format("normal = {{ control = \"fixed-load\", by = {} }}\ntangential = "
                             "{{ control = \"fixed-grips\", to = {} }}\nduration = {}\n",
                             -force_step, u0, ramp));
  for (std::size_t i = 0; i < holds.size(); ++i) {
    stages += held_stage(fmt::format("hold{}", i), fmt::format("duration = {}\n", holds[i]));
  }
  const RunResult r =
      run_held_tangential(held_tangential_text(kHtRelaxed, kHtArm, kHtDgamma, stages, 200));
  ASSERT_EQ(r.stages.size(), 3 + holds.size());
  ASSERT_TRUE(r.jumps.empty());
  const ContactSnapshot relaxed = r.stages[1].end;
  EXPECT_EQ(relaxed.indentation, depth);
  const double a = relaxed.contact_radius;
  const double tau_c = kHtTau * kHtGlassy / kHtRelaxed;
  const double rate = u0 / ramp;
  std::printf("a shear held under a fixed load (a = %.6e m, %lld springs)\n", a,
              static_cast<long long>(relaxed.springs_in_contact));
  std::printf("%8s %22s %10s %22s %10s\n", "h [s]", "d [m]", "rel. err", "F_x [N]", "rel. err");
  double h = 0.0;
  double worst_depth = 0.0;
  double worst_shear = 0.0;
  for (std::size_t i = 0; i < holds.size(); ++i) {
    h += holds[i];
    const ContactSnapshot& end = r.stages[3 + i].end;
    EXPECT_EQ(end.springs_in_contact, relaxed.springs_in_contact);
    EXPECT_NEAR(end.normal_force, relaxed.normal_force - force_step, 1e-12 * relaxed.normal_force);
    const double creep =
        ramp / kHtRelaxed - (1.0 / kHtRelaxed - 1.0 / kHtGlassy) * tau_c *
                                (std::exp(-h / tau_c) - std::exp(-(ramp + h) / tau_c));
    const double d = depth - force_step / (2.0 * a * ramp) * creep;
    const double fx = 2.0 * a *
                      (kHtRelaxed * u0 + kHtArm * rate * kHtTau * -std::expm1(-ramp / kHtTau) *
                                             std::exp(-h / kHtTau));
    const double depth_error = std::abs(end.indentation / d - 1.0);
    const double shear_error = std::abs(end.tangential_force / fx - 1.0);
    worst_depth = std::max(worst_depth, depth_error);
    worst_shear = std::max(worst_shear, shear_error);
    std::printf("%8g %22.15e %10.2e %22.15e %10.2e\n", h, end.indentation, depth_error,
                end.tangential_force, shear_error);
  }
  // Both are closed forms evaluated by the row at rounding: 1e-12.
  EXPECT_LT(worst_depth, 1e-12);
  EXPECT_LT(worst_shear, 1e-12);
  for (const StageRecord& s : r.stages) {
    const EnergyBalance& e = *s.energy;
    const double size = std::max({std::abs(e.machine_work), std::abs(e.stored_change),
                                  std::abs(e.dissipated_by_bulk), 1e-300});
    EXPECT_LT(std::abs(e.residual), 1e-12 * size) << s.name;
  }
}

/// Press under fixed grips to `depth` at `speed`, shear to `ux` at `speed`, pull off under a
/// fixed load lowered at `force_rate` [N/s] until separation.
std::string shear_then_load_pull(double depth, double ux, double speed, double force_rate) {
  return held_stage("press",
                    fmt::format("normal = {{ control = \"fixed-grips\", to = {} }}\nspeed = "
                                "{}\n",
                                depth, speed)) +
         held_stage(
             "shear",
             fmt::format("tangential = {{ control = \"fixed-grips\", to = {} }}\nspeed = {}\n", ux,
                         speed)) +
         held_stage("pull",
                    fmt::format("normal = {{ control = \"fixed-load\", by = -1.0 }}\nuntil = "
                                "\"separation\"\nduration = {}\n",
                                1.0 / force_rate));
}

TEST(ViscoelasticHeldTangential, ShearThenFixedLoadPullOffTendsToItsElasticLimits) {
  // Slow (1e-7 m/s, the force lowered at 1e-5 N/s: the arms' steady stress E_1 tau d' is
  // common to the glued springs and drops out of the force at each let-go) it is the elastic
  // program of (E_inf, G_inf) with dgamma E_0 / E_inf, to rounding (held to 1e-12); fast (100
  // m/s, 1e6 N/s: the cycle lasts ~1e-7 tau) it is the elastic program of (E_0, G_0) with
  // dgamma, up to the arms' relaxation over the cycle, ~t / tau (held to 1e-5).
  struct Limit {
    const char* name;
    double depth;       // [m]
    double ux;          // [m]
    double speed;       // [m/s]
    double force_rate;  // [N/s]
    double modulus;     // the elastic program's E* = G* [Pa]
    double dgamma;      // its work of adhesion [J/m^2]
    double tolerance;   // on the pull-off, relative
  };
  const Limit limits[] = {
      {"slow", 2.25e-4, 4.0e-6, 1.0e-7, 1.0e-5, kHtRelaxed, kHtDgamma * kHtGlassy / kHtRelaxed,
       1e-12},
      {"fast", 9.0e-6, 1.0e-6, 100.0, 1.0e6, kHtGlassy, kHtDgamma, 1e-5},
  };
  std::printf("shear then a fixed-load pull-off against the elastic limits\n");
  std::printf("%6s %8s %24s %24s %10s\n", "limit", "springs", "pull-off [N]", "elastic [N]",
              "rel. diff");
  for (const Limit& l : limits) {
    for (const std::int64_t springs : {200, 400}) {
      const std::string stages = shear_then_load_pull(l.depth, l.ux, l.speed, l.force_rate);
      const RunResult v =
          run_held_tangential(held_tangential_text(kHtRelaxed, kHtArm, kHtDgamma, stages, springs));
      const RunResult e =
          run_held_tangential(held_tangential_text(l.modulus, 0.0, l.dgamma, stages, springs));
      SCOPED_TRACE(fmt::format("{}, {} springs", l.name, springs));
      ASSERT_TRUE(v.peak && e.peak);
      ASSERT_TRUE(v.critical && e.critical);
      const double gap = std::abs(v.peak->normal_force / e.peak->normal_force - 1.0);
      std::printf("%6s %8lld %24.16e %24.16e %10.2e\n", l.name, static_cast<long long>(springs),
                  v.peak->normal_force, e.peak->normal_force, gap);
      EXPECT_LT(gap, l.tolerance);
      EXPECT_NEAR(v.critical->tangential_force, e.critical->tangential_force,
                  l.tolerance * std::abs(e.critical->tangential_force));
      EXPECT_EQ(v.critical->springs_in_contact, e.critical->springs_in_contact);
      EXPECT_EQ(v.status, e.status);
    }
  }
}

TEST(ViscoelasticHeldTangential, EveryStageBalances) {
  // machine_work + tangential_work = stored + surface + dissipated_by_bulk + jump_losses per
  // stage, each term summed in closed form apart (a held piece's tangential arms for all glued
  // springs at once): residual within 1e-12 of the stage's largest term. Programs of the
  // vanishing-arm test with the real arm, two terms, and a creep under a held shear.
  std::vector<std::string> programs;
  for (const HeldProgram& p : held_programs()) programs.push_back(p.stages);
  programs.push_back(held_stage("press",
                                "normal = { control = \"fixed-grips\", to = 5.0e-5 }\nspeed "
                                "= 1.0e-3\n") +
                     held_stage("shear",
                                "normal = { control = \"fixed-load\", by = 0.02 }\ntangential "
                                "= { control = \"fixed-grips\", to = 4.0e-6 }\nduration = "
                                "0.2\n") +
                     held_stage("hold", "duration = 0.5\n") +
                     held_stage("back",
                                "tangential = { control = \"fixed-grips\", to = -2.0e-6 "
                                "}\nduration = 0.1\n") +
                     held_stage("pull",
                                "normal = { control = \"compliant\", stiffness = 500.0, by = "
                                "-1.0 }\nuntil = \"separation\"\nduration = 100.0\n"));
  double worst = 0.0;
  for (const std::string& stages : programs) {
    for (const bool two_terms : {false, true}) {
      std::string text = held_tangential_text(kHtRelaxed, kHtArm, kHtDgamma, stages, 200);
      if (two_terms) {
        const std::string one = fmt::format("{{ modulus = {}, time = {} }}", kHtArm, kHtTau);
        text.replace(text.find(one), one.size(), one + ", { modulus = 3.0e6, time = 0.01 }");
      }
      const RunResult r = run_held_tangential(text);
      for (const StageRecord& s : r.stages) {
        const EnergyBalance& e = *s.energy;
        const double size = std::max({std::abs(e.machine_work), std::abs(e.stored_change),
                                      std::abs(e.dissipated_by_bulk), std::abs(e.surface_change),
                                      std::abs(e.jump_losses), 1e-300});
        worst = std::max(worst, std::abs(e.residual) / size);
        EXPECT_LT(std::abs(e.residual), 1e-12 * size) << s.name << "\n" << text;
      }
    }
  }
  std::printf("every stage's balance: largest residual %.2e of its stage's largest term\n", worst);
}

}  // namespace
}  // namespace mdrsim
