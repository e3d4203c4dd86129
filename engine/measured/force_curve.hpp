// Measured force curves as read from an instrument's file: segments, calibration, map position.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mdrsim::measured {

enum class SegmentKind { approach, retract, pause };

/// "approach", "retract" or "pause".
const char* segment_kind_name(SegmentKind kind);

/// One part of a curve: the channels as the file gives them, each either empty or as long as
/// the segment. Heights follow afmformats' sign: they decrease as the cantilever nears the
/// sample. A segment holds a height (piezo, measured or tip position) and a deflection or a force.
struct Segment {
  std::string name;  ///< the file's name for it (JPK "extend-spm"), else the kind's name
  SegmentKind kind = SegmentKind::approach;
  std::vector<double> time;             ///< [s] from the curve's start
  std::vector<double> piezo_height;     ///< [m] the piezo's commanded height
  std::vector<double> measured_height;  ///< [m] the height sensor's reading
  std::vector<double> tip_position;     ///< [m] given directly by a table
  std::vector<double> deflection;       ///< [m] cantilever deflection
  std::vector<double> force;            ///< [N]

  /// The number of samples (every non-empty channel has as many).
  std::size_t size() const;
};

/// A calibration value and where it came from (a property key, a note line, an override).
struct Calibrated {
  double value = 0.0;
  std::string source;
};

/// What turns the raw signal into SI units, each present only where the file (or an override)
/// gives it.
struct Calibration {
  std::optional<Calibrated> sensitivity;      ///< [m/V] inverse optical lever sensitivity
  std::optional<Calibrated> spring_constant;  ///< [N/m]
  std::optional<Calibrated> approach_speed;   ///< [m/s] piezo speed of the approach
  std::optional<Calibrated> retract_speed;    ///< [m/s] piezo speed of the retract
};

/// Where on the sample a curve of a map was taken.
struct MapPosition {
  double x = 0.0;  ///< [m]
  double y = 0.0;  ///< [m]
  long index = 0;  ///< the file's position index (JPK position-index, a table's point)
};

/// A map's grid as the file declares it (JPK force maps and QI).
struct MapGrid {
  long columns = 0;       ///< points along x (JPK ilength)
  long rows = 0;          ///< points along y (JPK jlength)
  double width = 0.0;     ///< [m] (JPK ulength)
  double height = 0.0;    ///< [m] (JPK vlength)
  double center_x = 0.0;  ///< [m]
  double center_y = 0.0;  ///< [m]
};

/// A curve of the file. In a file of several curves (a map), a curve that cannot be read keeps
/// its label and position and says why in `unreadable`, so that the map goes on without it.
struct ForceCurve {
  std::string label;  ///< where in the file: "index/109" of a map, "0" of an HDF5 file, "" alone
  std::string unreadable;  ///< empty for a curve that loaded; else its refusal line
  std::vector<Segment> segments;
  Calibration calibration;
  std::optional<MapPosition> position;
};

/// One file: a single curve, or the curves of a map, a QI image or an HDF5 export.
struct MeasuredFile {
  std::filesystem::path path;
  std::string format;  ///< "jpk-force", "jpk-force-map", "jpk-qi-data", "jpk-qi-series",
                       ///< "hdf5", "igor", "afm-workshop", "table"
  std::vector<ForceCurve> curves;
  std::optional<MapGrid> grid;
};

/// Calibration given by the user, used where the file lacks it or instead of the file's
/// (`--fix sensitivity=...`, `--fix spring_constant=...`).
struct CalibrationOverride {
  std::optional<double> sensitivity;      ///< [m/V]
  std::optional<double> spring_constant;  ///< [N/m]
};

}  // namespace mdrsim::measured
