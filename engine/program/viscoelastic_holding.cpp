// The holding tangential loads of a viscoelastic row's edge, each bisected once.
#include "engine/program/viscoelastic_holding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mdrsim {

HoldingTangentialLoads::HoldingTangentialLoads(const ViscoelasticEdge* edge, double spacing,
                                               std::size_t springs)
    : edge_(edge),
      spacing_(spacing),
      loads_(edge ? springs : 0, std::numeric_limits<double>::quiet_NaN()) {}

double HoldingTangentialLoads::at(std::size_t k) const {
  double& load = loads_[k];
  if (std::isnan(load)) load = bisect(k);
  return load;
}

double HoldingTangentialLoads::bisect(std::size_t k) const {
  const ViscoelasticEdge& edge = *edge_;
  if (!edge.criterion) return HUGE_VAL;
  const double x = spacing_ * static_cast<double>(k + 1);
  const auto holds = [&](double q) {
    return edge.criterion->margin({0.0, q / edge.glassy_shear_modulus, x}) > 0.0;
  };
  if (!holds(0.0)) return 0.0;
  double hi = std::max(edge.let_go_loads[k], 1e-300);
  for (int i = 0; i < 2000 && holds(hi); ++i) hi *= 2.0;
  if (holds(hi)) return HUGE_VAL;
  double lo = 0.0;
  for (;;) {
    const double mid = lo + 0.5 * (hi - lo);
    if (mid <= lo || mid >= hi) return lo;
    (holds(mid) ? lo : hi) = mid;
  }
}

}  // namespace mdrsim
