// A measured segment made ready for a fit: force over tip position, and the first guesses.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/fit/tip_shape.hpp"
#include "engine/measured/force_curve.hpp"

namespace mdrsim::fit {

/// One segment in SI units. Tip positions follow afmformats' sign (they decrease into the
/// sample), so the indentation is contact_point - tip_position.
struct PreparedSegment {
  std::vector<double> tip_position;  ///< [m] height + deflection, in the order measured
  std::vector<double> force;         ///< [N]
  std::string height_channel;        ///< "measured_height", "piezo_height" or "tip_position"
  double spring_constant = 0.0;      ///< [N/m] used (0 where the file gave force and tip)
};

/// An adhesive model's contact force (less the baseline) at one sample, and its derivatives.
struct ContactForce {
  double force = 0.0;      ///< [N]
  double d_depth = 0.0;    ///< [N/m]
  double d_modulus = 0.0;  ///< [m^2] per unit E*
  double d_work = 0.0;     ///< [m] per unit of the work of adhesion the sample's segment takes
};

/// Where the fit starts (the contact point guess and the baseline under it).
struct FirstGuess {
  bool contact = false;          ///< false: the curve never leaves the baseline's noise band
  double contact_point = 0.0;    ///< [m]
  double baseline_offset = 0.0;  ///< [N] the baseline's force at the contact point
  double baseline_slope = 0.0;   ///< [N/m] along the tip position
  double noise = 0.0;            ///< [N] the baseline's robust standard deviation (first fifth)
  double youngs_modulus = 0.0;   ///< [Pa]
};

/// The segment of `kind` (the first one of it) as force over tip position. Tip position =
/// height + deflection in afmformats' sign (SPEC's piezo height - deflection), the height
/// being the height sensor's reading of the piezo where the file has one, else the piezo's
/// commanded height; force = the file's force, else deflection x spring constant. Throws
/// SceneError (one line, without the file's name) when the curve has no such segment or a
/// needed spring constant is missing.
PreparedSegment prepare_segment(const measured::ForceCurve& curve, measured::SegmentKind kind);

/// The baseline (offset and slope) fitted on the samples before contact and a robust contact
/// point: the last sample, going in, inside the baseline's noise band (5 robust standard
/// deviations), the curve beyond it all above the band. `far_first`: the samples run from
/// far to near (an approach); else they are reversed first (a retract).
FirstGuess first_guess(const PreparedSegment& segment, const TipShape& tip, double poisson_ratio,
                       bool far_first = true);

}  // namespace mdrsim::fit
