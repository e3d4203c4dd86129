// The minimum of a function on [lo, hi], by Brent's method: the one minimizer of mdrsim.
#pragma once

#include <boost/math/tools/minima.hpp>

namespace mdrsim {

/// Where a minimum is and the function's value there.
struct Minimum {
  double at;
  double value;
};

/// The minimum of fn on [lo, hi], its place to about (hi - lo) 2^(1 - bits). The search runs
/// over t in [0, 1], x = lo + t (hi - lo): Boost's stopping rule has an absolute part,
/// 2^(1 - bits) / 4 in the variable searched, which in metres would end a search across
/// nanometres at its first step (a contact radius of 1e-8 m against an absolute 7e-9 at 26
/// bits) and return an end of the bracket as the minimum.
template <class Fn>
Minimum bracketed_minimum(Fn fn, double lo, double hi, int bits) {
  const double width = hi - lo;
  const auto r = boost::math::tools::brent_find_minima([&](double t) { return fn(lo + t * width); },
                                                       0.0, 1.0, bits);
  return {lo + r.first * width, r.second};
}

}  // namespace mdrsim
