// The held row's depth between events and the arms' response to it, against a trapezoidal
// (Crank-Nicolson) integration of the same equations written here, and the product integral
// against Simpson's rule.
#include "engine/model/prony_load_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mdrsim {
namespace {

const std::vector<PronyTerm> kTwoTerms{{9.0e6, 0.1}, {3.0e6, 1.0}};
constexpr double kRelaxed = 1.0e6;

/// The pressed set's arm sums S_j and depth d integrated by the trapezoidal rule over `steps`
/// steps of h: S_j+ (1 + h / 2 tau_j) = S_j (1 - h / 2 tau_j) + E_j n (d+ - d), with the
/// constraint (E* n + kappa) d+ + sum_j S_j+ = phi+ + E* sum g solved for d+ at each step.
/// Second order: at 20000 steps of 0.5 s its error is near 1e-9 of d.
double trapezoidal_depth(double n, double images, std::vector<double> sums, double kappa,
                         double phi0, double phi_rate, double span, int steps) {
  const double h = span / steps;
  double sum = 0.0;
  for (const double s : sums) sum += s;
  double d = (phi0 + kRelaxed * images - sum) / (kRelaxed * n + kappa);
  for (int i = 1; i <= steps; ++i) {
    const double phi = phi0 + phi_rate * h * i;
    // S_j+ = p_j + q_j d+, with p_j, q_j from the step's rule.
    double p_sum = 0.0, q_sum = 0.0;
    std::vector<double> p(sums.size()), q(sums.size());
    for (std::size_t j = 0; j < sums.size(); ++j) {
      const double r = h / (2.0 * kTwoTerms[j].time);
      p[j] = (sums[j] * (1.0 - r) - kTwoTerms[j].modulus * n * d) / (1.0 + r);
      q[j] = kTwoTerms[j].modulus * n / (1.0 + r);
      p_sum += p[j];
      q_sum += q[j];
    }
    const double next = (phi + kRelaxed * images - p_sum) / (kRelaxed * n + kappa + q_sum);
    for (std::size_t j = 0; j < sums.size(); ++j) sums[j] = p[j] + q[j] * next;
    d = next;
  }
  return d;
}

// A fixed load (kappa = 0) and a machine spring, a ramp of the held value, arms not at rest:
// the exponential sum against the integration at five times, to 1e-8 of the depth (the
// integration's own error is near 1e-9).
TEST(PronyLoadDrive, DepthMatchesATrapezoidalIntegration) {
  const std::vector<double> sums{2.0, -1.0};
  for (const double kappa : {0.0, 3.0e6}) {
    const double n = 5.0, images = 1.0e-5, phi0 = 40.0, phi_rate = 100.0;
    const ExponentialSum d =
        depth_under_held_axis(kRelaxed, kTwoTerms, {5, images, sums}, {kappa, phi0, phi_rate}, 0.0);
    ASSERT_EQ(d.decays.size(), 2u);
    for (const double t : {0.0, 0.05, 0.2, 0.5, 2.0}) {
      const double ref = trapezoidal_depth(n, images, sums, kappa, phi0, phi_rate, t,
                                           t == 0.0 ? 1 : static_cast<int>(t * 40000));
      EXPECT_NEAR(d.at(t), ref, 1e-8 * std::abs(ref)) << kappa << " " << t;
    }
  }
}

// Two terms of one relaxation time act as one arm: the depth is that of the merged term.
TEST(PronyLoadDrive, TermsOfOneTimeActAsOne) {
  const std::vector<PronyTerm> split{{4.0e6, 0.1}, {5.0e6, 0.1}};
  const std::vector<PronyTerm> merged{{9.0e6, 0.1}};
  const std::vector<double> split_sums{1.0, 2.0}, merged_sums{3.0};
  const ExponentialSum a =
      depth_under_held_axis(kRelaxed, split, {3, 2e-6, split_sums}, {0.0, 10.0, 5.0}, 0.0);
  const ExponentialSum b =
      depth_under_held_axis(kRelaxed, merged, {3, 2e-6, merged_sums}, {0.0, 10.0, 5.0}, 0.0);
  for (const double t : {0.0, 0.1, 1.0}) EXPECT_NEAR(a.at(t), b.at(t), 1e-14 * b.at(t));
}

// Without a pressed spring: a machine spring sets d = h, a fixed load leaves the depth.
TEST(PronyLoadDrive, WithoutPressedSprings) {
  const ExponentialSum spring =
      depth_under_held_axis(kRelaxed, kTwoTerms, {0, 0.0, {}}, {2.0, 4.0, 6.0}, 7.0);
  EXPECT_DOUBLE_EQ(spring.at(1.0), 5.0);
  const ExponentialSum load =
      depth_under_held_axis(kRelaxed, kTwoTerms, {0, 0.0, {}}, {0.0, 4.0, 6.0}, 7.0);
  EXPECT_DOUBLE_EQ(load.at(1.0), 7.0);
}

// The arm under w(s) = 1e-6 + 2e-6 s + 3e-6 exp(-s / 0.3) from sigma = 5: against the
// trapezoidal rule on d sigma/ds = E w' - sigma / tau (2e5 steps: error ~1e-11 of sigma).
TEST(PronyLoadDrive, ArmFollowsAnExponentialSumMotion) {
  const PronyTerm term{9.0e6, 0.1};
  const ExponentialSum motion{1e-6, 2e-6, {{3e-6, 0.3}}};
  const ExponentialSum sigma = arm_stress_under(5.0, term, motion);
  EXPECT_NEAR(sigma.at(0.0), 5.0, 1e-14);
  const int steps = 200000;
  const double span = 1.0, h = span / steps;
  double s = 5.0;
  double w = motion.at(0.0);
  for (int i = 1; i <= steps; ++i) {
    const double next = motion.at(h * i);
    const double r = h / (2.0 * term.time);
    s = (s * (1.0 - r) + term.modulus * (next - w)) / (1.0 + r);
    w = next;
  }
  EXPECT_NEAR(sigma.at(span), s, 1e-9 * std::abs(s));
}

// int_0^h f g over sums with lines and decays (one at a short time, where the ramp integral's
// series applies) against Simpson's rule on 2e4 panels (error ~1e-15 relative).
TEST(PronyLoadDrive, ProductIntegralMatchesSimpson) {
  const ExponentialSum f{1.5, -0.7, {{2.0, 0.3}, {-1.0, 1e3}}};
  const ExponentialSum g{-0.4, 2.0, {{0.5, 0.05}}};
  for (const double h : {1e-4, 0.2, 3.0}) {
    const int panels = 20000;
    const double step = h / panels;
    double sum = 0.0;
    for (int i = 0; i <= panels; ++i) {
      const double s = step * i;
      sum += f.at(s) * g.at(s) * (i == 0 || i == panels ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    const double simpson = sum * step / 3.0;
    EXPECT_NEAR(integral_of_product(f, g, h), simpson, 1e-12 * std::abs(simpson) + 1e-18) << h;
  }
}

}  // namespace
}  // namespace mdrsim
