// The power-law indenter f(r) = c r^n and its MDR image g(x) = kappa(n) c x^n.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "profiles/profile.hpp"

namespace mdrsim {

/// n > 0: n = 1 is a cone, n = 2 a parabola (c = 1/(2R)), large n approaches a flat punch.
class PowerLawProfile final : public Profile {
 public:
  PowerLawProfile(double coefficient, double exponent);

  /// kappa(n) = sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2), the factor of eq. 4 for r^n.
  static double image_factor(double exponent);

  double shape(double radius) const override;
  double mdr_image(double x) const override;
  bool always_one_disk() const override { return exponent_ >= 1.0; }  ///< convex
  /// sqrt(x) g'(x) = n k x^(n - 1/2): s = n - 1/2 at every x.
  std::optional<LogSlopeRange> image_slope_growth() const override {
    return LogSlopeRange{exponent_ - 0.5, exponent_ - 0.5};
  }
  double mdr_image_slope(double x) const override;
  double contact_radius_at_depth(double depth) const override;
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  std::optional<ExactIntegral> squared_gap_integral(double contact_radius,
                                                    double indentation) const override;
  /// In closed form: J = k c^n G(t) and dJ/dt = k n c^n tan(t) H(t) with H = int_0^t cos^n and
  /// G = H - t cos^n t: by their series in t where the zone is thin (where G would cancel), by
  /// H's series about t = pi/2 where it is wide, and by the incomplete beta function between
  /// them where n > 6 leaves a gap (relative accuracy about 1e-14 at every t).
  DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius,
                         double angle) const override;
  std::optional<PullOffScales> pull_off_scales(double effective_modulus,
                                               double work_of_adhesion) const override;

  /// The fixed-load pull-off of the image g = k x^n [m] on E* [Pa] with dgamma [J/m^2]:
  /// a0 = (3 sqrt(2 pi dgamma/E*)/(2 k n))^(2/(2n-1)), F0 = 2 E* k n (2n-1) a0^(n+1)/(3(n+1)),
  /// d0 = k a0^n/3 (= |d| there for n = 1 and 2); nullopt for n <= 1/2, where the force has
  /// no minimum, or when a scale is not a positive finite number.
  static std::optional<PullOffScales> pull_off_scales_of(double image_coefficient, double exponent,
                                                         double effective_modulus,
                                                         double work_of_adhesion,
                                                         std::string basis);

 private:
  double coefficient_;        ///< c [m^(1-n)]
  double exponent_;           ///< n [1]
  double image_coefficient_;  ///< kappa(n) c [m^(1-n)]

  /// Terms of the series of H(t)/t and G(t)/t in t^2, and of cos^n t / w^n and (H(pi/2) -
  /// H(t)) / w^(n+1) in w^2 = (pi/2 - t)^2 (dugdale_gap).
  static constexpr int kZoneSeriesTerms = 40;
  std::array<double, kZoneSeriesTerms> cosine_power_integral_{};  ///< H(t)/t's [1]
  std::array<double, kZoneSeriesTerms> cosine_power_excess_{};    ///< G(t)/t's [1]
  std::array<double, kZoneSeriesTerms> sine_power_{};             ///< sin^n w / w^n's [1]
  std::array<double, kZoneSeriesTerms> sine_power_integral_{};    ///< its integral's [1]
  /// The terms each of kZoneBins equal bins of t (of pi/2 - t) up to the series' range needs.
  static constexpr int kZoneBins = 32;
  std::array<int, kZoneBins> thin_zone_terms_{};
  std::array<int, kZoneBins> wide_zone_terms_{};
  double thin_zone_angle_ = 0.0;  ///< t below which H and G are summed in t [rad]
  double wide_zone_width_ = 0.0;  ///< pi/2 - t below which H is summed in pi/2 - t [rad]
  double half_beta_ = 0.0;        ///< H(pi/2) = B(1/2, (n + 1)/2)/2 [1]
};

}  // namespace mdrsim
