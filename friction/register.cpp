// Registration of the built-in friction law: one explicit call per part.
// Adding a friction law, in three steps:
// 1. Write a class implementing FrictionLaw (friction/friction_law.hpp: limit_at() is required;
//    uniform_coefficient() only for Coulomb's form, which runs on the ordered slip keys) in
//    friction/NAME_friction.hpp (a .cpp listed in friction/CMakeLists.txt).
// 2. Register it in register_builtin_friction_laws below with one call, its keys declared:
//      registry.add({.name = "NAME", .summary = "...", .parameters = {{.key = "coefficient",
//                    .help = "mu >= 0", .lower = Bound{0.0, true}, .example = 0.5}},
//                    .create = [](const ParameterValues& p) -> std::unique_ptr<FrictionLaw> {
//                      ...}});
// 3. `[friction] law = "NAME"` then works. Give each key an `example`:
//    tests/engine/scene/registries_test.cpp (EveryFrictionLawRunsAProgram) runs every registered
//    law from them against the row's Coulomb force, mu its one key (a law of another form adds its
//    own expectation there). Add it to docs/friction.md "Friction laws".
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
