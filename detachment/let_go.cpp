// Let-go location: a closed form where the criterion has one, else TOMS 748 on the margin.
#include "detachment/let_go.hpp"

#include <boost/math/tools/roots.hpp>
#include <cstdint>
#include <limits>

namespace mdrsim {

LetGo locate_let_go(const DetachmentCriterion& criterion, double a, double ux,
                    double elongation_scale) {
  const double at_zero = criterion.margin({0.0, ux, a});
  if (at_zero < 0.0) return {LetGo::Kind::now};
  if (const auto closed = criterion.critical_elongation(a, ux)) {
    return {LetGo::Kind::at_elongation, *closed > 0.0 ? *closed : 0.0};
  }
  if (at_zero == 0.0) return {LetGo::Kind::at_elongation, 0.0};

  const auto margin_at = [&](double e) { return criterion.margin({e, ux, a}); };
  double lo = 0.0;
  double hi = elongation_scale > 0.0 ? elongation_scale : 1e-300;
  int doublings = 0;
  while (margin_at(hi) > 0.0) {
    if (++doublings > 2100) return {LetGo::Kind::never};
    lo = hi;
    hi *= 2.0;
  }
  std::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      margin_at, lo, hi,
      boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 3),
      iterations);
  // The upper end: the spring surely lets go there (the margin is non-increasing).
  return {LetGo::Kind::at_elongation, bracket.second, static_cast<int>(iterations) + doublings};
}

}  // namespace mdrsim
