// Maugis' path as an instrument records it through a lever of finite stiffness: the synthetic
// approach and retract curves that the Maugis fit's tests and its bench line share (Maugis' own
// solution, apart from the MDR branch the fit samples).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/reference/maugis_reference.hpp"

namespace mdrsim::maugis_reference {

/// A lever of stiffness k whose base moves evenly. In Maugis' units (depth delta, force
/// pi w R, stiffness kappa = k delta / (pi w R)) the base stands at q = D + P / kappa (its
/// indentation); the tip sits on the path where q meets the base and jumps where q turns
/// (dP/dD = -kappa). The path runs from the zone's first touch (C = 0, D = -h0 = -2 / (pi
/// lambda), P = 0) along the no-contact branch in C up to C0, then the contact branch in A;
/// its parameter s is C below C0 and C0 + A above.
struct LeverPath {
  double lambda = 1.0, kappa = 1.0;
  double c0 = 0.0, a_max = 0.0;
  std::vector<double> s, q;  ///< the path's parameter on 3401 nodes and the base's position there

  LeverPath(double lambda, double kappa, double a_max);
  MaugisState state(double at) const;
  double base(double at) const;  ///< q at s = at
  /// The state where the base stands at `b` inside [s[j], s[j + 1]] (q monotone there).
  MaugisState solve(double b, std::size_t j) const;
};

/// A recorded segment in SI units: 2000 tip positions z [m] (the contact point less the
/// indentation) and forces [N] with a tilted baseline (offset 0.1 of the peak, slope 0.05 of
/// the peak over the largest indentation).
struct LeverCurve {
  std::vector<double> z, force;
  double contact_point = 3e-6;  ///< [m]
  double depth = 0.0;           ///< [m] the largest indentation
  double peak = 0.0;            ///< [N] the force there, peak_pulls fixed-load pull-offs
  double kappa_si = 0.0;        ///< [N/m] the lever's stiffness
};

/// An approach (far first) or a retract (deepest first) of 2000 evenly spaced base positions
/// from the deepest, q_top (where the force is peak_pulls fixed-load pull-offs), out to -far,
/// far = q_top / 2 + reach_lead h0, for a parabola of `scales`: the tip's position (the base's
/// plus the lever's bending, exact) and the force with the tilted baseline. The approach jumps
/// in at D = -h0 onto the path where q first rises through the base; the retract follows the
/// path down while q falls and jumps off where it turns. With reach_lead = 0 the free baseline
/// is what lies past -h0 in the half of q_top beyond contact, which at small lambda (h0 =
/// 2 / (pi lambda) depth units, 5.3 at 0.12) is little or nothing; with 1 the record runs half
/// of q_top past the zone's reach, where a user sees the force begin. `phase` shifts the base
/// positions by that fraction of a step: where a jump falls between two samples, which an
/// instrument does not choose.
LeverCurve lever_curve(const MaugisScales& scales, double lambda, bool approach, double kappa,
                       double peak_pulls, double phase, double reach_lead = 0.0);

}  // namespace mdrsim::maugis_reference
