// Igor binary waves (.ibw, version 5) as Asylum Research writes force curves: a 2-D wave whose
// columns are labelled (Raw, Defl, ZSnsr) and whose note holds "Key: value" lines.
#pragma once

#include <filesystem>

#include "engine/measured/force_curve.hpp"

namespace mdrsim::measured {

/// Reads the one curve of the wave; throws MeasuredFileError for a wave that is not version 5,
/// is truncated or damaged, or lacks the columns of a force curve.
MeasuredFile read_igor(const std::filesystem::path& path, const CalibrationOverride& overrides);

}  // namespace mdrsim::measured
