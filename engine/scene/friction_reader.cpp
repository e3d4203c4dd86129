// Reads the scene's [friction] table and refuses what the friction engine does not run.
#include "engine/scene/friction_reader.hpp"

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

  // What the friction engine does not run: refused with the reason, never ignored.
  const std::string key = settings.glued == GluedLaw::coulomb ? "glued" : "coefficient";
  if (scene.solver.method != SolverMethod::event) {
    t.fail_at(key, "friction runs with solver.method = \"event\" only");
  }
  return settings;
}

}  // namespace mdrsim
