// The scene's [friction] table: read into Scene::friction, bad values and combinations not run
// yet refused with file, line and key.
#include "engine/scene/friction_reader.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

// A fretting program; the line numbers in the messages below refer to it (the [friction] table
// starts on line 15).
constexpr std::string_view kProgram =
    R"(title = "fretting"
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.0
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
name = "press"
normal = { control = "fixed-load", to = 1.0e-3 }
[[loading.stage]]
name = "shear"
tangential = { control = "fixed-grips", by = 1.0e-6 }
[friction]
)";

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "scene.toml").build(registries);
}

TEST(FrictionScene, ACoefficientBeyondADoubleNamesItsKey) {
  EXPECT_THROW_MSG(build(std::string(kProgram) + "coefficient = 1e400\n"), SceneError,
                   "scene.toml:16:15: friction.coefficient = 1e400 is beyond the range of a double "
                   "(largest 1.8e308)");
  SceneDocument d =
      SceneDocument::from_text(std::string(kProgram) + "coefficient = 0.5\n", "scene.toml");
  EXPECT_THROW_MSG(d.set_value("friction.coefficient", "1e400"), SceneError,
                   "--set: friction.coefficient = 1e400 is beyond the range of a double (largest "
                   "1.8e308)");
  EXPECT_THROW_MSG(d.set_value("friction", "{ coefficient = -2e308, glued = \"coulomb\" }"),
                   SceneError,
                   "--set: friction.coefficient = -2e308 is beyond the range of a double (largest "
                   "1.8e308)");
}

TEST(FrictionScene, ANumberTooSmallForADoubleNamesItsKey) {
  SceneDocument d =
      SceneDocument::from_text(std::string(kProgram) + "coefficient = 0.5\n", "scene.toml");
  EXPECT_THROW_MSG(d.set_value("friction.shear_strength", "1e-400"), SceneError,
                   "--set: friction.shear_strength = 1e-400 is too small for a double (it would "
                   "read as 0; the smallest is 4.9e-324)");
  EXPECT_THROW_MSG(d.set_value("friction", "{ coefficient = 0.5, shear_strength = 2e-999 }"),
                   SceneError,
                   "--set: friction.shear_strength = 2e-999 is too small for a double (it would "
                   "read as 0; the smallest is 4.9e-324)");
  EXPECT_NO_THROW(d.set_value("friction.shear_strength", "0e-999"));
}

TEST(FrictionScene, ReadsTheTable) {
  const Scene scene = build(std::string(kProgram) + "coefficient = 0.5\n");
  ASSERT_TRUE(scene.friction.has_value());
  EXPECT_EQ(scene.friction->coefficient, 0.5);
  EXPECT_EQ(scene.friction->glued, GluedShear::unlimited);
  EXPECT_EQ(scene.friction->shear_strength, 0.0);
  // The result's scene names every key, the default included.
  EXPECT_EQ((*scene.resolved)["friction"]["glued"], "unlimited");
}

TEST(FrictionScene, ZeroCoefficientIsTheFrictionlessScene) {
  // mu = 0 under the unlimited glue changes nothing: no friction part, so that every run is the
  // frictionless scene's bit for bit (the shorthand too).
  EXPECT_FALSE(build(std::string(kProgram) + "coefficient = 0.0\n").friction.has_value());
}

TEST(FrictionScene, RefusesBadValues) {
  const std::string p(kProgram);
  EXPECT_THROW_MSG(build(p + "coefficient = -0.1\n"), SceneError,
                   "scene.toml:16:15: friction.coefficient = -0.1 is outside [0, inf)");
  EXPECT_THROW_MSG(build(p + "coeficient = 0.5\n"), SceneError,
                   "scene.toml:16:1: friction.coeficient: unknown key; did you mean 'coefficient'? "
                   "(known: coefficient, glued, law, shear_strength)");
  EXPECT_THROW_MSG(build(p), SceneError,
                   "scene.toml:15:1: friction.coefficient: missing, expected a number (Coulomb "
                   "coefficient mu >= 0)");
  EXPECT_THROW_MSG(build(p + "coefficient = 0.5\nglued = \"sticky\"\n"), SceneError,
                   "scene.toml:17:9: friction.glued: unknown 'sticky' (known: unlimited, coulomb)");
  EXPECT_THROW_MSG(build(p + "coefficient = 0.5\nshear_strength = 10.0\n"), SceneError,
                   "scene.toml:17:18: friction.shear_strength: applies only with glued = "
                   "\"coulomb\"");
}

// The shorthand with friction runs as its three stages (docs/programs.md "The shorthand as a
// program"): the preload pressed at fixed grips to its depth, the pull-off control and the
// tangential ramp, the normal held value lowered until separation by the preload's force per
// unit of the parameter under a fixed load.
TEST(FrictionScene, TheShorthandBecomesItsThreeStages) {
  std::string text(kProgram);
  text.replace(text.find("[[loading.stage]]"), std::string::npos,
               "[loading]\npreload = { depth = 1.0e-6 }\ntangential = { control = \"fixed-grips\", "
               "displacement = 2.0e-7 }\nnormal = { control = \"fixed-load\" }\n[friction]\n"
               "coefficient = 0.5\n");
  const Scene scene = build(text);
  ASSERT_TRUE(scene.friction.has_value());
  ASSERT_TRUE(scene.program.has_value());
  EXPECT_TRUE(scene.shorthand());
  EXPECT_FALSE(scene.program->rebinding);
  const auto& stages = scene.program->stages;
  ASSERT_EQ(stages.size(), 3u);
  EXPECT_EQ(stages[0].name, "preload");
  ASSERT_TRUE(stages[0].normal);
  EXPECT_EQ(stages[0].normal->control, "fixed-grips");
  EXPECT_EQ(stages[0].normal->motion, StageAxis::Motion::to);
  EXPECT_EQ(stages[0].normal->value, 1.0e-6);
  EXPECT_FALSE(stages[0].tangential);
  EXPECT_EQ(stages[1].name, "tangential");
  ASSERT_TRUE(stages[1].normal && stages[1].tangential);
  EXPECT_EQ(stages[1].normal->control, "fixed-load");
  EXPECT_EQ(stages[1].normal->motion, StageAxis::Motion::hold);
  EXPECT_EQ(stages[1].tangential->control, "fixed-grips");
  EXPECT_EQ(stages[1].tangential->motion, StageAxis::Motion::to);
  EXPECT_EQ(stages[1].tangential->value, 2.0e-7);
  EXPECT_EQ(stages[2].name, "pull-off");
  ASSERT_TRUE(stages[2].normal);
  EXPECT_TRUE(stages[2].until_separation);
  EXPECT_EQ(stages[2].normal->motion, StageAxis::Motion::by);
  EXPECT_EQ(stages[2].normal->value, -scene.preload_force);
  EXPECT_GT(scene.preload_force, 0.0);
}

TEST(FrictionScene, RefusesWhatDoesNotRunYet) {
  const std::string p(kProgram);
  // glued = "coulomb" runs, with its shear strength in Pa.
  const Scene coulomb =
      build(p + "coefficient = 0.5\nglued = \"coulomb\"\nshear_strength = 10.0\n");
  ASSERT_TRUE(coulomb.friction);
  EXPECT_EQ(coulomb.friction->glued, GluedShear::limited);
  EXPECT_EQ(coulomb.friction->shear_strength, 10.0);
  EXPECT_THROW_MSG(build(p + "coefficient = 0.5\n[solver]\nmethod = \"stepping\"\n"), SceneError,
                   "scene.toml:16:15: friction.coefficient: friction runs with solver.method = "
                   "\"event\" only");
  // A held tangential force with adhesion runs, in a program and in the shorthand (a glue
  // that lets go moves u_x within its jump, and the springs slip there: friction_held_force).
  std::string fixed_load(p);
  fixed_load.replace(fixed_load.find("tangential = { control = \"fixed-grips\""),
                     std::string_view("tangential = { control = \"fixed-grips\"").size(),
                     "tangential = { control = \"fixed-load\"");
  fixed_load.replace(fixed_load.find("work_of_adhesion = 0.0"),
                     std::string_view("work_of_adhesion = 0.0").size(), "work_of_adhesion = 0.05");
  EXPECT_TRUE(build(fixed_load + "coefficient = 0.5\n").friction.has_value());
  std::string shorthand(fixed_load);
  shorthand.replace(
      shorthand.find("[[loading.stage]]"), std::string::npos,
      "[loading]\npreload = { depth = 1.0e-6 }\ntangential = { control = \"fixed-load\", force "
      "= 1.0e-4 }\nnormal = { control = \"fixed-load\" }\n[friction]\ncoefficient = 0.5\n");
  EXPECT_TRUE(build(shorthand).program.has_value());
}

/// A law of its own for the reader: a coefficient per radius (key `slope`), no uniform one.
class SlopedLaw final : public FrictionLaw {
 public:
  explicit SlopedLaw(double slope) : slope_(slope) {}
  SlipLimit limit_at(double radius, double /*spacing*/) const override {
    return {slope_ * radius, 0.0};
  }

 private:
  double slope_;
};

Registries with_sloped_law() {
  Registries r = Registries::builtin();
  r.friction_laws.add({.name = "sloped",
                       .summary = "mu = slope x",
                       .parameters = {{.key = "slope", .help = "[1/m]", .lower = Bound{0.0, true}}},
                       .create = [](const ParameterValues& v) -> std::unique_ptr<FrictionLaw> {
                         return std::make_unique<SlopedLaw>(v.number("slope"));
                       }});
  return r;
}

// `law` names a registered friction law; its keys are read, the others' refused; a law with
// no one coefficient is kept as the scene's law (spring by spring), Coulomb's as its number.
TEST(FrictionScene, ALawOfItsOwnIsNamedByLaw) {
  const Registries registries = with_sloped_law();
  const auto with = [&](const std::string& keys) {
    return SceneDocument::from_text(std::string(kProgram) + keys, "scene.toml").build(registries);
  };
  const Scene sloped = with("law = \"sloped\"\nslope = 2000.0\n");
  ASSERT_TRUE(sloped.friction && sloped.friction->law);
  EXPECT_EQ(sloped.friction->law->limit_at(1e-4, 1e-6).coefficient, 0.2);
  EXPECT_FALSE(sloped.friction->law->uniform_coefficient().has_value());
  const Scene coulomb = with("law = \"coulomb\"\ncoefficient = 0.3\n");
  ASSERT_TRUE(coulomb.friction);
  EXPECT_EQ(coulomb.friction->law, nullptr);
  EXPECT_EQ(coulomb.friction->coefficient, 0.3);
  EXPECT_THROW_MSG(with("law = \"sloped\"\ncoefficient = 0.3\n"), SceneError,
                   "scene.toml:17:15: friction.coefficient: applies to law = \"coulomb\" only");
  EXPECT_THROW_MSG(
      with("law = \"sloped\"\nslope = 1.0\nglued = \"coulomb\"\n"), SceneError,
      "scene.toml:18:9: friction.glued: glued = \"coulomb\" slides at mu f_z with one mu, which "
      "law = \"sloped\" does not give: use a law with one coefficient");
  EXPECT_THROW_MSG(build(std::string(kProgram) + "law = \"sloped\"\n"), SceneError,
                   "scene.toml:16:7: friction.law: unknown 'sloped' (known: coulomb)");
}

}  // namespace
}  // namespace mdrsim::test
