// The fit of every curve of a file, and its JSON, CSV and summary forms.
#include "engine/fit/fit_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <exception>
#include <string>
#include <utility>

#include "engine/fit/prepared_curve.hpp"
#include "engine/measured/measured_error.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::fit {
namespace {

bool with_lambda(FitModel model) {
  return model == FitModel::maugis || model == FitModel::automatic;
}

bool has_values(const HertzFit& fit) {
  return fit.status == FitStatus::fitted || fit.status == FitStatus::not_converged;
}

nlohmann::ordered_json parameter_json(const FitParameter& p, bool valued) {
  nlohmann::ordered_json out;
  out["value"] = valued || p.fixed ? nlohmann::ordered_json(p.value) : nlohmann::ordered_json();
  out["standard_error"] =
      valued ? nlohmann::ordered_json(p.standard_error) : nlohmann::ordered_json();
  out["fixed"] = p.fixed;
  return out;
}

nlohmann::ordered_json calibrated_json(const std::optional<measured::Calibrated>& value) {
  if (!value) return nullptr;
  return {{"value", value->value}, {"source", value->source}};
}

std::string csv_cell(double value, bool valued) { return valued ? fmt::format("{}", value) : ""; }

/// A text cell quoted where it holds a comma, quote or line break (RFC 4180).
std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

AdhesiveFit fit_one(const PreparedSegment& prepared, measured::SegmentKind segment,
                    const CurveFitOptions& options) {
  if (options.model == FitModel::hertz) {
    HertzFitOptions hertz;
    hertz.tip = options.tip;
    hertz.poisson_ratio = options.poisson_ratio;
    hertz.fixed = options.fixed;
    hertz.far_first = segment == measured::SegmentKind::approach;
    AdhesiveFit out;
    static_cast<HertzFit&>(out) = fit_hertz(prepared, hertz);
    return out;
  }
  if (with_lambda(options.model)) {
    MaugisFitOptions maugis;
    maugis.tip = options.tip;
    maugis.poisson_ratio = options.poisson_ratio;
    maugis.fixed = options.fixed;
    maugis.retract = segment == measured::SegmentKind::retract;
    return fit_maugis(prepared, maugis);
  }
  AdhesiveFitOptions adhesive;
  adhesive.model = options.model == FitModel::dmt ? AdhesionModel::dmt : AdhesionModel::jkr;
  adhesive.tip = options.tip;
  adhesive.poisson_ratio = options.poisson_ratio;
  adhesive.fixed = options.fixed;
  adhesive.retract = segment == measured::SegmentKind::retract;
  return fit_adhesive(prepared, adhesive);
}

/// Why a free parameter is not determined by the curve ("" where it is): a J^T J singular in
/// it (its standard error 0 with residuals that are not: a claim of exactness), or, where
/// `error_above_value` is set, a standard error above its value (or not finite).
std::string undetermined(const FitParameter& p, const char* name, const char* unit,
                         double residual_rms, bool error_above_value) {
  if (p.fixed) return {};
  if (p.standard_error == 0.0 && residual_rms > 0.0) {
    return fmt::format("J^T J is singular in {}", name);
  }
  if (error_above_value &&
      !(std::isfinite(p.standard_error) && p.standard_error <= std::abs(p.value))) {
    return fmt::format("the standard error of {} ({:.3g} {}) exceeds its value", name,
                       p.standard_error, unit);
  }
  return {};
}

/// A fit has not found E when the curve does not determine it: no sample indented past the
/// fitted contact point, or undetermined() above. An adhesive model's work of adhesion is
/// undetermined only where J^T J is singular in it: a standard error above a small work says
/// the curve shows no measurable adhesion, which is a result. (The Maugis parameter is left
/// out: a lambda that runs off to the JKR limit is what `auto` reads as JKR.) It keeps its
/// numbers, as not-converged, with the reason.
void mark_undetermined(CombinedFit& fit, const CurveFitOptions& options) {
  if (fit.status != FitStatus::fitted) return;
  const double rms = fit.residual_rms;
  std::string why;
  if (!fit.youngs_modulus.fixed && !(fit.max_indentation > 0.0)) {
    why = "no sample is indented past the contact point";
  } else {
    why = undetermined(fit.youngs_modulus, "youngs_modulus", "Pa", rms, true);
  }
  if (why.empty() && options.model != FitModel::hertz) {
    why = undetermined(fit.work_of_adhesion, "work_of_adhesion", "J/m^2", rms, false);
    if (why.empty() && options.both_segments) {
      why = undetermined(fit.approach_work_of_adhesion, "approach_work_of_adhesion", "J/m^2", rms,
                         false);
    }
  }
  if (why.empty()) return;
  fit.status = FitStatus::not_converged;
  fit.message = "undetermined: " + why;
}

/// The grid cell holding `position`, or none where it lies outside the grid or the grid has
/// no extent.
std::optional<GridCell> grid_cell(const measured::MapGrid& grid,
                                  const measured::MapPosition& position) {
  if (grid.columns <= 0 || grid.rows <= 0 || !(grid.width > 0.0) || !(grid.height > 0.0)) {
    return std::nullopt;
  }
  // Positions are the cells' centres: the floor is half a cell from either edge.
  const double u = (position.x - (grid.center_x - grid.width / 2)) / (grid.width / grid.columns);
  const double v = (position.y - (grid.center_y - grid.height / 2)) / (grid.height / grid.rows);
  if (!(u >= 0.0 && u < grid.columns && v >= 0.0 && v < grid.rows)) return std::nullopt;
  return GridCell{static_cast<long>(std::floor(u)), static_cast<long>(std::floor(v))};
}

/// fit_one inside the indentation range: the samples chosen from the contact point's first
/// guess (or its held value), then once more from the fitted one where that chose others.
AdhesiveFit fit_in_range(const PreparedSegment& prepared, measured::SegmentKind segment,
                         const CurveFitOptions& options) {
  if (!options.range) return fit_one(prepared, segment, options);
  double contact = 0.0;
  if (options.fixed.contact_point) {
    contact = *options.fixed.contact_point;
  } else {
    const FirstGuess guess = first_guess(prepared, options.tip, options.poisson_ratio,
                                         segment == measured::SegmentKind::approach);
    if (!guess.contact) return fit_one(prepared, segment, options);
    contact = guess.contact_point;
  }
  PreparedSegment part = within_range(prepared, contact, *options.range);
  AdhesiveFit fit = fit_one(part, segment, options);
  if (!options.fixed.contact_point && has_values(fit)) {
    PreparedSegment again = within_range(prepared, fit.contact_point.value, *options.range);
    if (again.tip_position != part.tip_position) fit = fit_one(again, segment, options);
  }
  return fit;
}

CombinedFit fit_both(const PreparedSegment& approach, const PreparedSegment& retract,
                     const CurveFitOptions& options) {
  CombinedFitOptions both;
  both.adhesive = options.model != FitModel::hertz;
  both.model = options.model == FitModel::dmt ? AdhesionModel::dmt : AdhesionModel::jkr;
  both.tip = options.tip;
  both.poisson_ratio = options.poisson_ratio;
  both.fixed = options.fixed;
  both.approach_work_of_adhesion = options.approach_work_of_adhesion;
  both.maugis = options.model == FitModel::maugis;
  if (!options.range) return fit_combined(approach, retract, both);
  double contact = 0.0;
  if (options.fixed.contact_point) {
    contact = *options.fixed.contact_point;
  } else {
    const FirstGuess guess = first_guess(approach, options.tip, options.poisson_ratio, true);
    if (!guess.contact) return fit_combined(approach, retract, both);
    contact = guess.contact_point;
  }
  const auto fit_at = [&](double c) {
    return fit_combined(within_range(approach, c, *options.range),
                        within_range(retract, c, *options.range), both);
  };
  CombinedFit fit = fit_at(contact);
  if (!options.fixed.contact_point && has_values(fit)) {
    const double moved = fit.contact_point.value;
    if (within_range(approach, moved, *options.range).tip_position !=
            within_range(approach, contact, *options.range).tip_position ||
        within_range(retract, moved, *options.range).tip_position !=
            within_range(retract, contact, *options.range).tip_position) {
      fit = fit_at(moved);
    }
  }
  return fit;
}

/// The fit's warnings over the samples it was given: each segment inside the range as the
/// fitted contact point chooses them (the choice the fit ended on).
std::vector<std::string> warnings_of(const AdhesiveFit& fit, const CurveFitOptions& options,
                                     const PreparedSegment* approach,
                                     const PreparedSegment* retract) {
  if (fit.status != FitStatus::fitted) return {};
  std::optional<PreparedSegment> approach_part, retract_part;
  if (options.range) {
    if (approach) {
      approach =
          &approach_part.emplace(within_range(*approach, fit.contact_point.value, *options.range));
    }
    if (retract) {
      retract =
          &retract_part.emplace(within_range(*retract, fit.contact_point.value, *options.range));
    }
  }
  const double reach =
      fitted_reach(fit, options.tip, options.poisson_ratio, with_lambda(options.model));
  return fit_warnings({approach, retract}, fit, reach, options.model != FitModel::hertz);
}

/// The hysteresis of a curve that has both segments, less the approach's baseline; nullopt
/// where it has not both.
std::optional<double> curve_hysteresis(const measured::ForceCurve& curve,
                                       const CurveFitOptions& options) {
  try {
    const PreparedSegment approach = prepare_segment(curve, measured::SegmentKind::approach);
    const PreparedSegment retract = prepare_segment(curve, measured::SegmentKind::retract);
    const FirstGuess guess = first_guess(approach, options.tip, options.poisson_ratio, true);
    const double energy = hysteresis_energy(approach, retract, guess.contact_point,
                                            guess.baseline_offset, guess.baseline_slope);
    if (!std::isfinite(energy)) return std::nullopt;
    return energy;
  } catch (const SceneError&) {
    return std::nullopt;
  }
}

}  // namespace

const char* fit_model_name(FitModel model) {
  switch (model) {
    case FitModel::hertz:
      return "hertz";
    case FitModel::dmt:
      return "dmt";
    case FitModel::jkr:
      return "jkr";
    case FitModel::maugis:
      return "maugis";
    case FitModel::automatic:
      return "auto";
  }
  return "hertz";
}

CurveFit fit_curve(const measured::MeasuredFile& file, std::size_t index,
                   measured::SegmentKind segment, const CurveFitOptions& options) {
  const measured::ForceCurve& curve = file.curves.at(index);
  CurveFit out;
  out.file = file.path.string();
  out.curve = curve.label;
  out.position = curve.position;
  if (curve.position && file.grid) out.cell = grid_cell(*file.grid, *curve.position);
  out.calibration = curve.calibration;
  out.fit.status = FitStatus::unreadable;
  if (!curve.unreadable.empty()) {
    out.fit.message = curve.unreadable;
    return out;
  }
  try {
    if (options.both_segments) {
      const PreparedSegment approach = prepare_segment(curve, measured::SegmentKind::approach);
      const PreparedSegment retract = prepare_segment(curve, measured::SegmentKind::retract);
      out.height_channel = approach.height_channel;
      out.fit = fit_both(approach, retract, options);
      mark_undetermined(out.fit, options);
      out.warnings = warnings_of(out.fit, options, &approach, &retract);
    } else {
      const PreparedSegment prepared = prepare_segment(curve, segment);
      out.height_channel = prepared.height_channel;
      static_cast<AdhesiveFit&>(out.fit) = fit_in_range(prepared, segment, options);
      mark_undetermined(out.fit, options);
      const bool retract = segment == measured::SegmentKind::retract;
      out.warnings = warnings_of(out.fit, options, retract ? nullptr : &prepared,
                                 retract ? &prepared : nullptr);
    }
    out.hysteresis_energy = curve_hysteresis(curve, options);
  } catch (const SceneError& e) {
    out.fit.message = curve.label.empty() ? e.what() : curve.label + ": " + e.what();
  } catch (const std::exception& e) {
    // The model itself refused a trial (a sphere indented past its radius): this curve's
    // fit failed, the map goes on.
    out.fit = CombinedFit();
    out.fit.status = FitStatus::not_converged;
    out.fit.message = std::string("the model failed: ") + e.what();
  }
  return out;
}

void check_fittable(const measured::MeasuredFile& file, measured::SegmentKind segment) {
  std::string first_refusal;
  for (const measured::ForceCurve& curve : file.curves) {
    std::string refusal = curve.unreadable;
    if (refusal.empty()) {
      try {
        prepare_segment(curve, segment);
        return;
      } catch (const SceneError& e) {
        refusal = curve.label.empty() ? e.what() : curve.label + ": " + e.what();
      }
    }
    if (first_refusal.empty()) first_refusal = refusal;
  }
  measured::refuse(file.path, "{}", first_refusal);
}

std::vector<CurveFit> fit_file(const measured::MeasuredFile& file, measured::SegmentKind segment,
                               const CurveFitOptions& options) {
  check_fittable(file, segment);
  std::vector<CurveFit> fits;
  fits.reserve(file.curves.size());
  for (std::size_t c = 0; c < file.curves.size(); ++c) {
    fits.push_back(fit_curve(file, c, segment, options));
  }
  return fits;
}

nlohmann::ordered_json curve_fit_json(const CurveFit& fit, const CurveFitOptions& options,
                                      measured::SegmentKind segment) {
  const bool valued = has_values(fit.fit);
  nlohmann::ordered_json out;
  out["file"] = fit.file;
  out["curve"] = fit.curve;
  if (fit.position) {
    out["position"] = {
        {"x", fit.position->x}, {"y", fit.position->y}, {"index", fit.position->index}};
    if (fit.cell) {
      out["position"]["column"] = fit.cell->column;
      out["position"]["row"] = fit.cell->row;
    }
  }
  out["status"] = fit_status_name(fit.fit.status);
  if (!fit.fit.message.empty()) out["message"] = fit.fit.message;
  out["model"] = fit_model_name(options.model);
  out["tip"] = options.tip.text;
  if (!options.tip.approximation.empty()) out["tip_approximation"] = options.tip.approximation;
  out["segment"] = options.both_segments ? "both" : measured::segment_kind_name(segment);
  if (options.range) out["range"] = {options.range->from, options.range->to};
  out["poisson_ratio"] = options.poisson_ratio;
  out["youngs_modulus"] = parameter_json(fit.fit.youngs_modulus, valued);
  if (options.model != FitModel::hertz) {
    out["work_of_adhesion"] = parameter_json(fit.fit.work_of_adhesion, valued);
    if (options.both_segments) {
      out["approach_work_of_adhesion"] = parameter_json(fit.fit.approach_work_of_adhesion, valued);
    }
  }
  if (with_lambda(options.model)) {
    out["maugis_parameter"] = parameter_json(fit.fit.maugis_parameter, valued);
  }
  // auto picks from a fitted lambda only (not-converged values are no basis for a choice).
  if (options.model == FitModel::automatic && fit.fit.status == FitStatus::fitted) {
    const RegimeChoice choice = choose_regime(fit.fit.maugis_parameter.value);
    out["auto"] = {{"picked", choice.model}, {"reason", choice.reason}};
  }
  out["contact_point"] = parameter_json(fit.fit.contact_point, valued);
  out["baseline_offset"] = parameter_json(fit.fit.baseline_offset, valued);
  out["baseline_slope"] = parameter_json(fit.fit.baseline_slope, valued);
  out["residual_rms"] = valued ? nlohmann::ordered_json(fit.fit.residual_rms) : nullptr;
  out["max_indentation"] = valued ? nlohmann::ordered_json(fit.fit.max_indentation) : nullptr;
  if (options.model != FitModel::hertz) {
    out["adhesion_force"] = {
        {"fitted", valued ? nlohmann::ordered_json(fit.fit.adhesion_force_fitted) : nullptr},
        {"measured", valued ? nlohmann::ordered_json(fit.fit.adhesion_force_measured) : nullptr}};
    out["contact_samples"] = fit.fit.contact_samples;
  }
  out["hysteresis_energy"] =
      fit.hysteresis_energy ? nlohmann::ordered_json(*fit.hysteresis_energy) : nullptr;
  out["points"] = fit.fit.points;
  out["iterations"] = fit.fit.iterations;
  out["warnings"] = fit.warnings;
  out["tip_position_from"] = fit.height_channel;
  out["calibration"] = {{"spring_constant", calibrated_json(fit.calibration.spring_constant)},
                        {"sensitivity", calibrated_json(fit.calibration.sensitivity)}};
  return out;
}

std::string curve_fit_csv_header() {
  return "file,curve,x,y,index,column,row,status,youngs_modulus,youngs_modulus_error,contact_point,"
         "contact_point_error,baseline_offset,baseline_offset_error,baseline_slope,"
         "baseline_slope_error,residual_rms,max_indentation,points,spring_constant,sensitivity,"
         "model,"
         "work_of_adhesion,work_of_adhesion_error,adhesion_force_fitted,adhesion_force_measured,"
         "approach_work_of_adhesion,approach_work_of_adhesion_error,hysteresis_energy,"
         "maugis_parameter,maugis_parameter_error,auto_model,warnings";
}

std::string curve_fit_csv_row(const CurveFit& fit, FitModel model, bool both_segments) {
  const bool valued = has_values(fit.fit);
  const CombinedFit& f = fit.fit;
  std::string row = fmt::format("{},{},", csv_text(fit.file), csv_text(fit.curve));
  row += fit.position
             ? fmt::format("{},{},{},", fit.position->x, fit.position->y, fit.position->index)
             : ",,,";
  row += fit.cell ? fmt::format("{},{},", fit.cell->column, fit.cell->row) : ",,";
  row += fit_status_name(f.status);
  for (const FitParameter* p :
       {&f.youngs_modulus, &f.contact_point, &f.baseline_offset, &f.baseline_slope}) {
    row += fmt::format(",{},{}", csv_cell(p->value, valued || p->fixed),
                       csv_cell(p->standard_error, valued));
  }
  row += fmt::format(",{},{},{},", csv_cell(f.residual_rms, valued),
                     csv_cell(f.max_indentation, valued), f.points);
  row += fit.calibration.spring_constant ? fmt::format("{}", fit.calibration.spring_constant->value)
                                         : "";
  row += ",";
  row += fit.calibration.sensitivity ? fmt::format("{}", fit.calibration.sensitivity->value) : "";
  row += fmt::format(",{}", fit_model_name(model));
  const bool adhesive = model != FitModel::hertz;
  row += fmt::format(
      ",{},{},{},{}",
      csv_cell(f.work_of_adhesion.value, adhesive && (valued || f.work_of_adhesion.fixed)),
      csv_cell(f.work_of_adhesion.standard_error, adhesive && valued),
      csv_cell(f.adhesion_force_fitted, adhesive && valued),
      csv_cell(f.adhesion_force_measured, adhesive && valued));
  const bool approach_work = adhesive && both_segments;
  row += fmt::format(",{},{},{}",
                     csv_cell(f.approach_work_of_adhesion.value,
                              approach_work && (valued || f.approach_work_of_adhesion.fixed)),
                     csv_cell(f.approach_work_of_adhesion.standard_error, approach_work && valued),
                     fit.hysteresis_energy ? fmt::format("{}", *fit.hysteresis_energy) : "");
  const bool lambda = with_lambda(model);
  row += fmt::format(
      ",{},{},{}",
      csv_cell(f.maugis_parameter.value, lambda && (valued || f.maugis_parameter.fixed)),
      csv_cell(f.maugis_parameter.standard_error, lambda && valued),
      model == FitModel::automatic && f.status == FitStatus::fitted
          ? choose_regime(f.maugis_parameter.value).model
          : "");
  row += "," + csv_text(fmt::format("{}", fmt::join(fit.warnings, "; ")));
  return row;
}

std::string curve_fit_summary(const CurveFit& fit, FitModel model) {
  const std::string where =
      fit.curve.empty() ? fit.file : fmt::format("{}[{}]", fit.file, fit.curve);
  const CombinedFit& f = fit.fit;
  if (!has_values(f))
    return fmt::format("{}: {} ({})", where, fit_status_name(f.status), f.message);
  std::string line = fmt::format(
      "{}: {} E = {:.6g} +- {:.2g} Pa, contact point = {:.9g} +- {:.2g} m, baseline = {:.4g} N "
      "{:+.4g} N/m (z - contact point), rms = {:.3g} N over {} points",
      where, fit_status_name(f.status), f.youngs_modulus.value, f.youngs_modulus.standard_error,
      f.contact_point.value, f.contact_point.standard_error, f.baseline_offset.value,
      f.baseline_slope.value, f.residual_rms, f.points);
  if (model != FitModel::hertz) {
    line += fmt::format(
        ", {} w = {:.4g} +- {:.2g} J/m^2, adhesion force = {:.4g} N fitted, {:.4g} N measured",
        fit_model_name(model), f.work_of_adhesion.value, f.work_of_adhesion.standard_error,
        f.adhesion_force_fitted, f.adhesion_force_measured);
  }
  if (f.approach_work_of_adhesion.value > 0.0) {
    line += fmt::format(", approach w = {:.4g} +- {:.2g} J/m^2", f.approach_work_of_adhesion.value,
                        f.approach_work_of_adhesion.standard_error);
  }
  if (fit.hysteresis_energy) line += fmt::format(", hysteresis = {:.4g} J", *fit.hysteresis_energy);
  if (with_lambda(model)) {
    line += fmt::format(", lambda = {:.4g} +- {:.2g}", f.maugis_parameter.value,
                        f.maugis_parameter.standard_error);
  }
  if (model == FitModel::automatic && f.status == FitStatus::fitted) {
    line += fmt::format(" ({})", choose_regime(f.maugis_parameter.value).reason);
  }
  if (!f.message.empty()) line += fmt::format(" ({})", f.message);
  return line;
}

std::string curve_fit_warning_lines(const CurveFit& fit) {
  const std::string where =
      fit.curve.empty() ? fit.file : fmt::format("{}[{}]", fit.file, fit.curve);
  std::string lines;
  for (const std::string& warning : fit.warnings) {
    lines += fmt::format("{}: warning: {}\n", where, warning);
  }
  return lines;
}

}  // namespace mdrsim::fit
