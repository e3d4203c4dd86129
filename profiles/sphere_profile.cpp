// The sphere's closed forms, written to keep full precision at contact radii small against R.
#include "profiles/sphere_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
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

// g(x) = x artanh(x/R) = R sum_k u^(2k+2)/(2k+1), u = x/R, term by term in x = c cos(psi)
// (the power law's J, dugdale_gap there): J = R sum_k rho^(k+1) G_(2k+2)(t)/(2k+1) and dJ/dt
// = R tan(t) sum_k rho^(k+1) (2k+2)/(2k+1) H_(2k+2)(t), rho = (c/R)^2, with H_n = int_0^t cos^n
// and G_n = H_n - t cos^n t. Integrating cos^n by parts gives H_n = ((n-1) H_(n-2) + cos^(n-1)t
// sin t)/n from H_0 = t, and so G_n = ((n-1) G_(n-2))/n + cos^(n-2)t (D/n + t sin^2 t) from G_0
// = 0, D = sin t cos t - t: each a sum of positive terms (D/n + t sin^2 t >= (sin(2t)/2 - t
// cos(2t))/2 > 0 for n >= 2), where H_n - t cos^n t would cancel to eps/(n t^2). G_n grows
// like n t^3/3 at most and H_n falls with n, so the terms fall about as fast as rho^k: rho^K
// <= 2^-56 ends the sum (30 terms at rho = 1/4, two ulps left at most).
DugdaleGap SphereProfile::dugdale_gap(double a, double c, double t) const {
  const double rho = (c / radius_) * (c / radius_);
  if (!(rho <= 0.25)) return dugdale_gap_quadrature(*this, a, c, t);
  const int terms =
      rho > 0.0 ? std::clamp(static_cast<int>(std::ceil(-56.0 * std::numbers::ln2 / std::log(rho))),
                             1, 30)
                : 1;
  const double sin_t = std::sin(t), cos_t = std::cos(t);
  // D = (sin 2t - 2t)/2 by its series below t = 1, where the difference cancels: sum_(j>=1)
  // (-1)^j (2t)^(2j+1)/(2 (2j+1)!), 14 terms to below 1e-25 of its first.
  double d = 0.0;
  if (t < 1.0) {
    const double u2 = 4.0 * t * t;
    double term = t;
    for (int j = 1; j <= 14; ++j) {
      term *= -u2 / ((2.0 * j) * (2.0 * j + 1.0));
      d += term;
    }
  } else {
    d = sin_t * cos_t - t;
  }
  const double cos2 = cos_t * cos_t;
  const double t_sin2 = t * sin_t * sin_t;
  double h = t, g = 0.0;
  double cos_power = 1.0;  // cos^(n-2) t
  double rho_power = 1.0;
  double integral = 0.0, slope = 0.0;
  for (int k = 0; k < terms; ++k) {
    const double n = 2.0 * k + 2.0;
    g = ((n - 1.0) * g) / n + cos_power * (d / n + t_sin2);
    h = ((n - 1.0) * h + cos_power * cos_t * sin_t) / n;
    rho_power *= rho;
    integral += rho_power * g / (2.0 * k + 1.0);
    slope += rho_power * h * n / (2.0 * k + 1.0);
    cos_power *= cos2;
  }
  return {.integral = radius_ * integral, .angle_slope = radius_ * std::tan(t) * slope};
}

}  // namespace mdrsim
