// Units: one dimensionless scene at tip radii from 1e-9 m to 1 m and moduli from 1e3 to 1e12 Pa
// gives one dimensionless critical point.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"

using mdrsim::RunResult;
using mdrsim::test::JkrScenario;
using mdrsim::test::run_quietly;

namespace {

std::string fmt_g17(double v) { return fmt::format("{:.17g}", v); }

/// A scene in JKR units: everything but R, E and dgamma, which set the scales.
struct DimensionlessScene {
  std::string name;
  std::string normal;
  double stiffness = 0.0;  ///< compliant machine, in F0/d0
  double poisson_ratio = 0.0;
  std::optional<double> tangential_displacement;  ///< in d0
  std::optional<double> tangential_force;         ///< in F0
  std::string criterion = "mode-mixed";
  std::string criterion_extra;
  std::string method = "event";
};

void PrintTo(const DimensionlessScene& d, std::ostream* os) { *os << d.name; }

std::vector<DimensionlessScene> scenes() {
  return {
      {.name = "fixed-load", .normal = "fixed-load"},
      {.name = "fixed-grips with u = 2 d0",
       .normal = "fixed-grips",
       .tangential_displacement = 2.0},
      {.name = "compliant k = F0/d0, Fx = 1.5 F0",
       .normal = "compliant",
       .stiffness = 1.0,
       .tangential_force = 1.5},
      {.name = "stepping, fixed-grips",
       .normal = "fixed-grips",
       .tangential_displacement = 1.0,
       .method = "stepping"},
      {.name = "stress, nu = 0.3",
       .normal = "fixed-load",
       .poisson_ratio = 0.3,
       .tangential_displacement = 2.5,
       .criterion = "stress"},
      {.name = "mode-dependent, nu = 0.3",
       .normal = "fixed-grips",
       .poisson_ratio = 0.3,
       .tangential_displacement = 2.5,
       .criterion = "mode-dependent",
       .criterion_extra = "lambda = 0.5"},
  };
}

struct Dimensionless {
  double normal_force, tangential_force, contact_radius, indentation, tangential_displacement;
  std::int64_t springs;
};

Dimensionless run_at(const DimensionlessScene& d, double radius, double modulus,
                     double work_of_adhesion) {
  JkrScenario s;
  s.springs = 2000;
  s.radius = radius;
  s.youngs_modulus = modulus;
  s.work_of_adhesion = work_of_adhesion;
  s.poisson_ratio = d.poisson_ratio;
  s.normal = d.normal;
  s.tangential_displacement = d.tangential_displacement;
  s.tangential_force = d.tangential_force;
  s.criterion = d.criterion;
  s.criterion_extra = d.criterion_extra;
  s.method = d.method;
  const auto k = s.scales();
  if (d.stiffness > 0.0) {
    s.normal_extra = "stiffness = " + fmt_g17(d.stiffness * k.force / k.depth);
  }
  const RunResult r = run_quietly(s.build());
  EXPECT_EQ(r.status, mdrsim::RunStatus::instability) << d.name;
  const auto c = r.critical.value_or(mdrsim::ContactSnapshot{});
  return {
      c.normal_force / k.force, c.tangential_force / k.force,        c.contact_radius / k.radius,
      c.indentation / k.depth,  c.tangential_displacement / k.depth, c.springs_in_contact};
}

}  // namespace

// The spring row in JKR units (a/a0, d/d0, F/F0, paper eq. 16) depends only on the
// dimensionless inputs: the glued radius in a0, the tangential load in d0 or F0, the machine
// stiffness in F0/d0, nu, the springs and the criterion. So R from 1e-9 m to 1 m, E from 1e3 to
// 1e12 Pa (and dgamma from 1e-3 to 10 J/m^2) must give the same dimensionless critical point as
// R = 1 cm, E = 1 MPa, dgamma = 0.05 J/m^2: the same spring, and every value within 1e-9
// relative (1e-9 absolute for values that are zero, e.g. F_x without tangential load). The
// arithmetic is scale-free up to rounding (below 1e-12 here, measured); a unit slip anywhere (a
// hard-coded absolute tolerance, a length mixed with a force) would show as a difference of
// order one at some scale.
class UnitsInvariance : public ::testing::TestWithParam<DimensionlessScene> {};

TEST_P(UnitsInvariance, SameDimensionlessCriticalPointAtEveryScale) {
  const DimensionlessScene& d = GetParam();
  const Dimensionless want = run_at(d, 0.01, 1e6, 0.05);
  const auto close = [](double got, double expected) {
    return std::abs(got - expected) <= 1e-9 * std::max(std::abs(expected), 1.0);
  };
  for (const double radius : {1e-9, 1e-6, 1e-3, 1.0}) {
    for (const double modulus : {1e3, 1e6, 1e9, 1e12}) {
      for (const double work : {1e-3, 10.0}) {
        const Dimensionless got = run_at(d, radius, modulus, work);
        const std::string where = d.name + " at R = " + fmt_g17(radius) +
                                  " m, E = " + fmt_g17(modulus) + " Pa, dgamma = " + fmt_g17(work);
        EXPECT_EQ(got.springs, want.springs) << where;
        EXPECT_PRED2(close, got.normal_force, want.normal_force) << where;
        EXPECT_PRED2(close, got.tangential_force, want.tangential_force) << where;
        EXPECT_PRED2(close, got.contact_radius, want.contact_radius) << where;
        EXPECT_PRED2(close, got.indentation, want.indentation) << where;
        EXPECT_PRED2(close, got.tangential_displacement, want.tangential_displacement) << where;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, UnitsInvariance, ::testing::ValuesIn(scenes()),
                         [](const ::testing::TestParamInfo<DimensionlessScene>& info) {
                           return "Scene" + std::to_string(info.index);
                         });
