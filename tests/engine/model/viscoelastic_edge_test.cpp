// The viscoelastic edge's per-spring rules against their closed forms: every built-in criterion,
// built on the glassy material, lets a spring with no tangential displacement go at
// |q| = sqrt(2 pi x dgamma E_0); the glue gap is sqrt(2 pi x dgamma_a / E_0); a glassy step
// moves each arm by E_j times it.
#include "engine/model/viscoelastic_edge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "engine/scene/registries.hpp"

namespace mdrsim {
namespace {

Material relaxing_material() {
  Material m = Material::from_youngs_modulus(1.0e6, 0.5, 0.05);
  m.approach_work_of_adhesion = 0.02;
  m.relaxation = {{9.0e6, 0.1}, {3.0e6, 2.0}};
  return m;
}

TEST(ViscoelasticEdge, EveryCriterionLetsGoAtTheGlassyHessLoadWithoutShear) {
  const Material m = relaxing_material();
  const Material glassy = glassy_material(m);
  const double e0 = m.effective_modulus + 12.0e6;
  EXPECT_DOUBLE_EQ(glassy.effective_modulus, e0);
  EXPECT_DOUBLE_EQ(glassy.effective_shear_modulus,
                   m.effective_shear_modulus * e0 / m.effective_modulus);
  const Registries registries = Registries::builtin();
  const double dx = 1.0e-5;
  const std::size_t n = 50;
  std::printf("%16s  largest |q - sqrt(2 pi x dgamma E_0)| / that, %zu springs\n", "criterion", n);
  for (const std::string& name : registries.criteria.names()) {
    const auto* entry = registries.criteria.find(name);
    ParameterValues values;  // each parameter at its default, or its example
    for (const ParameterSpec& spec : entry->parameters) {
      if (const auto v = spec.default_value ? spec.default_value : spec.example) {
        values.set(spec.key, *v);
      }
    }
    const auto criterion = entry->create(values, glassy);
    const ViscoelasticEdge edge = viscoelastic_edge(*criterion, m, dx, n, false);
    ASSERT_EQ(edge.let_go_loads.size(), n);
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = dx * static_cast<double>(i + 1);
      const double hess = std::sqrt(2.0 * std::numbers::pi * x * 0.05 * e0);
      worst = std::max(worst, std::abs(edge.let_go_loads[i] - hess) / hess);
      EXPECT_NEAR(edge.glue_gaps[i], std::sqrt(2.0 * std::numbers::pi * x * 0.02 / e0),
                  1e-15 * std::sqrt(2.0 * std::numbers::pi * x * 0.02 / e0));
      EXPECT_NEAR(edge.surface_energies[i], std::numbers::pi * x * 0.05, 1e-15 * x);
    }
    std::printf("%16s  %.2e\n", name.c_str(), worst);
    // A closed form or a root to the criterion's own tolerance.
    EXPECT_LT(worst, 1e-9) << name;
  }
}

TEST(ViscoelasticEdge, AGlassyStepMovesEachArmByItsModulus) {
  const std::vector<PronyTerm> terms{{9.0e6, 0.1}, {3.0e6, 2.0}};
  std::vector<double> stresses{1.0, -2.0};
  glassy_step(stresses, terms, -1.0e-6);
  EXPECT_DOUBLE_EQ(stresses[0], 1.0 - 9.0);
  EXPECT_DOUBLE_EQ(stresses[1], -2.0 - 3.0);
}

}  // namespace
}  // namespace mdrsim
