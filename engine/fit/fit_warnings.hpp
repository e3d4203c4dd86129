// What a fit that says "fitted" cannot vouch for: a baseline its record does not fix, and a
// residual far above the curve's own noise (a model that does not describe the curve).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"

namespace mdrsim::fit {

/// A record fixes its baseline from this many free samples, and from a tenth of its samples
/// (docs/afm.md "Warnings" gives the counts of the design table this lies between).
inline constexpr std::size_t kFewestFreeSamples = 50;
inline constexpr double kLeastFreeFraction = 0.1;
/// The residual rms over the fitted range may exceed the free samples' noise by this factor
/// before the fit is said not to describe the curve (the synthetic 1 %-noise curves of every
/// model give 0.89-1.15; docs/afm.md).
inline constexpr double kResidualOverNoise = 2.0;
/// Fewer free samples than this give no noise to compare the residual with.
inline constexpr std::size_t kNoiseSamples = 20;

/// [m] How far ahead of contact the fitted model's adhesion reaches: the Maugis-Dugdale zone's
/// h0 = dgamma / sigma_0 (sigma_0 from the fitted lambda, maugis_adhesive_stress); 0 for a
/// model whose force begins at contact (Hertz, DMT, JKR) or a fit without adhesion.
double fitted_reach(const AdhesiveFit& fit, const TipShape& tip, double poisson_ratio, bool maugis);

/// The samples the fit could read the baseline from and the noise about it.
struct BaselineReading {
  std::size_t samples = 0;       ///< in every segment fitted
  std::size_t free_samples = 0;  ///< those the fitted model leaves on the baseline
  double noise = 0.0;            ///< [N] 1.4826 x the median absolute deviation of the free samples
                                 ///< about the fitted baseline (0 with fewer than kNoiseSamples)
};

/// The samples a fit was given: an approach (far first) and a retract (deepest first), either
/// absent.
struct FittedSegments {
  const PreparedSegment* approach = nullptr;
  const PreparedSegment* retract = nullptr;
};

/// Counts the free samples: the approach's whose indentation contact_point - z < -reach, the
/// retract's past those the fitted model holds on its path (for an adhesive model, its
/// contact_samples less the approach's samples within the reach; JKR's neck, the zone's pull)
/// and out of contact (for Hertz, past the reach as the approach's); and their robust scatter
/// about the fitted baseline offset + slope (z - contact_point).
BaselineReading read_baseline(const FittedSegments& segments, const AdhesiveFit& fit, double reach,
                              bool adhesive);

/// The warnings of a fitted curve (none for another status), each one line without the
/// curve's name: free samples too few to fix the baseline (where its offset is fitted), and a
/// residual rms above kResidualOverNoise times the free samples' noise. `adhesive`: the
/// model fits a work of adhesion (the first warning says what the baseline does to it).
std::vector<std::string> fit_warnings(const FittedSegments& segments, const AdhesiveFit& fit,
                                      double reach, bool adhesive);

}  // namespace mdrsim::fit
