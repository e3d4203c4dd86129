// DMT's and JKR's models fitted to one prepared segment (approach or retract) by Eigen's
// Levenberg-Marquardt: youngs_modulus, work_of_adhesion, contact point and baseline, with
// standard errors and the adhesion force fitted and measured.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "engine/fit/hertz_fit.hpp"
#include "engine/fit/least_squares.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"
#include "profiles/profile.hpp"

namespace mdrsim::fit {

enum class AdhesionModel { dmt, jkr };

/// "dmt", "jkr".
const char* adhesion_model_name(AdhesionModel model);

struct AdhesiveFixed : HertzFixed {
  std::optional<double> work_of_adhesion;  ///< [J/m^2]
  std::optional<double> maugis_parameter;  ///< lambda [1] (the Maugis fit alone)
};

struct AdhesiveFitOptions {
  AdhesionModel model = AdhesionModel::jkr;
  TipShape tip;
  double poisson_ratio = 0.5;
  AdhesiveFixed fixed;
  bool retract = true;  ///< the samples run from the deepest point out (false: an approach)
};

struct AdhesiveFit : HertzFit {
  FitParameter work_of_adhesion;         ///< [J/m^2]
  FitParameter maugis_parameter;         ///< lambda [1] (the Maugis fit alone)
  double adhesion_force_fitted = 0.0;    ///< [N] the model's pull-off force under fixed load
  double adhesion_force_measured = 0.0;  ///< [N] the baseline less the lowest contact force
  std::size_t contact_samples = 0;       ///< the samples fitted on the contact branch
};

/// JKR's equilibrium branch of an axisymmetric tip by the MDR (Popov & Hess): with
/// s(a) = sqrt(2 pi a w / E*), the indentation d(a) = g(a) - s(a) and the force
/// F(a) = E* h(a) - 2 E* a s(a), g the tip's MDR image and h its Hertz force per modulus
/// (for the paraboloid, JKR's closed forms). Sampled in a from the fixed-grips end a*
/// (d'(a*) = 0) outward; a depth is placed on it by interpolation and one Newton step.
class JkrBranch {
 public:
  /// reduced_modulus E* [Pa], work_of_adhesion w [J/m^2], deepest indentation to cover [m].
  JkrBranch(const Profile& profile, double reduced_modulus, double work_of_adhesion,
            double deepest);

  struct State {
    double force = 0.0;              ///< [N]
    double d_force_d_depth = 0.0;    ///< [N/m]
    double d_force_d_modulus = 0.0;  ///< [m^2] per unit E*
    double d_force_d_work = 0.0;     ///< [m] per unit w
    double contact_radius = 0.0;     ///< [m]
  };
  /// The stable state at indentation `depth` [m]; below the branch's shallowest depth, its end.
  State at(double depth) const;
  /// [N] the lowest force along the branch (the pull-off under fixed load).
  double lowest_force() const { return lowest_force_; }
  double shallowest_depth() const { return depth_.front(); }  ///< [m] d(a*)

 private:
  const Profile& profile_;
  double reduced_;
  double work_;
  std::vector<double> radius_;
  std::vector<double> depth_;
  double lowest_force_ = 0.0;
  double depth_of(double a) const;
};

/// Fits the model. Retract: the samples from the deepest point to the jump off (the largest
/// rise of the force after its minimum) lie on the contact branch, the rest on the baseline.
/// Approach: the samples indented past the contact point lie on it. A curve without such a
/// jump or dip gets no-contact.
AdhesiveFit fit_adhesive(const PreparedSegment& segment, const AdhesiveFitOptions& options);

/// Where a model's own refusal ranks against numbers that are not finite: a model that could
/// not be evaluated at the minimum (the zone past the tip's edge) says so first; a bound on the
/// fitted values (E or w <= 0, which a NaN also fails) yields to the non-finite message.
enum class RefusalRank { before_non_finite, after_non_finite };

/// Settles every adhesive fit's status once its numbers are written: not-converged with the
/// minimiser's failure, else the model's refusal (nullptr: none) and the non-finite numbers
/// (residual, adhesion force, a parameter's value or standard error) in `rank`'s order, else
/// fitted. A fit left not finite is zeroed (values, errors, residual, adhesion force), its
/// parameters keeping their held flags.
void settle_status(AdhesiveFit& fit, std::span<FitParameter* const> parameters,
                   MinimizerOutcome outcome, const char* refusal, RefusalRank rank);

}  // namespace mdrsim::fit
