// Abel-type integrals of eqs. 4-5 with their 1/sqrt end singularity, by Boost's tanh-sinh.
#include "profiles/mdr_transform.hpp"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <numbers>

namespace mdrsim {
namespace {

/// integral_0^b k(s)/sqrt(b^2 - s^2) ds, split at the breaks inside (0, b). Boost passes the
/// signed distance to the nearer end of each piece (hi - s > 0 in its right half), from which
/// b^2 - s^2 = (b - s)(b + s) is formed exactly on the last piece; the two square roots are
/// taken apart, since their product underflows next to s = b.
double abel_integral(const std::function<double(double)>& kernel, double b,
                     const std::vector<double>& breaks) {
  // One integrator per call: a shared one is not re-entrant (it extends its node tables
  // while integrating), and the round trip nests eq. 4 inside eq. 5. Not const: Boost 1.74
  // defines the two-argument integrate() without its const.
  boost::math::quadrature::tanh_sinh<double> integrator;
  double sum = 0.0;
  double lo = 0.0;
  for (std::size_t k = 0; k <= breaks.size(); ++k) {
    const double hi = k < breaks.size() && breaks[k] < b ? breaks[k] : b;
    if (!(hi > lo)) continue;
    const auto integrand = [&](double s, double complement) {
      const double distance = complement > 0.0 ? b - hi + complement : b - s;
      // A node whose distance underflowed carries a weight ~ distance: its term ~ sqrt(distance).
      if (!(distance > 0.0)) return 0.0;
      return kernel(s) / (std::sqrt(distance) * std::sqrt(b + s));
    };
    sum += integrator.integrate(integrand, lo, hi, 1e-12);
    lo = hi;
    if (hi == b) break;
  }
  return sum;
}

}  // namespace

double mdr_transform(const std::function<double(double)>& shape_slope, double x,
                     const std::vector<double>& breaks) {
  if (!(x > 0.0)) return 0.0;
  return x * abel_integral(shape_slope, x, breaks);
}

double inverse_mdr_transform(const std::function<double(double)>& image, double r,
                             const std::vector<double>& breaks) {
  if (!(r > 0.0)) return 0.0;
  return 2.0 / std::numbers::pi * abel_integral(image, r, breaks);
}

}  // namespace mdrsim
