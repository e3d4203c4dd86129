// A pressed viscoelastic spring sliding at its slip limit mu f_z(t): its tangential stretch and
// arms under that prescribed load, its work, dissipation and the time it sticks again.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_slide.hpp"

namespace mdrsim {

/// What a sliding spring's tangential arms did over an interval, per unit x of one half [J/m].
struct SlideCount {
  double work = 0.0;      ///< int f_x du_x, the machine's
  double friction = 0.0;  ///< int |f_x| |slip'|: the limit times the slip distance
  double bulk = 0.0;      ///< the dashpots' sum_j int s_j^2 / (G_j tau_j)
};

/// One slide from `since` [s] within a drive of fixed u_x' and a normal load f_z(s) known as an
/// exponential sum: f_x = direction mu f_z, the stretch and arms response_to_load's, and the
/// slip u_x - w moving along `direction` until its velocity u_x' - w' turns.
class ViscoelasticSlide {
 public:
  /// From arm stresses `stresses` at `since`, the normal line load `normal_load` (s from
  /// since), u_x' `tangential_rate`.
  ViscoelasticSlide(const RetardationModes& modes, std::span<const double> stresses,
                    const ExponentialSum& normal_load, double coefficient, std::int8_t direction,
                    double tangential_rate, double since);

  std::int8_t direction() const { return direction_; }
  double load(double t) const { return load_.at(t - since_); }     ///< f_x at time t [N/m]
  const ExponentialSum& load_from_start() const { return load_; }  ///< f_x(s), s = t - since
  double since() const { return since_; }                          ///< [s]
  double stretch(double t) const { return response_.stretch.at(t - since_); }  ///< [m]
  FewValues<double> stresses(double t) const;                                  ///< [N/m] per term
  /// Its work, friction and dashpot dissipation from time `from` to `to` [s].
  SlideCount count(std::span<const PronyTerm> terms, double from, double to) const;
  /// The delay [s] from time `now` within `span` at which its slip velocity turns (it sticks):
  /// none within it. `just_slipped`: the level is where the velocity stands now (a slip at a
  /// tangency starts at zero velocity, to rounding).
  std::optional<double> stick_delay(double now, double span, bool just_slipped) const;

 private:
  ExponentialSum load_;
  PrescribedLoadResponse response_;
  std::int8_t direction_;
  double rate_;
  double since_;
};

}  // namespace mdrsim
