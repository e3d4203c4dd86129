// The energy the receding front releases, against the surface and shear energies in closed form.
#include "engine/continuum/continuum_work.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "controllers/builtin_controllers.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "detachment/normal_only_criterion.hpp"
#include "profiles/parabolic_profile.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

// Normal-only (e^2 = w x, w = 2 pi dgamma / E*) under a tangential fixed load H (u_x = H /
// (2 G* x)): int E* e^2 + G* u_x^2 dx from a down to b is pi dgamma (a^2 - b^2) +
// H^2 (1/b - 1/a) / (4 G*). The estimate covers the difference (plus 1e-15 of the closed
// form's own rounding) and stays within 1e-13 of the value: both parts are smooth in x.
TEST(ContinuumWork, ReleasedEnergyIsTheSurfaceAndShearEnergy) {
  const Material m = Material::from_youngs_modulus(1e6, 0.3, 0.05);
  const ParabolicProfile profile(0.01);
  const NormalOnlyCriterion criterion(m);
  const double held = 2e-3;  // [N]
  const ContinuumBranch branch(profile, criterion, m, FixedLoadController().constraint(),
                               FixedLoadController().constraint(), held);
  for (const auto& [from, to] : {std::pair{8e-4, 1e-4}, std::pair{8e-4, 7.9e-4}}) {
    const Estimated got = released_energy(branch, from, to);
    const double want = kPi * m.work_of_adhesion * (from * from - to * to) +
                        held * held * (1.0 / to - 1.0 / from) / (4.0 * m.effective_shear_modulus);
    EXPECT_LE(std::abs(got.value - want), got.error + 1e-15 * want) << from << " to " << to;
    EXPECT_LE(got.error, 1e-13 * want);
  }
  EXPECT_EQ(released_energy(branch, 1e-4, 8e-4).value, 0.0);  // no front moves out
}

// Mode-mixed under a held u_x (fixed grips): e^2 = w x - (G*/E*) u^2 falls to 0 at the
// shear-off radius a_s = G* u^2 / (E* w), where the path ends; from a down to a_s the springs
// release E* w (a - a_s)^2 / 2 + G* u^2 (a - a_s), the estimate covering the difference.
TEST(ContinuumWork, ReleasedEnergyDownToTheShearOffRadius) {
  const Material m = Material::from_youngs_modulus(1e6, 0.3, 0.05);
  const ParabolicProfile profile(0.01);
  const ModeMixedCriterion criterion(m);
  const double u = 5e-6;  // [m]
  ContinuumBranch branch(profile, criterion, m, FixedGripsController().constraint(),
                         FixedGripsController().constraint(), u);
  const double from = 8e-4;
  ASSERT_TRUE(branch.locate_shear_off(from));
  const double w = 2.0 * kPi * m.work_of_adhesion / m.effective_modulus;
  const double as = m.effective_shear_modulus * u * u / (m.effective_modulus * w);
  EXPECT_NEAR(branch.shear_off_radius(), as, 1e-12 * as);
  const double to = branch.shear_off_radius();
  const Estimated got = released_energy(branch, from, to);
  const double want = m.effective_modulus * w * (from - to) * (from - to) / 2.0 +
                      m.effective_shear_modulus * u * u * (from - to);
  EXPECT_LE(std::abs(got.value - want), got.error + 1e-15 * want);
  EXPECT_LE(got.error, 1e-13 * want);
}

}  // namespace
}  // namespace mdrsim
