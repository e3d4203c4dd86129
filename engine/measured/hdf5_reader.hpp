// HDF5 files in the layout afmformats writes: one group per curve ("0", "1", ...) with the
// metadata as attributes and one dataset per column.
#pragma once

#include <filesystem>

#include "engine/measured/force_curve.hpp"

namespace mdrsim::measured {

/// Reads every curve group; throws MeasuredFileError for a file HDF5 cannot open or that is not
/// in afmformats' layout.
MeasuredFile read_afmformats_hdf5(const std::filesystem::path& path,
                                  const CalibrationOverride& overrides);

}  // namespace mdrsim::measured
