// The one entry to measured force curves: dispatch on the extension, check the magic bytes,
// check what a fit needs.
#include "engine/measured/read_force_curves.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "engine/base/text.hpp"
#include "engine/measured/hdf5_reader.hpp"
#include "engine/measured/igor_reader.hpp"
#include "engine/measured/jpk_reader.hpp"
#include "engine/measured/measured_error.hpp"
#include "engine/measured/table_reader.hpp"

namespace mdrsim::measured {

namespace {

/// The file's first bytes (fewer if it is shorter).
std::string first_bytes(const std::filesystem::path& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, "cannot be opened ({})", system_reason(errno));
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

/// "index/109: segment 1 (retract)" or "segment 1 (retract)" for a file of one curve.
std::string where(const ForceCurve& curve, std::size_t number, const Segment& segment) {
  std::string text = curve.label.empty() ? "" : curve.label + ": ";
  return text + "segment " + std::to_string(number) + " (" + segment.name + ")";
}

void check_curve(const std::filesystem::path& path, const ForceCurve& curve) {
  if (curve.segments.empty()) {
    refuse(path, "{}no segments", curve.label.empty() ? "" : curve.label + ": ");
  }
  for (std::size_t s = 0; s < curve.segments.size(); ++s) {
    const Segment& segment = curve.segments[s];
    const std::string at = where(curve, s, segment);
    const std::size_t count = segment.size();
    if (count == 0) refuse(path, "{}: empty (no samples)", at);
    const std::array<std::pair<const std::vector<double>*, const char*>, 6> channels{{
        {&segment.time, "time"},
        {&segment.piezo_height, "piezo height"},
        {&segment.measured_height, "measured height"},
        {&segment.tip_position, "tip position"},
        {&segment.deflection, "deflection"},
        {&segment.force, "force"},
    }};
    for (const auto& [values, name] : channels) {
      if (!values->empty() && values->size() != count) {
        refuse(path, "{}: {} has {} samples, the segment {}", at, name, values->size(), count);
      }
      const auto bad =
          std::find_if(values->begin(), values->end(), [](double v) { return !std::isfinite(v); });
      if (bad != values->end()) {
        refuse(path, "{}: {} sample {} is {} (not a finite number)", at, name,
               bad - values->begin(), *bad);
      }
    }
    if (segment.piezo_height.empty() && segment.measured_height.empty() &&
        segment.tip_position.empty()) {
      refuse(path, "{}: no height (piezo, measured or tip position)", at);
    }
    if (segment.deflection.empty() && segment.force.empty()) {
      if (!curve.calibration.sensitivity) {
        refuse(path,
               "{}: no sensitivity: the deflection is in volts only, neither a distance "
               "nor a force (give the sensitivity and spring constant)",
               at);
      }
      refuse(path, "{}: no deflection or force", at);
    }
  }
}

}  // namespace

MeasuredFile read_force_curves(const std::filesystem::path& path,
                               const CalibrationOverride& overrides) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::string magic = first_bytes(path, 8);
  MeasuredFile file;
  if (extension == ".jpk-force" || extension == ".jpk-force-map" || extension == ".jpk-qi-data" ||
      extension == ".jpk-qi-series") {
    if (!magic.starts_with("PK\x03\x04") && !magic.starts_with("PK\x05\x06")) {
      refuse(path, "not a zip archive, as a JPK {} file is", extension);
    }
    file = read_jpk(path, extension.substr(1), overrides);
  } else if (extension == ".h5" || extension == ".hdf5") {
    if (magic != std::string_view("\x89HDF\r\n\x1a\n", 8)) {
      refuse(path, "not an HDF5 file (no HDF5 signature at its start)");
    }
    file = read_afmformats_hdf5(path, overrides);
  } else if (extension == ".ibw") {
    const bool igor = magic.size() >= 2 && ((magic[0] != 0 && magic[1] == 0 && magic[0] <= 5) ||
                                            (magic[0] == 0 && magic[1] != 0 && magic[1] <= 5));
    if (!igor) refuse(path, "not an Igor binary wave (no version number at its start)");
    file = read_igor(path, overrides);
  } else if (extension == ".csv" || extension == ".tsv" || extension == ".txt") {
    file = read_table(path, overrides);
  } else {
    refuse(path,
           "unknown kind of file '{}' (known: .jpk-force, .jpk-force-map, .jpk-qi-data, "
           ".jpk-qi-series, .h5, .hdf5, .ibw, .csv, .tsv, .txt)",
           extension);
  }
  if (file.curves.empty()) refuse(path, "no force curves");
  // One curve: its problem is the file's. Several: each bad curve is marked and the rest load,
  // unless none does.
  for (ForceCurve& curve : file.curves) {
    if (!curve.unreadable.empty()) continue;
    try {
      check_curve(path, curve);
    } catch (const MeasuredFileError& error) {
      if (file.curves.size() == 1) throw;
      curve.unreadable = error.what();
      curve.segments.clear();
    }
  }
  const bool any_readable = std::any_of(file.curves.begin(), file.curves.end(),
                                        [](const ForceCurve& c) { return c.unreadable.empty(); });
  if (!any_readable) throw MeasuredFileError(file.curves.front().unreadable);
  return file;
}

}  // namespace mdrsim::measured
