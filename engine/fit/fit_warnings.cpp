// The warnings of a fitted curve: a baseline the record does not fix, a residual far above the
// noise.
#include "engine/fit/fit_warnings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/fit/maugis_fit.hpp"

namespace mdrsim::fit {
namespace {

double median_of(std::vector<double>& values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (values.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

}  // namespace

double fitted_reach(const AdhesiveFit& fit, const TipShape& tip, double poisson_ratio,
                    bool maugis) {
  const double work = fit.work_of_adhesion.value;
  const double lambda = fit.maugis_parameter.value;
  if (!maugis || !(work > 0.0) || !(lambda > 0.0) || !(tip.radius > 0.0)) return 0.0;
  const double reduced = fit.youngs_modulus.value / (1.0 - poisson_ratio * poisson_ratio);
  const double stress = maugis_adhesive_stress(lambda, reduced, work, tip.radius);
  const double reach = work / stress;
  return std::isfinite(reach) ? reach : 0.0;
}

BaselineReading read_baseline(const FittedSegments& segments, const AdhesiveFit& fit, double reach,
                              bool adhesive) {
  BaselineReading out;
  const double contact = fit.contact_point.value;
  std::vector<double> residuals;
  const auto take = [&](const PreparedSegment& segment, std::size_t i) {
    residuals.push_back(segment.force[i] - fit.baseline_offset.value -
                        fit.baseline_slope.value * (segment.tip_position[i] - contact));
  };
  std::size_t approach_held = 0;
  if (const PreparedSegment* approach = segments.approach) {
    out.samples += approach->tip_position.size();
    for (std::size_t i = 0; i < approach->tip_position.size(); ++i) {
      if (contact - approach->tip_position[i] < -reach) {
        take(*approach, i);
      } else {
        ++approach_held;
      }
    }
  }
  if (const PreparedSegment* retract = segments.retract) {
    out.samples += retract->tip_position.size();
    // An adhesive model holds the retract's first samples (deepest first) on its path down to
    // the release, out of contact too (JKR's neck, the Maugis zone's pull): the rest are the
    // baseline's, wherever the tip has gone, so long as it is out of contact.
    const std::size_t held =
        adhesive ? fit.contact_samples - std::min(fit.contact_samples, approach_held) : 0;
    for (std::size_t i = held; i < retract->tip_position.size(); ++i) {
      const double depth = contact - retract->tip_position[i];
      if (adhesive ? depth < 0.0 : depth < -reach) take(*retract, i);
    }
  }
  out.free_samples = residuals.size();
  if (residuals.size() < kNoiseSamples) return out;
  const double centre = median_of(residuals);
  for (double& r : residuals) r = std::abs(r - centre);
  // 1.4826 MAD: the standard deviation of normal noise, unmoved by a few outliers.
  out.noise = 1.4826 * median_of(residuals);
  return out;
}

std::vector<std::string> fit_warnings(const FittedSegments& segments, const AdhesiveFit& fit,
                                      double reach, bool adhesive) {
  std::vector<std::string> out;
  if (fit.status != FitStatus::fitted) return out;
  const BaselineReading baseline = read_baseline(segments, fit, reach, adhesive);
  const double fewest = std::max(static_cast<double>(kFewestFreeSamples),
                                 kLeastFreeFraction * static_cast<double>(baseline.samples));
  if (!fit.baseline_offset.fixed && static_cast<double>(baseline.free_samples) < fewest) {
    const std::string where =
        reach > 0.0 ? fmt::format(
                          "beyond the fitted zone's reach (h0 = {:.3g} m ahead of "
                          "contact) or past the retract's release",
                          reach)
                    : "out of contact (the approach's before it, the retract's past its release)";
    const std::string effect =
        adhesive ? "dgamma, the contact force's offset from the baseline, is not told apart from "
                   "the baseline's offset: its value and standard error may be far off (record "
                   "the approach from farther out)"
                 : "E and the contact point lean on a baseline the samples do not fix (record "
                   "the approach from farther out)";
    out.push_back(fmt::format(
        "short baseline: {} of {} samples lie {}, fewer than {:.0f} to fix the baseline; {}",
        baseline.free_samples, baseline.samples, where, std::ceil(fewest), effect));
  }
  if (baseline.noise > 0.0 && fit.residual_rms > kResidualOverNoise * baseline.noise) {
    out.push_back(fmt::format(
        "the model does not describe the curve: the residual rms ({:.3g} N) is {:.3g} times the "
        "noise of the {} free samples about the fitted baseline ({:.3g} N)",
        fit.residual_rms, fit.residual_rms / baseline.noise, baseline.free_samples,
        baseline.noise));
  }
  return out;
}

}  // namespace mdrsim::fit
