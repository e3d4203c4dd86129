// Force curves in text tables: the AFM Workshop export (.csv) and SPEC's own CSV/TSV columns.
#pragma once

#include <filesystem>

#include "engine/measured/force_curve.hpp"

namespace mdrsim::measured {

/// Reads the one curve of the table; the AFM Workshop export is told by its first line
/// ("Force-Distance Curve"). Throws MeasuredFileError for a table it cannot read.
MeasuredFile read_table(const std::filesystem::path& path, const CalibrationOverride& overrides);

}  // namespace mdrsim::measured
