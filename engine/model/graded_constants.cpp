// M(k, nu), C_k, the graded springs and Hess's rule on them, as SPEC "Graded media" writes them.
#include "engine/model/graded_constants.hpp"

#include <cmath>
#include <numbers>

#include <boost/math/special_functions/beta.hpp>

namespace mdrsim {

double graded_point_force_compliance(const Grading& grading, double youngs_modulus,
                                     double poisson_ratio) {
  const double k = grading.exponent;
  const double nu = poisson_ratio;
  const double pi = std::numbers::pi;
  const double beta = std::sqrt((1.0 + k) * (1.0 - k * nu / (1.0 - nu)));
  const double half = std::tgamma(1.0 + 0.5 * k);
  const double dimensionless =
      (1.0 - nu * nu) * beta * std::sin(0.5 * pi * beta) * std::tgamma(0.5 * (3.0 + k + beta)) *
      std::tgamma(0.5 * (3.0 + k - beta)) / (pi * (1.0 + k) * (1.0 + k) * half * half);
  // M E0 z0^(-k) is dimensionless: E(z) = (E0 z0^(-k)) z^k.
  return dimensionless * std::pow(grading.depth, k) / youngs_modulus;
}

double graded_punch_constant(const Grading& grading, double youngs_modulus, double poisson_ratio) {
  const double k = grading.exponent;
  const double m = graded_point_force_compliance(grading, youngs_modulus, poisson_ratio);
  return 2.0 * std::cos(0.5 * std::numbers::pi * k) / (std::numbers::pi * (1.0 + k) * m);
}

double graded_spring_stiffness(double exponent, double punch_constant, double x) {
  return 0.5 * (1.0 + exponent) * punch_constant * std::pow(std::abs(x), exponent);
}

double graded_let_go_stretch(double exponent, double punch_constant, double work_of_adhesion,
                             double a) {
  return std::sqrt(4.0 * std::numbers::pi * std::pow(a, 1.0 - exponent) *
                   (work_of_adhesion / ((1.0 + exponent) * punch_constant)));
}

double graded_punch_surface_displacement(double exponent, double depth, double a, double r) {
  if (r <= a) return depth;
  const double k = exponent;
  // boost's beta(p, q, x) is the incomplete beta without the normalization.
  return depth * std::cos(0.5 * std::numbers::pi * k) *
         boost::math::beta(0.5 * (1.0 + k), 0.5 * (1.0 - k), (a / r) * (a / r)) / std::numbers::pi;
}

}  // namespace mdrsim
