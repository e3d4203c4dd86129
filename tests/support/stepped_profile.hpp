// A test profile with two folds under fixed grips: a cone-like tip that levels off, then a
// parabola. Shared by the continuum route's tests and the continuum reference's.
#pragma once

#include <cmath>

#include "profiles/profile.hpp"

namespace mdrsim::test {

/// g = A tanh(x/s) + x^2/R: a cone-like tip of slope A/s that levels off, then a parabola.
/// Under fixed grips d(a) has two minima, at the tip and on the parabola.
class SteppedProfile final : public Profile {
 public:
  SteppedProfile(double step, double width, double radius)
      : step_(step), width_(width), radius_(radius) {}
  double shape(double r) const override { return mdr_image(r); }  // not used by these tests
  double mdr_image(double x) const override {
    return step_ * std::tanh(x / width_) + x * x / radius_;
  }
  double mdr_image_slope(double x) const override {
    const double c = 1.0 / std::cosh(x / width_);
    return step_ / width_ * c * c + 2.0 * x / radius_;
  }
  // 2 integral_0^a x g'(x) dx = 2 A s (t tanh t - ln cosh t) + 4 a^3/(3R), t = a/s.
  double nonadhesive_force_per_modulus(double a) const override {
    const double t = a / width_;
    const double log_cosh = t + std::log1p(std::exp(-2.0 * t)) - std::log(2.0);
    return 2.0 * step_ * width_ * (t * std::tanh(t) - log_cosh) + 4.0 * a * a * a / (3.0 * radius_);
  }

 private:
  double step_;    ///< A [m]
  double width_;   ///< s [m]
  double radius_;  ///< R [m]
};

}  // namespace mdrsim::test
