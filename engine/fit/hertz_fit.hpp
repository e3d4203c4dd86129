// Hertz's model fitted to one prepared segment by Levenberg-Marquardt (Eigen's), with the
// standard errors of its parameters.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"

namespace mdrsim::fit {

/// What became of a curve (SPEC's statuses).
enum class FitStatus { fitted, no_contact, not_converged, unreadable };

/// "fitted", "no-contact", "not-converged", "unreadable".
const char* fit_status_name(FitStatus status);

struct FitParameter {
  double value = 0.0;
  double standard_error = 0.0;  ///< sqrt of (J^T J)^-1 s^2's diagonal; 0 when fixed
  bool fixed = false;
};

/// The parameters by SPEC's names; a value here holds that parameter (`--fix NAME=VALUE`).
struct HertzFixed {
  std::optional<double> youngs_modulus;   ///< [Pa]
  std::optional<double> contact_point;    ///< [m]
  std::optional<double> baseline_offset;  ///< [N]
  std::optional<double> baseline_slope;   ///< [N/m]
};

struct HertzFitOptions {
  TipShape tip;
  double poisson_ratio = 0.5;
  HertzFixed fixed;
  bool far_first = true;  ///< the samples run from far to near (approach); false: retract
};

/// The model: F(z) = offset + slope (z - contact_point) + E / (1 - nu^2) g(contact_point - z),
/// z the tip position, g the tip's Hertz law (zero out of contact).
struct HertzFit {
  FitStatus status = FitStatus::not_converged;
  std::string message;           ///< why, for a status other than fitted
  FitParameter youngs_modulus;   ///< [Pa]
  FitParameter contact_point;    ///< [m]
  FitParameter baseline_offset;  ///< [N] the baseline's force at the contact point
  FitParameter baseline_slope;   ///< [N/m] along the tip position
  double residual_rms = 0.0;     ///< [N]
  double max_indentation = 0.0;  ///< [m] contact_point - the lowest tip position
  std::size_t points = 0;
  long iterations = 0;
  long evaluations = 0;
};

/// The force of the model at tip position z [m] for the parameters of `fit`.
double hertz_force(const TipShape& tip, double poisson_ratio, const HertzFit& fit, double z);

/// Fits the model to the segment, starting from first_guess(). A curve without contact gets
/// no-contact; one whose minimiser stops on its evaluation limit, or at E <= 0, not-converged.
HertzFit fit_hertz(const PreparedSegment& segment, const HertzFitOptions& options);

}  // namespace mdrsim::fit
