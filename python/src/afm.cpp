// mdrsim._core's measured force curves: the readers' curves as NumPy arrays, and one curve fitted
// by engine/fit, its JSON the same text as `mdrsim fit --json` writes.
#include "python/src/afm.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/base/text.hpp"
#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/fit_file.hpp"
#include "engine/fit/maugis_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"
#include "engine/measured/read_force_curves.hpp"
#include "engine/scene/scene_error.hpp"

namespace py = pybind11;

namespace mdrsim::python {
namespace {

constexpr const char* kFitParameters =
    "youngs_modulus, work_of_adhesion, maugis_parameter, contact_point, baseline_offset, "
    "baseline_slope";

/// One curve of a file read once; the file stays alive while any of its curves does.
struct CurveHandle {
  std::shared_ptr<const measured::MeasuredFile> file;
  std::size_t index = 0;
  const measured::ForceCurve& curve() const { return file->curves[index]; }
};

py::object array_or_none(const std::vector<double>& values) {
  if (values.empty()) return py::none();
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::object calibrated(const std::optional<measured::Calibrated>& value) {
  if (!value) return py::none();
  py::dict out;
  out["value"] = value->value;
  out["source"] = value->source;
  return out;
}

/// The segment's tip position and force as the fit prepares them (engine/fit's one rule:
/// height + deflection, force = deflection x spring constant where the file gives none), or
/// None where the segment lacks what they need.
std::pair<py::object, py::object> prepared_channels(const measured::ForceCurve& curve,
                                                    const measured::Segment& segment) {
  measured::ForceCurve alone;
  alone.calibration = curve.calibration;
  alone.segments.push_back(segment);
  try {
    const fit::PreparedSegment prepared = fit::prepare_segment(alone, segment.kind);
    return {array_or_none(prepared.tip_position), array_or_none(prepared.force)};
  } catch (const SceneError&) {
    return {py::none(), py::none()};
  }
}

py::dict segment_dict(const measured::ForceCurve& curve, const measured::Segment& segment) {
  py::dict out;
  out["name"] = segment.name;
  out["kind"] = measured::segment_kind_name(segment.kind);
  out["time"] = array_or_none(segment.time);
  out["piezo_height"] = array_or_none(segment.piezo_height);
  out["measured_height"] = array_or_none(segment.measured_height);
  out["deflection"] = array_or_none(segment.deflection);
  auto [tip_position, force] = prepared_channels(curve, segment);
  out["tip_position"] =
      segment.tip_position.empty() ? tip_position : array_or_none(segment.tip_position);
  out["force"] = segment.force.empty() ? force : array_or_none(segment.force);
  return out;
}

py::dict curve_dict(const CurveHandle& handle) {
  const measured::ForceCurve& curve = handle.curve();
  py::dict out;
  out["handle"] = handle;
  out["label"] = curve.label;
  out["unreadable"] = curve.unreadable;
  py::dict calibration;
  calibration["spring_constant"] = calibrated(curve.calibration.spring_constant);
  calibration["sensitivity"] = calibrated(curve.calibration.sensitivity);
  calibration["approach_speed"] = calibrated(curve.calibration.approach_speed);
  calibration["retract_speed"] = calibrated(curve.calibration.retract_speed);
  out["calibration"] = calibration;
  if (curve.position) {
    out["position"] = py::make_tuple(curve.position->x, curve.position->y, curve.position->index);
  } else {
    out["position"] = py::none();
  }
  py::list segments;
  for (const measured::Segment& segment : curve.segments) {
    segments.append(segment_dict(curve, segment));
  }
  out["segments"] = segments;
  return out;
}

py::dict read_file(const std::string& path, std::optional<double> sensitivity,
                   std::optional<double> spring_constant) {
  measured::CalibrationOverride overrides;
  overrides.sensitivity = sensitivity;
  overrides.spring_constant = spring_constant;
  std::shared_ptr<const measured::MeasuredFile> file;
  {
    py::gil_scoped_release release;
    file = std::make_shared<const measured::MeasuredFile>(
        measured::read_force_curves(path, overrides));
  }
  py::dict out;
  out["path"] = file->path.string();
  out["format"] = file->format;
  if (file->grid) {
    py::dict grid;
    grid["columns"] = file->grid->columns;
    grid["rows"] = file->grid->rows;
    grid["width"] = file->grid->width;
    grid["height"] = file->grid->height;
    grid["center_x"] = file->grid->center_x;
    grid["center_y"] = file->grid->center_y;
    out["grid"] = grid;
  } else {
    out["grid"] = py::none();
  }
  py::list curves;
  for (std::size_t i = 0; i < file->curves.size(); ++i) curves.append(curve_dict({file, i}));
  out["curves"] = curves;
  return out;
}

fit::FitModel parse_model(const std::string& model) {
  if (model == "hertz") return fit::FitModel::hertz;
  if (model == "dmt") return fit::FitModel::dmt;
  if (model == "jkr") return fit::FitModel::jkr;
  if (model == "maugis") return fit::FitModel::maugis;
  if (model == "auto") return fit::FitModel::automatic;
  throw SceneError(fmt::format("model '{}': unknown (known: hertz, dmt, jkr, maugis, auto)",
                               printable(model, 40)));
}

measured::SegmentKind parse_segment(const std::string& segment) {
  if (segment == "approach") return measured::SegmentKind::approach;
  if (segment == "retract") return measured::SegmentKind::retract;
  throw SceneError(
      fmt::format("segment '{}': unknown (known: approach, retract)", printable(segment, 40)));
}

/// `fix` as the command's --fix reads it, less the calibration, which a file is read with.
fit::AdhesiveFixed parse_fixed(const std::map<std::string, double>& fix, fit::FitModel model) {
  fit::AdhesiveFixed fixed;
  for (const auto& [name, value] : fix) {
    if (!std::isfinite(value)) {
      throw SceneError(
          fmt::format("fix {}: {} is not a finite number", printable(name, 40), value));
    }
    const auto positive = [&] {
      if (!(value > 0.0)) throw SceneError(fmt::format("fix {}: must be > 0", name));
    };
    if (name == "youngs_modulus") {
      positive();
      fixed.youngs_modulus = value;
    } else if (name == "contact_point") {
      fixed.contact_point = value;
    } else if (name == "baseline_offset") {
      fixed.baseline_offset = value;
    } else if (name == "baseline_slope") {
      fixed.baseline_slope = value;
    } else if (name == "work_of_adhesion" && model != fit::FitModel::hertz) {
      positive();
      fixed.work_of_adhesion = value;
    } else if (name == "maugis_parameter" &&
               (model == fit::FitModel::maugis || model == fit::FitModel::automatic)) {
      positive();
      fixed.maugis_parameter = value;
    } else if (name == "work_of_adhesion" || name == "maugis_parameter") {
      throw SceneError(
          fmt::format("fix {}: not a parameter of model '{}'", name, fit::fit_model_name(model)));
    } else if (name == "spring_constant" || name == "sensitivity") {
      throw SceneError(fmt::format(
          "fix {0}: a calibration, given when the file is read (mdrsim.afm.load(path, {0}=...))",
          name));
    } else {
      throw SceneError(
          fmt::format("fix {}: unknown (known: {})", printable(name, 40), kFitParameters));
    }
  }
  return fixed;
}

/// The fitted model at every sample, for plotting: the baseline, and the contact force on
/// the samples the fit took as in contact (an adhesive fit's contact_samples, at the deepest
/// end of the segment).
std::vector<double> fitted_force(const fit::CurveFitOptions& options, const fit::AdhesiveFit& f,
                                 const std::vector<double>& z, bool retract) {
  std::vector<double> out(z.size(), 0.0);
  const double cp = f.contact_point.value;
  if (options.model == fit::FitModel::hertz) {
    for (std::size_t i = 0; i < z.size(); ++i) {
      out[i] = fit::hertz_force(options.tip, options.poisson_ratio, f, z[i]);
    }
    return out;
  }
  const double reduced =
      f.youngs_modulus.value / (1.0 - options.poisson_ratio * options.poisson_ratio);
  const double work = f.work_of_adhesion.value;
  const std::size_t n = z.size();
  const std::size_t contact = std::min(f.contact_samples, n);
  std::optional<fit::JkrBranch> branch;
  if (options.model == fit::FitModel::jkr && reduced > 0.0 && work > 0.0) {
    const auto [low, high] = std::minmax_element(z.begin(), z.end());
    branch.emplace(*options.tip.profile, reduced, work,
                   std::max(cp - *low, 1e-3 * std::max(*high - *low, 1e-30)));
  }
  std::optional<fit::MaugisBranch> maugis;
  const double lambda = f.maugis_parameter.value;
  if ((options.model == fit::FitModel::maugis || options.model == fit::FitModel::automatic) &&
      reduced > 0.0 && work > 0.0 && lambda > 0.0) {
    const DugdaleLaw law{fit::maugis_adhesive_stress(lambda, reduced, work, options.tip.radius),
                         work, reduced};
    const auto [low, high] = std::minmax_element(z.begin(), z.end());
    try {
      maugis.emplace(*options.tip.profile, law,
                     std::max(cp - *low, 1e-3 * std::max(*high - *low, 1e-30)));
    } catch (const std::domain_error&) {
      return {};  // the zone reaches past the tip: nothing to draw
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    double value = f.baseline_offset.value + f.baseline_slope.value * (z[i] - cp);
    const bool in_contact = retract ? i < contact : i >= n - contact;
    if (in_contact && options.model == fit::FitModel::dmt) {
      const double delta = std::max(cp - z[i], 0.0);
      value += reduced * options.tip.force_per_modulus(delta) -
               2.0 * std::numbers::pi * options.tip.radius * work;
    } else if (in_contact && branch) {
      value += branch->at(cp - z[i]).force;
    } else if (in_contact && maugis) {
      value += maugis->at(cp - z[i]).force;
    }
    out[i] = value;
  }
  return out;
}

/// fit()'s arguments checked and read as the command reads its flags.
struct FitRequest {
  fit::CurveFitOptions options;
  measured::SegmentKind kind = measured::SegmentKind::approach;
};

FitRequest parse_request(const std::string& model, const std::string& tip, double poisson_ratio,
                         const std::string& segment, const std::map<std::string, double>& fix) {
  FitRequest request;
  fit::CurveFitOptions& options = request.options;
  options.model = parse_model(model);
  request.kind = parse_segment(segment);
  if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5)) {
    throw SceneError(fmt::format("poisson_ratio {}: outside (-1, 0.5]", poisson_ratio));
  }
  options.tip = fit::parse_tip(tip);
  options.poisson_ratio = poisson_ratio;
  options.fixed = parse_fixed(fix, options.model);
  const fit::TipKind tip_kind = options.tip.kind;
  if (options.model == fit::FitModel::dmt && tip_kind != fit::TipKind::parabolic &&
      tip_kind != fit::TipKind::sphere) {
    throw SceneError(fmt::format(
        "model 'dmt': not for a {} (its DMT adhesion depends on the attraction's range; use "
        "model='jkr')",
        tip_kind == fit::TipKind::cone      ? "cone"
        : tip_kind == fit::TipKind::pyramid ? "pyramid"
                                            : "tip without an apex radius"));
  }
  return request;
}

py::tuple fit_curve(const CurveHandle& handle, const std::string& model, const std::string& tip,
                    double poisson_ratio, const std::string& segment,
                    const std::map<std::string, double>& fix) {
  const FitRequest request = parse_request(model, tip, poisson_ratio, segment, fix);
  const fit::CurveFitOptions& options = request.options;
  const measured::SegmentKind kind = request.kind;
  // The curve as a file of its own: fit_file's refusal and JSON are the command's.
  measured::MeasuredFile one;
  one.path = handle.file->path;
  one.format = handle.file->format;
  one.grid = handle.file->grid;  // the map's grid cell, as the command gives it
  one.curves.push_back(handle.curve());
  std::string json;
  fit::PreparedSegment prepared;
  std::vector<double> model_force;
  {
    py::gil_scoped_release release;
    const std::vector<fit::CurveFit> fits = fit::fit_file(one, kind, options);
    json = fit::curve_fit_json(fits.front(), options, kind).dump();
    const fit::AdhesiveFit& f = fits.front().fit;
    if (f.status == fit::FitStatus::fitted || f.status == fit::FitStatus::not_converged) {
      prepared = fit::prepare_segment(one.curves.front(), kind);
      model_force =
          fitted_force(options, f, prepared.tip_position, kind == measured::SegmentKind::retract);
    }
  }
  return py::make_tuple(json, array_or_none(prepared.tip_position), array_or_none(prepared.force),
                        array_or_none(model_force));
}

}  // namespace

void bind_afm(py::module_& m) {
  py::class_<CurveHandle>(m, "MeasuredCurve");
  m.def("afm_read", &read_file, py::arg("path"), py::arg("sensitivity") = py::none(),
        py::arg("spring_constant") = py::none(),
        "Reads every curve of a measured file (the GIL released while reading).");
  m.def(
      "afm_check_fit",
      [](const std::string& model, const std::string& tip, double poisson_ratio,
         const std::string& segment, const std::map<std::string, double>& fix) {
        parse_request(model, tip, poisson_ratio, segment, fix);
      },
      py::arg("model"), py::arg("tip"), py::arg("poisson_ratio"), py::arg("segment"),
      py::arg("fix"), "Checks fit()'s arguments as fit() does, without a curve.");
  m.def("afm_fit", &fit_curve, py::arg("curve"), py::arg("model"), py::arg("tip"),
        py::arg("poisson_ratio"), py::arg("segment"), py::arg("fix"),
        "Fits one curve: (the JSON of mdrsim fit --json, tip position, force, fitted force).");
}

}  // namespace mdrsim::python
