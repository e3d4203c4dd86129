// Every curve of a measured file fitted, each with its status, and the fits as JSON, CSV and
// a summary line.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/combined_fit.hpp"
#include "engine/fit/fit_range.hpp"
#include "engine/fit/fit_warnings.hpp"
#include "engine/fit/hertz_fit.hpp"
#include "engine/fit/maugis_fit.hpp"
#include "engine/measured/force_curve.hpp"

namespace mdrsim::fit {

/// automatic: `--model auto` (the Maugis fit, and the regime its lambda picks).
enum class FitModel { hertz, dmt, jkr, maugis, automatic };

/// "hertz", "dmt", "jkr", "maugis", "auto".
const char* fit_model_name(FitModel model);

/// What `mdrsim fit` asks of every curve: the model, the tip and the held parameters.
struct CurveFitOptions {
  FitModel model = FitModel::hertz;
  TipShape tip;
  double poisson_ratio = 0.5;
  /// work_of_adhesion is ignored by hertz, maugis_parameter by all but maugis
  AdhesiveFixed fixed;
  std::optional<double> approach_work_of_adhesion;  ///< [J/m^2] held (both segments)
  bool both_segments = false;  ///< approach and retract together (`segment` is then ignored)
  /// The samples fitted: indentation from the contact point (its first guess, then the fit's).
  std::optional<FitRange> range;
};

/// A curve's cell in its map's grid, from its position: column along x, row along y, each
/// from 0 at the grid's lower edge (a back-and-forth map's rows are not reversed here).
struct GridCell {
  long column = 0;
  long row = 0;
};

/// One curve's fit with where it came from and the calibration it used.
struct CurveFit {
  std::string file;
  std::string curve;  ///< the curve's label in its file ("" for a file of one curve)
  std::optional<measured::MapPosition> position;
  std::optional<GridCell> cell;  ///< where the file declares a grid and the position lies on it
  measured::Calibration calibration;
  std::string height_channel;  ///< the channel the tip position was made from
  CombinedFit fit;  ///< for hertz, the works of adhesion and adhesion forces stay 0; for one
                    ///< segment, approach_work_of_adhesion too
  /// [J] between approach and retract (combined_fit.hpp), where the curve has both.
  std::optional<double> hysteresis_energy;
  /// What the fit cannot vouch for, one line each without the curve's name (fit_warnings.hpp):
  /// a fitted curve whose baseline its record does not fix, or whose residual is far above its
  /// noise.
  std::vector<std::string> warnings;
};

/// Fits the first segment of `segment` kind of curve `index` of `file` (or its approach and
/// retract together, options.both_segments), inside options.range where given. A curve that cannot
/// be prepared (unreadable, no such segment, no spring constant) gets the status unreadable and its
/// reason; a fit whose standard error of E exceeds E (the curve does not determine it) is
/// not-converged with the reason "undetermined: ...". Safe to call from several threads.
CurveFit fit_curve(const measured::MeasuredFile& file, std::size_t index,
                   measured::SegmentKind segment, const CurveFitOptions& options);

/// Refuses the file (SceneError, one line naming it and its first curve's reason) when none of
/// its curves can be prepared for a fit: what fit_file and the map runner do before any fit.
void check_fittable(const measured::MeasuredFile& file, measured::SegmentKind segment);

/// Fits the first segment of `segment` kind of every curve (or its approach and retract
/// together, options.both_segments), inside options.range where given. A curve that cannot be
/// prepared (unreadable, no such segment, no spring constant) gets the status unreadable and its
/// reason; the file is refused (SceneError, one line naming it) when it holds no curve that could.
std::vector<CurveFit> fit_file(const measured::MeasuredFile& file, measured::SegmentKind segment,
                               const CurveFitOptions& options);

/// The fit as one JSON object; a parameter that has no value (no contact) is null.
nlohmann::ordered_json curve_fit_json(const CurveFit& fit, const CurveFitOptions& options,
                                      measured::SegmentKind segment);

/// The CSV header and one row per curve (the map position in x, y, index and the grid's
/// column, row); the adhesive models' columns come last, empty for hertz, then the Maugis
/// parameter and auto's pick.
std::string curve_fit_csv_header();
std::string curve_fit_csv_row(const CurveFit& fit, FitModel model, bool both_segments = false);

/// "FILE[curve]: fitted E = ... Pa +- ..., contact point ..., rms ... N" (and w, the adhesion
/// forces for dmt, jkr and maugis; lambda for maugis; auto's pick and why for auto).
std::string curve_fit_summary(const CurveFit& fit, FitModel model);

/// "FILE[curve]: warning: ..." for each of the fit's warnings, each line ending in '\n' (""
/// without warnings): what `mdrsim fit` prints after the fit's line.
std::string curve_fit_warning_lines(const CurveFit& fit);

}  // namespace mdrsim::fit
