// The simulated critical point against the paper's closed forms (Figs. 2 and 3a).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/events/event_recorder.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/parabolic_reference.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::RunResult;
using mdrsim::RunStatus;
using mdrsim::test::JkrScenario;
using mdrsim::test::run_quietly;

namespace {

struct Dimensionless {
  double normal_force, tangential_force, contact_radius, indentation;
};

Dimensionless dimensionless(const JkrScenario& s, const RunResult& r) {
  const auto k = s.scales();
  return {r.critical->normal_force / k.force, r.critical->tangential_force / k.force,
          r.critical->contact_radius / k.radius, r.critical->indentation / k.depth};
}

double gamma_of(double nu) { return (2.0 - 2.0 * nu) / (2.0 - nu); }  // paper eq. 9

}  // namespace

// Fig. 2: glued radius 2 a0, 10000 springs; the spring row's first-order error is
// about 1.5/springs here, so 1e-3 has a margin of 6.
TEST(PullOffReference, JkrFixedLoadPullOffIsMinusOne) {
  JkrScenario s;
  s.normal = "fixed-load";
  const RunResult r = run_quietly(s.build());
  EXPECT_EQ(r.status, RunStatus::instability);
  EXPECT_NEAR(dimensionless(s, r).normal_force, -1.0, 1e-3);
  EXPECT_NEAR(dimensionless(s, r).contact_radius, 1.0, 1e-3);
  EXPECT_NEAR(dimensionless(s, r).indentation, -1.0, 1e-3);
}

TEST(PullOffReference, JkrFixedGripsPullOffIsMinusFiveNinths) {
  JkrScenario s;
  s.normal = "fixed-grips";
  const RunResult r = run_quietly(s.build());
  EXPECT_EQ(r.status, RunStatus::instability);
  EXPECT_NEAR(dimensionless(s, r).normal_force, -5.0 / 9.0, 1e-3);
  EXPECT_NEAR(dimensionless(s, r).contact_radius, std::cbrt(1.0 / 9.0), 1e-3);
}

// Fig. 3a: u/d0 from 0 to 4 in 41 values; both coordinates within 2e-3.
class TangentialSweep : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(TangentialSweep, CriticalForcesFollowTheMasterCurves) {
  const auto& [normal, nu] = GetParam();
  const double gamma = gamma_of(nu);
  for (int i = 0; i <= 40; ++i) {
    const double u = 0.1 * i;
    JkrScenario s;
    s.normal = normal;
    s.poisson_ratio = nu;
    s.tangential_displacement = u;
    const auto got = dimensionless(s, run_quietly(s.build()));
    const auto want = normal == "fixed-grips" ? ref::fixed_grips_critical(u, gamma)
                                              : ref::fixed_load_critical(u, gamma);
    EXPECT_NEAR(got.normal_force, want.normal_force, 2e-3) << "u/d0 = " << u;
    EXPECT_NEAR(got.tangential_force, want.tangential_force, 2e-3) << "u/d0 = " << u;
    if (normal == "fixed-grips") {  // eq. 34 (eq. 35 at nu = 0) at the simulated F_x
      EXPECT_NEAR(got.normal_force, ref::fixed_grips_master_curve(got.tangential_force, gamma),
                  2e-3)
          << "u/d0 = " << u;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fig3a, TangentialSweep,
                         ::testing::Values(std::make_tuple("fixed-grips", 0.0),
                                           std::make_tuple("fixed-grips", 0.3),
                                           std::make_tuple("fixed-load", 0.0),
                                           std::make_tuple("fixed-load", 0.3)));

// A compliant machine of stiffness k = F0/d0 folds where dF/da + k dd/da = 0.
TEST(PullOffReference, CompliantMachineFoldsBetweenTheLimits) {
  for (const double k : {0.3, 1.0, 3.0}) {
    JkrScenario s;
    s.normal = "compliant";
    const auto scales = s.scales();
    s.normal_extra = "stiffness = " + std::to_string(k * scales.force / scales.depth);
    const auto got = dimensionless(s, run_quietly(s.build()));
    EXPECT_NEAR(got.normal_force, ref::compliant_critical(k).normal_force, 2e-3) << "k = " << k;
  }
}

// The paper's stepping ends at the fold and agrees with the event method
// within its finest increment: the last equilibrium it accepts lies at most one finest
// step above the exact fold of the same spring row.
class SteppingAgainstEvent : public ::testing::TestWithParam<std::tuple<std::string, int, double>> {
};

TEST_P(SteppingAgainstEvent, SameCriticalForceWithinTheStepTolerance) {
  const auto& [normal, max_halvings, u] = GetParam();
  JkrScenario s;
  s.normal = normal;
  s.springs = 2000;
  if (u > 0) s.tangential_displacement = u;
  const RunResult event = run_quietly(s.build());
  s.method = "stepping";
  s.solver_extra = "max_halvings = " + std::to_string(max_halvings);
  const mdrsim::Scene scene = s.build();
  mdrsim::EventRecorder recorder;
  mdrsim::ObserverList observers;
  observers.add(recorder);
  const RunResult stepping = mdrsim::run_pull_off(scene, observers);
  ASSERT_EQ(stepping.status, RunStatus::instability);
  EXPECT_GT(stepping.counts.halvings, 0);
  EXPECT_EQ(stepping.critical->springs_in_contact, event.critical->springs_in_contact);

  // Default base increment: 1e-3 of the control value at the preload; at the fold it has
  // been halved max_halvings times.
  const double preload_control = recorder.events().front().state.normal_control;
  const double finest = 1e-3 * std::abs(preload_control) * std::ldexp(1.0, -max_halvings);
  const double above = stepping.critical->normal_control - event.critical->normal_control;
  EXPECT_GE(above, -1e-12 * finest);
  EXPECT_LE(above, finest * (1.0 + 1e-9));
  // In force: the control itself under fixed load, the spring row's stiffness times the
  // depth difference under fixed grips.
  const double stiffness = 2.0 * scene.material.effective_modulus * scene.glued_radius /
                           static_cast<double>(scene.springs) *
                           static_cast<double>(event.critical->springs_in_contact);
  const double force_tolerance = normal == "fixed-load" ? finest : stiffness * finest;
  EXPECT_NEAR(stepping.critical->normal_force, event.critical->normal_force,
              force_tolerance * (1.0 + 1e-9) + 1e-15);
}

INSTANTIATE_TEST_SUITE_P(BothFolds, SteppingAgainstEvent,
                         ::testing::Values(std::make_tuple("fixed-load", 30, 0.0),
                                           std::make_tuple("fixed-grips", 30, 0.0),
                                           std::make_tuple("fixed-load", 8, 0.0),
                                           std::make_tuple("fixed-grips", 8, 0.0),
                                           std::make_tuple("fixed-load", 30, 2.0),
                                           std::make_tuple("fixed-grips", 30, 2.0)));
