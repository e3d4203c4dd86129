// material.grading: read into the material with its constant, and every key outside the graded
// half-space's scope refused in one line at that key (the exact texts).
#include "engine/scene/grading_reader.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <string>

#include "engine/model/graded_constants.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "g.toml").build(registries);
}

const char* kGraded =
    "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n"
    "grading = { exponent = 0.5, depth = 1.0e-3 }\n[profile]\ntype = \"parabolic\"\n"
    "radius = 0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\n"
    "normal = { control = \"fixed-load\" }\n";

TEST(GradingReader, ReadsTheKeyAndTakesTheContinuumRoute) {
  const Scene s = build(kGraded);
  EXPECT_EQ(s.material.grading.exponent, 0.5);
  EXPECT_EQ(s.material.grading.depth, 1.0e-3);
  EXPECT_EQ(s.material.grading.punch_constant,
            graded_punch_constant(s.material.grading, 1.0e6, 0.3));
  ASSERT_TRUE(s.graded_image);
  EXPECT_EQ(s.solver.method, SolverMethod::continuum);
  EXPECT_EQ(s.plan.engine, RouteEngine::continuum);
  // method = "continuum" named is taken as well.
  EXPECT_EQ(build(std::string(kGraded) + "[solver]\nmethod = \"continuum\"\n").plan.engine,
            RouteEngine::continuum);
}

TEST(GradingReader, EventMethodTakesTheGradedRow) {
  const Scene s = build(std::string(kGraded) + "[solver]\nmethod = \"event\"\n");
  EXPECT_EQ(s.solver.method, SolverMethod::event);
  EXPECT_EQ(s.plan.engine, RouteEngine::pull_off_row);
  // The resolved form names the row and leaves out [detachment]: it builds the scene again.
  EXPECT_EQ(s.resolved->at("solver").at("method"), "event");
  EXPECT_FALSE(s.resolved->contains("detachment"));
}

TEST(GradingReader, SphereTableAndWavyTakeTheQuadratureImage) {
  // The shapes with no closed form: an image by quadrature (a table of the parabola gives the
  // parabola's x^2 / ((1 + k) R) at its glued radius, 1e-10); a ripple of amplitude 0 is the
  // parabola's closed form. On the row: the continuum route refuses the ripple's many folds.
  for (const std::string profile : {"type = \"sphere\"\nradius = 0.01",
                                    "type = \"wavy\"\nradius = 0.01\namplitude = 1e-7\n"
                                    "wavelength = 1e-4",
                                    "type = \"tabulated\"\nr = [0.0, 2e-4, 4e-4, 6e-4, 8e-4]\n"
                                    "f = [0.0, 2e-6, 8e-6, 1.8e-5, 3.2e-5]"}) {
    SCOPED_TRACE(profile);
    std::string text(kGraded);
    text.replace(text.find("type = \"parabolic\"\nradius = 0.01"), 32, profile);
    const Scene s = build(text + "[solver]\nmethod = \"event\"\n");
    ASSERT_TRUE(s.graded_image);
    EXPECT_TRUE(s.graded_image->quadrature());
    if (profile.find("tabulated") != std::string::npos) {
      EXPECT_NEAR(s.graded_image->image(5e-4) / (5e-4 * 5e-4 / (1.5 * 0.01)), 1.0, 1e-10);
    }
  }
  std::string flat(kGraded);
  flat.replace(flat.find("type = \"parabolic\"\nradius = 0.01"), 32,
               "type = \"wavy\"\nradius = 0.01\namplitude = 0.0\nwavelength = 1e-4");
  const Scene s = build(flat);
  ASSERT_TRUE(s.graded_image);
  EXPECT_FALSE(s.graded_image->quadrature());
}

TEST(GradingReader, ExponentZeroKeepsTheRow) {
  std::string text(kGraded);
  text.replace(text.find("exponent = 0.5"), 14, "exponent = 0.0");
  const Scene s = build(text);
  EXPECT_FALSE(s.material.grading.graded());
  EXPECT_FALSE(s.graded_image);
  EXPECT_EQ(s.plan.engine, RouteEngine::pull_off_row);
}

struct Refusal {
  const char* name;
  const char* text;
  const char* message;
};

TEST(GradingReader, RefusesOneLineAtTheKey) {
  const Refusal refusals[] = {
      {"ExponentAtOne",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 1.0, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\n",
       "g.toml:5:24: material.grading.exponent = 1 is outside [0, 1)"},
      {"NegativeExponent",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = -0.1, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\n",
       "g.toml:5:24: material.grading.exponent = -0.1 is outside [0, 1)"},
      {"DepthZero",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 0.0 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\n",
       "g.toml:5:37: material.grading.depth = 0 is outside (0, inf)"},
      {"UnknownSubKey",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3, modulus = 2 }\n\n[profile]\ntype = "
       "\"parabolic\"\nradius = 0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { "
       "control = \"fixed-load\" }\n",
       "g.toml:5:45: material.grading.modulus: unknown key (known: depth, exponent)"},
      {"EffectiveModulus",
       "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\ngrading = { exponent = "
       "0.5, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\n",
       "g.toml:4:11: material.grading: needs youngs_modulus and poisson_ratio, not "
       "effective_modulus: the graded constant depends on nu itself (docs/graded.md)"},
      {"TangentialLoad",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\ntangential = { control = \"fixed-grips\", displacement = 1e-6 }\n",
       "g.toml:13:14: loading.tangential: a tangential load is not taken with material.grading "
       "(docs/graded.md \"What it refuses\")"},
      {"Friction",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\n[friction]\ncoefficient = 0.3",
       "g.toml:13:1: friction: friction is not taken with material.grading (docs/graded.md \"What "
       "it refuses\")"},
      {"Detachment",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = "
       "\"fixed-load\" }\n[detachment]\ncriterion = \"mode-mixed\"",
       "g.toml:13:1: detachment: no detachment criterion applies with material.grading: the "
       "boundary spring lets go by Hess's rule on the graded springs (docs/graded.md)"},
      {"AdhesiveStress",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\nadhesive_stress = 1.0e5\n[profile]\ntype = "
       "\"parabolic\"\nradius = 0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { "
       "control = \"fixed-load\" }\n",
       "g.toml:6:19: material.adhesive_stress: finite-range adhesion is not yet taken with "
       "material.grading (docs/graded.md \"What it refuses\")"},
      {"MaugisParameter",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\nmaugis_parameter = 1.0\n[profile]\ntype = "
       "\"parabolic\"\nradius = 0.01\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { "
       "control = \"fixed-load\" }\n",
       "g.toml:6:20: material.maugis_parameter: finite-range adhesion is not yet taken with "
       "material.grading (docs/graded.md \"What it refuses\")"},
      {"AdhesionByRadius",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = { r = [0.0, "
       "1.0e-3], value = [0.05, 0.06] }\ngrading = { exponent = 0.5, depth = 1.0e-3 "
       "}\n\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n[loading]\npreload = { contact_radius "
       "= 5.0e-4 }\nnormal = { control = \"fixed-load\" }\n",
       "g.toml:4:20: material.work_of_adhesion: a work of adhesion that varies with the radius is "
       "not yet taken with material.grading (docs/graded.md \"What it refuses\")"},
      {"TangentialStage",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\n[[loading.stage]]\nnormal = { control = \"fixed-grips\", to = 1e-5 }\n"
       "[[loading.stage]]\nname = \"shear\"\ntangential = { control = \"fixed-grips\", by = 1e-6 "
       "}\n",
       "g.toml:11:1: loading.stage: stage 'shear': a tangential axis is not taken with "
       "material.grading (docs/graded.md \"What it refuses\")"},
      {"ApproachByRadius",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n"
       "approach_work_of_adhesion = { mean = 0.03, amplitude = 0.01, wavelength = 1e-4 }\ngrading "
       "= { exponent = 0.5, depth = 1.0e-3 }\n\n[profile]\ntype = \"parabolic\"\nradius = "
       "0.01\n[loading]\n[[loading.stage]]\nnormal = { control = \"fixed-grips\", to = 1e-5 }\n",
       "g.toml:5:29: material.approach_work_of_adhesion: an approach work of adhesion that varies "
       "with the radius is not yet taken with material.grading (docs/graded.md \"What it "
       "refuses\")"},
      {"Springs",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = "
       "0.05\ngrading = { exponent = 0.5, depth = 1.0e-3 }\n\n[profile]\ntype = "
       "\"parabolic\"\nradius = 0.01\n[loading]\npreload = { contact_radius = 5.0e-4 "
       "}\nnormal = { control = \"fixed-load\" }\n[discretization]\nsprings = 1000",
       "g.toml:14:11: discretization.springs: the continuum route has no springs; give rtol "
       "(default 1e-10) or use solver.method = \"event\""},
  };
  for (const Refusal& r : refusals) {
    SCOPED_TRACE(r.name);
    EXPECT_THROW_MSG(build(r.text), SceneError, r.message);
  }
}

}  // namespace
}  // namespace mdrsim::test
