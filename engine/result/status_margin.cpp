// The fold of a row's branch against the radius where the glue shears off unstretched.
#include "engine/result/status_margin.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/boundary_let_go.hpp"

namespace mdrsim {
namespace {

/// a_s further below the critical spring than this many spacings: the status is plain.
constexpr double kFarSpacings = 8.0;
/// A fold closer to a_s than this share of it is the fit's rounding (about 1e-20 of a_s in
/// the random set's mode-dependent shear-offs), not a fold; the folds rows resolve lie far
/// above it (6e-5 a_s in the power-law scene of status_margin_test.cpp).
constexpr double kRoundingFold = 1e-12;

}  // namespace

std::optional<double> fold_of_let_go_branch(const std::array<double, 3>& positions,
                                            const std::array<double, 3>& controls, double a_s,
                                            double dx) {
  // Near a_s the let-go elongation goes like sqrt(a - a_s) (the margin at rest crosses zero
  // linearly in a), so the control along the branch is l(t) = A + B t - C sqrt(t), t = a - a_s,
  // with a fold where B = C / (2 sqrt(t)). A parabola in a misses it by many spacings where
  // the fold lies within one (the sqrt is not smooth there); this fit is exact for it.
  const double t[3] = {positions[0] - a_s, positions[1] - a_s, positions[2] - a_s};
  if (t[0] < 0.0) return std::nullopt;
  const std::array<double, 3>& l = controls;
  const double p = t[1] - t[0], q = std::sqrt(t[1]) - std::sqrt(t[0]);
  const double r = t[2] - t[0], w = std::sqrt(t[2]) - std::sqrt(t[0]);
  const double y1 = l[1] - l[0], y2 = l[2] - l[0];
  const double det = -p * w + q * r;  // of [[p, -q], [r, -w]]
  if (!(det != 0.0)) return std::nullopt;
  const double b = (-y1 * w + q * y2) / det;
  const double c = (p * y2 - r * y1) / det;
  if (!(b > 0.0) || !(c > 0.0)) return std::nullopt;  // no fold above a_s
  const double fold = 0.25 * (c / b) * (c / b);
  // A law whose elongation is not a sqrt there (mode-dependent) leaves c at rounding: a fold
  // some 1e-20 a_s above it, which no row of doubles resolves and no force feels.
  if (fold <= kRoundingFold * a_s) return std::nullopt;
  return fold / dx;
}

std::optional<double> program_fold_above_shear_off(
    const DetachmentCriterion& criterion, double tangential_stretch, double broken_position,
    const std::array<double, 3>& positions, const std::array<double, 3>& controls, double dx) {
  const auto margin = [&](double a) { return margin_at_rest(criterion, tangential_stretch, a); };
  const double lo = broken_position;
  const double hi = positions[0];
  if (!(lo > 0.0) || !(margin(lo) < 0.0) || !(margin(hi) >= 0.0)) return std::nullopt;
  return fold_of_let_go_branch(positions, controls, bracketed_root(margin, lo, hi), dx);
}

std::optional<double> fold_above_shear_off(const Contact& contact,
                                           const DetachmentCriterion& criterion,
                                           const std::optional<Contact::State>& outer2,
                                           const Contact::State& outer,
                                           const Contact::State& critical) {
  const std::int64_t n = critical.springs_in_contact;
  if (n < 2 || outer.springs_in_contact != n + 1) return std::nullopt;
  if (outer2 && outer2->springs_in_contact != n + 2) return std::nullopt;
  Contact probe = contact;
  probe.restore(critical);
  // The let-go controls at s = -1, 0, 1 and the spring at s = 0.
  double inner = 0.0;
  double at = 0.0;
  double out = 0.0;
  std::int64_t middle = 0;
  if (outer2) {
    inner = critical.normal_control;
    at = outer.normal_control;
    out = outer2->normal_control;
    middle = n + 1;
  } else {
    Contact next = probe;
    next.detach_boundary_spring();
    const BoundaryLetGo go = locate_boundary_let_go(next, criterion);
    if (go.let_go.kind != LetGo::Kind::at_elongation) return std::nullopt;
    inner = go.normal_control;
    at = critical.normal_control;
    out = outer.normal_control;
    middle = n;
  }
  const SpringFoundation& row = contact.foundation();
  const double dx = row.spacing();
  const auto margin_at_rest = [&](double a) {
    return criterion.margin({0.0, probe.tangential_displacement_at_radius(a), a});
  };
  const double hi = row.position(middle - 1);
  const double lo = std::max(0.0, row.position(middle) - kFarSpacings * dx);
  if (!(margin_at_rest(hi) >= 0.0) || lo <= 0.0 || margin_at_rest(lo) >= 0.0) {
    return std::nullopt;  // no shear-off radius near the critical point
  }
  const double a_s = bracketed_root(margin_at_rest, lo, hi);
  return fold_of_let_go_branch(
      {row.position(middle - 1), row.position(middle), row.position(middle + 1)}, {inner, at, out},
      a_s, dx);
}

bool status_resolved(const RunResult& row) {
  if (!row.fold_above_shear_off) return true;
  // A shear-off row with a fold above a_s, or an instability row whose fold is within a few
  // spacings of a_s: a finer row may tell otherwise.
  return row.status == RunStatus::instability && *row.fold_above_shear_off >= kStatusSpacings;
}

}  // namespace mdrsim
