// Hutchinson-Suo mode-dependent toughness: Gamma(psi) = 2 pi a dgamma (1 + tan^2((1-lambda) psi)).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "detachment/criterion.hpp"

namespace mdrsim {

/// lambda = 1 is the mode-mixed criterion, lambda = 0 the normal-only one. In between the
/// let-go has no closed form: it is tabulated once per lambda, at construction, as polynomial
/// pieces over log-spaced intervals, each checked against the exact root; calls are read-only.
class ModeDependentCriterion final : public DetachmentCriterion {
 public:
  ModeDependentCriterion(const InterfaceProperties& properties, double lambda);
  double margin(const BoundarySpring& spring) const override;
  std::optional<double> critical_elongation(double contact_radius,
                                            double tangential_displacement) const override;
  /// In x = sqrt(E*) e, y = sqrt(G*) |u_x|, polar (r, psi), the spring holds inside
  /// r cos(mu psi) = sqrt(2 pi a dgamma), mu = 1 - lambda: with r = sec(mu psi) (in that unit),
  /// r^2 + 2 r'^2 - r r'' = (1 - mu^2) sec^2(mu psi) >= 0, so the holding set is convex (and
  /// smooth across u_x = 0, r'(0) = 0); d(r cos(mu psi))/dx = cos(psi) cos(mu psi) + mu sin(psi)
  /// sin(mu psi) >= 0 for psi in [0, pi/2], so the margin falls with the elongation.
  bool proves_contract() const override { return true; }

 private:
  /// sin(phi) / sin(lambda pi/2 + (1 - lambda) phi) = e / sqrt(2 pi a dgamma / E*) on a quarter
  /// octave of t or of 1 - t, as a polynomial in x in [-1, 1]; all NaN where it failed its check.
  struct Piece {
    std::array<double, 12> coefficients;
  };

  double let_go_ratio(double t) const;
  double root_angle(double t, double s, double guess) const;
  double ratio_at(double phi) const;
  void fit(bool top, int octave, int quarter, double& angle);

  InterfaceProperties p_;
  ElongationScales scales_;
  double lambda_;                 ///< mode sensitivity in [0, 1]
  double cos_at_pure_shear_;      ///< cos((1 - lambda) pi/2): the margin's factor at zero stretch
  double mu_;                     ///< 1 - lambda, rounded as margin() rounds it
  double half_lambda_pi_ = 0.0;   ///< (1 - mu) pi/2 [rad]
  double sin_half_ = 0.0;         ///< sin(lambda pi/2): t = c sin(lambda pi/2) in [0, 1]
  double cot_half_ = 0.0;         ///< cot(lambda pi/2)
  double root_per_radius_ = 0.0;  ///< sqrt(2 pi dgamma / E*) [m^(1/2)]
  double t_per_root_ = 0.0;       ///< sqrt(G* / (2 pi dgamma)) sin(lambda pi/2) [m^(-1/2)]
  double series_end_ = 0.0;       ///< below this t, the ratio is 1 - series_ t^2
  double series_ = 0.0;           ///< (1 - mu^2) / (2 sin^2(lambda pi/2))
  int lowest_octave_ = 0;         ///< of t in the table
  std::vector<Piece> pieces_;     ///< quarter octaves of t in [2^lowest, 1/2), then of 1 - t
};

}  // namespace mdrsim
