// Registration of the built-in detachment criteria: one explicit call per part.
// Adding a criterion, in three steps:
// 1. Write a class implementing DetachmentCriterion (detachment/criterion.hpp: margin() is
//    required, critical_elongation() optional) that keeps the contract written there (every
//    run samples it), in detachment/NAME_criterion.{hpp,cpp}; list the .cpp in CMakeLists.txt.
// 2. Register it in register_builtin_criteria below with one call: plain<NameCriterion>("NAME",
//    "summary") for a criterion without keys, else as "mode-dependent" is, its keys declared:
//      registry.add({.name = "NAME", .summary = "...", .parameters = {{.key = "lambda", ...,
//                    .example = 0.5}}, .create = [](const ParameterValues& v,
//                    const InterfaceProperties& p) -> std::unique_ptr<DetachmentCriterion> {...}});
// 3. `[detachment] criterion = "NAME"` then works. Give each key an `example`: through
//    engine/reference/part_examples.cpp the tests over every registered criterion build it
//    (tests/engine/pull_off/invariants_test.cpp, tests/engine/model/criterion_contract_test.cpp,
//    tests/engine/scene/registries_test.cpp). Add its row to docs/scene.md's [detachment] table
//    and its closed forms to tests/detachment/criteria_test.cpp.
#include <memory>

#include "detachment/criterion_registry.hpp"
#include "detachment/deformation_criterion.hpp"
#include "detachment/mode_dependent_criterion.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "detachment/normal_only_criterion.hpp"
#include "detachment/stress_criterion.hpp"

namespace mdrsim {
namespace {

template <class Criterion>
CriterionRegistry::Entry plain(std::string name, std::string summary) {
  return {.name = std::move(name),
          .summary = std::move(summary),
          .parameters = {},
          .create = [](const ParameterValues&, const InterfaceProperties& p)
              -> std::unique_ptr<DetachmentCriterion> { return std::make_unique<Criterion>(p); }};
}

}  // namespace

void register_builtin_criteria(CriterionRegistry& registry) {
  registry.add(
      plain<ModeMixedCriterion>("mode-mixed", "E* uz^2 + G* ux^2 >= 2 pi a dgamma (paper eq. 20)"));
  registry.add(plain<DeformationCriterion>("deformation", "sqrt(uz^2 + ux^2) >= dl(a) (eq. 38)"));
  registry.add(plain<StressCriterion>("stress", "sqrt((E* uz)^2 + (G* ux)^2) >= E* dl(a)"));
  registry.add(plain<NormalOnlyCriterion>("normal-only", "|uz| >= dl(a), ux ignored"));
  registry.add({.name = "mode-dependent",
                .summary = "Hutchinson-Suo toughness 2 pi a dgamma (1 + tan^2((1-lambda) psi))",
                .parameters = {{.key = "lambda",
                                .help = "mode sensitivity: 0 = normal-only, 1 = mode-mixed",
                                .lower = Bound{0.0, true},
                                .upper = Bound{1.0, true},
                                .example = 0.5}},
                .create = [](const ParameterValues& v,
                             const InterfaceProperties& p) -> std::unique_ptr<DetachmentCriterion> {
                  return std::make_unique<ModeDependentCriterion>(p, v.number("lambda"));
                }});
}

}  // namespace mdrsim
