// Eigen's Levenberg-Marquardt over a ScaledProblem's free parameters, and the standard errors.
#include "engine/fit/least_squares.hpp"

#include <Eigen/Dense>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <algorithm>
#include <cmath>
#include <type_traits>

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

/// The residuals over the walked (nonlinear free) parameters x, the solved (linear free) ones
/// at their least-squares values for that x; the Jacobian is Kaufman's: the walked columns
/// with their part in the solved columns' span removed.
struct ProjectedFunctor : Eigen::DenseFunctor<double> {
  const ScaledProblem& problem;
  std::vector<int> walked;
  std::vector<int> solved;
  mutable std::vector<double> parameter_buffer;
  mutable std::vector<double> model_buffer;  ///< the model without the solved parameters
  mutable std::vector<double> derivative_buffer;
  mutable Eigen::MatrixXd columns;  ///< the solved parameters' columns, each of unit norm
  mutable Eigen::LDLT<Eigen::MatrixXd> normal;
  mutable Eigen::VectorXd coefficients;  ///< of the unit columns
  mutable Eigen::VectorXd solved_at;     ///< the x the members above belong to

  ProjectedFunctor(const ScaledProblem& problem_, std::vector<int> walked_,
                   std::vector<int> solved_)
      : Eigen::DenseFunctor<double>(static_cast<int>(walked_.size()),
                                    static_cast<int>(problem_.data->size())),
        problem(problem_),
        walked(std::move(walked_)),
        solved(std::move(solved_)),
        model_buffer(problem_.data->size()),
        derivative_buffer(problem_.data->size() * problem_.start.size()) {}

  /// Every parameter at x, the solved ones at their least-squares values (in a buffer the
  /// next call overwrites).
  const std::vector<double>& parameters(const InputType& x) const {
    std::vector<double>& p = parameter_buffer;
    // The minimiser asks for the Jacobian where it last evaluated the residuals.
    if (solved_at.size() == x.size() && solved_at == x) return p;
    p = problem.start;
    for (std::size_t j = 0; j < walked.size(); ++j) {
      const double xj = x[static_cast<Eigen::Index>(j)];
      const auto k = static_cast<std::size_t>(walked[j]);
      p[k] = problem.walk[k] == Walk::logarithmic
                 ? problem.start[k] * std::exp(std::clamp(xj, -50.0, 50.0))
                 : problem.start[k] + problem.scale[k] * xj;
    }
    for (const int k : solved) p[static_cast<std::size_t>(k)] = 0.0;
    const std::size_t points = problem.data->size();
    const auto rows = static_cast<Eigen::Index>(points);
    const auto count = static_cast<Eigen::Index>(solved.size());
    problem.model(p, model_buffer);
    problem.derivatives(p, derivative_buffer);
    columns.resize(rows, count);
    Eigen::VectorXd norms(count);
    for (Eigen::Index j = 0; j < count; ++j) {
      const Eigen::Map<const Eigen::VectorXd> column(
          &derivative_buffer[static_cast<std::size_t>(solved[static_cast<std::size_t>(j)]) *
                             points],
          rows);
      const double norm = column.norm();
      norms[j] = norm > 0.0 ? norm : 1.0;
      columns.col(j) = column / norms[j];
    }
    const Eigen::Map<const Eigen::VectorXd> data(problem.data->data(), rows);
    const Eigen::Map<const Eigen::VectorXd> rest(model_buffer.data(), rows);
    normal.compute(columns.transpose().lazyProduct(columns));
    coefficients = normal.solve(columns.transpose().lazyProduct(data - rest));
    for (Eigen::Index j = 0; j < count; ++j) {
      p[static_cast<std::size_t>(solved[static_cast<std::size_t>(j)])] = coefficients[j] / norms[j];
    }
    return p;
  }

  int operator()(const InputType& x, ValueType& residuals) const {
    parameters(x);
    const auto rows = static_cast<Eigen::Index>(problem.data->size());
    const Eigen::Map<const Eigen::VectorXd> data(problem.data->data(), rows);
    const Eigen::Map<const Eigen::VectorXd> rest(model_buffer.data(), rows);
    residuals = (rest + columns * coefficients - data) / problem.force_scale;
    return 0;
  }

  int df(const InputType& x, JacobianType& jacobian) const {
    const std::vector<double> p = parameters(x);
    const std::size_t points = problem.data->size();
    problem.derivatives(p, derivative_buffer);
    for (std::size_t j = 0; j < walked.size(); ++j) {
      const auto k = static_cast<std::size_t>(walked[j]);
      const double factor =
          (problem.walk[k] == Walk::logarithmic ? p[k] : problem.scale[k]) / problem.force_scale;
      const Eigen::Map<const Eigen::VectorXd> column(&derivative_buffer[k * points],
                                                     static_cast<Eigen::Index>(points));
      jacobian.col(static_cast<Eigen::Index>(j)) = column * factor;
    }
    const Eigen::MatrixXd along = normal.solve(columns.transpose().lazyProduct(jacobian));
    jacobian.noalias() -= columns.lazyProduct(along);
    return 0;
  }
};

/// x of the scaled walk at which parameter k takes the value p.
double walk_coordinate(const ScaledProblem& problem, std::size_t k, double p) {
  return problem.walk[k] == Walk::logarithmic ? std::log(p / problem.start[k])
                                              : (p - problem.start[k]) / problem.scale[k];
}

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
  std::vector<int> walked;
  std::vector<int> solved;
  for (const int k : free) {
    const auto kk = static_cast<std::size_t>(k);
    const bool linear = kk < problem.enters_linearly.size() && problem.enters_linearly[kk] &&
                        problem.walk[kk] == Walk::linear;
    (linear ? solved : walked).push_back(k);
  }
  const auto run = [&](auto& minimized, Eigen::VectorXd& at) {
    Eigen::LevenbergMarquardt<std::remove_reference_t<decltype(minimized)>> minimizer(minimized);
    minimizer.setFtol(1e-12);
    minimizer.setXtol(1e-12);
    minimizer.setMaxfev(400 * static_cast<Eigen::Index>(free.size() + 1));
    status = minimizer.minimize(at);
    // A refused start returns before Eigen counts anything.
    if (status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters) {
      solution.iterations = static_cast<long>(minimizer.iterations());
      solution.evaluations = static_cast<long>(minimizer.nfev());
    }
  };
  if (!walked.empty() && !solved.empty()) {
    ProjectedFunctor projected(problem, walked, solved);
    Eigen::VectorXd walked_x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(walked.size()));
    run(projected, walked_x);
    const std::vector<double>& p = projected.parameters(walked_x);
    for (std::size_t j = 0; j < free.size(); ++j) {
      const auto k = static_cast<std::size_t>(free[j]);
      x[static_cast<Eigen::Index>(j)] = walk_coordinate(problem, k, p[k]);
    }
  } else if (!free.empty()) {
    run(functor, x);
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
