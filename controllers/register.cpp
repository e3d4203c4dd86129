// Registration of the built-in controllers: one explicit call per part.
// Adding a controller, in three steps:
// 1. Write a class implementing AxisController (controllers/controller.hpp: constraint() and
//    held_value_key() are required; holds_force() and the other questions follow from the
//    constraint unless overridden) in controllers/builtin_controllers.hpp.
// 2. Register it in register_builtin_controllers below with one call, its keys declared:
//      registry.add({.name = "NAME", .summary = "...", .parameters = {{.key = "stiffness",
//                    .help = "k [N/m]", .lower = Bound{0.0, false}, .example = 1000.0}},
//                    .create = [](const ParameterValues& p)
//                        -> std::unique_ptr<AxisController> {...}});
// 3. `control = "NAME"` on an axis then works. Give each key an `example`: through
//    engine/reference/part_examples.cpp the tests over every registered controller build it
//    (tests/engine/pull_off/invariants_test.cpp, tests/engine/scene/registries_test.cpp;
//    bench/pull_off_bench.cpp times each). Add its row to docs/scene.md's controller table and
//    its name to tests/controllers/controller_test.cpp, which lists the registry's names.
#include <memory>

#include "controllers/builtin_controllers.hpp"
#include "controllers/controller_registry.hpp"

namespace mdrsim {

void register_builtin_controllers(ControllerRegistry& registry) {
  registry.add({.name = "fixed-grips",
                .summary = "holds the displacement of its axis",
                .parameters = {},
                .create = [](const ParameterValues&) -> std::unique_ptr<AxisController> {
                  return std::make_unique<FixedGripsController>();
                }});
  registry.add({.name = "fixed-load",
                .summary = "holds the force on its axis",
                .parameters = {},
                .create = [](const ParameterValues&) -> std::unique_ptr<AxisController> {
                  return std::make_unique<FixedLoadController>();
                }});
  registry.add({.name = "compliant",
                .summary = "drives the axis through a machine spring of stiffness k",
                .parameters = {{.key = "stiffness",
                                .help = "machine stiffness k [N/m]",
                                .lower = Bound{0.0, false},
                                .example = 1000.0}},  // about F0/d0 of the JKR test scene
                .create = [](const ParameterValues& p) -> std::unique_ptr<AxisController> {
                  return std::make_unique<CompliantController>(p.number("stiffness"));
                }});
}

}  // namespace mdrsim
