// material.relaxation: the Prony terms read into the material as plane-strain moduli, and every
// key outside the viscoelastic springs' scope refused in one line at that key (the exact texts).
#include "engine/scene/relaxation_reader.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <string>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "v.toml").build(registries);
}

// A parabola pressed at 1e-4 m/s for 0.2 s and withdrawn at the same speed into an SLS; the line
// numbers in the messages below refer to this text.
const std::string kViscous =
    "[material]\n"
    "youngs_modulus = 1.0e6\n"
    "poisson_ratio = 0.5\n"
    "work_of_adhesion = 0.0\n"
    "relaxation = [ { modulus = 9.0e6, time = 0.1 } ]\n"
    "[profile]\n"
    "type = \"parabolic\"\n"
    "radius = 0.01\n"
    "[[loading.stage]]\n"
    "normal = { control = \"fixed-grips\", to = 2.0e-5 }\n"
    "duration = 0.2\n"
    "[[loading.stage]]\n"
    "normal = { by = -1.0e-4 }\n"
    "until = \"separation\"\n"
    "duration = 1.0\n"
    "[discretization]\n"
    "springs = 100\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// E_i* = E_i / (1 - nu^2) with youngs_modulus; as given with effective_modulus.
TEST(RelaxationReader, ReadsTheTermsAsPlaneStrainModuli) {
  const auto read = [](const std::string& material, double factor) {
    const toml::table table = toml::parse(material);
    TomlReader reader(table, "material", "m.toml", ".");
    return read_relaxation(reader, factor);
  };
  const auto terms =
      read("relaxation = [ { modulus = 9.0e6, time = 0.1 }, { modulus = 2.0e6, time = 3.0 } ]\n",
           4.0 / 3.0);
  ASSERT_TRUE(terms.has_value());
  ASSERT_EQ(terms->size(), 2u);
  EXPECT_DOUBLE_EQ((*terms)[0].modulus, 1.2e7);
  EXPECT_EQ((*terms)[0].time, 0.1);
  EXPECT_DOUBLE_EQ((*terms)[1].modulus, 2.0e6 * 4.0 / 3.0);
  EXPECT_EQ((*terms)[1].time, 3.0);
  EXPECT_FALSE(read("youngs_modulus = 1.0\n", 1.0).has_value());
}

struct Refusal {
  const char* name;
  std::string text;
  const char* message;
};

TEST(RelaxationReader, RefusesOneLineAtTheKey) {
  const Refusal refusals[] = {
      {"ZeroModulus", replaced(kViscous, "modulus = 9.0e6", "modulus = 0.0"),
       "v.toml:5:28: material.relaxation.1.modulus = 0 is outside (0, inf)"},
      {"NegativeTime", replaced(kViscous, "time = 0.1", "time = -0.1"),
       "v.toml:5:42: material.relaxation.1.time = -0.1 is outside (0, inf)"},
      {"UnknownKey", replaced(kViscous, "time = 0.1", "time = 0.1, viscosity = 1.0"),
       "v.toml:5:47: material.relaxation.1.viscosity: unknown key (known: modulus, time)"},
      {"NotATable", replaced(kViscous, "[ { modulus = 9.0e6, time = 0.1 } ]", "9.0e6"),
       "v.toml:5:14: material.relaxation: expected an array of tables ([[material.relaxation]]), "
       "got 9000000"},
      {"Shorthand",
       replaced(kViscous,
                "[[loading.stage]]\nnormal = { control = \"fixed-grips\", to = 2.0e-5 }\nduration "
                "= 0.2\n[[loading.stage]]\nnormal = { by = -1.0e-4 }\nuntil = "
                "\"separation\"\nduration = 1.0\n",
                "[loading]\npreload = { depth = 2.0e-5 }\nnormal = { control = \"fixed-grips\" "
                "}\n"),
       "v.toml:5:14: material.relaxation: needs a loading program whose stages all have a duration "
       "or speed; the shorthand has no clock (docs/viscoelastic.md \"What it refuses\")"},
      {"Untimed", replaced(replaced(kViscous, "duration = 0.2\n", ""), "duration = 1.0\n", ""),
       "v.toml:5:14: material.relaxation: needs every loading stage to have a duration or speed "
       "(docs/viscoelastic.md \"What it refuses\")"},
      {"CoulombGlue", kViscous + "[friction]\ncoefficient = 0.3\nglued = \"coulomb\"\n",
       "v.toml:20:9: friction.glued: glued = \"coulomb\" is not yet taken with material.relaxation "
       "(docs/viscoelastic.md \"What it refuses\")"},
      // Slips are located along fixed grips only.
      {"FrictionUnderAHeldForce",
       replaced(replaced(kViscous + "[friction]\ncoefficient = 0.3\n", "normal = { by = -1.0e-4 }",
                         "normal = { control = \"fixed-load\", by = -1.0e-3 }"),
                "work_of_adhesion = 0.0\n", "work_of_adhesion = 0.05\n"),
       "v.toml:19:15: friction.coefficient: friction under a normal control other than fixed "
       "grips (loading.stage.2: \"fixed-load\") is not yet taken with material.relaxation "
       "(docs/viscoelastic.md \"What it refuses\")"},
      {"AdhesiveStress",
       replaced(kViscous, "work_of_adhesion = 0.0\n",
                "work_of_adhesion = 0.05\nadhesive_stress = 1.0e5\n"),
       "v.toml:5:19: material.adhesive_stress: finite-range adhesion is not taken with "
       "material.relaxation (docs/viscoelastic.md \"What it refuses\")"},
      {"Grading",
       replaced(kViscous, "work_of_adhesion = 0.0\n",
                "work_of_adhesion = 0.0\ngrading = { exponent = 0.5, depth = 1e-3 }\n"),
       "v.toml:5:11: material.grading: a graded half-space is not yet taken with "
       "material.relaxation (docs/viscoelastic.md \"What it refuses\")"},
      // A tangential axis runs under fixed grips, or holds a force or a machine spring's end on
      // a glue: not without adhesion, nor with friction.
      {"TangentialHeldForceWithoutAdhesion",
       replaced(kViscous, "until = \"separation\"\n",
                "tangential = { control = \"fixed-load\", by = 1e-3 }\nuntil = "
                "\"separation\"\n"),
       "v.toml:9:1: loading.stage: loading.stage.2: a tangential \"fixed-load\" control without "
       "adhesion is not yet taken with material.relaxation (docs/viscoelastic.md \"What it "
       "refuses\")"},
      {"TangentialHeldForceWithFriction",
       replaced(replaced(replaced(kViscous, "work_of_adhesion = 0.0", "work_of_adhesion = 0.05"),
                         "until = \"separation\"\n",
                         "tangential = { control = \"fixed-load\", by = 1e-3 }\nuntil = "
                         "\"separation\"\n"),
                "springs = 100\n", "springs = 100\n[friction]\ncoefficient = 0.5\n"),
       "v.toml:20:15: friction.coefficient: friction under a tangential control other than fixed "
       "grips (loading.stage.2: \"fixed-load\") is not yet taken with material.relaxation "
       "(docs/viscoelastic.md \"What it refuses\")"},
      {"Continuum", kViscous + "[solver]\nmethod = \"continuum\"\n",
       "v.toml:19:10: solver.method: a method other than \"event\" is not yet taken with "
       "material.relaxation (docs/viscoelastic.md \"What it refuses\")"},
  };
  for (const Refusal& r : refusals) {
    EXPECT_THROW_MSG(build(r.text), SceneError, r.message) << r.name;
  }
  // Within the scope the scene is built, its terms in the material.
  EXPECT_EQ(build(kViscous).material.relaxation.size(), 1u);
  // A fixed load lowered, to zero or until separation without adhesion: the contact is lost at
  // zero force (docs/viscoelastic.md).
  EXPECT_NO_THROW(build(replaced(kViscous, "normal = { by = -1.0e-4 }",
                                 "normal = { control = \"fixed-load\", by = -1.0e-3 }")));
  EXPECT_NO_THROW(build(replaced(kViscous, "normal = { control = \"fixed-grips\", to = 2.0e-5 }",
                                 "normal = { control = \"fixed-load\", to = 0.0 }")));
  // A tangential fixed-grips stage is within it under any normal control: under normal
  // fixed grips, under a held force, and a held force after a shear.
  EXPECT_NO_THROW(build(replaced(kViscous, "until = \"separation\"\n",
                                 "tangential = { control = \"fixed-grips\", by = 1e-6 }\n"
                                 "until = \"separation\"\n")));
  EXPECT_NO_THROW(
      build(replaced(replaced(kViscous, "normal = { control = \"fixed-grips\", to = 2.0e-5 }",
                              "normal = { control = \"fixed-load\", to = 0.05 }"),
                     "normal = { by = -1.0e-4 }\nuntil = \"separation\"\n",
                     "tangential = { control = \"fixed-grips\", by = 1e-6 }\n")));
  EXPECT_NO_THROW(
      build(replaced(replaced(kViscous, "work_of_adhesion = 0.0", "work_of_adhesion = 0.05"),
                     "normal = { by = -1.0e-4 }\nuntil = \"separation\"\nduration = 1.0\n",
                     "tangential = { control = \"fixed-grips\", by = 1e-6 }\nduration = 1.0\n"
                     "[[loading.stage]]\nnormal = { control = \"fixed-load\", by = -1e-3 }\n"
                     "until = \"separation\"\nduration = 1.0\n")));
  // A held tangential force on a glue is within it, pulled off under fixed grips or a fixed
  // load.
  EXPECT_NO_THROW(
      build(replaced(replaced(kViscous, "work_of_adhesion = 0.0", "work_of_adhesion = 0.05"),
                     "normal = { by = -1.0e-4 }\nuntil = \"separation\"\n",
                     "tangential = { control = \"fixed-load\", to = 1e-3 }\nduration = 1.0\n"
                     "[[loading.stage]]\nnormal = { control = \"fixed-load\", by = -1e-3 }\n"
                     "until = \"separation\"\n")));
  EXPECT_NO_THROW(
      build(replaced(replaced(kViscous, "work_of_adhesion = 0.0", "work_of_adhesion = 0.05"),
                     "until = \"separation\"\n",
                     "tangential = { control = \"fixed-load\", by = 1e-3 }\n"
                     "until = \"separation\"\n")));
  // So is a tangential machine spring.
  EXPECT_NO_THROW(
      build(replaced(replaced(kViscous, "work_of_adhesion = 0.0", "work_of_adhesion = 0.05"),
                     "until = \"separation\"\n",
                     "tangential = { control = \"compliant\", stiffness = 1e3, by = 1e-6 }\n"
                     "until = \"separation\"\n")));
  // A held force that stays pressing and a machine spring are within it.
  EXPECT_NO_THROW(build(replaced(
      replaced(kViscous, "normal = { control = \"fixed-grips\", to = 2.0e-5 }",
               "normal = { control = \"fixed-load\", to = 0.05 }"),
      "normal = { by = -1.0e-4 }", "normal = { control = \"fixed-grips\", by = -1.0e-4 }")));
  EXPECT_NO_THROW(
      build(replaced(kViscous, "normal = { by = -1.0e-4 }",
                     "normal = { control = \"compliant\", stiffness = 1e3, by = -1e-4 }")));
  // Adhesion under fixed grips is within it: the criterion then sees the glassy modulus.
  const Scene adhesive =
      build(replaced(kViscous, "work_of_adhesion = 0.0", "work_of_adhesion = 0.05"));
  EXPECT_EQ(adhesive.material.work_of_adhesion, 0.05);
  // rtol alone and Richardson refine the viscoelastic row (the continuum route has no relaxing
  // bulk, so rtol alone does not choose it).
  const Scene by_rtol = build(replaced(kViscous, "springs = 100", "rtol = 1e-3"));
  EXPECT_EQ(by_rtol.plan.engine, RouteEngine::program_row);
  EXPECT_EQ(by_rtol.plan.driver, RouteDriver::rtol);
  const Scene by_richardson =
      build(replaced(kViscous, "springs = 100", "springs = 100\nextrapolation = \"richardson\""));
  EXPECT_EQ(by_richardson.plan.engine, RouteEngine::program_row);
  EXPECT_EQ(by_richardson.plan.driver, RouteDriver::richardson);
}

}  // namespace
}  // namespace mdrsim::test
