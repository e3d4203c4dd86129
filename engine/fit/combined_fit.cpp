// Approach and retract fitted together on the one LM driver, and the hysteresis energy.
#include "engine/fit/combined_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "engine/fit/hertz_fit.hpp"
#include "engine/fit/least_squares.hpp"
#include "engine/fit/maugis_fit.hpp"

namespace mdrsim::fit {
namespace {

// youngs_modulus, work_of_adhesion (retract), approach_work_of_adhesion, contact_point,
// baseline_offset, baseline_slope.
constexpr std::size_t kJointParameters = 6;
enum : std::size_t { kModulus, kWork, kApproachWork, kContact, kOffset, kSlope };

bool has_values(const HertzFit& fit) {
  return fit.status == FitStatus::fitted || fit.status == FitStatus::not_converged;
}

/// The retract's last contact sample (measured order, deepest first): before the largest rise
/// of the force after its lowest sample, as fit_adhesive reads it.
std::size_t retract_jump(const std::vector<double>& f) {
  const auto lowest = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
  std::size_t jump = lowest;
  double rise = -1.0;
  for (std::size_t i = lowest; i + 1 < f.size(); ++i) {
    if (f[i + 1] - f[i] > rise) {
      rise = f[i + 1] - f[i];
      jump = i;
    }
  }
  return jump;
}

/// Both segments as one list of samples, each knowing its segment and whether it is in contact.
struct Samples {
  std::vector<double> z;
  std::vector<double> force;
  std::vector<char> approach;  // 1: an approach sample
  std::vector<char> contact;   // adhesive models: in contact (set once per fit)
  double z_low = 0.0;
};

Samples join(const PreparedSegment& approach, const PreparedSegment& retract) {
  Samples s;
  for (const PreparedSegment* seg : {&approach, &retract}) {
    s.z.insert(s.z.end(), seg->tip_position.begin(), seg->tip_position.end());
    s.force.insert(s.force.end(), seg->force.begin(), seg->force.end());
    s.approach.insert(s.approach.end(), seg->force.size(), seg == &approach ? 1 : 0);
  }
  s.contact.assign(s.z.size(), 0);
  s.z_low = *std::min_element(s.z.begin(), s.z.end());
  return s;
}

/// Contact: the retract's samples up to its jump off; the approach's indented past `contact`.
void mark_contact(Samples& s, std::size_t approach_points, std::size_t retract_jump_index,
                  double contact) {
  for (std::size_t i = 0; i < s.z.size(); ++i) {
    s.contact[i] = i < approach_points ? (contact - s.z[i] > 0.0)
                                       : (i - approach_points <= retract_jump_index);
  }
}

/// Calls visit(i, force or nullptr) for every sample at parameters p.
template <class Visit>
void each_sample(const Samples& s, const CombinedFitOptions& options, std::span<const double> p,
                 Visit visit) {
  const double reduced = p[kModulus] / (1.0 - options.poisson_ratio * options.poisson_ratio);
  const double deepest = std::max(p[kContact] - s.z_low, 0.0);
  std::optional<JkrBranch> retract_branch, approach_branch;
  if (options.adhesive && options.model == AdhesionModel::jkr) {
    retract_branch.emplace(*options.tip.profile, reduced, p[kWork], deepest);
    approach_branch.emplace(*options.tip.profile, reduced, p[kApproachWork], deepest);
  }
  const double pull = 2.0 * std::numbers::pi * options.tip.radius;
  for (std::size_t i = 0; i < s.z.size(); ++i) {
    const double depth = p[kContact] - s.z[i];
    ContactForce c;
    if (!options.adhesive) {
      if (depth <= 0.0) {
        visit(i, static_cast<const ContactForce*>(nullptr));
        continue;
      }
      const double g = options.tip.force_per_modulus(depth);
      c = {reduced * g, reduced * options.tip.stiffness_per_modulus(depth), g, 0.0};
    } else if (!s.contact[i]) {
      visit(i, static_cast<const ContactForce*>(nullptr));
      continue;
    } else if (options.model == AdhesionModel::jkr) {
      const JkrBranch::State st = (s.approach[i] ? *approach_branch : *retract_branch).at(depth);
      c = {st.force, st.d_force_d_depth, st.d_force_d_modulus, st.d_force_d_work};
    } else {
      // DMT as fit_adhesive: Hertz less 2 pi w R, held at depth 0 above the contact point.
      const double delta = std::max(depth, 0.0);
      const double g = options.tip.force_per_modulus(delta);
      const double work = s.approach[i] ? p[kApproachWork] : p[kWork];
      c = {reduced * g - pull * work, reduced * options.tip.stiffness_per_modulus(delta), g, -pull};
    }
    visit(i, &c);
  }
}

}  // namespace

CombinedFit fit_combined(const PreparedSegment& approach, const PreparedSegment& retract,
                         const CombinedFitOptions& options) {
  CombinedFit fit;
  if (options.maugis) {
    MaugisFitOptions maugis;
    maugis.tip = options.tip;
    maugis.poisson_ratio = options.poisson_ratio;
    maugis.fixed = options.fixed;
    static_cast<AdhesiveFit&>(fit) = fit_maugis_both(approach, retract, maugis);
    // The one zone's dgamma: the approach's is the retract's.
    fit.approach_work_of_adhesion = fit.work_of_adhesion;
    fit.approach_points = approach.force.size();
    fit.retract_points = retract.force.size();
    return fit;
  }
  fit.approach_points = approach.force.size();
  fit.retract_points = retract.force.size();
  fit.points = fit.approach_points + fit.retract_points;
  const double compliance = 1.0 - options.poisson_ratio * options.poisson_ratio;

  // Each segment's own fit gives the start.
  std::array<double, kJointParameters> start{};
  std::size_t jump = 0;
  double approach_contact = 0.0;
  if (!options.adhesive) {
    HertzFitOptions hertz;
    hertz.tip = options.tip;
    hertz.poisson_ratio = options.poisson_ratio;
    hertz.fixed = options.fixed;
    HertzFit first = fit_hertz(approach, hertz);
    if (!has_values(first)) {
      hertz.far_first = false;
      first = fit_hertz(retract, hertz);
    }
    if (!has_values(first)) {
      static_cast<HertzFit&>(fit) = first;
      fit.points = fit.approach_points + fit.retract_points;
      return fit;
    }
    start = {first.youngs_modulus.value,
             0.0,
             0.0,
             first.contact_point.value,
             first.baseline_offset.value,
             first.baseline_slope.value};
    // E walks as a logarithm: a one-segment fit that went to E <= 0 starts from its size.
    if (!(start[kModulus] > 0.0)) {
      start[kModulus] = std::abs(start[kModulus]) > 0.0 ? std::abs(start[kModulus]) : 1.0;
    }
  } else {
    AdhesiveFitOptions one;
    one.model = options.model;
    one.tip = options.tip;
    one.poisson_ratio = options.poisson_ratio;
    one.fixed = options.fixed;
    one.retract = true;
    const AdhesiveFit out = fit_adhesive(retract, one);
    if (!has_values(out)) {
      static_cast<AdhesiveFit&>(fit) = out;
      fit.message = "retract: " + out.message;
      fit.points = fit.approach_points + fit.retract_points;
      return fit;
    }
    one.retract = false;
    if (options.approach_work_of_adhesion) {
      one.fixed.work_of_adhesion = options.approach_work_of_adhesion;
    }
    // The approach's own fit: its contact point marks its samples in contact, its w starts w_a.
    AdhesiveFit in = fit_adhesive(approach, one);
    if (!has_values(in) || !(in.work_of_adhesion.value > 0.0)) {
      one.fixed.contact_point = out.contact_point.value;
      in = fit_adhesive(approach, one);
    }
    // An approach without a visible jump in starts from a tenth of the retract's w.
    const bool approach_fitted = has_values(in) && in.work_of_adhesion.value > 0.0;
    const double approach_work =
        approach_fitted ? in.work_of_adhesion.value : 0.1 * out.work_of_adhesion.value;
    approach_contact = approach_fitted ? in.contact_point.value : out.contact_point.value;
    start = {out.youngs_modulus.value, out.work_of_adhesion.value, approach_work,
             out.contact_point.value,  out.baseline_offset.value,  out.baseline_slope.value};
    fit.adhesion_force_measured = out.adhesion_force_measured;
    jump = retract_jump(retract.force);
  }

  Samples samples = join(approach, retract);
  const auto [z_low, z_high] = std::minmax_element(samples.z.begin(), samples.z.end());
  const double z_range = std::max(*z_high - *z_low, 1e-30);
  double force_scale = 0.0;
  for (const double v : samples.force) force_scale = std::max(force_scale, std::abs(v));
  force_scale = std::max(force_scale, 1e-300);

  const std::array<std::optional<double>, kJointParameters> held = {
      options.fixed.youngs_modulus,
      options.adhesive ? options.fixed.work_of_adhesion : std::optional<double>(0.0),
      options.adhesive ? options.approach_work_of_adhesion : std::optional<double>(0.0),
      options.fixed.contact_point,
      options.fixed.baseline_offset,
      options.fixed.baseline_slope};
  ScaledProblem problem;
  problem.data = &samples.force;
  problem.force_scale = force_scale;
  problem.walk = {Walk::logarithmic, Walk::logarithmic, Walk::logarithmic,
                  Walk::linear,      Walk::linear,      Walk::linear};
  problem.model = [&](std::span<const double> p, std::span<double> model) {
    each_sample(samples, options, p, [&](std::size_t i, const ContactForce* c) {
      model[i] = p[kOffset] + p[kSlope] * (samples.z[i] - p[kContact]) + (c ? c->force : 0.0);
    });
  };
  problem.derivatives = [&](std::span<const double> p, std::span<double> d) {
    // A column per parameter (least_squares.hpp): d[k * m + i] is d model_i / d p_k.
    const std::size_t m = samples.z.size();
    each_sample(samples, options, p, [&](std::size_t i, const ContactForce* c) {
      d[kModulus * m + i] = c ? c->d_modulus / compliance : 0.0;
      d[kWork * m + i] = c && !samples.approach[i] ? c->d_work : 0.0;
      d[kApproachWork * m + i] = c && samples.approach[i] ? c->d_work : 0.0;
      d[kContact * m + i] = -p[kSlope] + (c ? c->d_depth : 0.0);
      d[kOffset * m + i] = 1.0;
      d[kSlope * m + i] = samples.z[i] - p[kContact];
    });
  };
  FitParameter* out[kJointParameters] = {
      &fit.youngs_modulus, &fit.work_of_adhesion, &fit.approach_work_of_adhesion,
      &fit.contact_point,  &fit.baseline_offset,  &fit.baseline_slope};
  ScaledSolution solution;
  // The approach's contact: past its own fit's contact point, then once more past the joint
  // fit's where that moves a sample across it (the two segments' contact points differ by the
  // piezo's creep and hysteresis on a real curve).
  for (int pass = 0; pass < 2; ++pass) {
    problem.held.assign(kJointParameters, false);
    for (std::size_t k = 0; k < kJointParameters; ++k) {
      problem.held[k] = held[k].has_value();
      if (held[k]) start[k] = *held[k];
    }
    problem.start.assign(start.begin(), start.end());
    const double depth = std::max(start[kContact] - *z_low, 1e-3 * z_range);
    problem.scale = {1.0, 1.0, 1.0, depth, force_scale, force_scale / z_range};
    const std::vector<char> before = samples.contact;
    if (options.adhesive) {
      mark_contact(samples, fit.approach_points, jump,
                   pass == 0 ? approach_contact : start[kContact]);
    }
    if (pass == 1 && samples.contact == before) break;
    solution = minimize_scaled(problem, out);
    fit.iterations += solution.iterations;
    fit.evaluations += solution.evaluations;
    std::copy(solution.values.begin(), solution.values.end(), start.begin());
    if (!options.adhesive) break;
  }

  const std::span<const double> p(solution.values);
  fit.residual_rms =
      std::sqrt(solution.sum_squares / static_cast<double>(fit.points)) * force_scale;
  fit.max_indentation = std::max(0.0, p[kContact] - *z_low);
  fit.contact_samples = 0;
  for (std::size_t i = 0; i < samples.z.size(); ++i) {
    fit.contact_samples += options.adhesive ? samples.contact[i] != 0 : p[kContact] > samples.z[i];
  }
  if (options.adhesive && options.model == AdhesionModel::dmt) {
    fit.adhesion_force_fitted = 2.0 * std::numbers::pi * options.tip.radius * p[kWork];
  } else if (options.adhesive && p[kModulus] > 0.0 && p[kWork] > 0.0) {
    fit.adhesion_force_fitted =
        -JkrBranch(*options.tip.profile, p[kModulus] / compliance, p[kWork], fit.max_indentation)
             .lowest_force();
  }
  const bool positive =
      p[kModulus] > 0.0 && (!options.adhesive || (p[kWork] > 0.0 && p[kApproachWork] > 0.0));
  settle_status(fit, out, solution.outcome,
                positive ? nullptr : "the fit went to a modulus or work of adhesion <= 0",
                RefusalRank::after_non_finite);
  return fit;
}

double hysteresis_energy(const PreparedSegment& approach, const PreparedSegment& retract,
                         double contact_point, double baseline_offset, double baseline_slope) {
  double energy = 0.0;
  for (const PreparedSegment* seg : {&approach, &retract}) {
    const std::vector<double>& z = seg->tip_position;
    const auto force = [&](std::size_t i) {
      return seg->force[i] - baseline_offset - baseline_slope * (z[i] - contact_point);
    };
    for (std::size_t i = 0; i + 1 < z.size(); ++i) {
      energy += 0.5 * (force(i) + force(i + 1)) * (z[i] - z[i + 1]);
    }
  }
  return energy;
}

}  // namespace mdrsim::fit
