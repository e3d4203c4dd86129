// One spring that sticks and slips at its slip limit: its events along a linear motion.
#pragma once

#include <cstdint>
#include <optional>

#include "friction/friction_law.hpp"

namespace mdrsim {

/// What the law needs of one spring (MDR: each spring independent, paper eq. 7).
struct SpringGeometry {
  double normal_stiffness;      ///< kz = E* dx [N/m]
  double tangential_stiffness;  ///< kx = G* dx [N/m]
  double image;                 ///< g(x_i) [m]
};

/// The indenter between two events: d and u_x linear in the stage parameter t.
struct LinearMotion {
  double start = 0.0;             ///< t0 [1]
  double indentation = 0.0;       ///< d(t0) [m]
  double tangential = 0.0;        ///< u_x(t0) [m]
  double indentation_rate = 0.0;  ///< dd/dt [m]
  double tangential_rate = 0.0;   ///< du_x/dt [m]

  double indentation_at(double t) const { return indentation + indentation_rate * (t - start); }
  double tangential_at(double t) const { return tangential + tangential_rate * (t - start); }
  /// The same motion seen from `t` on.
  LinearMotion from(double t) const {
    return {t, indentation_at(t), tangential_at(t), indentation_rate, tangential_rate};
  }
};

/// One spring's memory: the indenter's u_x at which it carries no tangential force (where it
/// touched or glued, plus every slip since), and whether it slides now. f_x = kx (u_x - offset).
struct StickSlipSpring {
  double offset = 0.0;      ///< [m]
  std::int8_t sliding = 0;  ///< 0: sticks; +1 / -1: slides along +x / -x, f_x = +limit / -limit
};

/// The trajectory's event kinds (docs/friction.md): `slip` (a sticking spring reaches its limit and
/// starts to slide) and `stick` (a sliding spring's slip would reverse: it sticks again, keeping
/// its offset). A `limit_kink` is no event of the trajectory: a sliding glued spring
/// (GluedShear::limited) whose f_z changes sign, where its limit, and so the row's tangential
/// response, changes slope.
enum class FrictionEventKind { slip, stick, limit_kink };

struct FrictionEvent {
  FrictionEventKind kind;
  double at;              ///< the stage parameter t of the event [1]
  std::int8_t direction;  ///< slip: the sign of the slide that starts; stick: of the one that ends
};

/// kz (d - g): positive when pressed [N].
inline double spring_normal_force(const SpringGeometry& spring, double indentation) {
  return spring.normal_stiffness * (indentation - spring.image);
}
/// mu max(f_z, 0) + constant [N].
double slip_limit(const SlipLimit& law, const SpringGeometry& spring, double indentation);
/// kx (u_x - offset) of a sticking spring; +-limit of a sliding one [N].
double spring_tangential_force(const StickSlipSpring& state, const SlipLimit& law,
                               const SpringGeometry& spring, double indentation, double tangential);

/// The first event of the spring along `motion` in [motion.start, end]: a sticking spring's
/// slip where |f_x| reaches the limit (both are linear in t, so a linear root on each side of
/// the limit, and on each side of f_z = 0 for a glued spring under GluedShear::limited), a sliding
/// spring's stick where its slip velocity u_x' - sigma limit'/kx has the sign opposed to its slide.
/// An event at motion.start itself means the spring must change at once (a sticking spring
/// on its limit moving outwards, a sliding one whose motion reverses); nullopt: none up to end.
std::optional<FrictionEvent> next_friction_event(const StickSlipSpring& state, const SlipLimit& law,
                                                 const SpringGeometry& spring,
                                                 const LinearMotion& motion, double end);

/// Moves the spring along `motion` from motion.start to t, with no event in between (the
/// locator's answer): a sticking spring keeps its offset, a sliding one follows its limit,
/// offset = u_x - sigma limit/kx. Returns the work the slip dissipated, the integral of the
/// limit over the slip distance (exact: both are linear in t on each side of f_z = 0) [J].
double advance_spring(StickSlipSpring& state, const SlipLimit& law, const SpringGeometry& spring,
                      const LinearMotion& motion, double t);

/// Applies an event the locator found, after advance_spring to its time: slip starts the slide
/// in its direction, stick ends it (the offset stays), a limit kink changes nothing.
void apply_friction_event(StickSlipSpring& state, const FrictionEvent& event);

/// A spring over its limit at once (its glue let go while it stays pressed, keeping its
/// stretch): it slips to the limit within the jump and slides on. Returns the dissipated work,
/// limit times slip distance [J]; 0 and no change for a spring within its limit.
double slip_to_limit(StickSlipSpring& state, const SlipLimit& law, const SpringGeometry& spring,
                     double indentation, double tangential);

}  // namespace mdrsim
