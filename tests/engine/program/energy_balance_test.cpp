// The energy balance of a program's stages (docs/outputs.md "energy"): each term computed on its
// own, the residual rounding, the jump losses never negative, and the terms against closed forms:
// the surface a glue takes and gives back, a JKR cycle's loop, the glue peeling under friction.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

// R = 1 cm, E* = G* = 1 MPa, dgamma = 0.05 J/m^2; 12 d0: glued on touch at a_g = 2 a0.
constexpr double kRadius = 0.01;
constexpr double kModulus = 1e6;
constexpr double kWork = 0.05;
constexpr double kDepth = 2.713781792333937e-5;
constexpr int kSprings = 4000;

RunResult run_text(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return run_scene(SceneDocument::from_text(text, "energy.toml").build(registries), {});
}

/// A glued sphere sheared under fixed grips by 4e-5 m with d held (the scene:
/// scenes/programs/adhesion_to_friction_chi_*.toml), `friction` the [friction] table's keys.
std::string shear_scene(const std::string& friction, int springs = kSprings) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[[loading.stage]]\nname = \"glue\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\n[[loading.stage]]\nname = "
      "\"shear\"\ntangential = {{ control = \"fixed-grips\", by = 4.0e-5 }}\n[friction]\n{}\n"
      "[discretization]\nsprings = {}\n",
      kDepth, friction, springs);
}

/// The size of the balance's terms: its rounding is relative to it.
double scale_of(const EnergyBalance& e) {
  return std::abs(e.machine_work) + std::abs(e.stored_change) + std::abs(e.surface_change) +
         e.dissipated_by_friction + std::abs(e.jump_losses);
}

// Each term is a sum over at most a few thousand events or springs (trapezoids, compensated
// sums, the stored energy's expanded squares), each good to a few eps of the scale: 1e-12 of it
// is a thousand times that, and 1e3 below the smallest term the tests tell apart (O(1/N)).
constexpr double kRounding = 1e-12;

/// Every stage's and the total balance closes to rounding and loses no negative energy; the
/// total is the stages' sum.
void expect_closes(const RunResult& r) {
  ASSERT_TRUE(r.energy);
  EnergyBalance sum;
  for (const StageRecord& s : r.stages) {
    SCOPED_TRACE(s.name);
    ASSERT_TRUE(s.energy);
    const EnergyBalance& e = *s.energy;
    EXPECT_NEAR(e.residual, 0.0, kRounding * scale_of(e));
    EXPECT_GE(e.jump_losses, -kRounding * scale_of(e));
    EXPECT_EQ(e.machine_work, s.work.normal + s.work.tangential);
    EXPECT_EQ(e.dissipated_by_friction, s.work.friction);
    sum += e;
  }
  EXPECT_NEAR(r.energy->machine_work, sum.machine_work, kRounding * scale_of(sum));
  EXPECT_NEAR(r.energy->jump_losses, sum.jump_losses, kRounding * scale_of(sum));
  EXPECT_NEAR(r.energy->residual, 0.0, kRounding * scale_of(*r.energy));
}

/// The row's glued surface at a_g: sum of 2 pi x_i dgamma dx over i <= N, x_i = i a_g / N, is
/// pi a_g^2 dgamma (1 + 1/N).
double glued_disk_surface() { return std::numbers::pi * kRadius * kDepth * kWork; }

/// The glue peeling under friction (docs/friction.md "From adhesion to sliding friction"): the
/// front's spring at c lets go where u - mu (E*/G*) (d - g(c)) reaches sqrt(2 pi c dgamma / G*),
/// F_x = 2 [G* c u + mu E* int_c^a (d - g) dx]; under fixed grips the front recedes while u
/// rises, and the rest of the glue breaks where u(c) is largest, at c*^(3/2) = R / (4 mu)
/// sqrt(2 pi dgamma / G*) (E* = G*).
struct Peeling {
  double mu;
  double a = std::sqrt(kRadius * kDepth);
  double u_at(double c) const {
    return mu * (a * a - c * c) / kRadius +
           std::sqrt(2.0 * std::numbers::pi * c * kWork / kModulus);
  }
  double force_at(double c) const {
    return 2.0 * (kModulus * c * u_at(c) +
                  mu * kModulus / kRadius * (a * a * (a - c) - (a * a * a - c * c * c) / 3.0));
  }
  double breaking_front() const {
    return std::pow(kRadius / (4.0 * mu) * std::sqrt(2.0 * std::numbers::pi * kWork / kModulus),
                    2.0 / 3.0);
  }
};

// The scene: sheared past the glue's strength, the broken glue creates pi a_g^2 dgamma of
// surface (to O(1/N): bound 1.5/N), which the machine pays; the glue taken on touch lost as much.
// The rest of the glue breaks where the peeling's u_x is largest: u and F_x there within 2/N
// (the row's front moves by spacings). With a pressed spring's glue let go by its whole stretch,
// friction keeping it, the break came at u_c = 1.28e-5 m and the shear's jump losses were
// -3.5e-8 J: energy out of nothing.
TEST(EnergyBalance, GlueShearedIntoFrictionPaysItsSurface) {
  for (const double mu : {1.0, 0.5}) {
    SCOPED_TRACE(mu);
    const RunResult r = run_text(shear_scene(fmt::format("coefficient = {}", mu)));
    expect_closes(r);
    ASSERT_EQ(r.stages.size(), 2u);
    const EnergyBalance& glue = *r.stages[0].energy;
    const EnergyBalance& shear = *r.stages[1].energy;
    EXPECT_NEAR(shear.surface_change, glued_disk_surface(), 1.5 / kSprings * glued_disk_surface());
    EXPECT_NEAR(glue.surface_change, -shear.surface_change, kRounding * scale_of(glue));
    EXPECT_NEAR(glue.jump_losses, -glue.surface_change, kRounding * scale_of(glue));
    EXPECT_GT(shear.dissipated_by_friction, 0.0);
    EXPECT_EQ(r.stages[1].end.glued_radius, 0.0);
    const Peeling p{.mu = mu};
    const double c = p.breaking_front();
    ASSERT_FALSE(r.jumps.empty());
    const auto& jump = r.jumps.back();
    EXPECT_NEAR(jump.critical.tangential_displacement, p.u_at(c), 2.0 / kSprings * p.u_at(c));
    EXPECT_NEAR(jump.critical.tangential_force, p.force_at(c), 2.0 / kSprings * p.force_at(c));
    EXPECT_NEAR(jump.critical.glued_radius, c, 0.05 * c);  // the fold is flat in c
  }
}

// Without friction (no [friction] table) the glue lets go by its whole stretch, which its
// frictionless spring then releases: the shear's jump losses are positive.
TEST(EnergyBalance, GlueShearedWithoutFrictionCloses) {
  std::string text = shear_scene("");
  text.erase(text.find("[friction]"), std::string("[friction]\n\n").size());
  const RunResult r = run_text(text);
  expect_closes(r);
  EXPECT_NEAR(r.stages[1].energy->surface_change, glued_disk_surface(),
              1.5 / kSprings * glued_disk_surface());
  EXPECT_GT(r.stages[1].energy->jump_losses, 0.1 * glued_disk_surface());
}

// glued = "coulomb": the glued springs slide at their limit, the edge (no normal force) at none,
// so nothing lets go; the balance closes with the slides' dissipation (1000 springs: a glued
// `coulomb` row costs O(N^2)).
TEST(EnergyBalance, CoulombGlueCloses) {
  const RunResult r = run_text(shear_scene("coefficient = 1.0\nglued = \"coulomb\"", 1000));
  expect_closes(r);
  EXPECT_GT(r.stages[1].energy->dissipated_by_friction, 0.0);
}

// glued = "coulomb" with a shear strength: pressed to d = a^2/R at a = 2e-4 m, sheared past
// full slip (u* = (mu E* a^2/R + 2 tau_0 a)/E* = 2.4e-6 m), back to -u*/2 and retracted until
// separation: the glued springs slide pressed (mu f_z + c_i) and in tension (c_i alone), change
// class as d falls past their images, and every let-go shrinks every c_i. The stored energy
// counts each class's sliders at their limits; by symmetry the reversal's full slip stores what
// the forward one did.
TEST(EnergyBalance, CoulombGlueWithAShearStrengthCloses) {
  const std::string text =
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[[loading.stage]]\nname = \"press\"\n"
      "normal = { control = \"fixed-grips\", to = 4.0e-6 }\n[[loading.stage]]\nname = "
      "\"shear\"\ntangential = { control = \"fixed-grips\", to = 3.6e-6 }\n[[loading.stage]]\n"
      "name = \"back\"\ntangential = { control = \"fixed-grips\", to = -1.2e-6 }\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = { by = -2.0e-5 }\nuntil = "
      "\"separation\"\n[friction]\ncoefficient = 0.4\nglued = \"coulomb\"\n"
      "shear_strength = 2000.0\n[discretization]\nsprings = 400\n";
  const RunResult r = run_text(text);
  expect_closes(r);
  ASSERT_EQ(r.stages.size(), 4u);
  const EnergyBalance& shear = *r.stages[1].energy;
  const EnergyBalance& back = *r.stages[2].energy;
  EXPECT_GT(shear.stored_change, 0.0);
  EXPECT_GT(back.dissipated_by_friction, 0.0);
  EXPECT_NEAR(back.stored_change, 0.0, kRounding * scale_of(back));
  EXPECT_GT(r.stages[3].energy->dissipated_by_friction, 0.0);
  EXPECT_EQ(r.stages[3].end.glued_radius, 0.0);
}

// A JKR cycle without friction: glued on touch to 12 d0 at fixed grips, retracted until
// separation. Nothing is stored or glued at the end, so the machine's work is all jump losses:
// the glue taken on touch, pi a_max^2 dgamma, and the jump out of the fold of d(a) = a^2/R -
// sqrt(2 pi a dgamma / E*), at a_f^(3/2) = (R/4) sqrt(2 pi dgamma / E*), of its stored energy
// U_f = E* int_0^a_f (d_f - x^2/R)^2 dx less the surface it creates, pi a_f^2 dgamma (the peel
// in between loses only O(1/N)). Bound 4/N.
TEST(EnergyBalance, JkrCycleLosesItsLoopEnergyInJumps) {
  const std::string text = fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[[loading.stage]]\nname = \"approach\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\n[[loading.stage]]\nname = "
      "\"retract\"\nnormal = {{ by = {:.17g} }}\nuntil = \"separation\"\n"
      "[discretization]\nsprings = {}\n",
      kDepth, -kDepth, kSprings);
  const RunResult r = run_text(text);
  expect_closes(r);
  const double pi = std::numbers::pi;
  const double a_f = std::pow(kRadius / 4.0 * std::sqrt(2.0 * pi * kWork / kModulus), 2.0 / 3.0);
  const double d_f = a_f * a_f / kRadius - std::sqrt(2.0 * pi * a_f * kWork / kModulus);
  const double stored =
      kModulus * (d_f * d_f * a_f - 2.0 * d_f * std::pow(a_f, 3) / (3.0 * kRadius) +
                  std::pow(a_f, 5) / (5.0 * kRadius * kRadius));
  const double loop = glued_disk_surface() + stored - pi * a_f * a_f * kWork;
  const EnergyBalance& e = *r.energy;
  EXPECT_NEAR(e.stored_change, 0.0, kRounding * scale_of(e));
  EXPECT_NEAR(e.surface_change, 0.0, kRounding * scale_of(e));
  EXPECT_NEAR(e.jump_losses, e.machine_work, kRounding * scale_of(e));
  EXPECT_NEAR(e.jump_losses, loop, 4.0 / kSprings * loop);
  EXPECT_NEAR(r.stages[0].energy->jump_losses, glued_disk_surface(),
              1.5 / kSprings * glued_disk_surface());
}

// Held forces and a machine spring: a glue sheared under a held F_x that slides away (the stage
// ends at the flight's start, with its stored energy there), and the JKR cycle through a
// compliant machine, whose spring's energy is part of what is stored.
TEST(EnergyBalance, HeldForcesAndMachineSpringsClose) {
  std::string held = shear_scene("coefficient = 0.5");
  held.replace(held.find("control = \"fixed-grips\", by = 4.0e-5"),
               std::string("control = \"fixed-grips\", by = 4.0e-5").size(),
               "control = \"fixed-load\", to = 0.015");
  const RunResult sliding = run_text(held);
  EXPECT_TRUE(sliding.sliding);
  expect_closes(sliding);
  const std::string compliant = fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[[loading.stage]]\nname = \"approach\"\n"
      "normal = {{ control = \"compliant\", stiffness = 200.0, to = {:.17g} }}\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = {{ by = {:.17g} }}\n"
      "until = \"separation\"\n[discretization]\nsprings = 2000\n",
      3.0 * kDepth, -3.0 * kDepth);
  const RunResult r = run_text(compliant);
  expect_closes(r);
  EXPECT_GT(r.energy->jump_losses, 0.0);
}

}  // namespace
}  // namespace mdrsim
