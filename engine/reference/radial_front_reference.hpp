// The fixed-grips loop of a parabolic contact whose work of adhesion varies with radius, tracked
// front by front from the MDR equilibrium alone (no spring row, no program engine).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace mdrsim::radial_front_reference {

// SI units. The indenter f(r) = r^2/(2R) has the MDR image g(x) = x^2/R. A contact of radius a
// is in equilibrium (Griffith at the front, a reversible interface: the same w(r) advancing and
// receding) at the indentation
//   d(a) = g(a) - sqrt(2 pi a w(a) / E*),
// and presses with F(a) = 2 E* int_0^a (d - g(x)) dx = E* (2 a d - 2 a^3/(3R)). Under fixed
// grips (d the control) a piece of d(a) with d'(a) > 0 is stable. The curve d(a) is cut into
// rising and falling branches at the roots of d'(a) (found after sampling d' on a grid fine
// enough for w) and at the steps of w: at a step b, d(a) is two-valued, and the vertical piece
// between d(b-) and d(b+) belongs to a rising branch when d(b+) > d(b-) (a tougher core: the
// front pins at b while d runs over that interval) and to a falling one otherwise.
//
// The loop: out of contact the front sits at a = 0 until d = 0 (d(0) = 0); then, as d rises, it
// follows its rising branch and, when d passes the branch's top (a local maximum of d(a)), it
// jumps forward at that d to the first a beyond where d(a) comes back to it (this is the first
// passage of d(a) through the present d, the touch at d = 0 included). At the deepest d it
// turns; as d falls it follows its branch back and, past the branch's bottom (a local minimum),
// jumps backward at that d to the largest smaller a where d(a) equals it on a rising branch; with
// none the contact separates (the front jumps to a = 0, F = 0). The jumps happen at constant d,
// so the loop energy, the closed integral of F dd, is the sum over the stable stretches of
// int F(a) d'(a) da (Gauss-Kronrod), and over a pinned stretch of int F dd with F linear in d.

/// w(r) [J/m^2], smooth between the listed steps.
struct RadialWorkOfAdhesion {
  std::function<double(double)> value;  ///< w(r) > 0 [J/m^2]
  std::function<double(double)> slope;  ///< dw/dr between the steps [J/m^3]
  /// The shortest length over which w changes [m] (a wavelength; R for a uniform w): d'(a) is
  /// sampled with samples_per_scale points per this length (or per the touch radius
  /// (2 pi w(0) R^2/E*)^(1/3) when that is shorter).
  double finest_scale = 0.0;
  /// Radii where w jumps [m], ascending and > 0; the front pins there while d crosses the gap.
  /// Either one-sided value may be w(b): the tracker asks w just inside and just outside b.
  std::vector<double> steps = {};
};

/// One equilibrium: the front at radius a under the indentation d.
struct RadialFrontState {
  double indentation = 0.0;     ///< d [m]
  double contact_radius = 0.0;  ///< a [m]
  double normal_force = 0.0;    ///< F = E* (2 a d - 2 a^3/(3R)) [N]
};

/// A stretch of the path with no jump: the front moves along d(a) from `from` to `to` (or stays
/// pinned at a step of w: from.contact_radius == to.contact_radius).
struct RadialFrontSegment {
  RadialFrontState from;
  RadialFrontState to;
};

/// A jump of the front at constant d: forward on the approach (the touch, from_radius = 0,
/// included), backward on the retract (the separation, to_radius = 0, included).
struct RadialFrontJump {
  double indentation = 0.0;  ///< d [m]
  double from_radius = 0.0;  ///< a before [m]
  double to_radius = 0.0;    ///< a after [m]
  bool advancing = false;    ///< a jump-in (approach), else a jump-out (retract)
};

/// The loop of one approach from the touch (d = 0) to the deepest d and the retract from there
/// to the separation.
struct RadialLoopReference {
  std::vector<RadialFrontSegment> approach;  ///< in order, from d = 0 to the deepest d
  std::vector<RadialFrontSegment> retract;   ///< in order, from the deepest d to the separation
  std::vector<RadialFrontJump> jumps;        ///< in the order of the loop
  /// The state of the most negative F on the retract path (its normal_force: the peak tension
  /// [N]): a stable state, a jump-out's start or the separation's.
  RadialFrontState peak_tension;
  /// The last equilibrium before the contact separates (its indentation: the separation depth).
  RadialFrontState separation;
  /// The closed integral of F dd over approach, retract and the separated way back from the
  /// separation depth to d = 0 (where F = 0) [J]: the energy the jumps dissipate, >= 0.
  double loop_energy = 0.0;

  std::size_t jumps_in() const;   ///< advancing jumps, the touch included
  std::size_t jumps_out() const;  ///< receding jumps, the separation included
};

/// The fixed-grips loop to the deepest indentation d_max >= 0 [m] (E* [Pa], R [m]). Every root
/// (extremum of d(a), landing radius) is located by bracketing to about 1e-14 relative; d'(a)
/// is sampled at `samples_per_scale` points per RadialWorkOfAdhesion::finest_scale (at least
/// 2). Throws std::invalid_argument for a bad argument and std::runtime_error if d(a) does
/// not reach d_max within 10^8 samples.
RadialLoopReference radial_fixed_grips_loop(double effective_modulus, double tip_radius,
                                            const RadialWorkOfAdhesion& work_of_adhesion,
                                            double deepest_indentation,
                                            int samples_per_scale = 200);

/// The same loop where the front advances on its own w_a(r) <= w(r) (`approach`) and recedes on
/// w(r): the approach follows d_a(a) = g(a) - sqrt(2 pi a w_a(a)/E*) to d_max, where the front
/// sits at the first passage a_max of d_a(a) through d_max; the retract holds it pinned there
/// (F linear in d) until d falls to d(a_max), then follows d(a) as above: along its branch
/// where d'(a_max) > 0, else at once jumping back to the nearest rising branch below (none:
/// separation).
RadialLoopReference radial_fixed_grips_loop(double effective_modulus, double tip_radius,
                                            const RadialWorkOfAdhesion& work_of_adhesion,
                                            const RadialWorkOfAdhesion& approach,
                                            double deepest_indentation,
                                            int samples_per_scale = 200);

}  // namespace mdrsim::radial_front_reference
