// Tangential stages under a held tangential force (normal fixed grips) on the viscoelastic row,
// run by `mdrsim run`'s path, against derivations written here (no engine code).
//
// The derivations. The MDR's springs do not couple the axes: under normal fixed grips the depth
// is prescribed and only the glued springs' tangential arms see F_x. A spring glued at u_x = u_g
// carries q_x = G_inf (u_x - u_g) + s, s' = G_1 u_x' - s / tau, and the n glued springs together
// carry F_x = 2 dx sum q_x. So:
// - with E_1 -> 0 (G_1 = E_1 G* / E* -> 0) the row is the elastic program of (E_inf, G_inf):
//   every load differs by that share;
// - n springs glued and none changing are one standard linear solid of stiffness k(t) =
//   2 a [G_inf + G_1 exp(-t / tau)], a = n dx: a ramp of F_x from 0 to F over T then a hold
//   creeps with the compliance J(t) = 1/k_inf - (1/k_inf - 1/k_0) exp(-t / tau_r), k_inf = 2 a
//   G_inf, k_0 = 2 a G_0, tau_r = tau G_0 / G_inf, so u_x(t) = int_0^T J(t - s) F/T ds =
//   F/k_inf - (1/k_inf - 1/k_0) (F/T) tau_r [exp(-(t - T)/tau_r) - exp(-t/tau_r)] for t >= T.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kSfRadius = 0.01;                    // R [m]
constexpr double kSfRelaxed = 1.0e6;                  // E*_inf = G*_inf [Pa] (G* = E*)
constexpr double kSfArm = 9.0e6;                      // E*_1 [Pa]
constexpr double kSfTau = 0.1;                        // [s]
constexpr double kSfDgamma = 0.05;                    // [J/m^2]
constexpr double kSfVanishing = 1.0e-9 * kSfRelaxed;  // E*_1 [Pa] that is nearly none

/// A parabola of material (E*_inf, one arm `arm` unless 0, dgamma), mode-mixed, `stages`.
std::string shear_force_text(double arm, const std::string& stages, std::int64_t springs) {
  std::string text = fmt::format("[material]\neffective_modulus = {}\nwork_of_adhesion = {}\n",
                                 kSfRelaxed, kSfDgamma);
  if (arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", arm, kSfTau);
  }
  text += fmt::format("[profile]\ntype = \"parabolic\"\nradius = {}\n", kSfRadius);
  text += "[detachment]\ncriterion = \"mode-mixed\"\n";
  text += stages;
  text += fmt::format("[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n", springs);
  return text;
}

RunResult run_shear_force(const std::string& text) {
  return run_scene(SceneDocument::from_text(text, "sf.toml").build(Registries::builtin()), {});
}

std::string shear_force_stage(const std::string& name, const std::string& body) {
  return fmt::format("[[loading.stage]]\nname = \"{}\"\n{}", name, body);
}

struct ShearForceProgram {
  std::string name;
  std::string stages;
};

/// Pressed under fixed grips to `depth`, held, F_x ramped to `force`, held, then (unless the
/// ramp shears it off) pulled off under fixed grips with F_x held.
ShearForceProgram shear_force_program(double depth, double force, bool pull) {
  std::string stages =
      shear_force_stage("press", fmt::format("normal = {{ control = \"fixed-grips\", to = {} }}\n"
                                             "speed = 1.0e-3\n",
                                             depth)) +
      shear_force_stage("hold", "duration = 1.0\n") +
      shear_force_stage("shear",
                        fmt::format("tangential = {{ control = \"fixed-load\", to = {} }}\n"
                                    "duration = 0.05\n",
                                    force)) +
      shear_force_stage("creep", "duration = 0.5\n");
  if (pull) {
    stages += shear_force_stage("pull",
                                "normal = { control = \"fixed-grips\", by = -1.0e-3 }\n"
                                "until = \"separation\"\nspeed = 1.0e-3\n");
  }
  return {fmt::format("d = {}, F_x = {}{}", depth, force, pull ? ", pulled off" : ""), stages};
}

/// Pressed, sheared by F_x = `force`, held and pulled off under a held normal control: a fixed
/// load (`machine` false) or a machine spring of 2000 N/m.
ShearForceProgram held_normal_program(bool machine, double force) {
  const std::string press =
      machine ? "normal = { control = \"compliant\", stiffness = 2000.0, by = 3.0e-4 }\n"
                "duration = 0.3\n"
              : "normal = { control = \"fixed-load\", to = 0.2 }\nduration = 0.5\n";
  const std::string pull =
      machine ? "normal = { control = \"compliant\", stiffness = 2000.0, by = -1.0 }\n"
                "until = \"separation\"\nduration = 1000.0\n"
              : "normal = { control = \"fixed-load\", by = -1.0 }\nuntil = \"separation\"\n"
                "duration = 10.0\n";
  const std::string stages =
      shear_force_stage("press", press) +
      shear_force_stage("shear",
                        fmt::format("tangential = {{ control = \"fixed-load\", to = {} }}\n"
                                    "duration = 0.05\n",
                                    force)) +
      shear_force_stage("creep", "duration = 0.5\n") + shear_force_stage("pull", pull);
  return {fmt::format("{}, F_x = {}, pulled off", machine ? "machine spring" : "fixed load", force),
          stages};
}

/// Pressed (normal fixed grips, or a fixed load of 0.2 N), u_x driven through a tangential
/// machine spring of 2000 N/m whose end moves to 10 um, held, pulled off.
ShearForceProgram tangential_spring_program(bool held_normal) {
  const std::string press =
      held_normal ? "normal = { control = \"fixed-load\", to = 0.2 }\nduration = 0.5\n"
                  : "normal = { control = \"fixed-grips\", to = 2.25e-4 }\nspeed = 1.0e-3\n";
  const std::string pull =
      held_normal ? "normal = { control = \"fixed-load\", by = -1.0 }\nuntil = \"separation\"\n"
                    "duration = 10.0\n"
                  : "normal = { control = \"fixed-grips\", by = -1.0e-3 }\n"
                    "until = \"separation\"\nspeed = 1.0e-3\n";
  const std::string stages =
      shear_force_stage("press", press) +
      shear_force_stage("shear",
                        "tangential = { control = \"compliant\", stiffness = 2000.0, to = 1.0e-5 "
                        "}\nduration = 0.05\n") +
      shear_force_stage("creep", "duration = 0.5\n") + shear_force_stage("pull", pull);
  return {fmt::format("tangential machine spring, normal {}", held_normal ? "fixed load" : "grips"),
          stages};
}

/// Every program of the tests: normal fixed grips, then held normal controls.
std::vector<ShearForceProgram> shear_force_programs() {
  return {
      // F_x held through the pull-off: the glue goes while springs stay pressed (sliding).
      shear_force_program(2.25e-4, 0.01, true),
      // A small F_x: the pull-off parts the contact in tension.
      shear_force_program(2.25e-5, 1.0e-3, true),
      // F_x beyond what the glue carries: the ramp shears it off.
      shear_force_program(2.25e-5, 0.05, false),
      held_normal_program(false, 0.01),
      held_normal_program(false, 1.0e-3),
      held_normal_program(true, 0.01),
      held_normal_program(true, 1.0e-3),
      tangential_spring_program(false),
      tangential_spring_program(true),
  };
}

TEST(ViscoelasticShearForce, AVanishingArmIsTheElasticProgramUnderAHeldTangentialForce) {
  // E_1 = 1e-9 E_inf: every load differs from the elastic row's by that share, so every state
  // the two report agrees to 1e-9 of the path's largest force (u_x to 1e-9 of the largest u_x:
  // it is a held force over a stiffness that differs by that share); counts, statuses and
  // jumps equal, by_shear included (the shear-off ramp's jump is one).
  const std::vector<ShearForceProgram> programs = shear_force_programs();
  std::printf("vanishing arm under a held F_x: largest gap to the elastic program / F_max\n");
  for (const ShearForceProgram& p : programs) {
    SCOPED_TRACE(p.name);
    const RunResult v = run_shear_force(shear_force_text(kSfVanishing, p.stages, 300));
    const RunResult e = run_shear_force(shear_force_text(0.0, p.stages, 300));
    ASSERT_EQ(v.stages.size(), e.stages.size());
    ASSERT_EQ(v.critical.has_value(), e.critical.has_value());
    double scale = 0.0;
    double ux_scale = 0.0;
    for (const StageRecord& s : e.stages) {
      scale = std::max({scale, std::abs(s.end.normal_force), std::abs(s.end.tangential_force)});
      ux_scale = std::max(ux_scale, std::abs(s.end.tangential_displacement));
    }
    double gap = 0.0;
    const auto compare = [&](const ContactSnapshot& a, const ContactSnapshot& b,
                             const std::string& what, bool count = true) {
      SCOPED_TRACE(what);
      gap = std::max({gap, std::abs(a.normal_force - b.normal_force) / scale,
                      std::abs(a.tangential_force - b.tangential_force) / scale});
      EXPECT_NEAR(a.normal_force, b.normal_force, 1e-9 * scale);
      EXPECT_NEAR(a.tangential_force, b.tangential_force, 1e-9 * scale);
      EXPECT_NEAR(a.tangential_displacement, b.tangential_displacement, 1e-9 * ux_scale);
      // Depths are differences of the images' size: 1e-9 of the deepest.
      EXPECT_NEAR(a.indentation, b.indentation, 1e-9 * 2.25e-4);
      if (count) {
        EXPECT_EQ(a.springs_in_contact, b.springs_in_contact);
      }
    };
    if (v.critical) compare(*v.critical, *e.critical, "critical");
    for (std::size_t i = 0; i < v.stages.size(); ++i) {
      // The press ends under fixed grips at the row's spring N, whose image is its depth: the
      // elastic row counts it, the viscoelastic row's touch falls a rounding of the time beyond
      // the stage's end (as without a shear); the hold after it takes it.
      compare(v.stages[i].end, e.stages[i].end, v.stages[i].name, i > 0);
    }
    EXPECT_EQ(v.status, e.status);
    EXPECT_EQ(v.sliding, e.sliding);
    ASSERT_EQ(v.jumps.size(), e.jumps.size());
    for (std::size_t i = 0; i < v.jumps.size(); ++i) {
      EXPECT_EQ(v.jumps[i].inward, e.jumps[i].inward) << i;
      EXPECT_EQ(v.jumps[i].end, e.jumps[i].end) << i;
      EXPECT_EQ(v.jumps[i].springs, e.jumps[i].springs) << i;
      EXPECT_EQ(v.jumps[i].glued_springs, e.jumps[i].glued_springs) << i;
      EXPECT_EQ(v.jumps[i].by_shear, e.jumps[i].by_shear) << i;
      compare(v.jumps[i].critical, e.jumps[i].critical, "jump");
    }
    std::printf("  %-44s %.2e (status %d, %zu jumps, critical F %.10e / %.10e)\n", p.name.c_str(),
                gap, static_cast<int>(v.status), v.jumps.size(),
                v.critical ? v.critical->normal_force : 0.0,
                e.critical ? e.critical->normal_force : 0.0);
  }
}

TEST(ViscoelasticShearForce, AGluedFlatPunchCreepsAsTheStandardLinearSolid) {
  // A flat punch glued on touch (dgamma = 1e3 J/m^2: the boundary holds q_x^2 / G_0 <=
  // (F / 2a)^2 / G_0 ~ 1.6e-1 J/m^2 against 2 pi a dgamma ~ 6 J/m^2, so nothing lets go), F_x
  // ramped to F over T then held: the header's closed form at each hold's end.
  const double modulus = 1.0e6;
  const double shear_modulus = 8.0e5;  // G*_inf [Pa]
  const double arm = 9.0e6;            // E*_1 [Pa]
  const double radius = 1.0e-3;        // a [m]
  const double force = 0.05;           // F [N]
  const double ramp = 1.0e-2;          // T [s], far below tau_r = 1.125 s
  const std::vector<double> holds{0.01, 0.1, 0.3, 1.0, 3.0, 10.0};
  std::string stages =
      shear_force_stage("press",
                        "normal = { control = \"fixed-grips\", to = 1.0e-6 }\nduration = 0.01\n") +
      shear_force_stage("ramp", fmt::format("tangential = {{ control = \"fixed-load\", to = {} }}\n"
                                            "duration = {}\n",
                                            force, ramp));
  for (std::size_t i = 0; i < holds.size(); ++i) {
    stages += shear_force_stage(fmt::format("hold{}", i), fmt::format("duration = {}\n", holds[i]));
  }
  const std::string text = fmt::format(
      "[material]\neffective_modulus = {}\neffective_shear_modulus = {}\nwork_of_adhesion = "
      "1.0e3\nrelaxation = [ {{ modulus = {}, time = {} }} ]\n[profile]\ntype = "
      "\"flat_punch\"\nradius = {}\n[detachment]\ncriterion = \"mode-mixed\"\n{}"
      "[discretization]\nsprings = 200\n[solver]\nmethod = \"event\"\n",
      modulus, shear_modulus, arm, kSfTau, radius, stages);
  const RunResult r = run_shear_force(text);
  ASSERT_EQ(r.stages.size(), 2 + holds.size());
  // The glued contact: n springs of spacing dx, a = n dx.
  const ContactSnapshot& pressed = r.stages[0].end;
  const double a = pressed.contact_radius;
  ASSERT_EQ(pressed.springs_in_contact, 200);
  const double relaxed = shear_modulus;
  const double glassy = shear_modulus * (modulus + arm) / modulus;  // G_0 = G_inf + G_1
  const double k_inf = 2.0 * a * relaxed;
  const double k_0 = 2.0 * a * glassy;
  const double tau_r = kSfTau * glassy / relaxed;
  const double start = r.stages[0].end.time;
  double worst = 0.0;
  std::printf("glued flat punch under a held F_x: u_x against the SLS creep\n");
  for (std::size_t i = 1; i < r.stages.size(); ++i) {
    const ContactSnapshot& s = r.stages[i].end;
    EXPECT_EQ(s.springs_in_contact, 200);
    const double t = s.time - start;
    const double expected = force / k_inf - (1.0 / k_inf - 1.0 / k_0) * (force / ramp) * tau_r *
                                                std::exp(-(t - ramp) / tau_r) *
                                                -std::expm1(-ramp / tau_r);
    // (exp(-(t - T)/tau_r) - exp(-t/tau_r) as exp(-(t - T)/tau_r) (1 - exp(-T/tau_r)), the
    // latter by expm1: T / tau_r ~ 1e-2 would lose two digits to the difference.) During the
    // ramp u_x is a + b s + c exp(-s / tau_r) with |a|, |c| ~ (F/T) tau_r / k_inf ~ 1e2 F / k_inf
    // cancelling: some 1e-14 of F / k_inf lost there; 1e-12 leaves room for the row's sums over
    // 200 springs.
    const double error = std::abs(s.tangential_displacement - expected) / (force / k_inf);
    worst = std::max(worst, error);
    EXPECT_LT(error, 1e-12) << r.stages[i].name;
    EXPECT_NEAR(s.tangential_force, force, 1e-12 * force) << r.stages[i].name;
    std::printf("  t = %-8.4g u_x %.15e, closed form %.15e (%.1e of F/k_inf)\n", t,
                s.tangential_displacement, expected, error);
  }
  std::printf("  worst %.2e\n", worst);
}

TEST(ViscoelasticShearForce, EveryStageBalancesItsEnergy) {
  // machine_work = stored + surface + dissipated_by_bulk + jump_losses, each summed in closed
  // form (the held F_x's work int F_x du_x along u_x's exponential sum, the arms' dissipation
  // likewise, the let-gos' glassy steps of u_x): to rounding, 1e-12 of the largest term. A
  // stage's terms are differences of the run's totals, so the rounding they carry is that of
  // the totals: the largest term counts the totals so far (a shear stage's own terms, 1e-9 J,
  // sit beside a press's stored 1e-4 J).
  const std::vector<ShearForceProgram> programs = shear_force_programs();
  std::printf("held F_x on a relaxing bulk: worst energy residual / largest term per program\n");
  for (const ShearForceProgram& p : programs) {
    SCOPED_TRACE(p.name);
    const RunResult r = run_shear_force(shear_force_text(kSfArm, p.stages, 300));
    double worst = 0.0;
    EnergyBalance totals;
    double largest = 0.0;
    for (const StageRecord& s : r.stages) {
      ASSERT_TRUE(s.energy.has_value());
      const EnergyBalance& e = *s.energy;
      totals += e;
      for (const EnergyBalance& b : {e, totals}) {
        largest = std::max({largest, std::abs(b.machine_work), std::abs(b.stored_change),
                            std::abs(b.surface_change), std::abs(b.dissipated_by_bulk),
                            std::abs(b.jump_losses)});
      }
      if (largest == 0.0) continue;
      const double residual = e.machine_work - e.stored_change - e.surface_change -
                              e.dissipated_by_bulk - e.jump_losses;
      worst = std::max(worst, std::abs(residual) / largest);
      EXPECT_LT(std::abs(residual), 1e-12 * largest) << s.name;
      EXPECT_GE(e.jump_losses, -1e-12 * largest) << s.name;
    }
    std::printf("  %-44s %.2e (status %d)\n", p.name.c_str(), worst, static_cast<int>(r.status));
  }
}

}  // namespace
}  // namespace mdrsim
