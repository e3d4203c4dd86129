// The shared-drive sums of Maxwell arms against each member updated on its own, and against the
// closed form of two springs pressed at a constant rate from different times.
#include "engine/model/prony_shared_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/model/prony_arms.hpp"

namespace mdrsim {
namespace {

const std::vector<PronyTerm> kTerms{{9.0e6, 0.1}, {2.0e6, 3.0}};

// Two fresh springs (weight dx each) join at t = 0 and t = T under a constant rate r: term j sums
// to dx E_j r tau_j [(1 - exp(-t / tau_j)) + (1 - exp(-(t - T) / tau_j))]. 1e-14 relative.
TEST(PronySharedDrive, TwoSpringsPressedFromDifferentTimes) {
  SharedDriveArms arms(kTerms);
  const double dx = 1e-5, rate = 1e-4, joined = 0.07, t = 0.25;
  const std::vector<double> fresh(kTerms.size(), 0.0);
  arms.enter(fresh, dx);
  arms.advance(rate, joined);
  arms.enter(fresh, dx);
  arms.advance(rate, t - joined);
  for (std::size_t j = 0; j < kTerms.size(); ++j) {
    const PronyTerm& term = kTerms[j];
    const double expected = dx * term.modulus * rate * term.time *
                            (2.0 - std::exp(-t / term.time) - std::exp(-(t - joined) / term.time));
    EXPECT_NEAR(arms.arm_force(j), expected, 1e-14 * expected) << j;
  }
  EXPECT_DOUBLE_EQ(arms.weight(), 2.0 * dx);
  EXPECT_DOUBLE_EQ(arms.time(), t);
}

// Members entering with stresses of their own, a drive that presses, holds and withdraws, members
// leaving: every member's stress and every sum against springs advanced one by one
// (maxwell_arm_after each), to 1e-12 of the largest stress (the sums' additions and removals).
TEST(PronySharedDrive, AgreesWithEachSpringAdvancedAlone) {
  SharedDriveArms arms(kTerms);
  struct Alone {
    std::vector<double> stresses;
    double weight;
    SharedDriveMember member;
    bool in;
  };
  std::vector<Alone> springs;
  const auto join = [&](std::vector<double> stresses, double weight) {
    springs.push_back({stresses, weight, arms.enter(stresses, weight), true});
  };
  const auto drive = [&](double rate, double duration) {
    arms.advance(rate, duration);
    for (Alone& spring : springs) {
      if (spring.in) {
        advance_arms(spring.stresses, kTerms, rate, duration);
      }
    }
  };
  join({0.0, 0.0}, 1e-5);
  drive(1e-4, 0.05);
  join({0.0, 0.0}, 1e-5);
  join({-30.0, 12.0}, 2e-5);  // a spring pressed back with arms of its own
  drive(1e-4, 0.1);
  drive(0.0, 0.3);
  const auto left = arms.leave(springs[1].member);
  springs[1].stresses.assign(left.begin(), left.end());
  springs[1].in = false;
  drive(-2e-4, 0.02);
  join({5.0, -1.0}, 1e-5);
  drive(-2e-4, 0.4);
  double scale = 0.0;
  std::vector<double> sums(kTerms.size(), 0.0);
  for (const Alone& spring : springs) {
    for (std::size_t j = 0; j < kTerms.size(); ++j) {
      scale = std::max(scale, std::abs(spring.stresses[j]));
      if (spring.in) {
        sums[j] += spring.weight * spring.stresses[j];
        EXPECT_NEAR(arms.stress(spring.member, j), spring.stresses[j], 1e-12 * scale);
      }
    }
  }
  for (std::size_t j = 0; j < kTerms.size(); ++j) {
    EXPECT_NEAR(arms.arm_force(j), sums[j], 1e-12 * scale * 5e-5) << j;
  }
  EXPECT_NEAR(arms.arm_force(), sums[0] + sums[1], 2e-12 * scale * 5e-5);
  // Everyone leaves: the set is empty and sums to zero exactly.
  for (Alone& spring : springs) {
    if (spring.in) {
      arms.leave(spring.member);
    }
  }
  EXPECT_EQ(arms.arm_force(), 0.0);
  EXPECT_EQ(arms.weight(), 0.0);
}

}  // namespace
}  // namespace mdrsim
