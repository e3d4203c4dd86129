// The shared arms' work and dissipation along an exponential-sum drive, in closed form.
#include "engine/model/prony_held_shear.hpp"

#include "engine/model/prony_load_drive.hpp"

namespace mdrsim {

SharedArmsPiece shared_arms_motion_piece(const SharedDriveArms& arms,
                                         const SharedArmOwnSquares& own,
                                         const ExponentialSum& motion, double duration) {
  SharedArmsPiece piece;
  const double weight = arms.weight();
  const ExponentialSum one{1.0, 0.0, {}};
  for (std::size_t j = 0; j < arms.terms().size(); ++j) {
    const PronyTerm& term = arms.terms()[j];
    const double history0 = arms.history(j);
    const double decaying = arms.arm_force(j) - weight * history0;
    const ExponentialSum history = arm_stress_under(history0, term, motion);
    const ExponentialSum own_decay{0.0, 0.0, {{1.0, term.time}}};
    const ExponentialSum own_decay_squared{0.0, 0.0, {{1.0, 0.5 * term.time}}};
    piece.load_integral += weight * integral_of_product(history, one, duration) +
                           decaying * integral_of_product(own_decay, one, duration);
    const double squares = weight * integral_of_product(history, history, duration) +
                           2.0 * decaying * integral_of_product(history, own_decay, duration) +
                           own[j] * integral_of_product(own_decay_squared, one, duration);
    piece.dissipated += squares / (term.modulus * term.time);
  }
  return piece;
}

}  // namespace mdrsim
