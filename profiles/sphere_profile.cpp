// The sphere's closed forms, written to keep full precision at contact radii small against R.
#include "profiles/sphere_profile.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mdrsim {

SphereProfile::SphereProfile(double radius) : radius_(radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("the sphere's radius must be positive and finite");
  }
}

// r^2/(R + sqrt(R^2 - r^2)) is R - sqrt(R^2 - r^2) without its cancellation at small r.
double SphereProfile::shape(double r) const {
  if (r > radius_) return std::numeric_limits<double>::infinity();
  return r * r / (radius_ + std::sqrt((radius_ - r) * (radius_ + r)));
}

double SphereProfile::mdr_image(double x) const {
  if (x >= radius_) return std::numeric_limits<double>::infinity();
  return x * std::atanh(x / radius_);
}

// d/dx [x artanh(x/R)] = artanh(x/R) + x R/(R^2 - x^2).
double SphereProfile::mdr_image_slope(double x) const {
  if (x >= radius_) return std::numeric_limits<double>::infinity();
  return std::atanh(x / radius_) + x * radius_ / ((radius_ - x) * (radius_ + x));
}

// 2 integral_0^a (g(a) - g) dx = (a^2 + R^2) artanh(a/R) - a R = R^2 ((1 + t^2) artanh t - t)
// with t = a/R: the exact Hertz force of a sphere over E*. Below t = 0.1 the difference
// loses digits to cancellation, so its series sum_k 4k/(4k^2 - 1) t^(2k+1) is used there
// (ratio t^2 <= 0.01: 9 terms reach 1e-18).
double SphereProfile::nonadhesive_force_per_modulus(double a) const {
  if (a >= radius_) return std::numeric_limits<double>::infinity();
  const double t = a / radius_;
  double bracket = 0.0;
  if (t < 0.1) {
    const double t2 = t * t;
    double power = t * t2;
    for (int k = 1; k <= 9; ++k) {
      bracket += 4.0 * k / (4.0 * k * k - 1.0) * power;
      power *= t2;
    }
  } else {
    bracket = (1.0 + t * t) * std::atanh(t) - t;
  }
  return radius_ * radius_ * bracket;
}

}  // namespace mdrsim
