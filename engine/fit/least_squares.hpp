// The one Levenberg-Marquardt driver of every fitted model: scaled parameters, held ones,
// standard errors and the write-back into FitParameter.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "engine/fit/hertz_fit.hpp"

namespace mdrsim::fit {

/// How a parameter is walked by the minimiser: p = start + scale x (linear), or
/// p = start exp(x) (logarithmic: it stays positive and its scale is its own size).
enum class Walk { linear, logarithmic };

/// A model to fit, over all its parameters (held ones included).
///
/// The model is a pair of std::function callbacks over whole samples, not a template: one
/// call evaluates every sample (a JKR or Maugis branch is built once per call), so the
/// indirection costs nothing measurable, and the driver, Eigen's minimiser and its error
/// algebra are compiled once in least_squares.cpp instead of in every model's file.
struct ScaledProblem {
  std::vector<double> start;  ///< every parameter's start (a held one: its held value)
  std::vector<double> scale;  ///< of a linear parameter; ignored for a logarithmic one
  std::vector<Walk> walk;
  std::vector<bool> held;
  /// Parameters the model is linear in (their derivative columns do not depend on their own
  /// values). Where given and some free parameter is not linear, the minimiser walks only the
  /// others and solves the free linear ones exactly at each step (variable projection, Golub
  /// and Pereyra; Kaufman's Jacobian): the same minimum, found in a 10000 x 1 problem instead
  /// of a 10000 x 4 one. Only a parameter walked linearly is solved. Empty: every parameter
  /// is walked.
  std::vector<bool> enters_linearly;
  const std::vector<double>* data = nullptr;  ///< the measured forces [N]
  double force_scale = 1.0;                   ///< the residuals are (model - data) / force_scale
  /// Writes the model's force at every sample for parameters p.
  std::function<void(std::span<const double> p, std::span<double> model)> model;
  /// Writes d model_i / d p_k at [k * points + i] (a column per parameter) for every sample i
  /// and every free parameter k (a held one's column is not read).
  std::function<void(std::span<const double> p, std::span<double> derivatives)> derivatives;
};

enum class MinimizerOutcome { converged, evaluation_limit, refused_start };

struct ScaledSolution {
  std::vector<double> values;  ///< every parameter at the minimum
  double sum_squares = 0.0;    ///< of the scaled residuals
  MinimizerOutcome outcome = MinimizerOutcome::converged;
  long iterations = 0;
  long evaluations = 0;
};

/// Minimises the scaled residuals by Eigen's Levenberg-Marquardt (MINPACK's lmder; ftol and
/// xtol 1e-12, 400 (free + 1) evaluations) from x = 0 (over the nonlinear free parameters
/// only where problem.enters_linearly says so), and writes each parameter's value,
/// held flag and standard error (sqrt of (J^T J)^-1 s^2's diagonal, s^2 = sum_squares /
/// (points - free), times dp/dx) into out[k], in the problem's order.
ScaledSolution minimize_scaled(const ScaledProblem& problem, std::span<FitParameter* const> out);

/// The message of a status other than converged ("the minimiser reached its limit of
/// evaluations", "the minimiser refused its start"); nullptr for converged.
const char* minimizer_failure(MinimizerOutcome outcome);

}  // namespace mdrsim::fit
