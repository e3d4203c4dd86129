// Every curve of a measured file fitted, each with its status, and the fits as JSON, CSV and
// a summary line.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "engine/fit/hertz_fit.hpp"
#include "engine/measured/force_curve.hpp"

namespace mdrsim::fit {

/// One curve's fit with where it came from and the calibration it used.
struct CurveFit {
  std::string file;
  std::string curve;  ///< the curve's label in its file ("" for a file of one curve)
  std::optional<measured::MapPosition> position;
  measured::Calibration calibration;
  std::string height_channel;  ///< the channel the tip position was made from
  HertzFit fit;
};

/// Fits the first segment of `segment` kind of every curve. A curve that cannot be prepared
/// (unreadable, no such segment, no spring constant) gets the status unreadable and its reason;
/// the file is refused (SceneError, one line naming it) when it holds no curve that could.
std::vector<CurveFit> fit_file(const measured::MeasuredFile& file, measured::SegmentKind segment,
                               const HertzFitOptions& options);

/// The fit as one JSON object; a parameter that has no value (no contact) is null.
nlohmann::ordered_json curve_fit_json(const CurveFit& fit, const HertzFitOptions& options,
                                      measured::SegmentKind segment);

/// The CSV header and one row per curve (the map position in x, y, index).
std::string curve_fit_csv_header();
std::string curve_fit_csv_row(const CurveFit& fit);

/// "FILE[curve]: fitted E = ... Pa +- ..., contact point ..., rms ... N".
std::string curve_fit_summary(const CurveFit& fit);

}  // namespace mdrsim::fit
