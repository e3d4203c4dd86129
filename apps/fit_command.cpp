// mdrsim fit: measured force curves read, preprocessed and fitted; one JSON object, CSV row or
// summary line per curve.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "apps/commands.hpp"
#include "apps/output_file.hpp"
#include "engine/base/text.hpp"
#include "engine/fit/fit_file.hpp"
#include "engine/measured/read_force_curves.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr const char* kParameters =
    "youngs_modulus, work_of_adhesion, contact_point, baseline_offset, "
    "baseline_slope, spring_constant, sensitivity";

struct Fixed {
  fit::AdhesiveFixed parameters;
  measured::CalibrationOverride calibration;
};

Fixed parse_fixes(const std::vector<std::string>& fixes, fit::FitModel model) {
  Fixed fixed;
  for (const std::string& text : fixes) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw UsageError(fmt::format("--fix: '{}' is not NAME=VALUE", printable(text, 80)));
    }
    const std::string name = text.substr(0, eq);
    const std::string_view number = std::string_view(text).substr(eq + 1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (number.empty() || error != std::errc{} || end != number.data() + number.size() ||
        !std::isfinite(value)) {
      throw UsageError(fmt::format("--fix {}: '{}' is not a number", printable(name, 40),
                                   printable(number, 40)));
    }
    const auto positive = [&] {
      if (!(value > 0.0)) throw UsageError(fmt::format("--fix {}: must be > 0", name));
    };
    if (name == "youngs_modulus") {
      positive();
      fixed.parameters.youngs_modulus = value;
    } else if (name == "contact_point") {
      fixed.parameters.contact_point = value;
    } else if (name == "baseline_offset") {
      fixed.parameters.baseline_offset = value;
    } else if (name == "baseline_slope") {
      fixed.parameters.baseline_slope = value;
    } else if (name == "spring_constant") {
      positive();
      fixed.calibration.spring_constant = value;
    } else if (name == "sensitivity") {
      positive();
      fixed.calibration.sensitivity = value;
    } else if (name == "work_of_adhesion" && model != fit::FitModel::hertz) {
      positive();
      fixed.parameters.work_of_adhesion = value;
    } else if (name == "work_of_adhesion" || name == "approach_work_of_adhesion" ||
               name == "maugis_parameter") {
      throw UsageError(
          fmt::format("--fix {}: not a parameter of --model {}", name, fit::fit_model_name(model)));
    } else {
      throw UsageError(
          fmt::format("--fix {}: unknown (known: {})", printable(name, 40), kParameters));
    }
  }
  return fixed;
}

}  // namespace

int fit_command(const FitOptions& options) {
  fit::FitModel model = fit::FitModel::hertz;
  if (options.model == "dmt") {
    model = fit::FitModel::dmt;
  } else if (options.model == "jkr") {
    model = fit::FitModel::jkr;
  } else if (options.model == "maugis" || options.model == "auto") {
    throw UsageError(fmt::format("--model {}: not yet (hertz, dmt or jkr)", options.model));
  } else if (options.model != "hertz") {
    throw UsageError(fmt::format("--model {}: unknown (known: hertz, dmt, jkr, maugis, auto)",
                                 printable(options.model, 40)));
  }
  measured::SegmentKind segment = measured::SegmentKind::approach;
  if (options.segment == "retract") {
    segment = measured::SegmentKind::retract;
  } else if (options.segment == "both") {
    throw UsageError("--segment both: not yet (approach or retract)");
  } else if (options.segment != "approach") {
    throw UsageError(fmt::format("--segment {}: unknown (known: approach, retract, both)",
                                 printable(options.segment, 40)));
  }
  if (!(options.poisson_ratio > -1.0 && options.poisson_ratio <= 0.5)) {
    throw UsageError(fmt::format("--poisson-ratio {}: outside (-1, 0.5]", options.poisson_ratio));
  }
  if (options.json == "-" && options.csv == "-") {
    throw UsageError("--csv: cannot share standard output with --json -");
  }
  require_distinct_outputs({{"--json", options.json}, {"--csv", options.csv}}, std::string());
  const Fixed fixed = parse_fixes(options.fixes, model);
  fit::CurveFitOptions fit_options;
  fit_options.model = model;
  fit_options.tip = fit::parse_tip(options.tip);
  fit_options.poisson_ratio = options.poisson_ratio;
  fit_options.fixed = fixed.parameters;
  if (model == fit::FitModel::dmt && fit_options.tip.kind == fit::TipKind::cone) {
    // A cone's adhesion outside the contact depends on the range of the attraction, not on
    // work_of_adhesion alone: DMT's limit has no closed form in w for it.
    throw UsageError(
        "--model dmt: not for a cone (its DMT adhesion depends on the attraction's range; use "
        "--model jkr)");
  }

  // Every file is read before any is fitted: a bad file is refused before output is written.
  std::vector<measured::MeasuredFile> files;
  files.reserve(options.curves.size());
  for (const std::string& path : options.curves) {
    files.push_back(measured::read_force_curves(path, fixed.calibration));
  }
  std::vector<fit::CurveFit> fits;
  for (const measured::MeasuredFile& file : files) {
    for (fit::CurveFit& one : fit::fit_file(file, segment, fit_options)) {
      fits.push_back(std::move(one));
    }
  }

  std::optional<OutputFile> json_file;
  if (!options.json.empty()) json_file.emplace("--json", options.json);
  std::optional<OutputFile> csv_file;
  if (!options.csv.empty()) csv_file.emplace("--csv", options.csv);
  if (json_file) {
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (const fit::CurveFit& one : fits) {
      all.push_back(fit::curve_fit_json(one, fit_options, segment));
    }
    json_file->stream() << all.dump(2) << '\n';
    json_file->commit();
  }
  if (csv_file) {
    csv_file->stream() << fit::curve_fit_csv_header() << '\n';
    for (const fit::CurveFit& one : fits)
      csv_file->stream() << fit::curve_fit_csv_row(one, model) << '\n';
    csv_file->commit();
  }
  if (!json_file && !csv_file) {
    for (const fit::CurveFit& one : fits) {
      std::fputs((fit::curve_fit_summary(one, model) + "\n").c_str(), stdout);
    }
  }
  return 0;
}

}  // namespace mdrsim::cli
