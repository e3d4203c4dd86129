// The criterion contract sampled: monotone in the elongation, convex where the spring holds.
#include "engine/model/criterion_contract.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/base/hess_scale.hpp"

namespace mdrsim {
namespace {

/// The grid in the criterion's scales: elongations from 0 to 64 Hess elongations, u_x both
/// ways to 2 shear-off displacements.
constexpr double kElongations[] = {0.0, 1.0 / 64, 1.0 / 16, 0.25, 0.5,  0.75,
                                   1.0, 1.5,      2.0,      4.0,  16.0, 64.0};
constexpr double kTangentials[] = {-2.0, -1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0, 2.0};
/// Rounding a margin may carry, relative to the margins compared and to the margin at rest
/// (a margin is a difference of terms of that size: zero on the holding boundary, to their
/// rounding, whatever the scale).
constexpr double kRounding = 1e-9;

[[noreturn]] void broken(std::string_view name, const std::string& what) {
  throw std::runtime_error(fmt::format(
      "detachment criterion '{}' breaks the contract the engine relies on (see the criterion "
      "interface): {}; its let-gos would be wrong",
      name, what));
}

void check_at(const DetachmentCriterion& criterion, std::string_view name, const Material& material,
              double a) {
  const double hess =
      std::sqrt(hess_scale(material.work_of_adhesion_at(a), material.effective_modulus) * a);
  const double e_scale = hess > 0.0 && std::isfinite(hess) ? hess : 1e-6 * a;
  const double ratio = material.effective_modulus / material.effective_shear_modulus;
  const double u_scale = std::isfinite(ratio) && ratio > 0.0 ? e_scale * std::sqrt(ratio) : e_scale;
  struct Point {
    double e, u, margin;
  };
  std::vector<Point> holding;
  // The criterion holds at rest (its contract): the size of the terms its margins subtract.
  const double at_rest = std::max(margin_at_rest(criterion, 0.0, a), 0.0);
  for (const double ut : kTangentials) {
    const double u = ut * u_scale;
    double previous = 0.0;
    double previous_e = 0.0;
    bool first = true;
    for (const double et : kElongations) {
      const double e = et * e_scale;
      const double m = criterion.margin({e, u, a});
      if (!first &&
          m > previous + kRounding * std::max({std::abs(m), std::abs(previous), at_rest})) {
        broken(name, fmt::format("its margin rises with the elongation at a = {:.6g} m, u_x = "
                                 "{:.6g} m: {:.6g} at {:.6g} m, {:.6g} at {:.6g} m",
                                 a, u, previous, previous_e, m, e));
      }
      if (m > 0.0) holding.push_back({e, u, m});
      previous = m;
      previous_e = e;
      first = false;
    }
  }
  for (std::size_t i = 0; i < holding.size(); ++i) {
    for (std::size_t j = i + 1; j < holding.size(); ++j) {
      const Point& p = holding[i];
      const Point& q = holding[j];
      const double e = 0.5 * (p.e + q.e);
      const double u = 0.5 * (p.u + q.u);
      const double m = criterion.margin({e, u, a});
      if (m < -kRounding * std::max({p.margin, q.margin, at_rest})) {
        broken(name, fmt::format("the states where a spring holds are not convex at a = {:.6g} "
                                 "m: it holds at (elongation, u_x) = ({:.6g}, {:.6g}) m and "
                                 "({:.6g}, {:.6g}) m but not half way, margin {:.6g}",
                                 a, p.e, p.u, q.e, q.u, m));
      }
    }
  }
}

}  // namespace

void sample_criterion_contract(const DetachmentCriterion& criterion, std::string_view name,
                               const Material& material, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) return;
  for (const double a : {radius, 0.25 * radius, radius / 16.0}) {
    check_at(criterion, name, material, a);
  }
}

void check_criterion_contract(const DetachmentCriterion& criterion, std::string_view name,
                              const Material& material, double radius) {
  if (criterion.proves_contract()) return;
  sample_criterion_contract(criterion, name, material, radius);
}

}  // namespace mdrsim
