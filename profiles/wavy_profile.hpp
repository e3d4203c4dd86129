// Guduru's wavy sphere f(r) = r^2/(2R) + A (1 - cos(2 pi r / lambda)) and its MDR image.
#pragma once

#include <numbers>
#include <optional>

#include "profiles/profile.hpp"

namespace mdrsim {

/// The axisymmetric roughness of Guduru (J. Mech. Phys. Solids 2007): a parabola of tip
/// radius R with a ripple of amplitude A and wavelength lambda. With k = 2 pi / lambda the
/// image is, term by term (paper eq. 4, r = x sin theta),
///   g(x) = x^2/R + A k x I(k x),   I(z) = int_0^{pi/2} sin(z sin theta) dtheta,
/// and I(z) = 2 sum_{j >= 0} J_{2j+1}(z) / (2j + 1) (the Jacobi-Anger expansion of the sine),
/// evaluated with all J_n(z) from one backward recurrence (wavy_image.hpp). Where the ripple
/// outweighs the curvature (A k^2 R > 1 about) f and g decrease between crests: a front then
/// jumps over the dip, and the contact may stop being one disk.
class WavyProfile final : public Profile {
 public:
  /// R > 0, A > 0 and lambda > 0 [m]; A = 0 is the parabola (register.cpp builds
  /// ParabolicProfile for it, so that its results are `parabolic`'s bit for bit).
  WavyProfile(double radius, double amplitude, double wavelength);

  double shape(double radius) const override;
  double mdr_image(double x) const override;
  double mdr_image_slope(double x) const override;
  /// In closed form: 2 int_0^a (g(a) - g(x)) dx = 2 [2 a^3/(3R) + (A/k) Z (Z I(Z) - (1 - I'(Z)))]
  /// with Z = k a, as int_0^Z z I(z) dz = (pi/2) Z H_1(Z) = Z (1 - I'(Z)) (d(z H_1)/dz = z H_0).
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  /// The parabola's J in closed form (ParabolicProfile::dugdale_gap) and the ripple's by
  /// wavy_ripple_gap (wavy_gap.hpp), about 1e-14 of J; dugdale_gap_quadrature where the contact
  /// holds more than kMaxWavyGapHalfWaves half wavelengths of the ripple.
  DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius,
                         double angle) const override;
  std::optional<double> jkr_scale_radius() const override { return radius_; }
  bool folds_at_every_crest() const override { return true; }

  std::optional<double> shortest_feature() const override {
    return 2.0 * std::numbers::pi / wavenumber_;
  }

 private:
  double radius_;      ///< R [m]
  double amplitude_;   ///< A [m]
  double wavenumber_;  ///< k = 2 pi / lambda [1/m]
};

}  // namespace mdrsim
