// The shared arms' work and dissipation over a piece of constant drive rate against each
// member's arms integrated on their own (Simpson's rule on the closed-form stress), and the own
// squares against their definition after members enter, leave and the drive moves.
#include "engine/model/prony_shared_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mdrsim {
namespace {

const std::vector<PronyTerm> kEnergyTerms{{9.0e6, 0.1}, {2.0e6, 0.03}};

/// A member's arm stress s after its start at `stress0` under the drive's `rate`:
/// c + (stress0 - c) exp(-s / tau), c = E rate tau (the Maxwell arm's ODE solved by hand).
double arm_stress_at(const PronyTerm& term, double stress0, double rate, double s) {
  const double c = term.modulus * rate * term.time;
  return c + (stress0 - c) * std::exp(-s / term.time);
}

TEST(PronySharedEnergy, APieceIsEveryMembersIntegralSummed) {
  // Three members: fresh at t = 0, one entering with stresses of its own at t = 0.02, one
  // leaving at t = 0.05; then a piece of h = 0.04 s at a new rate. Simpson's rule with 2000
  // intervals on smooth exponentials is exact to ~1e-13 of the integrals (h / tau <= 1.3).
  SharedDriveArms arms(kEnergyTerms);
  SharedArmOwnSquares own;
  own.reset(kEnergyTerms.size());
  const double rate = 2e-4;
  const std::vector<double> fresh(kEnergyTerms.size(), 0.0);
  const std::vector<double> stressed{150.0, -40.0};
  own.change(arms, fresh, 1.0);
  const SharedDriveMember a = arms.enter(fresh, 1.0);
  own.change(arms, fresh, 1.0);
  const SharedDriveMember b = arms.enter(fresh, 1.0);
  arms.advance(rate, 0.02);
  own.advance(kEnergyTerms, 0.02);
  own.change(arms, stressed, 1.0);
  const SharedDriveMember c = arms.enter(stressed, 1.0);
  arms.advance(-rate, 0.03);
  own.advance(kEnergyTerms, 0.03);
  const std::vector<SharedDriveMember> staying{a, c};
  {
    const FewValues<double> leaving = arms.leave(b);
    own.change(arms, leaving, -1.0);
  }
  // The own squares against their definition.
  for (std::size_t j = 0; j < kEnergyTerms.size(); ++j) {
    double squares = 0.0;
    for (const SharedDriveMember& m : staying) {
      const double delta = arms.stress(m, j) - arms.history(j);
      squares += delta * delta;
    }
    EXPECT_NEAR(own[j], squares, 1e-12 * squares) << j;
  }
  const double piece_rate = 5e-4;
  const double h = 0.04;
  const SharedArmsPiece piece = shared_arms_linear_piece(arms, own, piece_rate, h);
  constexpr int kIntervals = 2000;
  double load = 0.0;
  double dissipated = 0.0;
  for (const SharedDriveMember& m : staying) {
    for (std::size_t j = 0; j < kEnergyTerms.size(); ++j) {
      const PronyTerm& term = kEnergyTerms[j];
      const double stress0 = arms.stress(m, j);
      double stress_integral = 0.0;
      double square_integral = 0.0;
      for (int i = 0; i <= kIntervals; ++i) {
        const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
        const double sigma = arm_stress_at(term, stress0, piece_rate, h * i / kIntervals);
        stress_integral += weight * sigma;
        square_integral += weight * sigma * sigma;
      }
      const double step = h / kIntervals / 3.0;
      load += stress_integral * step;
      dissipated += square_integral * step / (term.modulus * term.time);
    }
  }
  EXPECT_NEAR(piece.load_integral, load, 1e-12 * std::abs(load));
  EXPECT_NEAR(piece.dissipated, dissipated, 1e-12 * dissipated);
}

}  // namespace
}  // namespace mdrsim
