// The Dugdale zone's gap integral of the wavy profile's ripple, by exchanging the order of the
// MDR transform's double integral.
#pragma once

#include "profiles/profile.hpp"

namespace mdrsim {

/// J and dJ/dt at fixed a (Profile::dugdale_gap) of the ripple f = A (1 - cos k r) alone, for
/// 0 <= a < c with t = arccos(a/c). With g(x) = x int_0^x f'(r) / sqrt(x^2 - r^2) dr, the order
/// of J's double integral exchanged, and r = a cos(psi) below a:
///   J = (pi/2) (f(c) - f(a)) + a int_0^(pi/2) f'(a cos psi) B(psi) dpsi,
///   B = sin(psi) arctan(tan(t) / sin(psi)) - t,
///   dB/dt = -tan^2(t) cos^2(psi) / (sin^2(psi) + tan^2(t)),
/// an elementary integrand of f' = A k sin(k r). B <= 0 has a layer of width tan(t) at psi = 0
/// (r = a): panels in psi doubling from it cover the ripple's first half wave below a, and
/// below that a 16-point Gauss-Legendre rule every two wavelengths in r, whose sines at the
/// nodes are the same in every panel. About 1.3 k a + 10 log2(1 / tan t) + 14 points; within
/// about 1e-14 of J (of the J of the parabolas r^2/(2R) and A k^2 r^2/2 where the ripple
/// outweighs the curvature and J changes sign along the zone).
DugdaleGap wavy_ripple_gap(double amplitude, double wavenumber, double contact_radius,
                           double cohesive_radius, double angle);

/// The most half wavelengths of the ripple over (0, a) that WavyProfile::dugdale_gap gives to
/// wavy_ripple_gap (whose points grow with them); beyond, the quadrature over (a, c).
inline constexpr double kMaxWavyGapHalfWaves = 256.0;

}  // namespace mdrsim
