// Each built-in criterion: its closed-form let-go zeroes its margin, and the docs' formulas hold.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "detachment/criterion_registry.hpp"
#include "detachment/let_go.hpp"
#include "detachment/mode_dependent_criterion.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "detachment/normal_only_criterion.hpp"

namespace {

const mdrsim::InterfaceProperties kInterface{1e6, 0.8e6, 0.05};
constexpr double kRadius = 2e-4;

double dl(double a) {
  return std::sqrt(2 * std::numbers::pi * a * kInterface.work_of_adhesion /
                   kInterface.effective_modulus);
}

std::unique_ptr<mdrsim::DetachmentCriterion> make(const std::string& name) {
  mdrsim::CriterionRegistry registry;
  mdrsim::register_builtin_criteria(registry);
  mdrsim::ParameterValues values;
  values.set("lambda", 0.5);
  return registry.find(name)->create(values, kInterface);
}

}  // namespace

class EveryCriterion : public ::testing::TestWithParam<std::string> {};

// The closed form, where given, is the root of the margin; the margin falls with stretch.
TEST_P(EveryCriterion, LetGoIsTheZeroOfAFallingMargin) {
  const auto c = make(GetParam());
  for (const double ux : {0.0, 0.3 * dl(kRadius), 0.8 * dl(kRadius)}) {
    const mdrsim::LetGo go = mdrsim::locate_let_go(*c, kRadius, ux, dl(kRadius));
    ASSERT_EQ(go.kind, mdrsim::LetGo::Kind::at_elongation);
    EXPECT_NEAR(c->margin({go.elongation, ux, kRadius}), 0.0,
                1e-12 * std::abs(c->margin({0.0, 0.0, kRadius})));
    EXPECT_GT(c->margin({0.999 * go.elongation, ux, kRadius}), 0.0);
    EXPECT_LT(c->margin({1.001 * go.elongation, ux, kRadius}), 0.0);
    if (const auto closed = c->critical_elongation(kRadius, ux)) {
      // The root search on the margin alone lands on the same elongation.
      struct MarginOnly final : mdrsim::DetachmentCriterion {
        const mdrsim::DetachmentCriterion* inner;
        double margin(const mdrsim::BoundarySpring& s) const override { return inner->margin(s); }
      } margin_only;
      margin_only.inner = c.get();
      const auto searched = mdrsim::locate_let_go(margin_only, kRadius, ux, dl(kRadius));
      EXPECT_GT(searched.root_iterations, 0);
      EXPECT_NEAR(searched.elongation, *closed, 1e-14 * dl(kRadius));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Builtin, EveryCriterion,
                         ::testing::Values("mode-mixed", "deformation", "stress", "normal-only",
                                           "mode-dependent"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& ch : n) ch = ch == '-' ? '_' : ch;
                           return n;
                         });

// the criterion table of docs/scene.md, evaluated by hand at one state.
TEST(Criteria, SpecFormulasAtOneState) {
  const double a = kRadius, e = 0.5 * dl(a), ux = 0.4 * dl(a);
  const double E = kInterface.effective_modulus, G = kInterface.effective_shear_modulus;
  const double w = 2 * std::numbers::pi * a * kInterface.work_of_adhesion;
  EXPECT_DOUBLE_EQ(make("mode-mixed")->margin({e, ux, a}), w - E * e * e - G * ux * ux);
  EXPECT_DOUBLE_EQ(make("deformation")->margin({e, ux, a}), dl(a) - std::hypot(e, ux));
  EXPECT_DOUBLE_EQ(make("stress")->margin({e, ux, a}), E * dl(a) - std::hypot(E * e, G * ux));
  EXPECT_DOUBLE_EQ(make("normal-only")->margin({e, ux, a}), dl(a) - e);
  // Hutchinson-Suo with lambda = 0.5: Gamma = w (1 + tan^2(psi/2)), tan psi = sqrt(G/E) ux/e.
  const double psi = std::atan(std::sqrt(G / E) * ux / e);
  const double toughness = w * (1 + std::pow(std::tan(0.5 * psi), 2));
  const double release = E * e * e + G * ux * ux;
  const double margin = make("mode-dependent")->margin({e, ux, a});
  EXPECT_NEAR(
      margin,
      toughness * std::pow(std::cos(0.5 * psi), 2) - release * std::pow(std::cos(0.5 * psi), 2),
      1e-12 * w);
}

// Eq. 20 with no stretch: G* ux^2 > 2 pi a dgamma breaks the glue at once.
TEST(Criteria, TangentialLoadAloneLetsGoAtOnce) {
  const auto c = make("mode-mixed");
  const double limit = std::sqrt(2 * std::numbers::pi * kRadius * kInterface.work_of_adhesion /
                                 kInterface.effective_shear_modulus);
  EXPECT_EQ(mdrsim::locate_let_go(*c, kRadius, 1.001 * limit, dl(kRadius)).kind,
            mdrsim::LetGo::Kind::now);
  EXPECT_EQ(mdrsim::locate_let_go(*c, kRadius, 0.999 * limit, dl(kRadius)).kind,
            mdrsim::LetGo::Kind::at_elongation);
  // normal-only ignores the tangential displacement entirely.
  EXPECT_DOUBLE_EQ(make("normal-only")->critical_elongation(kRadius, 100 * limit).value(),
                   dl(kRadius));
}

// Pure mode II under lambda = 0: the toughness grows without bound, the margin stays finite.
TEST(Criteria, ModeDependentIsFiniteAtPureShear) {
  const mdrsim::ModeDependentCriterion c(kInterface, 0.0);
  const double m = c.margin({0.0, 10 * dl(kRadius), kRadius});
  EXPECT_TRUE(std::isfinite(m));
  EXPECT_GT(m, 0.0);
  EXPECT_THROW(mdrsim::ModeDependentCriterion(kInterface, 1.5), std::invalid_argument);
}

// A criterion that never lets go is reported, not looped on.
TEST(Criteria, NeverLettingGoIsReported) {
  struct Glue final : mdrsim::DetachmentCriterion {
    double margin(const mdrsim::BoundarySpring&) const override { return 1.0; }
  } glue;
  EXPECT_EQ(mdrsim::locate_let_go(glue, kRadius, 0.0, dl(kRadius)).kind,
            mdrsim::LetGo::Kind::never);
}
