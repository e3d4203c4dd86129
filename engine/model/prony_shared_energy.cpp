// The shared arms' work and dissipation over a piece of constant drive rate, in closed form.
#include "engine/model/prony_shared_energy.hpp"

#include <algorithm>
#include <cmath>

namespace mdrsim {

void SharedArmOwnSquares::change(const SharedDriveArms& arms, std::span<const double> stresses,
                                 double weight) {
  for (std::size_t j = 0; j < squares_.size(); ++j) {
    const double own = stresses[j] - arms.history(j);
    squares_[j] += weight * own * own;
  }
}

void SharedArmOwnSquares::advance(std::span<const PronyTerm> terms, double duration) {
  for (std::size_t j = 0; j < squares_.size(); ++j) {
    squares_[j] *= std::exp(-2.0 * duration / terms[j].time);
  }
}

double SharedArmOwnSquares::operator[](std::size_t j) const { return std::max(squares_[j], 0.0); }

SharedArmsPiece shared_arms_linear_piece(const SharedDriveArms& arms,
                                         const SharedArmOwnSquares& own, double rate,
                                         double duration) {
  SharedArmsPiece piece;
  const double weight = arms.weight();
  for (std::size_t j = 0; j < arms.terms().size(); ++j) {
    const PronyTerm& term = arms.terms()[j];
    const double steady = term.modulus * rate * term.time;
    const double history = arms.history(j);
    const double transient = history - steady;
    const double decaying = arms.arm_force(j) - weight * history;
    // int_0^h exp(-s / tau) ds and int_0^h exp(-2 s / tau) ds.
    const double once = -std::expm1(-duration / term.time) * term.time;
    const double twice = -std::expm1(-2.0 * duration / term.time) * term.time * 0.5;
    piece.load_integral += weight * (steady * duration + transient * once) + decaying * once;
    const double history_squared = steady * steady * duration + 2.0 * steady * transient * once +
                                   transient * transient * twice;
    const double history_decay = steady * once + transient * twice;
    const double squares =
        weight * history_squared + 2.0 * decaying * history_decay + own[j] * twice;
    piece.dissipated += squares / (term.modulus * term.time);
  }
  return piece;
}

}  // namespace mdrsim
