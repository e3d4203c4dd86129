// Closed forms of the graded image of power-law shapes and its weighted integrals.
#include "engine/model/graded_image.hpp"

#include <cmath>
#include <numbers>

namespace mdrsim {

GradedImage GradedImage::of_power_law(double coefficient, double exponent,
                                      double grading_exponent) {
  GradedImage g;
  const double n = exponent, k = grading_exponent;
  // B(n/2, (1+k)/2) through lgamma: tgamma of n/2 overflows for large exponents.
  const double log_beta =
      std::lgamma(0.5 * n) + std::lgamma(0.5 * (1.0 + k)) - std::lgamma(0.5 * (n + 1.0 + k));
  g.coefficient_ = coefficient * 0.5 * n * std::exp(log_beta);
  g.exponent_ = n;
  g.grading_ = k;
  return g;
}

GradedImage GradedImage::of_flat_punch(double grading_exponent) {
  GradedImage g;
  g.grading_ = grading_exponent;
  return g;
}

std::optional<GradedImage> GradedImage::of_profile(const std::string& type, double first,
                                                   double second, double grading_exponent) {
  if (type == "parabolic") return of_power_law(0.5 / first, 2.0, grading_exponent);
  if (type == "cone") {
    return of_power_law(std::tan(first * std::numbers::pi / 180.0), 1.0, grading_exponent);
  }
  if (type == "power_law") return of_power_law(first, second, grading_exponent);
  if (type == "flat_punch") return of_flat_punch(grading_exponent);
  return std::nullopt;
}

double GradedImage::image(double x) const {
  return coefficient_ * std::pow(std::abs(x), exponent_);
}

double GradedImage::image_slope(double x) const {
  return coefficient_ * exponent_ * std::pow(std::abs(x), exponent_ - 1.0);
}

double GradedImage::nonadhesive_force_per_constant(double a) const {
  const double n = exponent_, k = grading_;
  return coefficient_ * n * std::pow(a, n + 1.0 + k) / (n + 1.0 + k);
}

double GradedImage::squared_gap_integral(double a, double d) const {
  const double n = exponent_, k = grading_;
  const double ak = std::pow(a, 1.0 + k);
  const double ga = image(a);
  // (1+k) [d^2 a^(1+k)/(1+k) - 2 d K a^(n+1+k)/(n+1+k) + K^2 a^(2n+1+k)/(2n+1+k)]
  return ak * (d * d - 2.0 * (1.0 + k) * d * ga / (n + 1.0 + k) +
               (1.0 + k) * ga * ga / (2.0 * n + 1.0 + k));
}

double GradedImage::radius_at_depth(double d) const {
  return std::pow(d / coefficient_, 1.0 / exponent_);
}

double GradedImage::radius_at_force(double force, double punch_constant) const {
  const double n = exponent_, k = grading_;
  return std::pow(force * (n + 1.0 + k) / (punch_constant * coefficient_ * n), 1.0 / (n + 1.0 + k));
}

}  // namespace mdrsim
