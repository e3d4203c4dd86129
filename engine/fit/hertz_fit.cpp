// Hertz's model fitted by the one Levenberg-Marquardt driver (least_squares) in scaled parameters.
#include "engine/fit/hertz_fit.hpp"

#include <Eigen/Dense>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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

/// Hertz's law of the tip at the indentation delta [m]: g(delta) [m^2] and the contact radius
/// a(delta) [m] (the stiffness per modulus is 2 a). The paraboloid's closed forms are inline,
/// in ParabolicProfile's arithmetic, without its two virtual calls per sample.
struct HertzLaw {
  double force_per_modulus = 0.0;
  double contact_radius = 0.0;
};

HertzLaw hertz_law(const TipShape& tip, double delta) {
  if (!(delta > 0.0)) return {};
  if (tip.kind == TipKind::parabolic) {
    const double a = std::sqrt(tip.radius * delta);
    return {4.0 * a * a * a / (3.0 * tip.radius), a};
  }
  const double a = tip.contact_radius(delta);
  return {tip.profile->nonadhesive_force_per_modulus(a), a};
}

/// The model's linear parameters (E, offset, slope) at the contact point c: the free ones
/// solved exactly by least squares, the held ones at their values.
struct Projection {
  double sum_squares = 0.0;           ///< [N^2] over the samples used
  std::array<double, 3> linear = {};  ///< E [Pa], offset [N], slope [N/m]
};

/// Given the contact point, Hertz's model is linear in E, the offset and the slope (variable
/// projection): their best values over every stride-th sample solve a 3 x 3 system, the sum of
/// squares follows from the same sums.
Projection project(const std::vector<double>& z, const std::vector<double>& force,
                   const TipShape& tip, double compliance,
                   const std::array<std::optional<double>, 4>& held, double c, std::size_t stride) {
  // The sums of the normal equations' lower triangle over the columns (g / (1 - nu^2), 1, z - c).
  double sgg = 0.0, sg = 0.0, sgd = 0.0, sn = 0.0, sd = 0.0, sdd = 0.0;
  double sgt = 0.0, st = 0.0, sdt = 0.0, stt = 0.0;
  const double held_modulus = held[0] ? *held[0] : 0.0;
  const double held_offset = held[2] ? *held[2] : 0.0;
  const double held_slope = held[3] ? *held[3] : 0.0;
  for (std::size_t i = 0; i < z.size(); i += stride) {
    const double g = hertz_law(tip, c - z[i]).force_per_modulus / compliance;
    const double d = z[i] - c;
    const double t = force[i] - held_modulus * g - held_offset - held_slope * d;
    sgg += g * g;
    sg += g;
    sgd += g * d;
    sn += 1.0;
    sd += d;
    sdd += d * d;
    sgt += g * t;
    st += t;
    sdt += d * t;
    stt += t * t;
  }
  Eigen::Matrix3d normal;
  normal << sgg, sg, sgd, sg, sn, sd, sgd, sd, sdd;
  Eigen::Vector3d right(sgt, st, sdt);
  const double target_squares = stt;
  const std::array<bool, 3> free = {!held[0], !held[2], !held[3]};
  // Held or empty columns become identity rows, the rest are scaled to a unit diagonal so
  // that the modulus (g ~ delta^1.5) and the baseline share one precision.
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  for (int k = 0; k < 3; ++k) {
    if (free[static_cast<std::size_t>(k)] && normal(k, k) > 0.0) {
      scale[k] = 1.0 / std::sqrt(normal(k, k));
    } else {
      normal.row(k).setZero();
      normal.col(k).setZero();
      normal(k, k) = 1.0;
      right[k] = 0.0;
      scale[k] = 1.0;
    }
  }
  const Eigen::Matrix3d scaled = scale.asDiagonal() * normal * scale.asDiagonal();
  const Eigen::Vector3d solved = scaled.ldlt().solve(scale.cwiseProduct(right));
  const Eigen::Vector3d x = scale.cwiseProduct(solved);
  Projection projection;
  projection.sum_squares = std::max(0.0, target_squares - x.dot(right));
  projection.linear = {held[0] ? *held[0] : x[0], held[2] ? *held[2] : x[1],
                       held[3] ? *held[3] : x[2]};
  return projection;
}

/// The contact point that minimises the projected sum of squares over roughly 256 of the
/// samples: a scan of the tip positions from just above the deepest one to half the first
/// guess's depth beyond it, then Brent's search (Boost's) in the best cell and its neighbours.
/// The minimiser then starts from its best linear parameters, a step or two from its minimum.
double projected_contact_point(const std::vector<double>& z, const std::vector<double>& force,
                               const TipShape& tip, double compliance,
                               const std::array<std::optional<double>, 4>& held, double guess,
                               double z_low, double z_high) {
  const std::size_t stride = std::max<std::size_t>(1, z.size() / 256);
  const double depth = guess - z_low;
  if (!(depth > 0.0)) return guess;
  const double lo = z_low + depth / 64.0;
  const double hi = std::min(z_high, guess + 0.5 * depth);
  if (!(hi > lo)) return guess;
  const int cells = 32;
  const double width = (hi - lo) / cells;
  // A contact point whose best modulus is negative is judged with the modulus at zero.
  std::array<std::optional<double>, 4> no_modulus = held;
  no_modulus[0] = 0.0;
  const auto sum_at = [&](double c) {
    const Projection projection = project(z, force, tip, compliance, held, c, stride);
    if (held[0] || projection.linear[0] > 0.0) return projection.sum_squares;
    return project(z, force, tip, compliance, no_modulus, c, stride).sum_squares;
  };
  int best = 0;
  double best_sum = sum_at(lo);
  for (int k = 1; k <= cells; ++k) {
    const double sum = sum_at(lo + k * width);
    if (sum < best_sum) {
      best_sum = sum;
      best = k;
    }
  }
  const double left = lo + std::max(0, best - 1) * width;
  const double span = lo + std::min(cells, best + 1) * width - left;
  std::uintmax_t iterations = 40;
  const double t = boost::math::tools::brent_find_minima(
                       [&](double u) { return sum_at(left + u * span); }, 0.0, 1.0, 20, iterations)
                       .first;
  return left + t * span;
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
  const double compliance = 1.0 - options.poisson_ratio * options.poisson_ratio;
  if (held[1]) {
    start[1] = *held[1];
  } else {
    start[1] = projected_contact_point(segment.tip_position, segment.force, options.tip, compliance,
                                       held, start[1], *z_low, *z_high);
  }
  const Projection projection =
      project(segment.tip_position, segment.force, options.tip, compliance, held, start[1], 1);
  start[0] = projection.linear[0];
  start[2] = projection.linear[1];
  start[3] = projection.linear[2];
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
  ScaledProblem problem;
  problem.start.assign(start.begin(), start.end());
  problem.scale = {std::abs(start[0]), depth, force_scale, force_scale / z_range};
  problem.walk.assign(kParameters, Walk::linear);
  problem.enters_linearly = {true, false, true, true};
  for (int j = 0; j < kParameters; ++j) problem.held.push_back(held[j].has_value());
  problem.data = &segment.force;
  problem.force_scale = force_scale;
  problem.model = [&](std::span<const double> p, std::span<double> model) {
    const double reduced = p[0] / compliance;
    for (std::size_t i = 0; i < z.size(); ++i) {
      model[i] =
          p[2] + p[3] * (z[i] - p[1]) + reduced * hertz_law(tip, p[1] - z[i]).force_per_modulus;
    }
  };
  problem.derivatives = [&](std::span<const double> p, std::span<double> d) {
    const double reduced = p[0] / compliance;
    const std::size_t n = z.size();
    for (std::size_t i = 0; i < n; ++i) {
      const HertzLaw law = hertz_law(tip, p[1] - z[i]);
      d[i] = law.force_per_modulus / compliance;
      d[n + i] = -p[3] + reduced * 2.0 * law.contact_radius;
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
