// Approach and retract fitted together (`--segment both`): one modulus, contact point and
// baseline, a work of adhesion for each segment; and the hysteresis energy between them.
#pragma once

#include <cstddef>
#include <optional>

#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"

namespace mdrsim::fit {

struct CombinedFitOptions {
  bool adhesive = true;  ///< false: Hertz on both segments (no adhesion)
  AdhesionModel model = AdhesionModel::jkr;
  TipShape tip;
  double poisson_ratio = 0.5;
  AdhesiveFixed fixed;
  std::optional<double> approach_work_of_adhesion;  ///< [J/m^2] held
  /// Maugis-Dugdale on one path (fit_maugis_both): one dgamma and lambda for both segments,
  /// reported as approach_work_of_adhesion too; `model` is not read.
  bool maugis = false;
};

/// work_of_adhesion is the retract's (the contact peeling off), approach_work_of_adhesion the
/// approach's (the contact forming); both stay 0 for Hertz.
struct CombinedFit : AdhesiveFit {
  FitParameter approach_work_of_adhesion;  ///< [J/m^2]
  std::size_t approach_points = 0;
  std::size_t retract_points = 0;
};

/// Fits the model to both segments at once, starting from each segment's own fit. Contact:
/// on the retract down to its jump off (as fit_adhesive), on the approach where it is indented
/// past the contact point (the approach's own fit's first, then once more the joint fit's).
/// Hertz's model holds on both wherever indented.
CombinedFit fit_combined(const PreparedSegment& approach, const PreparedSegment& retract,
                         const CombinedFitOptions& options);

/// [J] The area between the approach and the retract over the tip position, by the trapezoid
/// rule on each segment's measured samples: sum over both, in their order, of F d(-z), with F
/// the force less the baseline `offset + slope (z - contact_point)` (the approach's).
/// Positive when the retract runs below the approach (energy left in the sample).
double hysteresis_energy(const PreparedSegment& approach, const PreparedSegment& retract,
                         double contact_point, double baseline_offset, double baseline_slope);

}  // namespace mdrsim::fit
