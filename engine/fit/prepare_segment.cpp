// Preprocessing of a measured segment: force over tip position, the baseline and the contact
// point's first guess.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "engine/fit/prepared_curve.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::fit {
namespace {

/// Least-squares line F = offset + slope (z - z_ref) over samples [0, count).
struct Line {
  double z_ref = 0.0;
  double offset = 0.0;
  double slope = 0.0;
  double at(double z) const { return offset + slope * (z - z_ref); }
};

Line fit_line(const std::vector<double>& z, const std::vector<double>& force, std::size_t count) {
  Line line;
  double mean_z = 0.0;
  double mean_f = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    mean_z += z[i];
    mean_f += force[i];
  }
  mean_z /= static_cast<double>(count);
  mean_f /= static_cast<double>(count);
  double szz = 0.0;
  double szf = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    szz += (z[i] - mean_z) * (z[i] - mean_z);
    szf += (z[i] - mean_z) * (force[i] - mean_f);
  }
  line.z_ref = mean_z;
  line.offset = mean_f;
  line.slope = szz > 0.0 ? szf / szz : 0.0;
  return line;
}

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// 1.4826 x the median absolute deviation: the standard deviation of Gaussian noise, unmoved
/// by the few spikes a baseline has.
double robust_deviation(const std::vector<double>& z, const std::vector<double>& force,
                        std::size_t count, const Line& line) {
  std::vector<double> residuals(count);
  for (std::size_t i = 0; i < count; ++i) residuals[i] = force[i] - line.at(z[i]);
  const double centre = median(residuals);
  for (double& r : residuals) r = std::abs(r - centre);
  return 1.4826 * median(residuals);
}

}  // namespace

PreparedSegment prepare_segment(const measured::ForceCurve& curve, measured::SegmentKind kind) {
  const auto found = std::find_if(curve.segments.begin(), curve.segments.end(),
                                  [kind](const measured::Segment& s) { return s.kind == kind; });
  if (found == curve.segments.end()) {
    throw SceneError(fmt::format("no {} segment", measured::segment_kind_name(kind)));
  }
  const measured::Segment& segment = *found;
  const auto& k = curve.calibration.spring_constant;
  PreparedSegment prepared;
  prepared.spring_constant = k ? k->value : 0.0;
  const bool needs_k = segment.force.empty() || segment.tip_position.empty();
  if (needs_k && (!k || !(k->value > 0.0))) {
    throw SceneError(fmt::format(
        "segment {}: no spring constant to turn {} (give --fix spring_constant=K [N/m])",
        segment.name,
        segment.force.empty() ? "the deflection into a force" : "the force into a deflection"));
  }
  const std::size_t n = segment.size();
  prepared.force = segment.force;
  if (prepared.force.empty()) {
    prepared.force.resize(n);
    for (std::size_t i = 0; i < n; ++i) prepared.force[i] = segment.deflection[i] * k->value;
  }
  if (!segment.tip_position.empty()) {
    prepared.tip_position = segment.tip_position;
    prepared.height_channel = "tip_position";
    return prepared;
  }
  // The height sensor reads where the piezo really is; the commanded height lags and
  // overshoots it. Both are the cantilever base's height that SPEC calls the piezo height.
  const bool measured = !segment.measured_height.empty();
  const std::vector<double>& height = measured ? segment.measured_height : segment.piezo_height;
  prepared.height_channel = measured ? "measured_height" : "piezo_height";
  prepared.tip_position.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double deflection =
        segment.deflection.empty() ? prepared.force[i] / k->value : segment.deflection[i];
    prepared.tip_position[i] = height[i] + deflection;
  }
  return prepared;
}

FirstGuess first_guess(const PreparedSegment& segment, const TipShape& tip, double poisson_ratio,
                       bool far_first) {
  std::vector<double> z = segment.tip_position;
  std::vector<double> force = segment.force;
  if (!far_first) {
    std::reverse(z.begin(), z.end());
    std::reverse(force.begin(), force.end());
  }
  FirstGuess guess;
  const std::size_t n = z.size();
  if (n < 10) return guess;
  // The first fifth lies far from the sample on any curve worth fitting.
  const std::size_t head = std::max<std::size_t>(5, n / 5);
  Line line = fit_line(z, force, head);
  double noise = robust_deviation(z, force, head, line);
  double force_range = 0.0;
  for (std::size_t i = 0; i < n; ++i) force_range = std::max(force_range, std::abs(force[i]));
  noise = std::max(noise, 1e-12 * force_range);
  const double band = 5.0 * noise;
  std::size_t last_inside = 0;
  for (std::size_t i = n; i-- > 0;) {
    if (force[i] - line.at(z[i]) <= band) {
      last_inside = i;
      break;
    }
  }
  if (n - 1 - last_inside < std::max<std::size_t>(3, n / 100)) return guess;
  // The noise stays the first fifth's: a median over the whole baseline again (two selections
  // over up to every sample) cost as much as a 2000-point fit and moved nothing downstream.
  if (last_inside + 1 >= 5) line = fit_line(z, force, last_inside + 1);
  guess.contact = true;
  guess.contact_point = z[last_inside];
  guess.baseline_offset = line.at(guess.contact_point);
  guess.baseline_slope = line.slope;
  guess.noise = noise;
  // The modulus that best fits the indented part with the contact point held: linear in E.
  double gg = 0.0;
  double gf = 0.0;
  for (std::size_t i = last_inside + 1; i < n; ++i) {
    const double g = tip.force_per_modulus(guess.contact_point - z[i]);
    gg += g * g;
    gf += g * (force[i] - line.at(z[i]));
  }
  const double reduced = gg > 0.0 && gf > 0.0 ? gf / gg : 0.0;
  guess.youngs_modulus = reduced * (1.0 - poisson_ratio * poisson_ratio);
  return guess;
}

}  // namespace mdrsim::fit
