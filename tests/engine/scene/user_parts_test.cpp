// A user's own part is registered by one call and then used from a scene.
#include <gtest/gtest.h>

#include <memory>

#include "detachment/criterion.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "profiles/profile.hpp"

using mdrsim::test::JkrScenario;

namespace {

/// The rule of Hess with a user-chosen factor on dl(a), given by margin only: the engine has
/// to root-find its let-go.
class ScaledHessCriterion final : public mdrsim::DetachmentCriterion {
 public:
  ScaledHessCriterion(const mdrsim::InterfaceProperties& p, double factor)
      : p_(p), factor_(factor) {}
  double margin(const mdrsim::BoundarySpring& s) const override {
    return factor_ * mdrsim::hess_elongation_limit(p_, s.contact_radius) - s.elongation;
  }

 private:
  mdrsim::InterfaceProperties p_;
  double factor_;
};

/// The parabola with only the two required operations: every other one is the default.
class BareParabola final : public mdrsim::Profile {
 public:
  explicit BareParabola(double r) : r_(r) {}
  double shape(double r) const override { return r * r / (2 * r_); }
  double mdr_image(double x) const override { return x * x / r_; }
  std::optional<double> jkr_scale_radius() const override { return r_; }

 private:
  double r_;
};

mdrsim::Registries with_user_parts() {
  auto registries = mdrsim::Registries::builtin();
  registries.criteria.add(
      {.name = "scaled-hess",
       .summary = "dl(a) times a factor",
       .parameters = {{.key = "factor", .help = "[1]", .lower = mdrsim::Bound{0.0, false}}},
       .create = [](const mdrsim::ParameterValues& v, const mdrsim::InterfaceProperties& p)
           -> std::unique_ptr<mdrsim::DetachmentCriterion> {
         return std::make_unique<ScaledHessCriterion>(p, v.number("factor"));
       }});
  registries.profiles.add(
      {.name = "bare-parabola",
       .summary = "parabola without closed forms",
       .parameters = {{.key = "radius", .lower = mdrsim::Bound{0.0, false}}},
       .create = [](const mdrsim::ParameterValues& v) -> std::unique_ptr<mdrsim::Profile> {
         return std::make_unique<BareParabola>(v.number("radius"));
       }});
  return registries;
}

mdrsim::Scene build(const std::string& text, const mdrsim::Registries& registries) {
  return mdrsim::SceneDocument::from_text(text, "user.toml").build(registries);
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

}  // namespace

// Factor 1 is the normal-only rule: the root-found let-go matches its closed form.
TEST(UserParts, RegisteredCriterionIsUsableFromAScene) {
  JkrScenario s;
  s.criterion = "normal-only";
  s.springs = 3000;
  const auto builtin = mdrsim::test::run_quietly(s.build());
  const auto registries = with_user_parts();
  const auto user = mdrsim::test::run_quietly(build(
      replace(s.toml(), "criterion = \"normal-only\"", "criterion = \"scaled-hess\"\nfactor = 1.0"),
      registries));
  EXPECT_GT(user.counts.root_iterations, 0);
  EXPECT_EQ(user.critical->springs_in_contact, builtin.critical->springs_in_contact);
  EXPECT_NEAR(user.critical->normal_force, builtin.critical->normal_force,
              1e-12 * std::abs(builtin.critical->normal_force));
  // A stronger interface holds on longer and pulls off harder.
  const auto strong = mdrsim::test::run_quietly(build(
      replace(s.toml(), "criterion = \"normal-only\"", "criterion = \"scaled-hess\"\nfactor = 1.5"),
      registries));
  EXPECT_LT(strong.critical->normal_force, user.critical->normal_force);
}

// The Profile defaults (root search for the Hertz radius, quadrature for the Hertz force)
// reproduce the parabola's closed forms, preloaded by force.
TEST(UserParts, ProfileWithOnlyRequiredOperationsMatchesTheParabola) {
  JkrScenario s;
  s.springs = 3000;
  const auto registries = with_user_parts();
  const std::string by_force =
      replace(s.toml(), "preload = { contact_radius", "preload = { force = 0.005 } #");
  const auto parabola = build(by_force, registries);
  const auto bare =
      build(replace(by_force, "type = \"parabolic\"", "type = \"bare-parabola\""), registries);
  EXPECT_NEAR(bare.glued_radius, parabola.glued_radius, 1e-12 * parabola.glued_radius);
  EXPECT_NEAR(bare.preload_depth, parabola.preload_depth, 1e-10 * parabola.preload_depth);
  EXPECT_NEAR(mdrsim::test::run_quietly(bare).critical->normal_force,
              mdrsim::test::run_quietly(parabola).critical->normal_force, 1e-9);
}

TEST(UserParts, NamesMustBeUnique) {
  auto registries = mdrsim::Registries::builtin();
  EXPECT_THROW(registries.controllers.add({.name = "fixed-load",
                                           .summary = "",
                                           .parameters = {},
                                           .create =
                                               [](const mdrsim::ParameterValues&) {
                                                 return std::unique_ptr<mdrsim::AxisController>();
                                               }}),
               std::invalid_argument);
}
