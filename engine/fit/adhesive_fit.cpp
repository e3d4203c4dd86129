// DMT and JKR fitted by the one Levenberg-Marquardt driver (least_squares) in scaled parameters;
// JKR's force from the MDR branch sampled in the contact radius.
#include "engine/fit/adhesive_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "engine/fit/least_squares.hpp"

namespace mdrsim::fit {
namespace {

constexpr int kAdhesiveParameters =
    5;  // youngs_modulus, work_of_adhesion, contact_point, offset, slope
constexpr std::size_t kBranchSamples = 256;

/// DMT's force for the paraboloid and the sphere: Hertz's less the adhesive force outside the
/// contact, 2 pi w R in Derjaguin's approximation about the apex (exact for the paraboloid in
/// Maugis' DMT limit; for the sphere while the contact stays small against R).
ContactForce dmt_force(const TipShape& tip, double reduced, double work, double depth) {
  const double delta = std::max(depth, 0.0);
  const double g = tip.force_per_modulus(delta);
  const double pull = 2.0 * std::numbers::pi * tip.radius;
  return {reduced * g - pull * work, reduced * tip.stiffness_per_modulus(delta), g, -pull};
}

struct FreeLine {
  double offset = 0.0;  // at z_ref
  double slope = 0.0;
  double z_ref = 0.0;
};

FreeLine fit_free_line(const std::vector<double>& z, const std::vector<double>& f, std::size_t from,
                       std::size_t to) {
  double mz = 0.0, mf = 0.0;
  const auto n = static_cast<double>(to - from);
  for (std::size_t i = from; i < to; ++i) {
    mz += z[i];
    mf += f[i];
  }
  mz /= n;
  mf /= n;
  double szz = 0.0, szf = 0.0;
  for (std::size_t i = from; i < to; ++i) {
    szz += (z[i] - mz) * (z[i] - mz);
    szf += (z[i] - mz) * (f[i] - mf);
  }
  return {mf, szz > 0.0 ? szf / szz : 0.0, mz};
}

/// The contact branch of every sample: which samples touch, and the model's force there.
struct AdhesiveSamples {
  const AdhesiveFitOptions& options;
  double compliance;
  const std::vector<double>& z;
  std::size_t jump;  // retract: samples [0, jump] in contact; approach: [jump, n)
  double deepest;

  bool in_contact(std::size_t i) const { return options.retract ? i <= jump : i >= jump; }

  /// Calls visit(i, contact force or nullptr) for every sample at parameters p.
  template <class Visit>
  void each(std::span<const double> p, Visit visit) const {
    const double reduced = p[0] / compliance;
    const double work = p[1];
    const double deep = std::max(deepest, p[2] - *std::min_element(z.begin(), z.end()));
    if (options.model == AdhesionModel::jkr) {
      const JkrBranch branch(*options.tip.profile, reduced, work, deep);
      for (std::size_t i = 0; i < z.size(); ++i) {
        const double depth = p[2] - z[i];
        if (!in_contact(i)) {
          visit(i, static_cast<const ContactForce*>(nullptr));
          continue;
        }
        const JkrBranch::State s = branch.at(depth);
        const ContactForce c{s.force, s.d_force_d_depth, s.d_force_d_modulus, s.d_force_d_work};
        visit(i, &c);
      }
    } else {
      for (std::size_t i = 0; i < z.size(); ++i) {
        const double depth = p[2] - z[i];
        if (!in_contact(i)) {
          visit(i, static_cast<const ContactForce*>(nullptr));
          continue;
        }
        const ContactForce c = dmt_force(options.tip, reduced, work, depth);
        visit(i, &c);
      }
    }
  }
};

}  // namespace

const char* adhesion_model_name(AdhesionModel model) {
  return model == AdhesionModel::dmt ? "dmt" : "jkr";
}

double JkrBranch::depth_of(double a) const {
  return profile_.mdr_image(a) - std::sqrt(2.0 * std::numbers::pi * a * work_ / reduced_);
}

JkrBranch::JkrBranch(const Profile& profile, double reduced_modulus, double work_of_adhesion,
                     double deepest)
    : profile_(profile), reduced_(reduced_modulus), work_(work_of_adhesion) {
  const double limit = profile.outer_radius();
  // a* solves a g'(a)^2 = pi w / (2 E*), whose left side rises with a for a convex tip.
  const double target = std::numbers::pi * work_ / (2.0 * reduced_);
  const auto rise = [&](double a) {
    const double slope = profile.mdr_image_slope(a);
    return a * slope * slope;
  };
  double low = 1e-12, high = 1e-9;
  if (std::isfinite(limit)) high = std::min(high, 0.5 * limit);
  while (rise(high) < target && high < 1.0) {
    low = high;
    high = std::isfinite(limit) ? std::min(2.0 * high, 0.5 * (high + limit)) : 2.0 * high;
  }
  while (rise(low) > target && low > 1e-30) low *= 0.5;
  for (int k = 0; k < 100 && high - low > 1e-12 * high; ++k) {
    const double mid = 0.5 * (low + high);
    (rise(mid) < target ? low : high) = mid;
  }
  const double a_star = 0.5 * (low + high);
  double a_high = std::max(2.0 * a_star, profile.contact_radius_at_depth(std::max(deepest, 0.0)));
  if (std::isfinite(limit)) a_high = std::min(a_high, 0.5 * (a_star + limit));
  for (int k = 0; k < 200 && depth_of(a_high) < deepest; ++k) {
    a_high = std::isfinite(limit) ? 0.5 * (a_high + limit) : 1.5 * a_high;
  }
  // Denser near a*, where the depth is flat in a and a(d) turns like a square root.
  radius_.resize(kBranchSamples);
  depth_.resize(kBranchSamples);
  lowest_force_ = 0.0;
  for (std::size_t k = 0; k < kBranchSamples; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(kBranchSamples - 1);
    radius_[k] = a_star + (a_high - a_star) * t * t;
    depth_[k] = depth_of(radius_[k]);
    const double a = radius_[k];
    const double s = std::sqrt(2.0 * std::numbers::pi * a * work_ / reduced_);
    lowest_force_ = std::min(lowest_force_, reduced_ * profile.nonadhesive_force_per_modulus(a) -
                                                2.0 * reduced_ * a * s);
  }
}

JkrBranch::State JkrBranch::at(double depth) const {
  double a = radius_.front();
  bool end = depth <= depth_.front();
  if (!end) {
    const auto it = std::upper_bound(depth_.begin(), depth_.end(), depth);
    if (it == depth_.end()) {
      a = radius_.back();
    } else {
      const auto k = static_cast<std::size_t>(it - depth_.begin());
      const double t = (depth - depth_[k - 1]) / (depth_[k] - depth_[k - 1]);
      a = radius_[k - 1] + t * (radius_[k] - radius_[k - 1]);
    }
  }
  const double pi = std::numbers::pi;
  double s = std::sqrt(2.0 * pi * a * work_ / reduced_);
  double slope = profile_.mdr_image_slope(a);
  double d_depth_d_a = slope - s / (2.0 * a);
  // Two Newton steps from the interpolated radius leave round-off.
  for (int step = 0; step < 2 && !end && d_depth_d_a > 0.0; ++step) {
    const double next = a - (profile_.mdr_image(a) - s - depth) / d_depth_d_a;
    if (!(next > radius_.front() && next < 2.0 * a)) break;
    a = next;
    s = std::sqrt(2.0 * pi * a * work_ / reduced_);
    slope = profile_.mdr_image_slope(a);
    d_depth_d_a = slope - s / (2.0 * a);
  }
  State out;
  out.contact_radius = a;
  const double hertz = profile_.nonadhesive_force_per_modulus(a);
  out.force = reduced_ * hertz - 2.0 * reduced_ * a * s;
  // At fixed a: dF/dE* = h - a s, dF/dw = -E* a s / w, dd/dE* = s / (2 E*), dd/dw = -s / (2 w);
  // dF/da = 2 E* a g' - 3 E* s. At fixed depth, a moves by -(dd/dp) / (dd/da).
  const double d_force_d_a = 2.0 * reduced_ * a * slope - 3.0 * reduced_ * s;
  out.d_force_d_modulus = hertz - a * s;
  out.d_force_d_work = -reduced_ * a * s / work_;
  if (!end && d_depth_d_a > 1e-9 * slope) {
    out.d_force_d_depth = d_force_d_a / d_depth_d_a;
    out.d_force_d_modulus -= d_force_d_a * (s / (2.0 * reduced_)) / d_depth_d_a;
    out.d_force_d_work -= d_force_d_a * (-s / (2.0 * work_)) / d_depth_d_a;
  }
  return out;
}

AdhesiveFit fit_adhesive(const PreparedSegment& segment, const AdhesiveFitOptions& options) {
  AdhesiveFit fit;
  const std::vector<double>& z = segment.tip_position;
  const std::vector<double>& f = segment.force;
  const std::size_t n = f.size();
  fit.points = n;
  if (n < 20) {
    fit.status = FitStatus::no_contact;
    fit.message = "too few samples";
    return fit;
  }
  // Where contact ends (retract, measured order: deepest first) or begins (approach).
  const auto lowest = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
  std::size_t jump = lowest;
  std::size_t free_from = 0, free_to = 0;  // the samples off contact, for the baseline
  if (options.retract) {
    double rise = -1.0;
    for (std::size_t i = lowest; i + 1 < n; ++i) {
      if (f[i + 1] - f[i] > rise) {
        rise = f[i + 1] - f[i];
        jump = i;
      }
    }
    free_from = jump + 1;
    free_to = n;
  } else {
    // The jump in: the largest fall of the force before its minimum.
    double fall = 1.0;
    for (std::size_t i = 0; i < lowest; ++i) {
      if (f[i + 1] - f[i] < fall) {
        fall = f[i + 1] - f[i];
        jump = i + 1;
      }
    }
    free_from = 0;
    free_to = jump;
  }
  if (free_to < free_from + 5 || (options.retract ? jump + 1 : n - jump) < 5) {
    fit.status = FitStatus::no_contact;
    fit.message = "no jump off the contact branch and baseline to fit";
    return fit;
  }
  const FreeLine base = fit_free_line(z, f, free_from, free_to);
  const double contact_guess = options.fixed.contact_point.value_or(z[jump]);
  const double base_at_contact = base.offset + base.slope * (contact_guess - base.z_ref);
  fit.adhesion_force_measured = base.offset + base.slope * (z[lowest] - base.z_ref) - f[lowest];
  if (!(fit.adhesion_force_measured > 0.0)) {
    fit.status = FitStatus::no_contact;
    fit.message = "the force never falls below the baseline";
    return fit;
  }
  const auto [z_low, z_high] = std::minmax_element(z.begin(), z.end());
  const double z_range = std::max(*z_high - *z_low, 1e-30);
  double force_scale = 0.0;
  for (const double v : f) force_scale = std::max(force_scale, std::abs(v));
  force_scale = std::max(force_scale, 1e-300);
  const double compliance = 1.0 - options.poisson_ratio * options.poisson_ratio;

  // E* and the adhesion as Hertz less a constant, linear in both, on the indented samples.
  double sgg = 0, sg = 0, sn = 0, sgf = 0, sf = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double depth = contact_guess - z[i];
    if (depth <= 0.0 || !(options.retract ? i <= jump : i >= jump)) continue;
    const double g = options.tip.force_per_modulus(depth);
    const double rest = f[i] - (base.offset + base.slope * (z[i] - base.z_ref));
    sgg += g * g;
    sg += g;
    sn += 1;
    sgf += g * rest;
    sf += rest;
  }
  const double det = sgg * sn - sg * sg;
  double reduced = det > 0.0 ? (sgf * sn - sg * sf) / det : 0.0;
  if (!(reduced > 0.0)) {
    const double g = options.tip.force_per_modulus(contact_guess - *z_low);
    reduced = g > 0.0 ? force_scale / g : 1.0;
  }
  if (options.fixed.youngs_modulus) reduced = *options.fixed.youngs_modulus / compliance;
  const double deepest = std::max(contact_guess - *z_low, 1e-3 * z_range);
  double work = 0.0;
  if (options.model == AdhesionModel::dmt) {
    work = fit.adhesion_force_measured / (2.0 * std::numbers::pi * options.tip.radius);
  } else {
    // The w whose fixed-load pull-off is the measured adhesion force, by bisection in log w.
    double low = -60.0, high = 10.0;
    // 24 halvings of a span of 70 in log w: w to 4e-6, for a start.
    for (int k = 0; k < 24; ++k) {
      const double mid = 0.5 * (low + high);
      const JkrBranch branch(*options.tip.profile, reduced, std::exp(mid), deepest);
      (-branch.lowest_force() < fit.adhesion_force_measured ? low : high) = mid;
    }
    work = std::exp(0.5 * (low + high));
  }
  if (options.fixed.work_of_adhesion) work = *options.fixed.work_of_adhesion;

  const std::array<std::optional<double>, kAdhesiveParameters> held = {
      options.fixed.youngs_modulus, options.fixed.work_of_adhesion, options.fixed.contact_point,
      options.fixed.baseline_offset, options.fixed.baseline_slope};
  std::array<double, kAdhesiveParameters> start = {reduced * compliance, work, contact_guess,
                                                   base_at_contact, base.slope};
  for (int j = 0; j < kAdhesiveParameters; ++j) {
    if (held[j]) start[j] = *held[j];
  }
  const AdhesiveSamples samples{options, compliance, z, jump, deepest};
  ScaledProblem problem;
  problem.start.assign(start.begin(), start.end());
  // E and w as start x exp(x): both stay positive, and the minimiser walks a curve whose
  // adhesion fades towards w -> 0 instead of through it. The rest as start + scale x.
  problem.scale = {1.0, 1.0, deepest, force_scale, force_scale / z_range};
  problem.walk = {Walk::logarithmic, Walk::logarithmic, Walk::linear, Walk::linear, Walk::linear};
  for (int j = 0; j < kAdhesiveParameters; ++j) problem.held.push_back(held[j].has_value());
  problem.data = &f;
  problem.force_scale = force_scale;
  problem.model = [&](std::span<const double> p, std::span<double> model) {
    samples.each(p, [&](std::size_t i, const ContactForce* c) {
      model[i] = p[3] + p[4] * (z[i] - p[2]) + (c ? c->force : 0.0);
    });
  };
  problem.derivatives = [&](std::span<const double> p, std::span<double> d) {
    const std::size_t m = z.size();
    samples.each(p, [&](std::size_t i, const ContactForce* c) {
      d[i] = c ? c->d_modulus / compliance : 0.0;
      d[m + i] = c ? c->d_work : 0.0;
      d[2 * m + i] = -p[4] + (c ? c->d_depth : 0.0);
      d[3 * m + i] = 1.0;
      d[4 * m + i] = z[i] - p[2];
    });
  };
  FitParameter* const out[kAdhesiveParameters] = {&fit.youngs_modulus, &fit.work_of_adhesion,
                                                  &fit.contact_point, &fit.baseline_offset,
                                                  &fit.baseline_slope};
  const ScaledSolution solution = minimize_scaled(problem, out);
  fit.iterations = solution.iterations;
  fit.evaluations = solution.evaluations;
  const std::vector<double>& p = solution.values;
  fit.residual_rms = std::sqrt(solution.sum_squares / static_cast<double>(n)) * force_scale;
  fit.max_indentation = std::max(0.0, p[2] - *z_low);
  fit.contact_samples = 0;
  for (std::size_t i = 0; i < n; ++i) fit.contact_samples += samples.in_contact(i);
  const double fitted_reduced = p[0] / compliance;
  if (options.model == AdhesionModel::dmt) {
    fit.adhesion_force_fitted = 2.0 * std::numbers::pi * options.tip.radius * p[1];
  } else if (p[0] > 0.0 && p[1] > 0.0) {
    fit.adhesion_force_fitted =
        -JkrBranch(*options.tip.profile, fitted_reduced, p[1], fit.max_indentation).lowest_force();
  }
  const bool positive = p[0] > 0.0 && p[1] > 0.0;
  settle_status(fit, out, solution.outcome,
                positive ? nullptr : "the fit went to a modulus or work of adhesion <= 0",
                RefusalRank::after_non_finite);
  return fit;
}

void settle_status(AdhesiveFit& fit, std::span<FitParameter* const> parameters,
                   MinimizerOutcome outcome, const char* refusal, RefusalRank rank) {
  bool finite = std::isfinite(fit.residual_rms) && std::isfinite(fit.adhesion_force_fitted);
  for (const FitParameter* q : parameters) {
    finite = finite && std::isfinite(q->value) && std::isfinite(q->standard_error);
  }
  const char* non_finite = finite ? nullptr : "the fit gave numbers that are not finite";
  const char* first = rank == RefusalRank::before_non_finite ? refusal : non_finite;
  const char* second = rank == RefusalRank::before_non_finite ? non_finite : refusal;
  const char* failure = minimizer_failure(outcome);
  const char* message = failure ? failure : first ? first : second;
  fit.status = message ? FitStatus::not_converged : FitStatus::fitted;
  if (message) fit.message = message;
  if (!finite) {
    for (FitParameter* q : parameters) *q = FitParameter{0.0, 0.0, q->fixed};
    fit.residual_rms = 0.0;
    fit.adhesion_force_fitted = 0.0;
  }
}

}  // namespace mdrsim::fit
