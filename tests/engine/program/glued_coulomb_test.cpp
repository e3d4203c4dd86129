// glued = "coulomb" through the program engine: a glued contact sheared at fixed grips against
// Cattaneo-Mindlin with a shear strength, and the pull-off after shear against JKR (the glued
// edge carries no tangential stretch in tension, so the shear does not weaken the pull-off).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

// E* = G* = 1 MPa (nu = 0), R = 1 cm, dgamma = 0.05 J/m^2, mu = 0.4.
constexpr double kModulus = 1e6;
constexpr double kRadius = 0.01;
constexpr double kMu = 0.4;
constexpr double kA = 2e-4;                               // glued radius [m]
constexpr double kD = kA * kA / kRadius;                  // pressed to g(a) = d [m]
constexpr double kTau = 0.25 * kMu * kModulus * kD / kA;  // tau_0 [Pa]

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "scene.toml").build(registries);
}

/// Glued on touch while pressed to kD at fixed grips, then sheared at fixed grips to u.
std::string sheared(double u, std::int64_t springs) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[detachment]\ncriterion = \"normal-only\"\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {:.17g} "
      "}}\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to = "
      "{:.17g} "
      "}}\n[friction]\ncoefficient = {}\nglued = \"coulomb\"\nshear_strength = {:.17g}\n"
      "[discretization]\nsprings = {}\n",
      kD, u, kMu, kTau, springs);
}

/// The closed form (docs/friction.md): the annulus c < r < a slides at mu p + tau_0, whose MDR
/// image is mu E* (d - x^2/R) + 2 tau_0 sqrt(a^2 - x^2); with s = sqrt(a^2 - c^2) the root of
/// G* u = mu E* s^2/R + 2 tau_0 s (both halves).
double loading_force(double u) {
  const double stiff = kMu * kModulus / kRadius;
  const double s = std::min(
      (-2.0 * kTau + std::sqrt(4.0 * kTau * kTau + 4.0 * stiff * kModulus * u)) / (2.0 * stiff),
      kA);
  const double c = std::sqrt(std::max(kA * kA - s * s, 0.0));
  return 2.0 * (kModulus * u * c + stiff * (kA * kA * (kA - c) - (kA * kA * kA - c * c * c) / 3.0) +
                kTau * (std::numbers::pi * kA * kA / 2.0 - c * s - kA * kA * std::asin(c / kA)));
}

// The program's F_x at the shear stage's end on the closed form at 400 and 800 springs, within
// the row's bound 2 dx (mu E* d + 2 tau_0 a) (a sum of a monotone line load at x_i = i dx), the
// error halving with dx; past u* every spring slides and F_x = mu F_z + tau_0 pi a^2.
TEST(GluedCoulomb, ShearedGlueFollowsCattaneoMindlinWithAShearStrength) {
  const double full_slip = (kMu * kModulus * kA * kA / kRadius + 2.0 * kTau * kA) / kModulus;
  const double fz = 4.0 * kModulus * kA * kA * kA / (3.0 * kRadius);
  EXPECT_NEAR(loading_force(1.5 * full_slip), kMu * fz + kTau * std::numbers::pi * kA * kA,
              1e-12 * fz);
  std::vector<double> errors(2, 0.0);
  for (const double xi : {0.3, 0.7, 1.5}) {
    for (std::size_t j = 0; j < 2; ++j) {
      const std::int64_t n = j == 0 ? 400 : 800;
      SCOPED_TRACE(fmt::format("u/u* = {}, {} springs", xi, n));
      const RunResult r = run_scene(build(sheared(xi * full_slip, n)), {});
      ASSERT_EQ(r.status, RunStatus::completed);
      ASSERT_EQ(r.stages.size(), 2u);
      const ContactSnapshot& end = r.stages[1].end;
      EXPECT_EQ(end.springs_in_contact, n);
      const double dx = kA / static_cast<double>(n);
      const double bound = 2.0 * dx * (kMu * kModulus * kD + 2.0 * kTau * kA);
      const double exact = loading_force(xi * full_slip);
      EXPECT_NEAR(end.tangential_force, exact, bound);
      errors[j] = std::max(errors[j], std::abs(end.tangential_force - exact));
      if (xi > 1.0) {
        EXPECT_EQ(end.springs_sliding, n);
      } else {
        EXPECT_LT(end.springs_sliding, n);
        EXPECT_GT(end.springs_sliding, 0);
      }
    }
  }
  EXPECT_NEAR(std::log2(errors[0] / errors[1]), 1.0, 0.15) << errors[0] << " " << errors[1];
}

/// Fig. 3a under fixed load (glued at 2 a0, u_x held at `u`, pulled off by the mode-mixed
/// criterion) with friction and the glue `glued`.
std::string fig3a(double u, const char* glued) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[loading]\n"
      "preload = {{ contact_radius = 5.209397078678047e-4 }}\n"
      "tangential = {{ control = \"fixed-grips\", displacement = {:.17g} }}\n"
      "normal = {{ control = \"fixed-load\" }}\n[detachment]\ncriterion = \"mode-mixed\"\n"
      "[friction]\ncoefficient = 0.5\nglued = \"{}\"\n{}[discretization]\nsprings = 2000\n",
      u, glued, std::string(glued) == "coulomb" ? "shear_strength = 100.0\n" : "");
}

// Under glued = "coulomb" the glued edge's limit is mu max(f_z, 0) alone: in tension the boundary
// spring slides at zero stretch, so the criterion sees pure opening, as without shear, and the
// fixed-load pull-off is JKR's -F0 = -(3/2) pi dgamma R (within the row's 1e-3 at 2000
// springs), the same to rounding whether the contact was sheared by d0 or not. The paper's
// unlimited glue carries the shear to its edge and lets go earlier: -0.9366 F0 at d0 (Fig. 3a,
// scenes/fig3a_fixed_load.toml; measured -0.9374 F0 here at 2000 springs), 6 % short.
TEST(GluedCoulomb, AShearedCoulombGlueKeepsItsPullOff) {
  const double f0 = 1.5 * std::numbers::pi * 0.05 * kRadius;
  const double d0 = 2.2614848269449475e-6;
  const RunResult unsheared = run_scene(build(fig3a(0.0, "coulomb")), {});
  const RunResult sheared = run_scene(build(fig3a(d0, "coulomb")), {});
  const RunResult paper = run_scene(build(fig3a(d0, "unlimited")), {});
  for (const RunResult* r : {&unsheared, &sheared, &paper}) {
    ASSERT_EQ(r->status, RunStatus::instability);
    ASSERT_TRUE(r->critical);
  }
  EXPECT_NEAR(unsheared.critical->normal_force / f0, -1.0, 1e-3);
  EXPECT_NEAR(sheared.critical->normal_force, unsheared.critical->normal_force, 1e-9 * f0);
  EXPECT_NEAR(paper.critical->normal_force / f0, -0.9366, 2e-3);
}

}  // namespace
}  // namespace mdrsim
