// Registration of the built-in friction law: one explicit call per part.
#include <memory>

#include "friction/coulomb_friction.hpp"
#include "friction/friction_law_registry.hpp"

namespace mdrsim {

void register_builtin_friction_laws(FrictionLawRegistry& registry) {
  registry.add({.name = "coulomb",
                .summary = "slides at mu max(f_z, 0), one coefficient everywhere",
                .parameters = {{.key = "coefficient",
                                .help = "Coulomb coefficient mu >= 0",
                                .lower = Bound{0.0, true},
                                .example = 0.5}},
                .create = [](const ParameterValues& p) -> std::unique_ptr<FrictionLaw> {
                  return std::make_unique<CoulombFriction>(p.number("coefficient"));
                }});
}

}  // namespace mdrsim
