// The mode-dependent let-go against a long double root of the law, its limits, and its margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>
#include <vector>

#include "detachment/let_go.hpp"
#include "detachment/mode_dependent_criterion.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "detachment/normal_only_criterion.hpp"

namespace {

using mdrsim::InterfaceProperties;
using mdrsim::ModeDependentCriterion;
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// The let-go elongation [m] in long double and its condition |d ln e / d ln c|, where
/// c = |ux| sqrt(G* / (2 pi a dgamma)): bisection to the last bit of a long double on
/// cos(phi) = c sin(lambda pi/2 + (1 - lambda) phi), phi = pi/2 - psi (psi the phase angle),
/// then e = sqrt(2 pi a dgamma / E*) sin(phi) / sin(lambda pi/2 + (1 - lambda) phi). The
/// test `ReferenceIsTheRootOfTheMargin` ties this form to margin(). 1 - lambda is rounded to a
/// double first, as margin() rounds it: below 2^-54 the law is normal-only's.
struct Reference {
  long double elongation;
  long double condition;
};

Reference reference(const InterfaceProperties& p, double lambda, double a, double ux) {
  using ld = long double;
  const ld pi = std::numbers::pi_v<ld>;
  const ld work = 2 * pi * static_cast<ld>(a) * static_cast<ld>(p.work_of_adhesion);
  const ld c =
      std::fabs(static_cast<ld>(ux)) * std::sqrt(static_cast<ld>(p.effective_shear_modulus) / work);
  const ld mu = static_cast<ld>(1.0 - lambda), half = (1 - mu) * pi / 2;
  if (c * std::sin(half) >= 1) return {0, std::numeric_limits<ld>::infinity()};
  ld low = 0, high = pi / 2;
  for (;;) {
    const ld mid = (low + high) / 2;
    if (mid <= low || mid >= high) break;
    (std::cos(mid) - c * std::sin(half + mu * mid) > 0 ? low : high) = mid;
  }
  const ld phi = (low + high) / 2;
  const ld shifted_cot = std::cos(half + mu * phi) / std::sin(half + mu * phi);
  const ld d_log_e = std::cos(phi) / std::sin(phi) - mu * shifted_cot;
  const ld d_log_c = std::tan(phi) + mu * shifted_cot;
  return {std::sqrt(work / static_cast<ld>(p.effective_modulus)) * std::sin(phi) /
              std::sin(half + mu * phi),
          std::fabs(d_log_e / d_log_c)};
}

/// |ux| [m] at which the spring lets go with phase angle psi: c = sin psi / cos((1-lambda) psi).
double shear_at_angle(const InterfaceProperties& p, double lambda, double a, double psi) {
  const double c = std::sin(psi) / std::cos((1.0 - lambda) * psi);
  return c * std::sqrt(2.0 * std::numbers::pi * a * p.work_of_adhesion / p.effective_shear_modulus);
}

/// Interfaces and contact radii whose natural length sqrt(2 pi a dgamma / E*) spans 1e-12 to 1e3
/// times that of the paper's scene (~2.5e-4 m), with dgamma up to 5.1e306 J/m^2 (the fuzzer's),
/// radii down to 1e-290 m and G*/E* from 1e-3 to 4/3.
struct Case {
  InterfaceProperties properties;
  double radius;  ///< a [m]
};
const std::vector<Case>& cases() {
  static const std::vector<Case> all{
      {{1e6, 0.8e6, 0.05}, 2e-4},      {{1e6, 0.8e6, 0.05}, 2e-28},  {{1e6, 0.8e6, 0.05}, 2e2},
      {{630e6, 0.5e6, 5.1e306}, 1e-3}, {{2e6, 1.5e6, 5.05}, 1e-290}, {{1e6, 1e3, 0.05}, 2e-4},
      {{3e6, 4e6, 0.05}, 2e-4},
  };
  return all;
}

/// Phase angles of the let-go from 1e-12 rad (c ~ 1e-12) to within 2^-40 of 90 deg, where c nears
/// its supremum 1 / sin(lambda pi/2) (up to 1e16 here) and the let-go elongation goes to 0.
std::vector<double> phase_angles() {
  std::vector<double> psi{1e-12, 1e-9, 1e-6, 1e-3};
  for (int i = 0; i <= 40; ++i) psi.push_back(std::numbers::pi / 2 * i / 41);
  for (int k = 2; k <= 40; k += 2) psi.push_back(std::numbers::pi / 2 * (1 - std::ldexp(1.0, -k)));
  return psi;
}

std::vector<double> lambdas() {
  std::vector<double> all{0.0, 0x1p-54, 2e-16, 1e-12, 1e-6, 1e-3, 0.01};
  for (int i = 1; i < 40; ++i) all.push_back(i / 40.0);
  for (const double l : {0.99, 0.999, 1 - 1e-6, 1 - 1e-12, 1.0}) all.push_back(l);
  return all;
}

}  // namespace

// The let-go matches the long double root to 1e-13 wherever the law lets it: c carries about
// 4 roundings of a, ux and the properties (as mode-mixed's closed form does), which the law
// amplifies by its condition |d ln e / d ln c|, large only as c nears its supremum (e -> 0).
// Hence the bound 1e-13 + 8 eps condition; over this grid the method reaches ~2e-15 where
// the condition is below 1.
TEST(ModeDependentCriterion, MatchesTheLongDoubleRootOverLambdaAngleAndScale) {
  double worst_well_conditioned = 0.0;
  for (const Case& k : cases()) {
    for (const double lambda : lambdas()) {
      const ModeDependentCriterion criterion(k.properties, lambda);
      for (const double psi : phase_angles()) {
        const double ux = shear_at_angle(k.properties, lambda, k.radius, psi);
        const Reference want = reference(k.properties, lambda, k.radius, ux);
        const double got = criterion.critical_elongation(k.radius, ux).value();
        ASSERT_TRUE(std::isfinite(got)) << lambda << " " << psi;
        if (want.elongation == 0) {
          EXPECT_EQ(got, 0.0) << "lambda " << lambda << " psi " << psi;
          continue;
        }
        const double error =
            static_cast<double>(std::fabs(got - want.elongation) / want.elongation);
        const double condition = static_cast<double>(want.condition);
        EXPECT_LE(error, 1e-13 + 8 * kEps * condition)
            << "lambda " << lambda << " psi " << psi << " a " << k.radius << " condition "
            << condition;
        if (condition <= 1) worst_well_conditioned = std::max(worst_well_conditioned, error);
      }
    }
  }
  EXPECT_LE(worst_well_conditioned, 1e-14);  // 1e-14: the table's own error is ~2e-15
}

// The long double form above is the law of margin(): TOMS 748 on the margin alone (the engine's
// path for criteria without a closed form) lands on it, where the margin is well conditioned.
TEST(ModeDependentCriterion, ReferenceIsTheRootOfTheMargin) {
  struct MarginOnly final : mdrsim::DetachmentCriterion {
    const mdrsim::DetachmentCriterion* inner = nullptr;
    double margin(const mdrsim::BoundarySpring& s) const override { return inner->margin(s); }
  };
  const Case& k = cases()[0];
  for (const double lambda : {0.1, 0.4, 0.5, 0.75, 0.9}) {
    const ModeDependentCriterion criterion(k.properties, lambda);
    MarginOnly margin_only;
    margin_only.inner = &criterion;
    for (int i = 0; i < 8; ++i) {
      const double ux = shear_at_angle(k.properties, lambda, k.radius, 0.15 * i);
      const double dl =
          static_cast<double>(reference(k.properties, lambda, k.radius, 0).elongation);
      const auto searched = mdrsim::locate_let_go(margin_only, k.radius, ux, dl);
      const auto want = reference(k.properties, lambda, k.radius, ux);
      // 1e-13: TOMS 748 ends within a few eps of the margin's root, and the margin, a
      // difference of two terms near 2 pi a dgamma, is itself good to a few eps of that.
      EXPECT_NEAR(searched.elongation / static_cast<double>(want.elongation), 1.0, 1e-13)
          << "lambda " << lambda << " psi " << 0.15 * i;
    }
  }
}

// The let-go zeroes margin() and is the smallest stretch that does.
TEST(ModeDependentCriterion, MarginVanishesAtTheLetGo) {
  const Case& k = cases()[0];
  const double work = 2 * std::numbers::pi * k.radius * k.properties.work_of_adhesion;
  for (const double lambda : {0.05, 0.25, 0.5, 0.75, 0.95, 1.0}) {
    const ModeDependentCriterion criterion(k.properties, lambda);
    for (int i = 0; i <= 10; ++i) {
      const double psi = 0.14 * i;  // up to 80 deg, where the margin still varies with stretch
      const double ux = shear_at_angle(k.properties, lambda, k.radius, psi);
      const double e = criterion.critical_elongation(k.radius, ux).value();
      // 1e-14 of 2 pi a dgamma: the margin subtracts two terms of that size, each good to a
      // few eps, and the let-go is good to ~1e-15.
      EXPECT_NEAR(criterion.margin({e, ux, k.radius}), 0.0, 1e-14 * work)
          << "lambda " << lambda << " psi " << psi;
      // 1e-9: well above the margin's rounding, relative to its slope in the stretch.
      EXPECT_GT(criterion.margin({e * (1 - 1e-9), ux, k.radius}), 0.0);
      EXPECT_LT(criterion.margin({e * (1 + 1e-9), ux, k.radius}), 0.0);
    }
  }
}

// lambda = 0 is normal-only and lambda = 1 mode-mixed, to the bit; so is any lambda for which
// 1 - lambda rounds to 1, where margin() itself is normal-only's.
TEST(ModeDependentCriterion, LimitsAreNormalOnlyAndModeMixedToTheBit) {
  for (const Case& k : cases()) {
    const mdrsim::NormalOnlyCriterion normal_only(k.properties);
    const mdrsim::ModeMixedCriterion mode_mixed(k.properties);
    const ModeDependentCriterion at_zero(k.properties, 0.0), tiny(k.properties, 0x1p-54);
    const ModeDependentCriterion at_one(k.properties, 1.0);
    for (const double psi : phase_angles()) {
      const double ux = shear_at_angle(k.properties, 1.0, k.radius, psi);
      EXPECT_EQ(at_one.critical_elongation(k.radius, ux).value(),
                mode_mixed.critical_elongation(k.radius, ux).value());
      EXPECT_EQ(at_zero.critical_elongation(k.radius, ux).value(),
                normal_only.critical_elongation(k.radius, ux).value());
      EXPECT_EQ(tiny.critical_elongation(k.radius, ux).value(),
                normal_only.critical_elongation(k.radius, ux).value());
    }
  }
}

// Without shear every lambda lets go at the rule of Hess; at and past the supremum of the shear
// the let-go is at zero stretch; a = 0 and huge shear stay finite.
TEST(ModeDependentCriterion, EndsOfTheShearRange) {
  for (const Case& k : cases()) {
    const double dl = std::sqrt(2 * std::numbers::pi * k.radius *
                                (k.properties.work_of_adhesion / k.properties.effective_modulus));
    for (const double lambda : {1e-6, 0.3, 0.5, 0.9}) {
      const ModeDependentCriterion criterion(k.properties, lambda);
      // 4 eps: the let-go and dl are products of a few rounded factors.
      EXPECT_NEAR(criterion.critical_elongation(k.radius, 0.0).value() / dl, 1.0, 4 * kEps);
      const double supremum = shear_at_angle(k.properties, lambda, k.radius, std::numbers::pi / 2);
      EXPECT_EQ(criterion.critical_elongation(k.radius, 1.01 * supremum).value(), 0.0);
      EXPECT_EQ(criterion.critical_elongation(k.radius, 1e300).value(), 0.0);
      EXPECT_EQ(criterion.critical_elongation(0.0, supremum).value(), 0.0);
      EXPECT_EQ(criterion.critical_elongation(0.0, 0.0).value(), 0.0);
      // Just below the supremum the let-go is tiny but not negative: 2e-8 of dl at most for
      // 1 - 1e-15 of the supremum (condition ~1e15 there).
      const double near = criterion.critical_elongation(k.radius, (1 - 1e-15) * supremum).value();
      EXPECT_GE(near, 0.0);
      EXPECT_LE(near, 2e-8 * dl);
    }
  }
}

// The margin at zero stretch, taken from the constructor, is the general formula's to the bit.
TEST(ModeDependentCriterion, MarginAtZeroStretchIsTheGeneralFormula) {
  const Case& k = cases()[0];
  for (const double lambda : {0.0, 0.2, 0.5, 1.0}) {
    const ModeDependentCriterion criterion(k.properties, lambda);
    for (const double ux : {0.0, 1e-300, 1e-6, 1e-3, 1e200}) {
      const double shear = k.properties.effective_shear_modulus * ux * ux;
      const double c = std::cos((1.0 - lambda) * std::atan2(std::sqrt(shear), 0.0));
      const double general =
          2.0 * std::numbers::pi * k.radius * k.properties.work_of_adhesion - shear * c * c;
      EXPECT_EQ(criterion.margin({0.0, ux, k.radius}), general) << lambda << " " << ux;
      EXPECT_EQ(criterion.margin({-0.0, -ux, k.radius}), general) << lambda << " " << ux;
    }
  }
}

// Calls keep no state: any order, on any thread, gives the same bits.
TEST(ModeDependentCriterion, SameBitsWhateverTheOrderAndThread) {
  const Case& k = cases()[0];
  const ModeDependentCriterion criterion(k.properties, 0.37);
  std::vector<double> shear;
  for (const double psi : phase_angles()) {
    shear.push_back(shear_at_angle(k.properties, 0.37, k.radius, psi));
  }
  std::vector<double> forward(shear.size()), backward(shear.size()), threaded(shear.size());
  for (std::size_t i = 0; i < shear.size(); ++i) {
    forward[i] = criterion.critical_elongation(k.radius, shear[i]).value();
  }
  for (std::size_t i = shear.size(); i-- > 0;) {
    backward[i] = criterion.critical_elongation(k.radius, shear[i]).value();
  }
  std::vector<std::thread> threads;
  for (std::size_t start = 0; start < 4; ++start) {
    threads.emplace_back([&, start] {
      for (std::size_t i = start; i < shear.size(); i += 4) {
        threaded[i] = criterion.critical_elongation(k.radius, shear[i]).value();
      }
    });
  }
  for (std::thread& t : threads) t.join();
  const ModeDependentCriterion twin(k.properties, 0.37);
  for (std::size_t i = 0; i < shear.size(); ++i) {
    EXPECT_EQ(forward[i], backward[i]);
    EXPECT_EQ(forward[i], threaded[i]);
    EXPECT_EQ(forward[i], twin.critical_elongation(k.radius, shear[i]).value());
  }
}
