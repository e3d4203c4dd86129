// The tangential line load below which each spring of a viscoelastic row's edge holds glued
// with no elongation: found once per spring when first asked, then kept (it depends only on the
// spring's radius and the glassy criterion), so that rebinding's look along a sticking run costs
// no bisection an event.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/model/viscoelastic_edge.hpp"

namespace mdrsim {

class HoldingTangentialLoads {
 public:
  /// For the N springs of `edge` spaced dx [m]; the edge must outlive this.
  HoldingTangentialLoads(const ViscoelasticEdge* edge, double spacing, std::size_t springs);

  /// |q_x| [N/m] below which spring k holds with no elongation: the glassy criterion's margin
  /// at (0, q_x / G_0, x_k) is positive, bisected to the last bit (a built-in criterion's
  /// holding set is convex and symmetric in u_x); infinity without a criterion or where it
  /// always holds.
  double at(std::size_t k) const;

 private:
  double bisect(std::size_t k) const;

  const ViscoelasticEdge* edge_;
  double spacing_;
  mutable std::vector<double> loads_;  ///< NaN until asked
};

}  // namespace mdrsim
