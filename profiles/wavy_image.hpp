// The integrals of the wavy profile's MDR image: int_0^{pi/2} sin(z sin t) dt and its slope.
#pragma once

namespace mdrsim {

/// I(z) = int_0^{pi/2} sin(z sin t) dt = (pi/2) H_0(z) (Struve) and
/// I'(z) = int_0^{pi/2} sin t cos(z sin t) dt, for z >= 0.
struct RippleIntegrals {
  double value;  ///< I(z)
  double slope;  ///< I'(z)
  /// 1 - I'(z) = (pi/2) H_1(z), from its own series where z is small (there I' is 1 - z^2/3 + ...,
  /// and 1 - I' formed from it would keep only eps/z^2 of its digits).
  double slope_deficit;
};

/// Small z by their power series, I(z) = sum_j (-1)^j z^(2j+1) / ((2j+1)!!)^2; otherwise
/// from Bessel functions of the first kind (Jacobi-Anger):
///   I(z) = 2 sum_j J_{2j+1}(z) / (2j+1),   I'(z) = J_0(z) + 2 sum_{j>=1} J_{2j}(z) / (1 - 4 j^2),
/// with every J_n(z) from Miller's backward recurrence, normalized by J_0 + 2 sum J_{2j} = 1,
/// up to z = 100; from there the Struve functions' asymptotic series over Y_0 and Y_1, in O(1).
/// About 1e-15 relative to the scale of I (which is at most about 1.4). The last z's integrals
/// are kept per thread: a contact state asks them at one z for g, g' and the force.
RippleIntegrals ripple_integrals(double z);

}  // namespace mdrsim
