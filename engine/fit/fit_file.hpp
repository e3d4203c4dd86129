// Every curve of a measured file fitted, each with its status, and the fits as JSON, CSV and
// a summary line.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/hertz_fit.hpp"
#include "engine/measured/force_curve.hpp"

namespace mdrsim::fit {

enum class FitModel { hertz, dmt, jkr };

/// "hertz", "dmt", "jkr".
const char* fit_model_name(FitModel model);

/// What `mdrsim fit` asks of every curve: the model, the tip and the held parameters.
struct CurveFitOptions {
  FitModel model = FitModel::hertz;
  TipShape tip;
  double poisson_ratio = 0.5;
  AdhesiveFixed fixed;  ///< work_of_adhesion is ignored by hertz
};

/// One curve's fit with where it came from and the calibration it used.
struct CurveFit {
  std::string file;
  std::string curve;  ///< the curve's label in its file ("" for a file of one curve)
  std::optional<measured::MapPosition> position;
  measured::Calibration calibration;
  std::string height_channel;  ///< the channel the tip position was made from
  AdhesiveFit fit;             ///< for hertz, work_of_adhesion and the adhesion forces stay 0
};

/// Fits the first segment of `segment` kind of every curve. A curve that cannot be prepared
/// (unreadable, no such segment, no spring constant) gets the status unreadable and its reason;
/// the file is refused (SceneError, one line naming it) when it holds no curve that could.
std::vector<CurveFit> fit_file(const measured::MeasuredFile& file, measured::SegmentKind segment,
                               const CurveFitOptions& options);

/// The fit as one JSON object; a parameter that has no value (no contact) is null.
nlohmann::ordered_json curve_fit_json(const CurveFit& fit, const CurveFitOptions& options,
                                      measured::SegmentKind segment);

/// The CSV header and one row per curve (the map position in x, y, index); the adhesive
/// models' columns come last, empty for hertz.
std::string curve_fit_csv_header();
std::string curve_fit_csv_row(const CurveFit& fit, FitModel model);

/// "FILE[curve]: fitted E = ... Pa +- ..., contact point ..., rms ... N" (and w, the adhesion
/// forces for dmt and jkr).
std::string curve_fit_summary(const CurveFit& fit, FitModel model);

}  // namespace mdrsim::fit
