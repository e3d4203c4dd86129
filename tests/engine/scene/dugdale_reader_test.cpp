// material.adhesive_stress and material.maugis_parameter: read into the material, and every
// key outside the Dugdale law's scope refused in one line at that key.
#include "engine/scene/dugdale_reader.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <string>
#include <string_view>

#include "engine/model/dugdale_material.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "md.toml").build(registries);
}

/// [material] on lines 1-4 with `material` on line 5, [profile] and the shorthand after it,
/// then `rest`.
std::string scene(
    std::string_view material, std::string_view rest = "",
    std::string_view profile = "type = \"parabolic\"\nradius = 0.01",
    std::string_view loading =
        "preload = { contact_radius = 1e-4 }\nnormal = { control = \"fixed-load\" }") {
  return "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n# the Dugdale key\n" +
         std::string(material) + "\n[profile]\n" + std::string(profile) + "\n[loading]\n" +
         std::string(loading) + "\n" + std::string(rest);
}

TEST(DugdaleReader, ReadsEitherKey) {
  const Scene stress = build(scene("adhesive_stress = 2.0e5"));
  EXPECT_EQ(stress.material.adhesive_stress, 2.0e5);
  EXPECT_TRUE(stress.material.finite_range());
  EXPECT_EQ(stress.plan.engine, RouteEngine::continuum);
  EXPECT_EQ(stress.solver.method, SolverMethod::continuum);
  const Scene lambda = build(scene("maugis_parameter = 1.0"));
  EXPECT_DOUBLE_EQ(lambda.material.adhesive_stress,
                   adhesive_stress_of_maugis_parameter(1.0, 0.05, 1.0e6, 0.01));
  EXPECT_DOUBLE_EQ(maugis_parameter_of(lambda.material.adhesive_stress, 0.05, 1.0e6, 0.01), 1.0);
  const Scene sphere =
      build(scene("maugis_parameter = 1.0", "", "type = \"sphere\"\nradius = 0.01"));
  EXPECT_TRUE(sphere.material.finite_range());
  // Without either key: no range, the event method as before.
  const Scene jkr = build(scene(""));
  EXPECT_FALSE(jkr.material.finite_range());
  EXPECT_EQ(jkr.plan.engine, RouteEngine::pull_off_row);
}

// --set (and --vary) of one key replaces the other, as the preload's keys do.
TEST(DugdaleReader, SettingOneKeyReplacesTheOther) {
  static const Registries registries = Registries::builtin();
  SceneDocument doc = SceneDocument::from_text(scene("adhesive_stress = 2.0e5"), "md.toml");
  doc.set_value("material.maugis_parameter", "1.0");
  const Scene lambda = doc.build(registries);
  EXPECT_DOUBLE_EQ(lambda.material.adhesive_stress,
                   adhesive_stress_of_maugis_parameter(1.0, 0.05, 1.0e6, 0.01));
  doc.set_number("material.adhesive_stress", 3.0e5, "--vary");
  EXPECT_EQ(doc.build(registries).material.adhesive_stress, 3.0e5);
}

TEST(DugdaleReader, RefusesBadValuesOfTheKeys) {
  EXPECT_THROW_MSG(build(scene("adhesive_stress = 2.0e5\nmaugis_parameter = 1.0")), SceneError,
                   "md.toml:6:20: material.maugis_parameter: give adhesive_stress or "
                   "maugis_parameter, not both");
  EXPECT_THROW_MSG(build(scene("adhesive_stress = 0.0")), SceneError,
                   "md.toml:5:19: material.adhesive_stress = 0 is outside (0, inf)");
  EXPECT_THROW_MSG(build(scene("maugis_parameter = -1.0")), SceneError,
                   "md.toml:5:20: material.maugis_parameter = -1 is outside (0, inf)");
  EXPECT_THROW_MSG(build(scene("maugis_parameter = inf")), SceneError,
                   "md.toml:5:20: material.maugis_parameter = inf is not a finite number");
  EXPECT_THROW_MSG(
      build(scene("maugis_parameter = 1.0", "", "type = \"cone\"\nslope_angle_deg = 10")),
      SceneError,
      "md.toml:5:20: material.maugis_parameter: applies to profile.type = "
      "\"parabolic\" or \"sphere\" only, not \"cone\"; give adhesive_stress [Pa]");
}

TEST(DugdaleReader, RefusesAZeroOrVaryingOrApproachWorkOfAdhesion) {
  const std::string zero =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.0\nadhesive_stress = 1e5\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[loading]\n"
      "preload = { contact_radius = 1e-4 }\nnormal = { control = \"fixed-load\" }\n";
  EXPECT_THROW_MSG(build(zero), SceneError,
                   "md.toml:4:19: material.adhesive_stress: needs work_of_adhesion > 0 (the range "
                   "is work_of_adhesion / sigma_0)");
  const std::string varying =
      "[material]\neffective_modulus = 1.0e6\n"
      "work_of_adhesion = { mean = 0.05, amplitude = 0.2, wavelength = 1e-4 }\n"
      "adhesive_stress = 1e5\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n[loading]\n"
      "preload = { contact_radius = 1e-4 }\nnormal = { control = \"fixed-load\" }\n";
  EXPECT_THROW_MSG(build(varying), SceneError,
                   "md.toml:3:20: material.work_of_adhesion: a work of adhesion that varies with "
                   "the radius is not taken with adhesive_stress (docs/maugis.md \"Scope\")");
  EXPECT_THROW_MSG(build(scene("adhesive_stress = 1e5\napproach_work_of_adhesion = 0.0")),
                   SceneError,
                   "md.toml:6:29: material.approach_work_of_adhesion: not taken with "
                   "adhesive_stress: the Dugdale law is one law both ways, the approach included "
                   "(docs/maugis.md \"Scope\")");
}

TEST(DugdaleReader, RefusesWhatTheLawDoesNotYetTake) {
  const std::string md = "adhesive_stress = 1e5";
  EXPECT_THROW_MSG(build(scene(md, "", "type = \"parabolic\"\nradius = 0.01",
                               "preload = { contact_radius = 1e-4 }\n"
                               "tangential = { control = \"fixed-grips\", displacement = 1e-7 }\n"
                               "normal = { control = \"fixed-load\" }")),
                   SceneError,
                   "md.toml:11:14: loading.tangential: a tangential load is not taken with "
                   "material.adhesive_stress (docs/maugis.md \"Scope\")");
  EXPECT_THROW_MSG(build(scene(md, "[friction]\ncoefficient = 0.5\n")), SceneError,
                   "md.toml:12:1: friction: friction is not taken with material.adhesive_stress "
                   "(docs/maugis.md \"Scope\")");
  EXPECT_THROW_MSG(build(scene(md, "[detachment]\ncriterion = \"mode-mixed\"\n")), SceneError,
                   "md.toml:12:1: detachment: no detachment criterion applies with "
                   "material.adhesive_stress: the Dugdale law's two edge conditions decide where "
                   "the contact and its zone end (docs/maugis.md)");
  EXPECT_THROW_MSG(build(scene(md, "[solver]\nmethod = \"stepping\"\n")), SceneError,
                   "md.toml:13:10: solver.method: material.adhesive_stress is carried by the "
                   "spring row's event method, not by stepping; use method = \"event\" or "
                   "\"continuum\" (docs/maugis.md)");
  const std::string program =
      "rebinding = false\n[[loading.stage]]\nname = \"press\"\n"
      "normal = { control = \"fixed-grips\", to = 1e-6 }";
  EXPECT_THROW_MSG(build(scene(md, "", "type = \"parabolic\"\nradius = 0.01", program)), SceneError,
                   "md.toml:10:13: loading.rebinding: not taken with material.adhesive_stress: the "
                   "Dugdale zone pulls a spring that let go back as it nears (rebinding is "
                   "implied) (docs/maugis.md \"Scope\")");
  // A normal program runs on the continuum route; the spring row and a tangential axis do not
  // take it yet.
  const std::string press =
      "[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = 1e-6 }";
  EXPECT_EQ(build(scene(md, "", "type = \"parabolic\"\nradius = 0.01", press)).plan.engine,
            RouteEngine::continuum);
  EXPECT_THROW_MSG(
      build(scene(md, "[solver]\nmethod = \"event\"\n", "type = \"parabolic\"\nradius = 0.01",
                  press)),
      SceneError,
      "md.toml:14:10: solver.method: loading programs with material.adhesive_stress are not yet "
      "carried by the spring row (method = \"event\"); use method = \"continuum\" "
      "(docs/maugis.md \"Programs\")");
  EXPECT_THROW_MSG(
      build(scene(md, "", "type = \"parabolic\"\nradius = 0.01",
                  press + "\n[[loading.stage]]\nname = \"shear\"\n"
                          "tangential = { control = \"fixed-grips\", by = 1e-6 }")),
      SceneError,
      "md.toml:10:1: loading.stage: stage 'shear': a tangential axis is not taken with "
      "material.adhesive_stress (docs/maugis.md \"Scope\")");
  // With method = "continuum" given, or none, the shorthand runs.
  EXPECT_EQ(build(scene(md, "[solver]\nmethod = \"continuum\"\n")).plan.engine,
            RouteEngine::continuum);
  // rtol without a method keeps the continuum route; method = "event" takes the spring row.
  EXPECT_EQ(build(scene(md, "[discretization]\nrtol = 1e-6\n")).plan.engine,
            RouteEngine::continuum);
  EXPECT_EQ(build(scene(md, "[solver]\nmethod = \"event\"\n")).plan.engine,
            RouteEngine::pull_off_row);
}

}  // namespace
}  // namespace mdrsim::test
