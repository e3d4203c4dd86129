// Hertz's model fitted by the one Levenberg-Marquardt driver (least_squares) in scaled parameters.
#include "engine/fit/hertz_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "engine/fit/least_squares.hpp"

namespace mdrsim::fit {
namespace {

constexpr int kParameters = 4;  // youngs_modulus, contact_point, baseline_offset, baseline_slope

bool finite_fit(const HertzFit& fit) {
  for (const FitParameter* p :
       {&fit.youngs_modulus, &fit.contact_point, &fit.baseline_offset, &fit.baseline_slope}) {
    if (!std::isfinite(p->value) || !std::isfinite(p->standard_error)) return false;
  }
  return std::isfinite(fit.residual_rms);
}

}  // namespace

const char* fit_status_name(FitStatus status) {
  switch (status) {
    case FitStatus::fitted:
      return "fitted";
    case FitStatus::no_contact:
      return "no-contact";
    case FitStatus::not_converged:
      return "not-converged";
    case FitStatus::unreadable:
      return "unreadable";
  }
  return "unreadable";
}

double hertz_force(const TipShape& tip, double poisson_ratio, const HertzFit& fit, double z) {
  const double c = fit.contact_point.value;
  return fit.baseline_offset.value + fit.baseline_slope.value * (z - c) +
         fit.youngs_modulus.value / (1.0 - poisson_ratio * poisson_ratio) *
             tip.force_per_modulus(c - z);
}

HertzFit fit_hertz(const PreparedSegment& segment, const HertzFitOptions& options) {
  HertzFit fit;
  fit.points = segment.force.size();
  const FirstGuess guess =
      first_guess(segment, options.tip, options.poisson_ratio, options.far_first);
  if (!guess.contact && !options.fixed.contact_point) {
    fit.status = FitStatus::no_contact;
    fit.message = "the force never leaves the baseline's noise band";
    return fit;
  }
  const auto [z_low, z_high] =
      std::minmax_element(segment.tip_position.begin(), segment.tip_position.end());
  const double z_range = std::max(*z_high - *z_low, 1e-30);
  double force_scale = 0.0;
  for (const double f : segment.force) force_scale = std::max(force_scale, std::abs(f));
  force_scale = std::max(force_scale, 1e-300);

  const std::array<std::optional<double>, kParameters> held = {
      options.fixed.youngs_modulus, options.fixed.contact_point, options.fixed.baseline_offset,
      options.fixed.baseline_slope};
  std::array<double, kParameters> start = {guess.youngs_modulus, guess.contact_point,
                                           guess.baseline_offset, guess.baseline_slope};
  if (held[1]) start[1] = *held[1];
  if (!(start[0] > 0.0)) {
    // No positive modulus fits with the guessed contact point: start from the one that
    // reaches the largest force at the deepest point.
    const double g = options.tip.force_per_modulus(start[1] - *z_low);
    start[0] =
        g > 0.0 ? force_scale / g * (1.0 - options.poisson_ratio * options.poisson_ratio) : 1.0;
  }
  for (int j = 0; j < kParameters; ++j) {
    if (held[j]) start[j] = *held[j];
  }
  const double depth = std::max(start[1] - *z_low, 1e-3 * z_range);
  const std::vector<double>& z = segment.tip_position;
  const TipShape& tip = options.tip;
  const double compliance = 1.0 - options.poisson_ratio * options.poisson_ratio;
  ScaledProblem problem;
  problem.start.assign(start.begin(), start.end());
  problem.scale = {std::abs(start[0]), depth, force_scale, force_scale / z_range};
  problem.walk.assign(kParameters, Walk::linear);
  for (int j = 0; j < kParameters; ++j) problem.held.push_back(held[j].has_value());
  problem.data = &segment.force;
  problem.force_scale = force_scale;
  problem.model = [&](std::span<const double> p, std::span<double> model) {
    const double reduced = p[0] / compliance;
    for (std::size_t i = 0; i < z.size(); ++i) {
      model[i] = p[2] + p[3] * (z[i] - p[1]) + reduced * tip.force_per_modulus(p[1] - z[i]);
    }
  };
  problem.derivatives = [&](std::span<const double> p, std::span<double> d) {
    const double reduced = p[0] / compliance;
    const std::size_t n = z.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double delta = p[1] - z[i];
      d[i] = tip.force_per_modulus(delta) / compliance;
      d[n + i] = -p[3] + reduced * tip.stiffness_per_modulus(delta);
      d[2 * n + i] = 1.0;
      d[3 * n + i] = z[i] - p[1];
    }
  };
  FitParameter* const out[kParameters] = {&fit.youngs_modulus, &fit.contact_point,
                                          &fit.baseline_offset, &fit.baseline_slope};
  const ScaledSolution solution = minimize_scaled(problem, out);
  fit.iterations = solution.iterations;
  fit.evaluations = solution.evaluations;
  fit.residual_rms =
      std::sqrt(solution.sum_squares / static_cast<double>(fit.points)) * force_scale;
  fit.max_indentation = std::max(0.0, solution.values[1] - *z_low);
  if (const char* failure = minimizer_failure(solution.outcome)) {
    fit.status = FitStatus::not_converged;
    fit.message = failure;
  } else if (!finite_fit(fit)) {
    fit.status = FitStatus::not_converged;
    fit.message = "the fit gave numbers that are not finite";
  } else if (!(fit.youngs_modulus.value > 0.0)) {
    fit.status = FitStatus::not_converged;
    fit.message = "the fit went to a modulus <= 0";
  } else {
    fit.status = FitStatus::fitted;
  }
  if (fit.status != FitStatus::fitted && !finite_fit(fit)) {
    for (FitParameter* q : out) *q = FitParameter{0.0, 0.0, q->fixed};
    fit.residual_rms = 0.0;
  }
  return fit;
}

}  // namespace mdrsim::fit
