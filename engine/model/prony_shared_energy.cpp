// The shared arms' work and dissipation over a piece of constant drive rate, in closed form.
#include "engine/model/prony_shared_energy.hpp"

#include "engine/model/decay_integrals.hpp"

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
    const double decaying = arms.arm_force(j) - weight * history;
    // H_j(s) = H_j(0) E + steady D (decay_integrals.hpp: short pieces keep their digits).
    const DecayIntegrals i = decay_integrals(duration, term.time);
    const ArmStressIntegrals h = arm_stress_integrals(i, history, steady);
    piece.load_integral += weight * h.stress + decaying * i.decay;
    const double squares =
        weight * h.square + 2.0 * decaying * h.with_decay + own[j] * i.decay_squared;
    piece.dissipated += squares / (term.modulus * term.time);
  }
  return piece;
}

}  // namespace mdrsim
