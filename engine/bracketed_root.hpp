// The root of a function bracketed on [lo, hi], by TOMS 748 to full double precision.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <cstdint>
#include <limits>

namespace mdrsim {

/// fn(lo) and fn(hi) must differ in sign; returns the midpoint of the final bracket.
template <class Fn>
double bracketed_root(Fn fn, double lo, double hi) {
  std::uintmax_t iterations = 300;
  const auto r = boost::math::tools::toms748_solve(
      fn, lo, hi,
      boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 1),
      iterations);
  return 0.5 * (r.first + r.second);
}

}  // namespace mdrsim
