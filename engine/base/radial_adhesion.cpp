// dgamma(r): the table's linear pieces and steps, the sinusoid, and the checks of both.
#include "engine/base/radial_adhesion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace mdrsim {

std::optional<AdhesionTableProblem> find_adhesion_table_problem(const RadialAdhesion::Table& t) {
  if (t.radii.empty())
    return AdhesionTableProblem{"r", std::nullopt, "is empty: expected at least one point"};
  if (t.radii.size() != t.values.size()) {
    return AdhesionTableProblem{"value", std::nullopt,
                                fmt::format("has {} values for {} radii: expected as many of each",
                                            t.values.size(), t.radii.size())};
  }
  for (std::size_t i = 0; i < t.radii.size(); ++i) {
    if (!std::isfinite(t.radii[i]) || t.radii[i] < 0.0) {
      return AdhesionTableProblem{
          "r", i, fmt::format("r[{}] = {} is not a finite radius >= 0", i, t.radii[i])};
    }
    if (!std::isfinite(t.values[i]) || t.values[i] < 0.0) {
      return AdhesionTableProblem{
          "value", i,
          fmt::format("value[{}] = {} at r = {} is not a finite work of adhesion >= 0", i,
                      t.values[i], t.radii[i])};
    }
    if (i > 0 && t.radii[i] < t.radii[i - 1]) {
      return AdhesionTableProblem{
          "r", i,
          fmt::format("r[{}] = {} is below r[{}] = {}: expected radii in increasing order", i,
                      t.radii[i], i - 1, t.radii[i - 1])};
    }
    if (i > 1 && t.radii[i] == t.radii[i - 2]) {
      return AdhesionTableProblem{
          "r", i,
          fmt::format("r[{}] = r[{}] = r[{}] = {}: a radius at most twice (a step)", i - 2, i - 1,
                      i, t.radii[i])};
    }
  }
  return std::nullopt;
}

RadialAdhesion::RadialAdhesion(Table table) {
  if (const auto problem = find_adhesion_table_problem(table)) {
    throw std::invalid_argument(problem->message);
  }
  breakpoints_ = table.radii;
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
  largest_ = *std::max_element(table.values.begin(), table.values.end());
  for (std::size_t i = 1; i < breakpoints_.size(); ++i) {
    finest_length_ = std::min(finest_length_, breakpoints_[i] - breakpoints_[i - 1]);
  }
  form_ = std::move(table);
}

RadialAdhesion::RadialAdhesion(Sinusoid s) {
  if (!(std::isfinite(s.mean) && s.mean >= 0.0)) {
    throw std::invalid_argument(fmt::format("mean = {} is not a finite value >= 0", s.mean));
  }
  if (!(s.amplitude >= 0.0 && s.amplitude <= 1.0)) {
    throw std::invalid_argument(
        fmt::format("amplitude = {} is outside [0, 1] (dgamma >= 0 everywhere)", s.amplitude));
  }
  if (!(std::isfinite(s.wavelength) && s.wavelength > 0.0)) {
    throw std::invalid_argument(
        fmt::format("wavelength = {} is not a finite length > 0", s.wavelength));
  }
  largest_ = s.mean * (1.0 + s.amplitude);
  finest_length_ = s.wavelength;
  form_ = s;
}

std::string RadialAdhesion::describe() const {
  if (const Sinusoid* s = sinusoid()) {
    return fmt::format("{} (1 + {} sin(2 pi r / {}))", s->mean, s->amplitude, s->wavelength);
  }
  return fmt::format("a table of {} points", std::get<Table>(form_).radii.size());
}

std::optional<double> first_radius_where_approach_exceeds(const RadialAdhesion& approach,
                                                          const RadialAdhesion& receding,
                                                          double reach) {
  std::vector<double> radii{0.0};
  std::vector<double> inner;  // just inside each point: a step's inner value
  for (const RadialAdhesion* w : {&approach, &receding}) {
    for (const double r : w->breakpoints()) {
      radii.push_back(r);
      if (r > 0.0) inner.push_back(std::nextafter(r, 0.0));
    }
    if (const auto* s = w->sinusoid(); s && std::isfinite(reach)) {
      const double step = s->wavelength / 64.0;
      const double count = std::min(std::ceil(reach / step), 1e6);
      for (double k = 0.0; k <= count; k += 1.0) radii.push_back(k * step);
    }
  }
  std::sort(radii.begin(), radii.end());
  std::sort(inner.begin(), inner.end());
  // The points themselves first, so that a message names a point where there is one.
  for (const auto* list : {&radii, &inner}) {
    for (const double r : *list) {
      if (approach.at(r) > receding.at(r)) return r;
    }
  }
  return std::nullopt;
}

}  // namespace mdrsim
