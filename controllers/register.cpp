// Registration of the built-in controllers: one explicit call per part.
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
