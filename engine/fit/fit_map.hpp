// The curves of many measured files fitted on several threads: each curve's fit, reported in
// input order whatever the threads, with progress as the curves finish.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "engine/fit/fit_file.hpp"
#include "engine/measured/force_curve.hpp"

namespace mdrsim::fit {

/// One curve of one file: `files[file].curves[curve]`.
struct CurveRef {
  std::size_t file = 0;
  std::size_t curve = 0;
};

/// How fit_curves runs and what it tells its caller.
struct MapRun {
  int threads = 1;  ///< 1: on the calling thread alone
  /// Called with each fit in input order (position in `curves`), as soon as it and every fit
  /// before it are done; serialised (never two at once), on whichever thread finished it.
  std::function<void(std::size_t position, const CurveFit& fit)> on_fit;
  /// Called after on_fit with the number of fits reported so far; serialised as on_fit.
  std::function<void(std::size_t reported)> on_progress;
};

/// Every curve of `curves` fitted (fit_curve: a curve that cannot be fitted gets its status and
/// the rest go on), the results in the order of `curves`, identical for every thread count.
/// An exception from a callback or a fit stops the others and is rethrown (the first in input
/// order).
std::vector<CurveFit> fit_curves(const std::vector<measured::MeasuredFile>& files,
                                 const std::vector<CurveRef>& curves, measured::SegmentKind segment,
                                 const CurveFitOptions& options, const MapRun& run);

/// Every curve of every file, in order.
std::vector<CurveRef> every_curve(const std::vector<measured::MeasuredFile>& files);

}  // namespace mdrsim::fit
