// Reads the scene's [friction] table and refuses what the friction engine does not run yet.
#include "engine/scene/friction_reader.hpp"

#include <fmt/format.h>

#include <string>

namespace mdrsim {

std::optional<FrictionSettings> read_friction(TomlReader& t, const Scene& scene) {
  t.check_keys({"coefficient", "glued", "shear_strength"});
  FrictionSettings settings;
  settings.coefficient = t.number(
      {.key = "coefficient", .help = "Coulomb coefficient mu >= 0", .lower = Bound{0.0, true}});
  const std::string glued = t.name("glued", {"unlimited", "coulomb"}, std::string("unlimited"));
  settings.glued = glued == "coulomb" ? GluedLaw::coulomb : GluedLaw::unlimited;
  if (t.has("shear_strength") && settings.glued != GluedLaw::coulomb) {
    t.fail_at("shear_strength", "applies only with glued = \"coulomb\"");
  }
  if (settings.glued == GluedLaw::coulomb) {
    settings.shear_strength = t.optional_number({.key = "shear_strength",
                                                 .help = "tau_0 [Pa] >= 0",
                                                 .default_value = 0.0,
                                                 .lower = Bound{0.0, true}})
                                  .value_or(0.0);
  }
  const bool acts = settings.coefficient > 0.0 || settings.glued == GluedLaw::coulomb;
  if (!acts) return std::nullopt;

  // What the friction engine does not run yet: refused with the reason, never ignored.
  const std::string key = settings.glued == GluedLaw::coulomb ? "glued" : "coefficient";
  if (settings.glued == GluedLaw::coulomb) {
    t.fail_at("glued",
              "glued = \"coulomb\" is not run yet (issue 21): use glued = \"unlimited\" "
              "(docs/friction.md)");
  }
  if (scene.solver.method != SolverMethod::event) {
    t.fail_at(key, "friction runs with solver.method = \"event\" only");
  }
  // A held F_x with glue: a let-go would move u_x within the jump, past other springs' limits,
  // which the program loop does not solve yet.
  if (!scene.program && scene.tangential && !scene.tangential->controller->is_fixed_grips() &&
      scene.material.work_of_adhesion > 0.0) {
    t.fail_at(key, fmt::format("the shorthand holds the tangential axis with control = \"{}\": "
                               "with adhesion (work_of_adhesion > 0) friction runs with a "
                               "fixed-grips tangential axis only (u_x driven) so far",
                               scene.tangential->control));
  }
  if (!scene.program) return settings;  // the shorthand runs as its program (scene_builder)
  for (const Stage& stage : scene.program->stages) {
    if (stage.tangential && !stage.tangential->controller->is_fixed_grips() &&
        scene.material.work_of_adhesion > 0.0) {
      t.fail_at(key, fmt::format("stage '{}' drives the tangential axis with control = \"{}\": "
                                 "with adhesion (work_of_adhesion > 0) friction runs with a "
                                 "fixed-grips tangential axis only (u_x driven) so far",
                                 stage.name, stage.tangential->control));
    }
  }
  return settings;
}

}  // namespace mdrsim
