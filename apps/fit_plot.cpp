// mdrsim fit --plot: the CSV the embedded script reads, and the script run by python3.
#include "apps/fit_plot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "apps/fit_plot_script.hpp"
#include "apps/write_error.hpp"
#include "engine/base/text.hpp"
#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/hertz_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

extern char** environ;

namespace mdrsim::cli {
namespace {

/// Runs `python` with `arguments` and waits; its exit status, or -1 where it could not start.
/// `quiet` sends its output to /dev/null (the matplotlib probe); else it goes to stderr.
int run_python(const std::string& python, const std::vector<std::string>& arguments, bool quiet) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(python.c_str()));
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  } else {
    // Standard output may carry --json -: the script's words go to standard error.
    posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  }
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A folder of our own under the system's temporary folder, removed with its files.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "mdrsim-plot-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw WriteError(
          fmt::format("--plot: cannot make a temporary folder ({})", system_reason(errno)));
    }
    path_ = pattern;
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const char* name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// The fitted model's force at each sample. Hertz's is the fit's own; DMT's and JKR's follow
/// the fit's contact samples (its `contact_samples`: the first ones of a retract, measured from
/// the deepest, the last ones of an approach), on Hertz less 2 pi w R or on the MDR's JKR
/// branch, and the baseline elsewhere.
std::vector<double> model_forces(const fit::CurveFit& fit, const fit::PreparedSegment& prepared,
                                 measured::SegmentKind segment,
                                 const fit::CurveFitOptions& options) {
  const fit::AdhesiveFit& f = fit.fit;
  const double nu = options.poisson_ratio;
  const double reduced = f.youngs_modulus.value / (1.0 - nu * nu);
  const double cp = f.contact_point.value;
  const std::vector<double>& z = prepared.tip_position;
  const std::size_t n = z.size();
  std::vector<double> out;
  out.reserve(n);
  std::optional<fit::JkrBranch> branch;
  if (options.model == fit::FitModel::jkr) {
    branch.emplace(*options.tip.profile, reduced, f.work_of_adhesion.value,
                   std::max(cp - *std::min_element(z.begin(), z.end()), 0.0));
  }
  const bool retract = segment == measured::SegmentKind::retract;
  for (std::size_t i = 0; i < n; ++i) {
    if (options.model == fit::FitModel::hertz) {
      out.push_back(fit::hertz_force(options.tip, nu, f, z[i]));
      continue;
    }
    const double delta = cp - z[i];
    double force = f.baseline_offset.value + f.baseline_slope.value * (z[i] - cp);
    const bool contact = retract ? i < f.contact_samples : i + f.contact_samples >= n;
    if (contact && branch) {
      force += branch->at(delta).force;
    } else if (contact) {
      force += reduced * options.tip.force_per_modulus(std::max(delta, 0.0)) -
               2.0 * std::numbers::pi * f.work_of_adhesion.value * options.tip.radius;
    }
    out.push_back(force);
  }
  return out;
}

std::string cell(double value) { return std::isfinite(value) ? fmt::format("{}", value) : ""; }

/// The samples of the one curve fitted, with the model where the fit has values.
void write_curve_samples(const std::string& path, const std::optional<measured::ForceCurve>& curve,
                         const fit::CurveFit& fit, measured::SegmentKind segment,
                         const fit::CurveFitOptions& options) {
  if (!curve || fit.fit.status == fit::FitStatus::unreadable) {
    throw WriteError(fmt::format("--plot: {} has no samples to draw ({})", fit.file,
                                 fit::fit_status_name(fit.fit.status)));
  }
  const fit::PreparedSegment prepared = fit::prepare_segment(*curve, segment);
  const bool valued =
      fit.fit.status == fit::FitStatus::fitted || fit.fit.status == fit::FitStatus::not_converged;
  const std::vector<double> model =
      valued ? model_forces(fit, prepared, segment, options) : std::vector<double>();
  std::ofstream out(path);
  out << "tip_position,force,model\n";
  for (std::size_t i = 0; i < prepared.force.size(); ++i) {
    out << cell(prepared.tip_position[i]) << ',' << cell(prepared.force[i]) << ','
        << (valued ? cell(model[i]) : std::string()) << '\n';
  }
  if (!out) throw WriteError("--plot: cannot write the samples for the script");
}

}  // namespace

void PlotSource::note(const measured::MeasuredFile& file) {
  curves += file.curves.size();
  if (curves == 1 && file.curves.size() == 1) {
    only_curve = file.curves.front();
  } else {
    only_curve.reset();
  }
  if (!grid && file.grid) {
    grid = file.grid;
    grid_file = file.path.string();
  }
}

std::string plot_python() {
  std::vector<std::string> candidates;
  if (const char* chosen = std::getenv("MDRSIM_PYTHON"); chosen != nullptr && *chosen != '\0') {
    candidates.emplace_back(chosen);
  } else {
    candidates = {"/usr/bin/python3", "python3"};
  }
  for (const std::string& python : candidates) {
    if (run_python(python, {"-c", "import matplotlib"}, true) == 0) return python;
  }
  throw UsageError(
      fmt::format("--plot: needs python3 with matplotlib (tried {}; install "
                  "python3-matplotlib or set MDRSIM_PYTHON)",
                  fmt::join(candidates, ", ")));
}

void write_fit_plot(const std::string& python, const std::string& png, const PlotSource& source,
                    const std::vector<fit::CurveFit>& fits, const std::optional<std::string>& csv,
                    measured::SegmentKind segment, const fit::CurveFitOptions& options) {
  const TemporaryFolder folder;
  std::vector<std::string> arguments = {"-c", kPlotFitScript};
  if (fits.size() == 1 && !csv) {
    const std::string samples = folder.file("samples.csv");
    write_curve_samples(samples, source.only_curve, fits.front(), segment, options);
    arguments.insert(arguments.end(),
                     {"curve", samples, png, fit::curve_fit_summary(fits.front(), options.model)});
  } else {
    std::string table = csv.value_or(folder.file("fits.csv"));
    if (!csv) {
      std::ofstream out(table);
      out << fit::curve_fit_csv_header() << '\n';
      for (const fit::CurveFit& one : fits)
        out << fit::curve_fit_csv_row(one, options.model) << '\n';
      if (!out) throw WriteError("--plot: cannot write the fits for the script");
    }
    arguments.insert(arguments.end(), {"map", table, png});
    if (source.grid) {
      const measured::MapGrid& g = *source.grid;
      arguments.push_back(source.grid_file);
      for (const double v : {static_cast<double>(g.columns), static_cast<double>(g.rows), g.width,
                             g.height, g.center_x, g.center_y}) {
        arguments.push_back(fmt::format("{}", v));
      }
    }
  }
  const int status = run_python(python, arguments, false);
  if (status != 0) {
    throw WriteError(fmt::format(
        "--plot: {} ended with {} drawing '{}'", python,
        status < 0 ? std::string("an error") : fmt::format("exit {}", status), printable(png)));
  }
}

}  // namespace mdrsim::cli
