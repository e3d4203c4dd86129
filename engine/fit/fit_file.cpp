// The fit of every curve of a file, and its JSON, CSV and summary forms.
#include "engine/fit/fit_file.hpp"

#include <fmt/format.h>

#include <utility>

#include "engine/fit/prepared_curve.hpp"
#include "engine/measured/measured_error.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::fit {
namespace {

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
  AdhesiveFitOptions adhesive;
  adhesive.model = options.model == FitModel::dmt ? AdhesionModel::dmt : AdhesionModel::jkr;
  adhesive.tip = options.tip;
  adhesive.poisson_ratio = options.poisson_ratio;
  adhesive.fixed = options.fixed;
  adhesive.retract = segment == measured::SegmentKind::retract;
  return fit_adhesive(prepared, adhesive);
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
  }
  return "hertz";
}

std::vector<CurveFit> fit_file(const measured::MeasuredFile& file, measured::SegmentKind segment,
                               const CurveFitOptions& options) {
  std::vector<CurveFit> fits;
  std::string first_refusal;
  bool any_prepared = false;
  for (const measured::ForceCurve& curve : file.curves) {
    CurveFit out;
    out.file = file.path.string();
    out.curve = curve.label;
    out.position = curve.position;
    out.calibration = curve.calibration;
    out.fit.status = FitStatus::unreadable;
    if (!curve.unreadable.empty()) {
      out.fit.message = curve.unreadable;
    } else {
      try {
        const PreparedSegment prepared = prepare_segment(curve, segment);
        out.height_channel = prepared.height_channel;
        out.fit = fit_one(prepared, segment, options);
        any_prepared = true;
      } catch (const SceneError& e) {
        out.fit.message = curve.label.empty() ? e.what() : curve.label + ": " + e.what();
      }
    }
    if (out.fit.status == FitStatus::unreadable && first_refusal.empty()) {
      first_refusal = out.fit.message;
    }
    fits.push_back(std::move(out));
  }
  if (!any_prepared) measured::refuse(file.path, "{}", first_refusal);
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
  }
  out["status"] = fit_status_name(fit.fit.status);
  if (!fit.fit.message.empty()) out["message"] = fit.fit.message;
  out["model"] = fit_model_name(options.model);
  out["tip"] = options.tip.text;
  out["segment"] = measured::segment_kind_name(segment);
  out["poisson_ratio"] = options.poisson_ratio;
  out["youngs_modulus"] = parameter_json(fit.fit.youngs_modulus, valued);
  if (options.model != FitModel::hertz) {
    out["work_of_adhesion"] = parameter_json(fit.fit.work_of_adhesion, valued);
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
  out["points"] = fit.fit.points;
  out["iterations"] = fit.fit.iterations;
  out["tip_position_from"] = fit.height_channel;
  out["calibration"] = {{"spring_constant", calibrated_json(fit.calibration.spring_constant)},
                        {"sensitivity", calibrated_json(fit.calibration.sensitivity)}};
  return out;
}

std::string curve_fit_csv_header() {
  return "file,curve,x,y,index,status,youngs_modulus,youngs_modulus_error,contact_point,"
         "contact_point_error,baseline_offset,baseline_offset_error,baseline_slope,"
         "baseline_slope_error,residual_rms,max_indentation,points,spring_constant,sensitivity,"
         "model,"
         "work_of_adhesion,work_of_adhesion_error,adhesion_force_fitted,adhesion_force_measured";
}

std::string curve_fit_csv_row(const CurveFit& fit, FitModel model) {
  const bool valued = has_values(fit.fit);
  const AdhesiveFit& f = fit.fit;
  std::string row = fmt::format("{},{},", csv_text(fit.file), csv_text(fit.curve));
  row += fit.position
             ? fmt::format("{},{},{},", fit.position->x, fit.position->y, fit.position->index)
             : ",,,";
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
  return row;
}

std::string curve_fit_summary(const CurveFit& fit, FitModel model) {
  const std::string where =
      fit.curve.empty() ? fit.file : fmt::format("{}[{}]", fit.file, fit.curve);
  const AdhesiveFit& f = fit.fit;
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
  if (!f.message.empty()) line += fmt::format(" ({})", f.message);
  return line;
}

}  // namespace mdrsim::fit
