// Eigen's Levenberg-Marquardt over a ScaledProblem's free parameters, and the standard errors.
#include "engine/fit/least_squares.hpp"

#include <Eigen/Dense>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <algorithm>
#include <cmath>

namespace mdrsim::fit {
namespace {

/// The residuals over the free parameters x, each parameter at start + scale x or start exp(x).
struct ScaledFunctor : Eigen::DenseFunctor<double> {
  const ScaledProblem& problem;
  std::vector<int> free;
  mutable std::vector<double> parameter_buffer;
  mutable std::vector<double> model_buffer;
  mutable std::vector<double> derivative_buffer;

  ScaledFunctor(const ScaledProblem& problem_, std::vector<int> free_)
      : Eigen::DenseFunctor<double>(static_cast<int>(free_.size()),
                                    static_cast<int>(problem_.data->size())),
        problem(problem_),
        free(std::move(free_)),
        model_buffer(problem_.data->size()),
        derivative_buffer(problem_.data->size() * problem_.start.size()) {}

  /// Every parameter at x, in a buffer the next call overwrites (no allocation per call).
  const std::vector<double>& parameters(const InputType& x) const {
    std::vector<double>& p = parameter_buffer;
    p = problem.start;
    for (std::size_t j = 0; j < free.size(); ++j) {
      const double xj = x[static_cast<Eigen::Index>(j)];
      const auto k = static_cast<std::size_t>(free[j]);
      p[k] = problem.walk[k] == Walk::logarithmic
                 ? problem.start[k] * std::exp(std::clamp(xj, -50.0, 50.0))
                 : problem.start[k] + problem.scale[k] * xj;
    }
    return p;
  }

  /// dp/dx of parameter k at p.
  double slope(int k, const std::vector<double>& p) const {
    const auto kk = static_cast<std::size_t>(k);
    return problem.walk[kk] == Walk::logarithmic ? p[kk] : problem.scale[kk];
  }

  int operator()(const InputType& x, ValueType& residuals) const {
    const std::vector<double>& p = parameters(x);
    problem.model(p, model_buffer);
    const std::vector<double>& data = *problem.data;
    for (std::size_t i = 0; i < data.size(); ++i) {
      residuals[static_cast<Eigen::Index>(i)] = (model_buffer[i] - data[i]) / problem.force_scale;
    }
    return 0;
  }

  int df(const InputType& x, JacobianType& jacobian) const {
    const std::vector<double>& p = parameters(x);
    const std::size_t points = problem.data->size();
    problem.derivatives(p, derivative_buffer);
    for (std::size_t j = 0; j < free.size(); ++j) {
      const double* column = &derivative_buffer[static_cast<std::size_t>(free[j]) * points];
      const double factor = slope(free[j], p);
      for (std::size_t i = 0; i < points; ++i) {
        jacobian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            column[i] * factor / problem.force_scale;
      }
    }
    return 0;
  }
};

}  // namespace

const char* minimizer_failure(MinimizerOutcome outcome) {
  switch (outcome) {
    case MinimizerOutcome::converged:
      return nullptr;
    case MinimizerOutcome::evaluation_limit:
      return "the minimiser reached its limit of evaluations";
    case MinimizerOutcome::refused_start:
      return "the minimiser refused its start";
  }
  return nullptr;
}

ScaledSolution minimize_scaled(const ScaledProblem& problem, std::span<FitParameter* const> out) {
  std::vector<int> free;
  for (std::size_t k = 0; k < problem.start.size(); ++k) {
    if (!problem.held[k]) free.push_back(static_cast<int>(k));
  }
  ScaledFunctor functor(problem, free);
  const std::size_t points = problem.data->size();

  ScaledSolution solution;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free.size()));
  Eigen::LevenbergMarquardtSpace::Status status =
      Eigen::LevenbergMarquardtSpace::RelativeErrorTooSmall;
  Eigen::LevenbergMarquardt<ScaledFunctor> minimizer(functor);
  if (!free.empty()) {
    minimizer.setFtol(1e-12);
    minimizer.setXtol(1e-12);
    minimizer.setMaxfev(400 * static_cast<Eigen::Index>(free.size() + 1));
    status = minimizer.minimize(x);
    // A refused start returns before Eigen counts anything.
    if (status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters) {
      solution.iterations = static_cast<long>(minimizer.iterations());
      solution.evaluations = static_cast<long>(minimizer.nfev());
    }
  }
  if (status == Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation) {
    solution.outcome = MinimizerOutcome::evaluation_limit;
  } else if (status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters) {
    solution.outcome = MinimizerOutcome::refused_start;
  }
  solution.values = functor.parameters(x);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k]->value = solution.values[k];
    out[k]->fixed = problem.held[k];
  }
  Eigen::VectorXd residuals(static_cast<Eigen::Index>(points));
  functor(x, residuals);
  solution.sum_squares = residuals.squaredNorm();
  const auto dof = static_cast<double>(points) - static_cast<double>(free.size());
  if (!free.empty() && dof > 0.0) {
    Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(points),
                             static_cast<Eigen::Index>(free.size()));
    functor.df(x, jacobian);
    const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
    const Eigen::MatrixXd covariance =
        normal.ldlt().solve(Eigen::MatrixXd::Identity(normal.rows(), normal.cols())) *
        (solution.sum_squares / dof);
    for (std::size_t j = 0; j < free.size(); ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      out[static_cast<std::size_t>(free[j])]->standard_error =
          functor.slope(free[j], solution.values) * std::sqrt(std::max(0.0, covariance(jj, jj)));
    }
  }
  return solution;
}

}  // namespace mdrsim::fit
