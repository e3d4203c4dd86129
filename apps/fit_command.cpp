// mdrsim fit: measured force curves read, preprocessed and fitted; one JSON object, CSV row or
// summary line per curve.
#include <sys/stat.h>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "apps/commands.hpp"
#include "apps/csv_sink.hpp"
#include "apps/fit_plot.hpp"
#include "apps/output_file.hpp"
#include "engine/base/text.hpp"
#include "engine/fit/fit_file.hpp"
#include "engine/fit/fit_map.hpp"
#include "engine/measured/read_force_curves.hpp"
#include "engine/output/sweep_csv.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/sweep_grid.hpp"
#include "engine/sweep/sweep_progress.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr const char* kParameters =
    "youngs_modulus, work_of_adhesion, approach_work_of_adhesion, maugis_parameter, "
    "contact_point, baseline_offset, baseline_slope, spring_constant, sensitivity";

struct Fixed {
  fit::AdhesiveFixed parameters;
  std::optional<double> approach_work_of_adhesion;
  measured::CalibrationOverride calibration;
};

/// A number that is all of `text`; nullopt otherwise.
std::optional<double> whole_number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

/// --range FROM:TO, indentations [m] with FROM < TO.
fit::FitRange parse_range(const std::string& text) {
  const std::size_t colon = text.find(':');
  const auto from = whole_number(std::string_view(text).substr(0, colon));
  const auto to = colon == std::string::npos
                      ? std::nullopt
                      : whole_number(std::string_view(text).substr(colon + 1));
  if (!from || !to) {
    throw UsageError(
        fmt::format("--range: '{}' is not FROM:TO (indentations in m)", printable(text, 80)));
  }
  if (!(*from < *to)) {
    throw UsageError(fmt::format("--range {}: FROM must be below TO", printable(text, 80)));
  }
  return {*from, *to};
}

Fixed parse_fixes(const std::vector<std::string>& fixes, fit::FitModel model, bool both) {
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
    } else if (name == "maugis_parameter" &&
               (model == fit::FitModel::maugis || model == fit::FitModel::automatic)) {
      positive();
      fixed.parameters.maugis_parameter = value;
    } else if (name == "approach_work_of_adhesion" && model != fit::FitModel::hertz && both) {
      positive();
      fixed.approach_work_of_adhesion = value;
    } else if (name == "approach_work_of_adhesion" && model != fit::FitModel::hertz) {
      throw UsageError("--fix approach_work_of_adhesion: only with --segment both");
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

/// Splits one CSV record (RFC 4180 quoting) into its fields.
std::vector<std::string> csv_fields(std::string_view record) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < record.size(); ++i) {
    const char c = record[i];
    if (quoted) {
      if (c == '"' && i + 1 < record.size() && record[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

/// The whole records of `text` (a line break inside quotes stays in its record).
std::vector<std::string_view> csv_records(std::string_view text) {
  std::vector<std::string_view> records;
  bool quoted = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"') quoted = !quoted;
    if (text[i] == '\n' && !quoted) {
      records.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return records;
}

/// Where a --resume fit starts: the curves (file, label) a CSV of `mdrsim fit` holds already
/// and the bytes of its whole rows (a torn last row is cut and fitted again).
struct ResumePoint {
  bool fresh = true;  ///< no CSV yet (or only part of its header): write it from the start
  std::uint64_t keep = 0;
  std::set<std::pair<std::string, std::string>> done;
};

ResumePoint resume_point(const std::string& path, fit::FitModel model) {
  ResumePoint point;
  struct stat st {};
  if (stat(path.c_str(), &st) != 0 && errno == ENOENT) return point;  // a first try
  const SweepFile file = read_sweep_file(path, "--resume");
  const std::string header = fit::curve_fit_csv_header() + "\n";
  const std::string name = printable(path);
  if (file.first_line.empty() && header.compare(0, file.head.size(), file.head) == 0) {
    return point;  // killed before its header was whole
  }
  if (file.first_line + "\n" != header) {
    throw UsageError(fmt::format(
        "--resume: '{}' is not a CSV of this mdrsim fit (its first line is not the header of "
        "--csv)",
        name));
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(file.complete_bytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  const std::vector<std::string_view> records = csv_records(text);
  const std::vector<std::string> columns = csv_fields(records.front());
  const std::size_t model_column = static_cast<std::size_t>(
      std::find(columns.begin(), columns.end(), "model") - columns.begin());
  point.fresh = false;
  point.keep = 0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const std::vector<std::string> fields = csv_fields(records[r]);
    if (r > 0 && fields.size() != columns.size()) break;  // a row cut short: fitted again
    point.keep =
        static_cast<std::uint64_t>(records[r].data() + records[r].size() + 1 - text.data());
    if (r == 0) continue;
    if (fields[model_column] != fit::fit_model_name(model)) {
      throw UsageError(
          fmt::format("--resume: '{}' holds fits of --model {}; this run is --model {}", name,
                      printable(fields[model_column], 20), fit::fit_model_name(model)));
    }
    point.done.emplace(fields[0], fields[1]);
  }
  return point;
}

/// What the map flags ask: this shard's files, the curves a --resume CSV holds already, and
/// the Python that draws --plot (found before any fit, so that a missing one costs nothing).
struct MapPlan {
  Shard shard;
  ResumePoint resume;
  std::string python;
};

MapPlan plan_map(const FitOptions& options, fit::FitModel model) {
  MapPlan plan;
  if (!options.shard.empty()) plan.shard = parse_shard(options.shard);
  if (options.resume) {
    if (options.csv.empty() || options.csv == "-") {
      throw UsageError("--resume: needs --csv PATH (the CSV it finishes)");
    }
    plan.resume = resume_point(options.csv, model);
  }
  if (!options.plot.empty()) plan.python = plot_python();
  return plan;
}

/// The curves a batch holds at least before it is fitted (a file is never split): a study's
/// files are read a batch at a time, so that hundreds of maps need not be held at once.
constexpr std::size_t kBatchCurves = 512;

/// The fits of a run, and what --plot needs of the files once they are gone.
struct MapResult {
  std::vector<fit::CurveFit> fits;
  PlotSource plot;
};

/// The progress of a run: in curves for one file, in files for several.
class MapProgress {
 public:
  MapProgress(std::size_t files, std::chrono::steady_clock::time_point started)
      : by_file_(files > 1), files_(files), started_(started) {}
  /// Called once the first file is read: a single file's curves to fit are known then.
  void start(std::size_t curves) {
    if (!progress_) {
      progress_.emplace(0, by_file_ ? files_ : curves, started_, std::chrono::seconds(5), "fit",
                        by_file_ ? "files" : "curves");
    }
  }
  void report(std::size_t files_done, std::size_t curves_done) {
    const auto line =
        progress_->line(by_file_ ? files_done : curves_done, std::chrono::steady_clock::now());
    if (line) spdlog::info("{}", *line);
  }

 private:
  bool by_file_;
  std::size_t files_;
  std::chrono::steady_clock::time_point started_;
  std::optional<SweepProgress> progress_;
};

/// This shard's files read a batch at a time, each refused (SceneError) where none of its
/// curves can be prepared, and every curve not in the resume CSV fitted on --threads threads,
/// in input order; with --resume each row is appended to the CSV as soon as it and every row
/// before it are done (a killed run keeps them); progress on standard error for long runs.
MapResult fit_map(const measured::CalibrationOverride& calibration, const MapPlan& plan,
                  measured::SegmentKind segment, const fit::CurveFitOptions& fit_options,
                  const FitOptions& options) {
  std::vector<std::string> paths;
  for (std::size_t f = 0; f < options.curves.size(); ++f) {
    if (f % plan.shard.count == plan.shard.index) paths.push_back(options.curves[f]);
  }
  const auto started = std::chrono::steady_clock::now();
  MapProgress progress(paths.size(), started);
  MapResult result;
  std::optional<CsvSink> csv;
  std::size_t next = 0, files_done = 0, skipped = 0, total_curves = 0;
  while (next < paths.size()) {
    std::vector<measured::MeasuredFile> batch;
    std::size_t batch_curves = 0;
    while (next < paths.size() && batch_curves < kBatchCurves) {
      batch.push_back(measured::read_force_curves(paths[next++], calibration));
      fit::check_fittable(batch.back(), segment);
      batch_curves += batch.back().curves.size();
      total_curves += batch.back().curves.size();
      result.plot.note(batch.back());
    }
    // Each file's last curve to fit, where its fit completes the file.
    std::vector<fit::CurveRef> curves;
    std::vector<bool> ends_file;
    for (std::size_t f = 0; f < batch.size(); ++f) {
      const std::size_t before = curves.size();
      for (std::size_t c = 0; c < batch[f].curves.size(); ++c) {
        if (plan.resume.done.count({batch[f].path.string(), batch[f].curves[c].label})) {
          ++skipped;
        } else {
          curves.push_back({f, c});
          ends_file.push_back(false);
        }
      }
      if (curves.size() > before) {
        ends_file.back() = true;
      } else {
        ++files_done;
      }
    }
    progress.start(curves.size());
    if (options.resume && !csv) {
      csv.emplace(options.csv);
      if (plan.resume.fresh) {
        csv->open_fresh(fit::curve_fit_csv_header() + "\n");
      } else {
        csv->open_resumed(plan.resume.keep);
      }
    }
    const std::size_t curves_before = result.fits.size();
    fit::MapRun run;
    run.threads = options.threads;
    run.on_fit = [&](std::size_t position, const fit::CurveFit& one) {
      if (csv)
        csv->write_all(fit::curve_fit_csv_row(one, fit_options.model, fit_options.both_segments) +
                       "\n");
      files_done += ends_file[position];
    };
    run.on_progress = [&](std::size_t reported) {
      progress.report(files_done, curves_before + reported);
    };
    for (fit::CurveFit& one : fit::fit_curves(batch, curves, segment, fit_options, run)) {
      result.fits.push_back(std::move(one));
    }
  }
  if (total_curves > 1) {
    const std::size_t fitted = result.fits.size();
    spdlog::info(
        "fit: {} curves of {} on {} in {:.3g} s{}", fitted, counted(paths.size(), "file"),
        counted(std::max<std::size_t>(
                    1, std::min<std::size_t>(static_cast<std::size_t>(options.threads), fitted)),
                "thread"),
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
        skipped > 0 ? fmt::format(" ({} were in the CSV already)", skipped) : std::string());
  }
  return result;
}

}  // namespace

int fit_command(const FitOptions& options) {
  fit::FitModel model = fit::FitModel::hertz;
  if (options.model == "dmt") {
    model = fit::FitModel::dmt;
  } else if (options.model == "jkr") {
    model = fit::FitModel::jkr;
  } else if (options.model == "maugis") {
    model = fit::FitModel::maugis;
  } else if (options.model == "auto") {
    model = fit::FitModel::automatic;
  } else if (options.model != "hertz") {
    throw UsageError(fmt::format("--model {}: unknown (known: hertz, dmt, jkr, maugis, auto)",
                                 printable(options.model, 40)));
  }
  measured::SegmentKind segment = measured::SegmentKind::approach;
  const bool both = options.segment == "both";
  if (options.segment == "retract") {
    segment = measured::SegmentKind::retract;
  } else if (both) {
    segment = measured::SegmentKind::approach;
  } else if (options.segment != "approach") {
    throw UsageError(fmt::format("--segment {}: unknown (known: approach, retract, both)",
                                 printable(options.segment, 40)));
  }
  if (both && model == fit::FitModel::automatic) {
    // auto's pick names one segment's model; the joint fit runs the model named.
    throw UsageError(
        "--segment both: not with --model auto (approach and retract are fitted together by "
        "hertz, dmt, jkr and maugis)");
  }
  if (!(options.poisson_ratio > -1.0 && options.poisson_ratio <= 0.5)) {
    throw UsageError(fmt::format("--poisson-ratio {}: outside (-1, 0.5]", options.poisson_ratio));
  }
  if (options.json == "-" && options.csv == "-") {
    throw UsageError("--csv: cannot share standard output with --json -");
  }
  if (options.plot == "-") throw UsageError("--plot: needs a file path (a PNG), not -");
  require_distinct_outputs(
      {{"--json", options.json}, {"--csv", options.csv}, {"--plot", options.plot}}, std::string());
  const Fixed fixed = parse_fixes(options.fixes, model, both);
  fit::CurveFitOptions fit_options;
  fit_options.model = model;
  fit_options.tip = fit::parse_tip(options.tip);
  fit_options.poisson_ratio = options.poisson_ratio;
  fit_options.fixed = fixed.parameters;
  fit_options.approach_work_of_adhesion = fixed.approach_work_of_adhesion;
  fit_options.both_segments = both;
  if (!options.range.empty()) fit_options.range = parse_range(options.range);
  const fit::TipKind tip_kind = fit_options.tip.kind;
  if (model == fit::FitModel::dmt && tip_kind != fit::TipKind::parabolic &&
      tip_kind != fit::TipKind::sphere) {
    // A cone's adhesion outside the contact depends on the range of the attraction, not on
    // work_of_adhesion alone: DMT's limit has no closed form in w for it, nor for a tip without
    // an apex radius.
    throw UsageError(fmt::format(
        "--model dmt: not for a {} (its DMT adhesion depends on the attraction's range; use "
        "--model jkr)",
        tip_kind == fit::TipKind::cone      ? "cone"
        : tip_kind == fit::TipKind::pyramid ? "pyramid"
                                            : "tip without an apex radius"));
  }
  if (!fit_options.tip.approximation.empty()) {
    spdlog::warn("--tip {}: {}", fit_options.tip.text, fit_options.tip.approximation);
  }
  if ((model == fit::FitModel::maugis || model == fit::FitModel::automatic) &&
      fit_options.tip.kind == fit::TipKind::cone) {
    // SPEC defines lambda by the tip radius, as the scenes' maugis_parameter.
    throw UsageError(fmt::format(
        "--model {}: not for a cone (the Maugis parameter needs a tip radius: parabolic or "
        "sphere; use --model jkr)",
        options.model));
  }

  const MapPlan plan = plan_map(options, model);
  // Outputs are written once every file is read and fitted (--resume's CSV row by row): a file
  // refused on the way leaves no output behind.
  const MapResult map = fit_map(fixed.calibration, plan, segment, fit_options, options);
  const std::vector<fit::CurveFit>& fits = map.fits;

  std::optional<OutputFile> json_file;
  if (!options.json.empty()) json_file.emplace("--json", options.json);
  std::optional<OutputFile> csv_file;
  if (!options.csv.empty() && !options.resume) csv_file.emplace("--csv", options.csv);
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
      csv_file->stream() << fit::curve_fit_csv_row(one, model, both) << '\n';
    csv_file->commit();
  }
  if (!json_file && options.csv.empty()) {
    for (const fit::CurveFit& one : fits) {
      std::fputs(
          (fit::curve_fit_summary(one, model) + "\n" + fit::curve_fit_warning_lines(one)).c_str(),
          stdout);
    }
  }
  if (!options.plot.empty()) {
    write_fit_plot(plan.python, options.plot, map.plot, fits,
                   options.resume ? std::optional<std::string>(options.csv) : std::nullopt, segment,
                   fit_options);
  }
  return 0;
}

}  // namespace mdrsim::cli
