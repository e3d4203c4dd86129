// The root of a function bracketed on [lo, hi], by TOMS 748: the one root finder of mdrsim.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <cstdint>
#include <limits>

namespace mdrsim {

/// The final bracket of a root search and the iterations it took.
struct RootBracket {
  double lo;
  double hi;
  int iterations;
};

/// fn(lo) and fn(hi) must differ in sign. The bracket shrinks until its ends agree to
/// `digits` bits (full precision by default; a few less where fn is noisy near its root).
template <class Fn>
RootBracket bracket_root(Fn fn, double lo, double hi,
                         int digits = std::numeric_limits<double>::digits - 1) {
  std::uintmax_t iterations = 300;
  const auto r = boost::math::tools::toms748_solve(
      fn, lo, hi, boost::math::tools::eps_tolerance<double>(digits), iterations);
  return {r.first, r.second, static_cast<int>(iterations)};
}

/// The same from fn's values at the ends, known already (a scan's samples): two calls fewer.
template <class Fn>
RootBracket bracket_root(Fn fn, double lo, double hi, double fn_lo, double fn_hi,
                         int digits = std::numeric_limits<double>::digits - 1) {
  std::uintmax_t iterations = 300;
  const auto r = boost::math::tools::toms748_solve(
      fn, lo, hi, fn_lo, fn_hi, boost::math::tools::eps_tolerance<double>(digits), iterations);
  return {r.first, r.second, static_cast<int>(iterations)};
}

/// The midpoint of bracket_root's final bracket, at full precision.
template <class Fn>
double bracketed_root(Fn fn, double lo, double hi) {
  const RootBracket b = bracket_root(fn, lo, hi);
  return 0.5 * (b.lo + b.hi);
}

}  // namespace mdrsim
