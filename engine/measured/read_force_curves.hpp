// The one entry to measured force curves: the reader chosen by the file's extension, its magic
// bytes checked, and every curve checked for what a fit needs.
#pragma once

#include <filesystem>

#include "engine/measured/force_curve.hpp"

namespace mdrsim::measured {

/// Reads every curve of the file (JPK .jpk-force, .jpk-force-map, .jpk-qi-data, .jpk-qi-series;
/// afmformats' HDF5 .h5/.hdf5; Igor .ibw; .csv/.tsv/.txt tables). `overrides` replace or supply
/// the file's sensitivity and spring constant before its channels are converted.
///
/// Throws MeasuredFileError, one line naming the file, for an unknown extension, contents
/// that do not match it, a damaged or truncated file, a curve without segments, an empty
/// segment, a segment without a height or without a deflection or force in SI units (a file
/// without sensitivity), channels of unequal length and samples that are not finite. In a file
/// of several curves, a curve with such a problem is kept with its line in `unreadable` and no
/// segments; the file is refused only when no curve is readable.
MeasuredFile read_force_curves(const std::filesystem::path& path,
                               const CalibrationOverride& overrides = {});

}  // namespace mdrsim::measured
