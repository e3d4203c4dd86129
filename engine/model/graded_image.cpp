// Closed forms of the graded image of power-law shapes, the quadrature's dispatch, and the
// radius at a depth or force for both.
#include "engine/model/graded_image.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/graded_quadrature.hpp"

namespace mdrsim {
namespace {

/// The x in (0, outer) where fn(x) = target, fn rising from fn(0) = 0, as
/// Profile::contact_radius_at_depth finds it: a root bracketed by doubling from 1 m where the
/// shape has no end, by halving the distance to a pole (the sphere's fn = +infinity at R), and
/// refused beyond a table's last point.
template <class Fn>
double graded_inverse(Fn fn, double target, double outer, bool pole, const char* what) {
  const auto out_of_reach = [&] {
    return std::domain_error(std::string(what) + " is out of the profile's reach");
  };
  double lo = 0.0;
  double hi = std::isfinite(outer) ? (pole ? 0.5 * outer : outer) : 1.0;
  if (std::isfinite(outer) && pole) {
    double gap = 0.5 * outer;
    while (fn(hi) < target) {
      lo = hi;
      gap *= 0.5;
      hi = outer - gap;
      if (!(hi > lo)) throw out_of_reach();
    }
  } else if (std::isfinite(outer)) {
    if (fn(hi) < target) throw out_of_reach();
  } else {
    for (int i = 0; fn(hi) < target; ++i) {
      if (i > 2000) throw out_of_reach();
      lo = hi;
      hi *= 2.0;
    }
  }
  if (lo == 0.0) {
    for (double half = 0.5 * hi; half > 0.0 && fn(half) >= target; half *= 0.5) hi = half;
    lo = 0.5 * hi;
  }
  return bracket_root([&](double x) { return fn(x) - target; }, lo, hi,
                      std::numeric_limits<double>::digits - 2)
      .hi;
}

}  // namespace

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

GradedImage GradedImage::by_quadrature(std::shared_ptr<const GradedShape> shape,
                                       double grading_exponent) {
  GradedImage g;
  g.grading_ = grading_exponent;
  g.quadrature_ = std::make_shared<const GradedQuadrature>(std::move(shape), grading_exponent);
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
  if (quadrature_) return quadrature_->image(x);
  return coefficient_ * std::pow(std::abs(x), exponent_);
}

double GradedImage::image_slope(double x) const {
  if (quadrature_) return quadrature_->image_slope(x);
  return coefficient_ * exponent_ * std::pow(std::abs(x), exponent_ - 1.0);
}

double GradedImage::nonadhesive_force_per_constant(double a) const {
  if (quadrature_) return quadrature_->nonadhesive_force_per_constant(a);
  const double n = exponent_, k = grading_;
  return coefficient_ * n * std::pow(a, n + 1.0 + k) / (n + 1.0 + k);
}

double GradedImage::squared_gap_integral(double a, double d) const {
  if (quadrature_) return quadrature_->squared_gap_integral(a, d);
  const double n = exponent_, k = grading_;
  const double ak = std::pow(a, 1.0 + k);
  const double ga = image(a);
  // (1+k) [d^2 a^(1+k)/(1+k) - 2 d K a^(n+1+k)/(n+1+k) + K^2 a^(2n+1+k)/(2n+1+k)]
  return ak * (d * d - 2.0 * (1.0 + k) * d * ga / (n + 1.0 + k) +
               (1.0 + k) * ga * ga / (2.0 * n + 1.0 + k));
}

double GradedImage::radius_at_depth(double d) const {
  if (quadrature_) {
    return graded_inverse([this](double x) { return quadrature_->image(x); }, d,
                          quadrature_->outer_radius(), quadrature_->has_pole(),
                          "the preload depth");
  }
  return std::pow(d / coefficient_, 1.0 / exponent_);
}

double GradedImage::radius_at_force(double force, double punch_constant) const {
  if (quadrature_) {
    return graded_inverse(
        [this](double a) { return quadrature_->nonadhesive_force_per_constant(a); },
        force / punch_constant, quadrature_->outer_radius(), quadrature_->has_pole(),
        "the preload force");
  }
  const double n = exponent_, k = grading_;
  return std::pow(force * (n + 1.0 + k) / (punch_constant * coefficient_ * n), 1.0 / (n + 1.0 + k));
}

}  // namespace mdrsim
