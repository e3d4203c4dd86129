// Extreme materials: a work of adhesion near the largest double (the let-go's root search) and
// Poisson ratios at their limits (the master curves with their gamma = G*/E*).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "detachment/mode_mixed_criterion.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "tests/support/pull_off_runs.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::RunResult;
using mdrsim::RunStatus;
using mdrsim::test::gamma_of;
using mdrsim::test::JkrScenario;
using mdrsim::test::run_quietly;

// Without tangential load every criterion reduces to the rule of Hess (eq. 12), so mode-mixed's
// margin with its let-go root-searched (TOMS 748 on the margin, a test-only criterion) and the
// mode-dependent criterion (its own let-go table) must give the critical point of mode-mixed,
// whose let-go is a closed form: to 1e-9 (the search ends within a few eps). Also where the
// margin's own size, 2 pi a dgamma, nears the largest double: dgamma up to 5.1e306 J/m^2 (all
// values of the run stay finite: F0 = 1.2e308 N).
namespace {

/// mode-mixed's margin without its closed form, so that the engine root-finds the let-go
/// (detachment/let_go.cpp: TOMS 748, and bisection where the margin overflows); mode-dependent
/// has a let-go of its own and does not exercise that path.
class MarginOnlyModeMixed : public mdrsim::DetachmentCriterion {
 public:
  explicit MarginOnlyModeMixed(const mdrsim::InterfaceProperties& p) : inner_(p) {}
  double margin(const mdrsim::BoundarySpring& s) const override { return inner_.margin(s); }

 private:
  mdrsim::ModeMixedCriterion inner_;
};

mdrsim::Registries with_margin_only_criterion() {
  auto registries = mdrsim::Registries::builtin();
  registries.criteria.add(
      {.name = "margin-only",
       .summary = "mode-mixed, root-found",
       .create = [](const mdrsim::ParameterValues&, const mdrsim::InterfaceProperties& p)
           -> std::unique_ptr<mdrsim::DetachmentCriterion> {
         return std::make_unique<MarginOnlyModeMixed>(p);
       }});
  return registries;
}

}  // namespace

TEST(EdgeCases, RootSearchAtHugeWorkOfAdhesion) {
  const mdrsim::Registries registries = with_margin_only_criterion();
  for (const double work : {0.05, 1e100, 1e300, 5.1e306}) {
    const auto scene_text = [&](const char* criterion) {
      return fmt::format(
          "[material]\neffective_modulus = 630e6\neffective_shear_modulus = 0.5e6\n"
          "work_of_adhesion = {:.17g}\n[profile]\ntype = \"parabolic\"\nradius = 5.01\n"
          "[loading]\npreload = {{ force = 0.01 }}\nnormal = {{ control = \"fixed-load\" }}\n"
          "[detachment]\ncriterion = \"{}\"\n{}[discretization]\nsprings = 150\n",
          work, criterion, std::string(criterion) == "mode-dependent" ? "lambda = 0.4\n" : "");
    };
    const RunResult closed = run_quietly(mdrsim::test::build_scene_text(scene_text("mode-mixed")));
    const RunResult dependent =
        run_quietly(mdrsim::test::build_scene_text(scene_text("mode-dependent")));
    const RunResult searched = run_quietly(
        mdrsim::SceneDocument::from_text(scene_text("margin-only"), "test.toml").build(registries));
    EXPECT_GT(searched.counts.root_iterations, 0);
    EXPECT_EQ(dependent.critical->springs_in_contact, closed.critical->springs_in_contact) << work;
    EXPECT_NEAR(dependent.critical->normal_force / closed.critical->normal_force, 1.0, 1e-9)
        << "dgamma = " << work;
    ASSERT_TRUE(std::isfinite(closed.critical->normal_force)) << work;
    EXPECT_EQ(searched.critical->springs_in_contact, closed.critical->springs_in_contact) << work;
    EXPECT_NEAR(searched.critical->normal_force / closed.critical->normal_force, 1.0, 1e-9)
        << "dgamma = " << work;
  }
}

// nu = 0.5 (incompressible, G*/E* = 2/3) and nu = -0.999 (G*/E* = 1.333..., E* = 500 E): the
// dimensionless master curves only see gamma = G*/E* (eqs. 25-35), so both must follow them to
// the 2e-3 of the Fig. 3a test (10^4 springs, error about 1.5e-4). The shear limit at the
// preload, u/d0 = sqrt(16 a/a0 / gamma) (eq. 25 with a zero root), moves with gamma.
class ExtremePoissonRatio : public ::testing::TestWithParam<double> {};

TEST_P(ExtremePoissonRatio, FollowsTheMasterCurvesWithItsGamma) {
  const double nu = GetParam();
  const double gamma = gamma_of(nu);
  for (const char* normal : {"fixed-grips", "fixed-load"}) {
    for (const double u : {0.0, 1.0, 2.5, 4.0}) {
      JkrScenario s;
      s.normal = normal;
      s.poisson_ratio = nu;
      s.tangential_displacement = u;
      const RunResult r = run_quietly(s.build());
      ASSERT_EQ(r.status, RunStatus::instability) << normal << " u = " << u;
      const auto want = std::string(normal) == "fixed-grips" ? ref::fixed_grips_critical(u, gamma)
                                                             : ref::fixed_load_critical(u, gamma);
      const auto k = s.scales();
      EXPECT_NEAR(r.critical->normal_force / k.force, want.normal_force, 2e-3)
          << normal << " u = " << u;
      EXPECT_NEAR(r.critical->tangential_force / k.force, want.tangential_force, 2e-3)
          << normal << " u = " << u;
    }
  }
  JkrScenario s;
  s.poisson_ratio = nu;
  s.tangential_displacement = std::sqrt(16.0 * 2.0 / gamma) * 1.01;
  EXPECT_EQ(run_quietly(s.build()).status, RunStatus::shear_off);
  s.tangential_displacement = std::sqrt(16.0 * 2.0 / gamma) * 0.99;
  EXPECT_EQ(run_quietly(s.build()).status, RunStatus::instability);
}

INSTANTIATE_TEST_SUITE_P(Limits, ExtremePoissonRatio, ::testing::Values(0.5, -0.999));
