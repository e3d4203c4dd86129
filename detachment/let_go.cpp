// Let-go location: a closed form where the criterion has one, else TOMS 748 on the margin.
#include "detachment/let_go.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {

LetGo locate_let_go(const DetachmentCriterion& criterion, double a, double ux,
                    double elongation_scale) {
  const double at_zero = margin_at_rest(criterion, ux, a);
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
  // Margins in units of the one at zero stretch (> 0 here): TOMS 748 interpolates O(1)
  // values, where raw margins near 1e304 overflowed inside it and gave NaN.
  const auto relative_margin = [&](double e) { return margin_at(e) / at_zero; };
  if (!std::isfinite(relative_margin(hi))) {
    // The margin overflowed at the upper end (E* e^2 beyond a double): bisect on its sign.
    int halvings = 0;
    while (hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi && halvings < 2200) {
      const double mid = 0.5 * (lo + hi);
      (relative_margin(mid) > 0.0 ? lo : hi) = mid;
      ++halvings;
    }
    return {LetGo::Kind::at_elongation, hi, halvings + doublings};
  }
  const RootBracket bracket =
      bracket_root(relative_margin, lo, hi, std::numeric_limits<double>::digits - 3);
  // The upper end: the spring surely lets go there (the margin is non-increasing).
  return {LetGo::Kind::at_elongation, bracket.hi, bracket.iterations + doublings};
}

}  // namespace mdrsim
