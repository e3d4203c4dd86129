// JPK force files (.jpk-force, .jpk-force-map, .jpk-qi-data, .jpk-qi-series): zip archives of
// Java properties and big-endian channel data with conversion sets.
#pragma once

#include <filesystem>
#include <string>

#include "engine/measured/force_curve.hpp"

namespace mdrsim::measured {

/// Reads every curve of the archive; `format` names it in the result ("jpk-force", ...).
/// Throws MeasuredFileError for an archive that is not a JPK file or is damaged.
MeasuredFile read_jpk(const std::filesystem::path& path, const std::string& format,
                      const CalibrationOverride& overrides);

}  // namespace mdrsim::measured
