// Reads the scene's [friction] table: the law, how glued springs slide, the shear strength.
#include "engine/scene/friction_reader.hpp"

#include <memory>
#include <string>

namespace mdrsim {

std::optional<FrictionSettings> read_friction(TomlReader& t, const FrictionLawRegistry& laws) {
  const std::string name = t.name("law", laws.names(), std::string("coulomb"));
  check_part_keys(t, "law", name, laws, {"glued", "shear_strength"});
  const auto* entry = laws.find(name);
  const ParameterValues values = t.read_all(entry->parameters);
  const std::shared_ptr<const FrictionLaw> law =
      create_part(t, "law", [&] { return entry->create(values); });
  FrictionSettings settings;
  // One coefficient everywhere runs on the ordered slip keys; any other law spring by spring.
  if (const auto mu = law->uniform_coefficient()) {
    settings.coefficient = *mu;
  } else {
    settings.law = law;
  }
  const std::string glued = t.name("glued", {"unlimited", "coulomb"}, std::string("unlimited"));
  settings.glued = glued == "coulomb" ? GluedShear::limited : GluedShear::unlimited;
  if (t.has("shear_strength") && settings.glued != GluedShear::limited) {
    t.fail_at("shear_strength", "applies only with glued = \"coulomb\"");
  }
  if (settings.glued == GluedShear::limited) {
    if (settings.law) {
      t.fail_at("glued", fmt::format("glued = \"coulomb\" slides at mu f_z with one mu, which law "
                                     "= \"{}\" does not give: use a law with one coefficient",
                                     name));
    }
    settings.shear_strength = t.optional_number({.key = "shear_strength",
                                                 .help = "tau_0 [Pa] >= 0",
                                                 .default_value = 0.0,
                                                 .lower = Bound{0.0, true}})
                                  .value_or(0.0);
  }
  const bool acts =
      settings.law || settings.coefficient > 0.0 || settings.glued == GluedShear::limited;
  if (!acts) return std::nullopt;

  return settings;
}

std::string friction_acting_key(const FrictionSettings& settings) {
  return settings.glued == GluedShear::limited ? "glued" : settings.law ? "law" : "coefficient";
}

}  // namespace mdrsim
