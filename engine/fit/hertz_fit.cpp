// Hertz's model fitted by Eigen's Levenberg-Marquardt (MINPACK's lmder) in scaled parameters.
#include "engine/fit/hertz_fit.hpp"

#include <Eigen/Dense>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace mdrsim::fit {
namespace {

constexpr int kParameters = 4;  // youngs_modulus, contact_point, baseline_offset, baseline_slope

/// The residuals (model - data) / force_scale over the free parameters, each as
/// start + scale * x so that every x is of order one whatever the units.
struct ScaledHertz : Eigen::DenseFunctor<double> {
  const TipShape& tip;
  double compliance;  // (1 - nu^2)
  const std::vector<double>& z;
  const std::vector<double>& force;
  std::array<double, kParameters> start{};
  std::array<double, kParameters> scale{};
  std::vector<int> free;  // the indices of the fitted parameters
  double force_scale = 1.0;

  ScaledHertz(const TipShape& tip_, double nu, const std::vector<double>& z_,
              const std::vector<double>& force_, std::vector<int> free_)
      : Eigen::DenseFunctor<double>(static_cast<int>(free_.size()), static_cast<int>(z_.size())),
        tip(tip_),
        compliance(1.0 - nu * nu),
        z(z_),
        force(force_),
        free(std::move(free_)) {}

  std::array<double, kParameters> parameters(const InputType& x) const {
    std::array<double, kParameters> p = start;
    for (std::size_t j = 0; j < free.size(); ++j) {
      p[free[j]] = start[free[j]] + scale[free[j]] * x[static_cast<Eigen::Index>(j)];
    }
    return p;
  }

  int operator()(const InputType& x, ValueType& residuals) const {
    const auto p = parameters(x);
    const double reduced = p[0] / compliance;
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double model =
          p[2] + p[3] * (z[i] - p[1]) + reduced * tip.force_per_modulus(p[1] - z[i]);
      residuals[static_cast<Eigen::Index>(i)] = (model - force[i]) / force_scale;
    }
    return 0;
  }

  int df(const InputType& x, JacobianType& jacobian) const {
    const auto p = parameters(x);
    const double reduced = p[0] / compliance;
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double delta = p[1] - z[i];
      const std::array<double, kParameters> d = {tip.force_per_modulus(delta) / compliance,
                                                 -p[3] + reduced * tip.stiffness_per_modulus(delta),
                                                 1.0, z[i] - p[1]};
      for (std::size_t j = 0; j < free.size(); ++j) {
        jacobian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            d[free[j]] * scale[free[j]] / force_scale;
      }
    }
    return 0;
  }
};

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
  std::vector<int> free;
  for (int j = 0; j < kParameters; ++j) {
    if (held[j]) {
      start[j] = *held[j];
    } else {
      free.push_back(j);
    }
  }
  const double depth = std::max(start[1] - *z_low, 1e-3 * z_range);
  ScaledHertz model(options.tip, options.poisson_ratio, segment.tip_position, segment.force, free);
  model.start = start;
  model.scale = {std::abs(start[0]), depth, force_scale, force_scale / z_range};
  model.force_scale = force_scale;

  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free.size()));
  Eigen::LevenbergMarquardtSpace::Status status =
      Eigen::LevenbergMarquardtSpace::RelativeErrorTooSmall;
  Eigen::LevenbergMarquardt<ScaledHertz> minimizer(model);
  if (!free.empty()) {
    minimizer.setFtol(1e-12);
    minimizer.setXtol(1e-12);
    minimizer.setMaxfev(400 * static_cast<Eigen::Index>(free.size() + 1));
    status = minimizer.minimize(x);
    fit.iterations = static_cast<long>(minimizer.iterations());
    fit.evaluations = static_cast<long>(minimizer.nfev());
  }
  const auto p = model.parameters(x);
  FitParameter* out[kParameters] = {&fit.youngs_modulus, &fit.contact_point, &fit.baseline_offset,
                                    &fit.baseline_slope};
  for (int j = 0; j < kParameters; ++j) {
    out[j]->value = p[j];
    out[j]->fixed = held[j].has_value();
  }
  Eigen::VectorXd residuals(static_cast<Eigen::Index>(fit.points));
  model(x, residuals);
  const double sum_squares = residuals.squaredNorm();
  fit.residual_rms = std::sqrt(sum_squares / static_cast<double>(fit.points)) * force_scale;
  fit.max_indentation = std::max(0.0, p[1] - *z_low);
  const auto dof = static_cast<double>(fit.points) - static_cast<double>(free.size());
  if (!free.empty() && dof > 0.0) {
    Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(fit.points),
                             static_cast<Eigen::Index>(free.size()));
    model.df(x, jacobian);
    const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
    const Eigen::MatrixXd covariance =
        normal.ldlt().solve(Eigen::MatrixXd::Identity(normal.rows(), normal.cols())) *
        (sum_squares / dof);
    for (std::size_t j = 0; j < free.size(); ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      out[free[j]]->standard_error =
          model.scale[free[j]] * std::sqrt(std::max(0.0, covariance(jj, jj)));
    }
  }
  if (status == Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation ||
      status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters) {
    fit.status = FitStatus::not_converged;
    fit.message = status == Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation
                      ? "the minimiser reached its limit of evaluations"
                      : "the minimiser refused its start";
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
