// M(k, nu) and C_k of engine/model/graded_constants against the graded half-space solved apart
// (tests/support/graded_half_space: the Hankel-transformed equations, the kernel's quadrature).
#include "engine/model/graded_constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/support/graded_half_space.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(GradedConstants, HomogeneousIsBoussinesq) {
  for (double nu : {0.0, 0.3, 0.5}) {
    const double e0 = 2.5e6;
    const double m = graded_point_force_compliance({0.0, 1e-3}, e0, nu);
    // Gamma's and sin's rounding only.
    EXPECT_NEAR(m, (1.0 - nu * nu) / (kPi * e0), 1e-14 * m) << nu;
    EXPECT_NEAR(graded_punch_constant({0.0, 1e-3}, e0, nu), 2.0 * e0 / (1.0 - nu * nu), 1e-14 * e0);
  }
}

TEST(GradedConstants, PointForceMatchesTheHankelSolution) {
  // The integration's tolerances are 1e-14 and the growing pair it drops is e^-60 of the
  // decaying one at the surface; 1e-8 is the tolerance SPEC's check asks.
  for (double k : {0.0, 0.1, 0.25, 0.5, 0.75, 0.9}) {
    for (double nu : {0.0, 0.25, 0.3, 0.45, 0.49}) {
      const double e0 = 3.0e5, z0 = 2.0e-3;
      const double spec = graded_point_force_compliance({k, z0}, e0, nu);
      const double hankel = test::graded_point_force_compliance_by_hankel(k, e0, z0, nu);
      EXPECT_NEAR(spec / hankel, 1.0, 1e-8) << "k = " << k << ", nu = " << nu;
      // The table a reader checks against SPEC's formula: M E0 z0^-k and the two's distance.
      std::printf("k = %.2f  nu = %.2f  M E0 z0^-k = %.12f  Hankel %.12f  rel. diff %.1e\n", k, nu,
                  spec * e0 / std::pow(z0, k), hankel * e0 / std::pow(z0, k), spec / hankel - 1.0);
    }
  }
}

TEST(GradedConstants, FlatPunchMatchesTheKernelQuadrature) {
  // The pressure (a^2 - r^2)^((k-1)/2) under the punch deflects the disk uniformly; F over
  // that deflection and a^(1+k) is C_k. Quadratures to about 1e-12: 1e-8.
  for (double k : {0.25, 0.5, 0.75}) {
    for (double nu : {0.2, 0.4}) {
      const Grading grading{k, 1e-3};
      const double e0 = 1e6;
      const double m = graded_point_force_compliance(grading, e0, nu);
      const double a = 2e-4;
      const double force = 2.0 * kPi * std::pow(a, 1.0 + k) / (1.0 + k);
      for (double r : {0.0, 0.3 * a, 0.7 * a}) {
        const double deflection = test::graded_punch_deflection(k, m, a, r);
        EXPECT_NEAR(
            force / (deflection * std::pow(a, 1.0 + k)) / graded_punch_constant(grading, e0, nu),
            1.0, 1e-8)
            << "k = " << k << ", nu = " << nu << ", r/a = " << r / a;
      }
    }
  }
}

TEST(GradedConstants, PunchOuterSurfaceMatchesTheKernelQuadrature) {
  // Outside the punch the MDR's back-transform of the springs' uniform stretch against the
  // point-force kernel integrated over the punch's pressure: the deflection under the punch (d)
  // and outside it both from the kernel, their ratio against graded_punch_surface_displacement /
  // d. The outside's quadrature holds about 1e-13; d's carries 8.5e-9 at k = 0 (the pressure's
  // inverse square root at the rim, 1e-10 and less for k > 0): 2e-8.
  for (double k : {0.0, 0.25, 0.5, 0.75, 0.9}) {
    const Grading grading{k, 1e-3};
    const double m = graded_point_force_compliance(grading, 1e6, 0.3);
    const double a = 2e-4;
    const double d = test::graded_punch_deflection(k, m, a, 0.0);
    for (double r : {1.02 * a, 1.3 * a, 2.0 * a, 5.0 * a, 20.0 * a}) {
      const double kernel = test::graded_punch_deflection_outside(k, m, a, r);
      EXPECT_NEAR(graded_punch_surface_displacement(k, d, a, r) / kernel, 1.0, 2e-8)
          << "k = " << k << ", r/a = " << r / a;
    }
    EXPECT_EQ(graded_punch_surface_displacement(k, d, a, 0.5 * a), d);
  }
  // k = 0: Boussinesq's punch, (2 d / pi) asin(a / r).
  EXPECT_NEAR(graded_punch_surface_displacement(0.0, 1.0, 1.0, 2.0),
              2.0 / std::numbers::pi * std::asin(0.5), 1e-15);
}

TEST(GradedConstants, SpringsAddUpToThePunch) {
  // 2 int_0^a c_k(x) dx = C_k a^(1+k): the springs under a punch carry its force.
  const double k = 0.4, ck = 7.0e7, a = 3e-4;
  double sum = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * a / n;
    sum += 2.0 * graded_spring_stiffness(k, ck, x) * a / n;
  }
  // The midpoint rule's error at the x^k cusp: about n^-(1+k), 1e-6 at this n.
  EXPECT_NEAR(sum / (ck * std::pow(a, 1.0 + k)), 1.0, 1e-6);
}

TEST(GradedConstants, HessRuleBalancesTheGlue) {
  // c_k(a) e^2 = 2 pi a dgamma, and at k = 0 with C_0 = 2 E*: sqrt(2 pi a dgamma / E*).
  const double ck = 5e7, dgamma = 0.05, a = 1e-4;
  for (double k : {0.0, 0.3, 0.8}) {
    const double e = graded_let_go_stretch(k, ck, dgamma, a);
    EXPECT_NEAR(graded_spring_stiffness(k, ck, a) * e * e / (2.0 * kPi * a * dgamma), 1.0, 1e-14);
  }
  EXPECT_NEAR(graded_let_go_stretch(0.0, 2.0 * 1e6, dgamma, a),
              std::sqrt(2.0 * kPi * a * dgamma / 1e6), 1e-15 * std::sqrt(a));
}

}  // namespace
}  // namespace mdrsim
