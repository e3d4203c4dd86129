// Physical invariants run over every registered criterion and controller (Project Chrono's habit).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "controllers/controller.hpp"
#include "engine/events/event_recorder.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/part_examples.hpp"
#include "engine/scene/registries.hpp"

using mdrsim::Event;
using mdrsim::EventKind;
using mdrsim::test::JkrScenario;

namespace {

JkrScenario scenario_for(const std::string& criterion, const std::string& normal) {
  JkrScenario s;
  s.springs = 300;
  s.criterion = criterion;
  s.criterion_extra = mdrsim::test::example_keys("criterion", criterion, "\n");
  s.normal = normal;
  s.normal_extra = mdrsim::test::example_keys("controller", normal, ", ");
  s.tangential_displacement = 1.5;
  s.poisson_ratio = 0.3;  // G* != E*, so that the criteria differ
  return s;
}

/// 2 E* dx sum_{i<=n} (d - g(x_i)) by brute force over the attached springs.
double brute_force_normal_force(const mdrsim::Scene& scene, double d, std::int64_t n) {
  const double dx = scene.glued_radius / static_cast<double>(scene.springs);
  double sum = 0.0;
  for (std::int64_t i = 1; i <= n; ++i) {
    sum += d - scene.profile->mdr_image(scene.glued_radius * static_cast<double>(i) /
                                        static_cast<double>(scene.springs));
  }
  return 2.0 * scene.material.effective_modulus * dx * sum;
}

}  // namespace

class EveryPart
    : public ::testing::TestWithParam<std::tuple<std::string, std::string, std::string>> {};

TEST_P(EveryPart, EventsAreEquilibriaAtZeroMarginWithMonotoneControl) {
  const auto& [criterion, normal, method] = GetParam();
  JkrScenario s = scenario_for(criterion, normal);
  s.method = method;
  const mdrsim::Scene scene = s.build();
  mdrsim::EventRecorder recorder;
  mdrsim::ObserverList observers;
  observers.add(recorder);
  const auto result = mdrsim::run_pull_off(scene, observers);
  ASSERT_EQ(result.status, mdrsim::RunStatus::instability);

  const mdrsim::AffineConstraint c = scene.normal.controller->constraint();
  const double force_scale = s.scales().force;
  double last_control = INFINITY;
  int equilibria = 0;
  for (const Event& e : recorder.events()) {
    const auto& st = e.state;
    for (const double v : {st.indentation, st.normal_force, st.contact_radius,
                           st.tangential_displacement, st.tangential_force, st.normal_control}) {
      ASSERT_TRUE(std::isfinite(v)) << static_cast<int>(e.kind);
    }
    if (e.kind != EventKind::spring_detached) continue;
    // Monotone control: pulling only ever lowers the held value.
    EXPECT_LE(st.normal_control, last_control);
    last_control = st.normal_control;
    // Equilibrium: the spring sum and the controller's constraint.
    EXPECT_NEAR(st.normal_force,
                brute_force_normal_force(scene, st.indentation, st.springs_in_contact),
                1e-10 * force_scale);
    EXPECT_NEAR(
        c.displacement_coefficient * st.indentation + c.force_coefficient * st.normal_force,
        st.normal_control,
        1e-12 * std::abs(st.normal_control) + 1e-12 * force_scale * c.force_coefficient + 1e-20);
    if (e.in_cascade || method != "event") continue;
    // The event method stops exactly where the boundary spring's margin reaches zero.
    const double stretch = scene.profile->mdr_image(st.contact_radius) - st.indentation;
    const double capacity = scene.criterion->margin({0.0, 0.0, st.contact_radius});
    const double margin = scene.criterion->margin(
        {std::max(stretch, 0.0), st.tangential_displacement, st.contact_radius});
    EXPECT_LE(std::abs(margin), 1e-9 * capacity) << "spring " << e.spring;
    EXPECT_GT(scene.criterion->margin({std::max(stretch, 0.0) * (1 - 1e-6),
                                       st.tangential_displacement, st.contact_radius}),
              0.0);
    ++equilibria;
  }
  if (method == "event") {
    EXPECT_GT(equilibria, 10);
  }
}

std::vector<std::tuple<std::string, std::string, std::string>> every_combination() {
  const auto registries = mdrsim::Registries::builtin();
  std::vector<std::tuple<std::string, std::string, std::string>> out;
  for (const auto& criterion : registries.criteria.names()) {
    for (const auto& controller : registries.controllers.names()) {
      for (const char* method : {"event", "stepping"})
        out.emplace_back(criterion, controller, method);
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryPart, ::testing::ValuesIn(every_combination()),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param) + "_" +
                                              std::get<1>(info.param) + "_" +
                                              std::get<2>(info.param);
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

// With E* = G* (nu = 0) mode-mixed, deformation and stress are the same rule (docs).
TEST(CriteriaAgree, ModeMixedDeformationAndStressCoincideAtNuZero) {
  double forces[3];
  int i = 0;
  for (const char* criterion : {"mode-mixed", "deformation", "stress"}) {
    JkrScenario s;
    s.criterion = criterion;
    s.tangential_displacement = 2.0;
    s.springs = 2000;
    forces[i++] = mdrsim::test::run_quietly(s.build()).critical->normal_force;
  }
  EXPECT_DOUBLE_EQ(forces[0], forces[1]);
  EXPECT_DOUBLE_EQ(forces[0], forces[2]);
}

// mode-dependent's let-go (a table of its phase-angle equation, detachment/) reproduces its two
// limits; at lambda = 1 it is mode-mixed's closed form, with no root search.
TEST(CriteriaAgree, ModeDependentReachesModeMixedAndNormalOnly) {
  const auto run = [](const std::string& criterion, const std::string& extra) {
    JkrScenario s;
    s.criterion = criterion;
    s.criterion_extra = extra;
    s.tangential_displacement = 2.0;
    s.poisson_ratio = 0.3;
    s.springs = 2000;
    return mdrsim::test::run_quietly(s.build());
  };
  const auto mixed = run("mode-mixed", "");
  const auto normal_only = run("normal-only", "");
  const auto at_one = run("mode-dependent", "lambda = 1.0");
  const auto at_zero = run("mode-dependent", "lambda = 0.0");
  EXPECT_EQ(at_one.counts.root_iterations, 0);
  EXPECT_NEAR(at_one.critical->normal_force, mixed.critical->normal_force,
              1e-12 * std::abs(mixed.critical->normal_force));
  EXPECT_NEAR(at_zero.critical->normal_force, normal_only.critical->normal_force,
              1e-12 * std::abs(normal_only.critical->normal_force));
  EXPECT_NE(mixed.critical->normal_force, normal_only.critical->normal_force);
}
