// mdrsim fit --plot: the figure drawn by the embedded matplotlib script (scripts/plot_fit.py)
// from a CSV written for it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/fit/fit_file.hpp"
#include "engine/measured/force_curve.hpp"

namespace mdrsim::cli {

/// The Python that will draw: $MDRSIM_PYTHON if set, else /usr/bin/python3, else python3 on
/// PATH, provided it imports matplotlib. Throws UsageError ("--plot: ...", exit 2) otherwise:
/// called before any fit.
std::string plot_python();

/// What a figure needs of the files read, kept as they go by: the curve of a run of one, and
/// the first grid declared.
struct PlotSource {
  std::optional<measured::ForceCurve> only_curve;  ///< while the run has read one curve in all
  std::string grid_file;                           ///< the file of `grid`, as given
  std::optional<measured::MapGrid> grid;
  std::size_t curves = 0;

  /// Notes a file read.
  void note(const measured::MeasuredFile& file);
};

/// One curve: the measured force over tip position, the model and the residuals. A map or
/// several curves: images of E, work_of_adhesion (adhesive models) and the residual RMS on the
/// grid of the first file that declares one, else at the curves' positions, else by curve.
/// `csv` is a fit CSV of every curve to show (a --resume run's, with the rows of earlier runs);
/// without it, `fits` are written to one for the script.
void write_fit_plot(const std::string& python, const std::string& png, const PlotSource& source,
                    const std::vector<fit::CurveFit>& fits, const std::optional<std::string>& csv,
                    measured::SegmentKind segment, const fit::CurveFitOptions& options);

}  // namespace mdrsim::cli
