// TOML text of the JKR test scenes, at full precision.
#include "engine/reference/jkr_scenario.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "engine/base/material.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim::test {

JkrScales JkrScenario::scales() const {
  const Material m = Material::from_youngs_modulus(youngs_modulus, poisson_ratio, work_of_adhesion);
  const auto s = JkrScales::of(radius, m.effective_modulus, work_of_adhesion);
  if (!s) throw std::invalid_argument("JkrScenario: no JKR scales without adhesion");
  return *s;
}

std::string JkrScenario::toml() const {
  const JkrScales s = scales();
  std::string text = fmt::format(
      "[material]\nyoungs_modulus = {:.17g}\npoisson_ratio = {:.17g}\nwork_of_adhesion = {:.17g}\n"
      "[profile]\ntype = \"parabolic\"\nradius = {:.17g}\n"
      "[loading]\npreload = {{ contact_radius = {:.17g} }}\n"
      "normal = {{ control = \"{}\"{}{} }}\n",
      youngs_modulus, poisson_ratio, work_of_adhesion, radius, glued_radius * s.radius, normal,
      normal_extra.empty() ? "" : ", ", normal_extra);
  if (tangential_displacement) {
    text += fmt::format("tangential = {{ control = \"fixed-grips\", displacement = {:.17g} }}\n",
                        *tangential_displacement * s.depth);
  } else if (tangential_force) {
    text += fmt::format("tangential = {{ control = \"fixed-load\", force = {:.17g} }}\n",
                        *tangential_force * s.force);
  }
  text += fmt::format("[detachment]\ncriterion = \"{}\"\n{}\n", criterion, criterion_extra);
  text += "[discretization]\n";
  if (richardson) text += "extrapolation = \"richardson\"\n";
  text += rtol ? fmt::format("rtol = {:.17g}\n", *rtol) : fmt::format("springs = {}\n", springs);
  text += fmt::format("[solver]\nmethod = \"{}\"\n{}\n", method, solver_extra);
  return text;
}

Scene JkrScenario::build() const { return build_scene_text(toml()); }

Scene build_scene_text(std::string_view text) {
  return SceneDocument::from_text(text, "test.toml").build(Registries::builtin());
}

RunResult run_quietly(const Scene& scene) { return run_pull_off(scene, ObserverList{}); }

}  // namespace mdrsim::test
