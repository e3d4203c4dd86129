// The closed-form scales of the cone, the power law and the flat punch against the continuum
// fold (the branch reference) and the engine's own fixed-load pull-off; the parabola's are
// eq. 17, unchanged.
#include "engine/model/dimensionless_scales.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/model/jkr_scales.hpp"
#include "engine/reference/branch_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "profiles/power_law_profile.hpp"

namespace {

using mdrsim::PullOffScales;
using mdrsim::Scene;
using mdrsim::SceneDocument;

constexpr double kPi = std::numbers::pi;
constexpr double kModulus = 1e6;  // E* [Pa]
constexpr double kWork = 0.05;    // dgamma [J/m^2]

/// A fixed-load pull-off of `profile` (TOML keys), glued at `preload`, run to `rtol`.
SceneDocument document(const std::string& profile, const std::string& preload,
                       const std::string& discretization) {
  return SceneDocument::from_text(
      "[material]\neffective_modulus = 1e6\nwork_of_adhesion = 0.05\n[profile]\n" + profile +
          "\n[loading]\npreload = " + preload +
          "\nnormal = { control = \"fixed-load\" }\n[discretization]\n" + discretization + "\n",
      "scales.toml");
}

/// The scene glued at three times its own a0, so that the fold lies well inside the contact.
Scene glued_at_three_a0(const std::string& profile, const std::string& discretization) {
  const auto registries = mdrsim::Registries::builtin();
  const Scene probe =
      document(profile, "{ contact_radius = 1e-5 }", discretization).build(registries);
  const auto s = mdrsim::dimensionless_scales(*probe.profile, probe.material);
  SceneDocument d = document(profile, "{ contact_radius = 1e-5 }", discretization);
  d.set_number("loading.preload.contact_radius", 3.0 * s->radius, "--set");
  return d.build(registries);
}

struct Case {
  const char* name;
  const char* profile;          ///< TOML keys of [profile]
  double critical_indentation;  ///< d/d0 at the fixed-load pull-off
};

class PowerLawScales : public ::testing::TestWithParam<Case> {};

// The continuum fold of mode-mixed JKR (branch_reference: d(a) = g(a) - sqrt(2 pi a dgamma/E*),
// its force minimised to 1e-10) is the scales' definition: F = -F0 at a = a0, d = (3 - 2n) d0.
TEST_P(PowerLawScales, AreTheContinuumFixedLoadPullOff) {
  const Scene scene = glued_at_three_a0(GetParam().profile, "springs = 1000");
  const auto s = mdrsim::dimensionless_scales(*scene.profile, scene.material);
  ASSERT_TRUE(s.has_value());
  const auto critical = mdrsim::branch_reference::EquilibriumBranch(*scene.profile, scene.material)
                            .critical(scene.normal.controller->constraint(), scene.glued_radius);
  ASSERT_EQ(critical.kind, mdrsim::branch_reference::Critical::Kind::fold);
  // The force is stationary at the fold: 1e-9 in F, the square root of that in a and d.
  EXPECT_NEAR(critical.point.normal_force / s->force, -1.0, 1e-9);
  EXPECT_NEAR(critical.point.contact_radius / s->radius, 1.0, 1e-4);
  EXPECT_NEAR(critical.point.indentation / s->depth, GetParam().critical_indentation, 1e-4);
}

// The engine's own pull-off at rtol 1e-6 (its guarantee on the critical force): F/F0 = -1.
TEST_P(PowerLawScales, AreTheEnginesFixedLoadPullOff) {
  const Scene scene = glued_at_three_a0(GetParam().profile, "rtol = 1e-6");
  const auto s = mdrsim::dimensionless_scales(*scene.profile, scene.material);
  const auto result = mdrsim::run_scene(scene, mdrsim::ObserverList{});
  ASSERT_TRUE(result.critical.has_value());
  EXPECT_NEAR(result.critical->normal_force / s->force, -1.0, 1e-6);
  // Located between springs on the finest row: a few 1e-4 from the continuum's a and d.
  EXPECT_NEAR(result.critical->contact_radius / s->radius, 1.0, 2e-3);
  EXPECT_NEAR(result.critical->indentation / s->depth, GetParam().critical_indentation, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(
    Profiles, PowerLawScales,
    ::testing::Values(
        Case{"cone10", "type = \"cone\"\nslope_angle_deg = 10.0", 1.0},
        Case{"cone45", "type = \"cone\"\nslope_angle_deg = 45.0", 1.0},
        Case{"cone80", "type = \"cone\"\nslope_angle_deg = 80.0", 1.0},
        Case{"power_law_n0_75", "type = \"power_law\"\ncoefficient = 0.8\nexponent = 0.75", 1.5},
        Case{"power_law_n1_5", "type = \"power_law\"\ncoefficient = 0.8\nexponent = 1.5", 0.0},
        Case{"power_law_n3", "type = \"power_law\"\ncoefficient = 50.0\nexponent = 3.0", -3.0}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(ConeScales, AreTheClosedFormsNamedInTheirBasis) {
  const double theta = 30.0 * kPi / 180.0;
  const double t = std::tan(theta);
  const Scene scene = glued_at_three_a0("type = \"cone\"\nslope_angle_deg = 30.0", "springs = 100");
  const auto s = mdrsim::dimensionless_scales(*scene.profile, scene.material);
  ASSERT_TRUE(s.has_value());
  // Rounding of tan, logarithms and powers: a few ulps.
  EXPECT_NEAR(s->force / (54.0 * kWork * kWork / (kPi * kModulus * t * t * t)), 1.0, 1e-13);
  EXPECT_NEAR(s->radius / (18.0 * kWork / (kPi * kModulus * t * t)), 1.0, 1e-13);
  EXPECT_NEAR(s->depth / (3.0 * kWork / (kModulus * t)), 1.0, 1e-13);
  EXPECT_EQ(s->basis.rfind("cone: ", 0), 0u) << s->basis;
}

TEST(FlatPunchScales, AreKendallsPullOff) {
  const double radius = 1e-4;
  const auto registries = mdrsim::Registries::builtin();
  const Scene scene =
      document("type = \"flat_punch\"\nradius = 1e-4", "{ depth = 1e-6 }", "springs = 1000")
          .build(registries);
  const auto s = mdrsim::dimensionless_scales(*scene.profile, scene.material);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->force / std::sqrt(8.0 * kPi * radius * radius * radius * kModulus * kWork), 1.0,
              1e-14);
  EXPECT_EQ(s->radius, radius);
  EXPECT_NEAR(s->depth / std::sqrt(2.0 * kPi * radius * kWork / kModulus), 1.0, 1e-14);
  // Every spring lets go at once at the same stretch: the engine's pull-off is the closed form.
  const auto result = mdrsim::run_scene(scene, mdrsim::ObserverList{});
  ASSERT_TRUE(result.critical.has_value());
  EXPECT_NEAR(result.critical->normal_force / s->force, -1.0, 1e-12);
  EXPECT_NEAR(result.critical->indentation / s->depth, -1.0, 1e-12);
  EXPECT_EQ(s->basis.rfind("flat_punch: ", 0), 0u) << s->basis;
}

TEST(ParabolaScales, StayEquation17) {
  const auto registries = mdrsim::Registries::builtin();
  for (const char* type : {"parabolic", "sphere"}) {
    const Scene scene = document(std::string("type = \"") + type + "\"\nradius = 0.01",
                                 "{ depth = 1e-5 }", "springs = 100")
                            .build(registries);
    const auto s = mdrsim::dimensionless_scales(*scene.profile, scene.material);
    const auto jkr = mdrsim::JkrScales::of(0.01, kModulus, kWork);
    ASSERT_TRUE(s && jkr);
    // JkrScales::of itself; the compiler may fold this call's cube roots exactly, where
    // the engine's take libm's (an ulp apart).
    EXPECT_DOUBLE_EQ(s->force, jkr->force);
    EXPECT_DOUBLE_EQ(s->radius, jkr->radius);
    EXPECT_DOUBLE_EQ(s->depth, jkr->depth);
    EXPECT_EQ(s->basis.rfind("parabolic tip of radius R (paper eq. 17)", 0), 0u) << s->basis;
  }
  // The power law with n = 2, c = 1/(2R) is the same parabola: its own closed form agrees.
  const auto power =
      mdrsim::PowerLawProfile(1.0 / (2.0 * 0.01), 2.0).pull_off_scales(kModulus, kWork);
  const auto jkr = mdrsim::JkrScales::of(0.01, kModulus, kWork);
  ASSERT_TRUE(power.has_value());
  EXPECT_NEAR(power->force / jkr->force, 1.0, 1e-13);
  EXPECT_NEAR(power->radius / jkr->radius, 1.0, 1e-13);
  EXPECT_NEAR(power->depth / jkr->depth, 1.0, 1e-13);
}

TEST(PowerLawScales, NoneWithoutAFoldOrAdhesion) {
  // n <= 1/2: F(a) has no minimum, the contact peels off smoothly under fixed load.
  EXPECT_FALSE(mdrsim::PowerLawProfile(0.8, 0.5).pull_off_scales(kModulus, kWork).has_value());
  EXPECT_FALSE(mdrsim::PowerLawProfile(0.8, 0.3).pull_off_scales(kModulus, kWork).has_value());
  EXPECT_FALSE(mdrsim::PowerLawProfile(0.8, 1.5).pull_off_scales(kModulus, 0.0).has_value());
}

}  // namespace
