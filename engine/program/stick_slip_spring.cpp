// One spring that sticks and slips at its slip limit: its events along a linear motion.
#include "engine/program/stick_slip_spring.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mdrsim {

namespace {

/// The limit on one piece of the motion, where f_z keeps its sign: L(t) = at_start + rate (t -
/// start).
struct LimitPiece {
  double start;     ///< [1]
  double end;       ///< [1]
  double at_start;  ///< [N]
  double rate;      ///< [N]
};

/// The pieces of [motion.start, end] on each side of f_z = 0 (one piece when f_z keeps its
/// sign), each with its limit, linear in t.
struct LimitPieces {
  std::array<LimitPiece, 2> piece;
  int count;
};

LimitPiece limit_on(const SlipLimit& law, const SpringGeometry& spring, const LinearMotion& motion,
                    double start, double end) {
  // Pressed or not on the whole piece: decided at its middle, away from the crossing's rounding.
  const double middle = start + 0.5 * (end - start);
  const bool pressed = motion.indentation_at(middle) > spring.image ||
                       (end == start && motion.indentation_at(start) >= spring.image);
  if (!pressed) return {start, end, law.constant, 0.0};
  const double normal = spring_normal_force(spring, motion.indentation_at(start));
  return {start, end, law.coefficient * std::max(normal, 0.0) + law.constant,
          law.coefficient * spring.normal_stiffness * motion.indentation_rate};
}

LimitPieces limit_pieces(const SlipLimit& law, const SpringGeometry& spring,
                         const LinearMotion& motion, double end) {
  const double start = motion.start;
  if (motion.indentation_rate != 0.0) {
    const double crossing = start + (spring.image - motion.indentation) / motion.indentation_rate;
    if (crossing > start && crossing < end)
      return {{limit_on(law, spring, motion, start, crossing),
               limit_on(law, spring, motion, crossing, end)},
              2};
  }
  return {{limit_on(law, spring, motion, start, end), LimitPiece{}}, 1};
}

/// The first t in [piece.start, piece.end] where margin(t) = margin + slope (t - start) reaches
/// 0 from above; a margin already at or below 0 (rounding) counts only when it decreases.
std::optional<double> linear_root(double margin, double slope, const LimitPiece& piece) {
  if (slope >= 0.0) return std::nullopt;
  const double t = piece.start + std::max(margin, 0.0) / (-slope);
  if (t > piece.end) return std::nullopt;
  return t;
}

/// The first slip of a sticking spring on one piece.
std::optional<FrictionEvent> first_slip(const StickSlipSpring& state, const SpringGeometry& spring,
                                        const LinearMotion& motion, const LimitPiece& piece) {
  const double force =
      spring.tangential_stiffness * (motion.tangential_at(piece.start) - state.offset);
  const double force_rate = spring.tangential_stiffness * motion.tangential_rate;
  const auto forward = linear_root(piece.at_start - force, piece.rate - force_rate, piece);
  const auto backward = linear_root(piece.at_start + force, piece.rate + force_rate, piece);
  if (forward && (!backward || *forward <= *backward))
    return FrictionEvent{FrictionEventKind::slip, *forward, 1};
  if (backward) return FrictionEvent{FrictionEventKind::slip, *backward, -1};
  return std::nullopt;
}

/// The slip velocity d(offset)/dt of a sliding spring on one piece [m].
double slip_rate(const StickSlipSpring& state, const SpringGeometry& spring,
                 const LinearMotion& motion, const LimitPiece& piece) {
  return motion.tangential_rate - state.sliding * piece.rate / spring.tangential_stiffness;
}

double limit_at(const LimitPiece& piece, double t) {
  return piece.at_start + piece.rate * (t - piece.start);
}

}  // namespace

double slip_limit(const SlipLimit& law, const SpringGeometry& spring, double indentation) {
  return law.coefficient * std::max(spring_normal_force(spring, indentation), 0.0) + law.constant;
}

double spring_tangential_force(const StickSlipSpring& state, const SlipLimit& law,
                               const SpringGeometry& spring, double indentation,
                               double tangential) {
  if (state.sliding != 0) return state.sliding * slip_limit(law, spring, indentation);
  return spring.tangential_stiffness * (tangential - state.offset);
}

std::optional<FrictionEvent> next_friction_event(const StickSlipSpring& state, const SlipLimit& law,
                                                 const SpringGeometry& spring,
                                                 const LinearMotion& motion, double end) {
  if (end < motion.start) return std::nullopt;
  const LimitPieces pieces = limit_pieces(law, spring, motion, end);
  for (int p = 0; p < pieces.count; ++p) {
    const LimitPiece& piece = pieces.piece[static_cast<std::size_t>(p)];
    if (state.sliding == 0) {
      if (auto slip = first_slip(state, spring, motion, piece)) return slip;
      continue;
    }
    if (state.sliding * slip_rate(state, spring, motion, piece) < 0.0)
      return FrictionEvent{FrictionEventKind::stick, piece.start, state.sliding};
    // The next piece starts where f_z changes sign: a kink of a glued spring's limit. A spring
    // without glue lifts there (the row's event), so its limit's kink is none of the law's.
    if (p + 1 < pieces.count && law.constant > 0.0)
      return FrictionEvent{FrictionEventKind::limit_kink, pieces.piece[1].start, state.sliding};
  }
  return std::nullopt;
}

double advance_spring(StickSlipSpring& state, const SlipLimit& law, const SpringGeometry& spring,
                      const LinearMotion& motion, double t) {
  if (state.sliding == 0 || t <= motion.start) return 0.0;
  const LimitPieces pieces = limit_pieces(law, spring, motion, t);
  double dissipated = 0.0;
  for (int p = 0; p < pieces.count; ++p) {
    const LimitPiece& piece = pieces.piece[static_cast<std::size_t>(p)];
    const double limit_end = limit_at(piece, piece.end);
    const double offset =
        motion.tangential_at(piece.end) - state.sliding * limit_end / spring.tangential_stiffness;
    // The limit is linear in t and the slip velocity constant on the piece: the trapezoid is exact.
    dissipated +=
        0.5 * (limit_at(piece, piece.start) + limit_end) * std::abs(offset - state.offset);
    state.offset = offset;
  }
  return dissipated;
}

void apply_friction_event(StickSlipSpring& state, const FrictionEvent& event) {
  if (event.kind == FrictionEventKind::slip) state.sliding = event.direction;
  if (event.kind == FrictionEventKind::stick) state.sliding = 0;
}

double slip_to_limit(StickSlipSpring& state, const SlipLimit& law, const SpringGeometry& spring,
                     double indentation, double tangential) {
  const double force = spring.tangential_stiffness * (tangential - state.offset);
  const double limit = slip_limit(law, spring, indentation);
  if (std::abs(force) <= limit) return 0.0;
  const std::int8_t direction = force > 0.0 ? 1 : -1;
  const double offset = tangential - direction * limit / spring.tangential_stiffness;
  const double dissipated = limit * std::abs(offset - state.offset);
  state.offset = offset;
  state.sliding = direction;
  return dissipated;
}

}  // namespace mdrsim
