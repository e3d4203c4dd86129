// Numerical defaults of the Profile interface: root search on g(x) and quadrature of the force.
#include "profiles/profile.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace mdrsim {
namespace {

/// Smallest x in [0, outer] with fn(x) >= target, for fn non-decreasing; throws if none.
template <class Fn>
double invert_increasing(Fn fn, double target, double outer, const char* what) {
  if (fn(0.0) >= target) return 0.0;
  double lo = 0.0;
  double hi = std::isfinite(outer) ? outer : 1.0;
  if (!std::isfinite(outer)) {
    for (int i = 0; fn(hi) < target; ++i) {
      if (i > 2000) throw std::domain_error(std::string(what) + " is out of the profile's reach");
      lo = hi;
      hi *= 2.0;
    }
  } else if (fn(hi) < target) {
    throw std::domain_error(std::string(what) + " is out of the profile's reach");
  }
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      [&](double x) { return fn(x) - target; }, lo, hi,
      boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 2),
      iterations);
  return bracket.second;
}

}  // namespace

double Profile::contact_radius_at_depth(double depth) const {
  return invert_increasing([this](double x) { return mdr_image(x); }, depth, outer_radius(),
                           "the preload depth");
}

double Profile::nonadhesive_force_per_modulus(double contact_radius) const {
  const double ga = mdr_image(contact_radius);
  const double integral = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      [&](double x) { return ga - mdr_image(x); }, 0.0, contact_radius, 12, 1e-14);
  return 2.0 * integral;
}

double contact_radius_at_force(const Profile& profile, double force, double effective_modulus) {
  if (const auto fixed = profile.fixed_contact_radius()) return *fixed;
  return invert_increasing([&](double a) { return profile.nonadhesive_force_per_modulus(a); },
                           force / effective_modulus, profile.outer_radius(), "the preload force");
}

}  // namespace mdrsim
