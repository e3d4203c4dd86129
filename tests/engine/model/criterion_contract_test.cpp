// What both engines assume of a criterion, checked before a run: every built-in satisfies it,
// and a criterion that breaks it stops the run with its name instead of a wrong let-go.
#include "engine/model/criterion_contract.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "detachment/mode_dependent_criterion.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/part_examples.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "tests/support/expect_throw_msg.hpp"

namespace {

const mdrsim::Material kMaterial = mdrsim::Material::from_youngs_modulus(1e6, 0.3, 0.05);
constexpr double kRadius = 5e-4;  ///< 2 a0 of the tests' JKR scene [m]

/// Mode-mixed with a margin that rises again past 3 Hess elongations: it lets go, then holds.
struct Relapsing final : mdrsim::DetachmentCriterion {
  double margin(const mdrsim::BoundarySpring& s) const override {
    const double dl2 = 2.0 * std::numbers::pi * s.contact_radius * kMaterial.work_of_adhesion /
                       kMaterial.effective_modulus;
    const double e2 = s.elongation * s.elongation;
    return e2 < 9.0 * dl2 ? dl2 - e2 : e2 - 17.0 * dl2;
  }
};

/// Monotone in the elongation, but holding only where |u_x| is small or large: a ring.
struct Ring final : mdrsim::DetachmentCriterion {
  double margin(const mdrsim::BoundarySpring& s) const override {
    const double dl = std::sqrt(2.0 * std::numbers::pi * s.contact_radius *
                                kMaterial.work_of_adhesion / kMaterial.effective_modulus);
    const double band = std::abs(std::abs(s.tangential_displacement) - 0.5 * dl) - 0.2 * dl;
    return std::abs(band) - s.elongation;  // > 0 away from |u_x| = 0.5 dl +- 0.2 dl
  }
};

std::string message(const std::function<void()>& statement) {
  return mdrsim::test::thrown_message<std::runtime_error>(statement);
}

}  // namespace

// Every registered criterion, with its declared example values, keeps the contract at the
// radii a run reaches (a new built-in is covered by registering it).
TEST(CriterionContract, EveryBuiltinKeepsIt) {
  const auto registries = mdrsim::Registries::builtin();
  for (const std::string& name : registries.criteria.names()) {
    mdrsim::test::JkrScenario s;
    s.criterion = name;
    s.criterion_extra = mdrsim::test::example_keys("criterion", name, "\n");
    const mdrsim::Scene scene = s.build();
    EXPECT_NO_THROW(mdrsim::sample_criterion_contract(*scene.criterion, name, scene.material,
                                                      scene.glued_radius))
        << name;
  }
}

// A built-in declares the contract proven (runs skip the sampling), and the sampling agrees
// over materials (G*/E* from 1/100 to 100), radii and, for mode-dependent, lambda in [0, 1].
TEST(CriterionContract, EveryBuiltinProvesIt) {
  const auto registries = mdrsim::Registries::builtin();
  for (const std::string& name : registries.criteria.names()) {
    for (const double shear_ratio : {1e-2, 1.0, 1e2}) {
      for (const double lambda : {0.0, 0.1, 0.5, 0.9, 1.0}) {
        mdrsim::Material material = mdrsim::Material::from_youngs_modulus(1e6, 0.3, 0.05);
        material.effective_shear_modulus = shear_ratio * material.effective_modulus;
        mdrsim::ParameterValues values;
        values.set("lambda", lambda);
        const auto criterion = registries.criteria.find(name)->create(values, material);
        SCOPED_TRACE(name + " G*/E* " + std::to_string(shear_ratio) + " lambda " +
                     std::to_string(lambda));
        EXPECT_TRUE(criterion->proves_contract());
        for (const double a : {1e-9, 5e-4, 1.0}) {
          EXPECT_NO_THROW(mdrsim::sample_criterion_contract(*criterion, name, material, a));
        }
      }
    }
  }
}

// The run's check skips a criterion that declares the contract proven, and samples one that
// does not: the same broken margin, declared and not.
TEST(CriterionContract, RunChecksOnlyWhatIsNotProven) {
  struct Declared final : mdrsim::DetachmentCriterion {
    Relapsing broken;
    double margin(const mdrsim::BoundarySpring& s) const override { return broken.margin(s); }
    bool proves_contract() const override { return true; }
  };
  EXPECT_NO_THROW(mdrsim::check_criterion_contract(Declared(), "declared", kMaterial, kRadius));
  EXPECT_THROW(mdrsim::sample_criterion_contract(Declared(), "declared", kMaterial, kRadius),
               std::runtime_error);
  EXPECT_THROW(mdrsim::check_criterion_contract(Relapsing(), "relapsing", kMaterial, kRadius),
               std::runtime_error);
}

TEST(CriterionContract, MarginRisingWithTheElongationIsNamed) {
  const std::string m = message(
      [] { mdrsim::check_criterion_contract(Relapsing(), "relapsing", kMaterial, kRadius); });
  EXPECT_NE(m.find("detachment criterion 'relapsing' breaks the contract"), std::string::npos) << m;
  EXPECT_NE(m.find("rises with the elongation"), std::string::npos) << m;
}

TEST(CriterionContract, HoldingSetThatIsNotConvexIsNamed) {
  const std::string m =
      message([] { mdrsim::check_criterion_contract(Ring(), "ring", kMaterial, kRadius); });
  EXPECT_NE(m.find("detachment criterion 'ring' breaks the contract"), std::string::npos) << m;
  EXPECT_NE(m.find("not convex"), std::string::npos) << m;
}

// Through a run: a scene naming an outside criterion that breaks the contract stops with its
// name, under the shorthand and under a program.
TEST(CriterionContract, RunStopsWithTheCriterionsName) {
  auto registries = mdrsim::Registries::builtin();
  registries.criteria.add({"relapsing",
                           "lets go, then holds again",
                           {},
                           [](const mdrsim::ParameterValues&, const mdrsim::InterfaceProperties&) {
                             return std::make_unique<Relapsing>();
                           }});
  const std::string material =
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[detachment]\ncriterion = \"relapsing\"\n[discretization]\nsprings = 200\n";
  const std::string shorthand = material +
                                "[loading]\npreload = { contact_radius = 5e-4 }\n"
                                "normal = { control = \"fixed-load\" }\n";
  const std::string program = material +
                              "[[loading.stage]]\nnormal = { control = \"fixed-grips\", to = "
                              "1e-5 }\n[[loading.stage]]\nnormal = { control = \"fixed-grips\", "
                              "by = -1e-4 }\nuntil = \"separation\"\n";
  for (const std::string& text : {shorthand, program}) {
    const mdrsim::Scene scene =
        mdrsim::SceneDocument::from_text(text, "test.toml").build(registries);
    const std::string m = message([&] { mdrsim::run_scene(scene, mdrsim::ObserverList{}); });
    EXPECT_NE(m.find("detachment criterion 'relapsing' breaks the contract"), std::string::npos)
        << m;
  }
}

// Mode-dependent with lambda = 0 holds where E* e^2 < 2 pi a dgamma whatever u_x: the grid's
// elongation of one Hess elongation lies on its boundary, where the margin is a difference of
// equal terms, zero to their rounding. Its sign there is rounding, not a broken contract, at
// any scale: the check weighs rounding against the margin at rest, 2 pi a dgamma (the fuzzer's
// input: R = 1.1e-302 m, a = 2e-103 m, margins of 1e-101 J/m and rounding of 1e-117).
TEST(CriterionContract, RoundingOnTheHoldingBoundaryIsNoBreak) {
  mdrsim::Material material = mdrsim::Material::from_youngs_modulus(1e6, 0.0, 5.05);
  material.effective_shear_modulus = 1.5e6;  // the fuzzer's input gives E* and G* apart
  const mdrsim::ModeDependentCriterion criterion(material, 0.0);
  for (const double a : {2.02733e-103, 1e-60, 1e-20, 5e-4, 1e3}) {
    SCOPED_TRACE(a);
    EXPECT_NO_THROW(mdrsim::sample_criterion_contract(criterion, "mode-dependent", material, a));
  }
}
