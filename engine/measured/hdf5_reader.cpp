// HDF5 files in the layout afmformats writes, read through HDF5's C API.
#include "engine/measured/hdf5_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "engine/measured/measured_error.hpp"

namespace mdrsim::measured {
namespace {

/// An HDF5 handle closed by its own closing function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// A numeric attribute of the object, converted to double; nullopt when absent or not a number.
std::optional<double> number_attribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) return std::nullopt;
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_FLOAT && type_class != H5T_INTEGER) return std::nullopt;
  const Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1) return std::nullopt;
  double value = 0.0;
  if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) return std::nullopt;
  return value;
}

std::optional<Calibrated> calibrated_attribute(hid_t group, const char* name) {
  const auto value = number_attribute(group, name);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return Calibrated{*value, std::string("attribute '") + name + "'"};
}

/// The group's one-dimensional dataset `name` as doubles, empty when the group has none.
std::vector<double> column(const std::filesystem::path& path, hid_t group, const std::string& where,
                           const char* name) {
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) return {};
  const Handle dataset(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) refuse(path, "{}/{}: not a dataset HDF5 can open", where, name);
  const Handle space(H5Dget_space(dataset.get()), H5Sclose);
  if (H5Sget_simple_extent_ndims(space.get()) != 1) {
    refuse(path, "{}/{}: not a one-dimensional column", where, name);
  }
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  std::vector<double> values(static_cast<std::size_t>(std::max<hssize_t>(count, 0)));
  if (!values.empty() &&
      H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    refuse(path, "{}/{}: its data cannot be read (truncated file?)", where, name);
  }
  return values;
}

std::vector<std::string> group_names(hid_t file) {
  H5G_info_t info;
  if (H5Gget_info(file, &info) < 0) return {};
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length =
        H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length <= 0) continue;
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    names.push_back(std::move(name));
  }
  // afmformats numbers its curves "0", "1", ..., "10": in the order of those numbers.
  const auto numeric = [](const std::string& n) {
    return !n.empty() && n.size() <= 9 &&
           std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  std::erase_if(names, [&](const std::string& n) { return !numeric(n); });
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return names;
}

/// The samples [begin, end) of a column, or empty for an absent column.
std::vector<double> slice(const std::vector<double>& values, std::size_t begin, std::size_t end) {
  if (values.empty()) return {};
  return {values.begin() + static_cast<std::ptrdiff_t>(begin),
          values.begin() + static_cast<std::ptrdiff_t>(end)};
}

ForceCurve read_group(const std::filesystem::path& path, hid_t file, const std::string& name,
                      const CalibrationOverride& overrides) {
  const Handle group(H5Gopen2(file, name.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) refuse(path, "{}: not a group HDF5 can open", name);
  ForceCurve curve;
  curve.label = name;
  curve.calibration.sensitivity = calibrated_attribute(group.get(), "sensitivity");
  curve.calibration.spring_constant = calibrated_attribute(group.get(), "spring constant");
  curve.calibration.approach_speed = calibrated_attribute(group.get(), "speed approach");
  curve.calibration.retract_speed = calibrated_attribute(group.get(), "speed retract");
  if (overrides.sensitivity)
    curve.calibration.sensitivity = Calibrated{*overrides.sensitivity, "override"};
  if (overrides.spring_constant) {
    curve.calibration.spring_constant = Calibrated{*overrides.spring_constant, "override"};
  }
  const auto x = number_attribute(group.get(), "position x");
  const auto y = number_attribute(group.get(), "position y");
  if (x && y && std::isfinite(*x) && std::isfinite(*y)) {
    const auto index = number_attribute(group.get(), "enum");
    const bool whole = index && std::abs(*index) < 1e9;
    curve.position = MapPosition{*x, *y, whole ? std::lround(*index) : std::stol(name)};
  }

  const std::vector<double> segment_column = column(path, group.get(), name, "segment");
  const std::vector<double> time = column(path, group.get(), name, "time");
  const std::vector<double> piezo = column(path, group.get(), name, "height (piezo)");
  const std::vector<double> measured = column(path, group.get(), name, "height (measured)");
  const std::vector<double> tip = column(path, group.get(), name, "tip position");
  const std::vector<double> force = column(path, group.get(), name, "force");
  const std::size_t count = segment_column.size();
  for (const auto& [values, label] :
       {std::pair{&time, "time"}, std::pair{&piezo, "height (piezo)"},
        std::pair{&measured, "height (measured)"}, std::pair{&tip, "tip position"},
        std::pair{&force, "force"}}) {
    if (!values->empty() && values->size() != count) {
      refuse(path, "{}/{}: {} samples, the segment column has {}", name, label, values->size(),
             count);
    }
  }
  if (count == 0) refuse(path, "{}: no 'segment' column or an empty one", name);
  // Segments are runs of one segment number, in increasing order: the first the approach, the
  // last the retract, any between them pauses.
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 1; i < count; ++i) {
    if (segment_column[i] < segment_column[i - 1]) {
      refuse(path, "{}/segment: numbers decrease at sample {}", name, i);
    }
    if (segment_column[i] != segment_column[i - 1]) starts.push_back(i);
  }
  starts.push_back(count);
  const std::size_t segments = starts.size() - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    Segment segment;
    segment.kind = s == 0              ? SegmentKind::approach
                   : s + 1 == segments ? SegmentKind::retract
                                       : SegmentKind::pause;
    segment.name = segment_kind_name(segment.kind);
    const std::size_t begin = starts[s];
    const std::size_t end = starts[s + 1];
    segment.time = slice(time, begin, end);
    segment.piezo_height = slice(piezo, begin, end);
    segment.measured_height = slice(measured, begin, end);
    segment.tip_position = slice(tip, begin, end);
    segment.force = slice(force, begin, end);
    curve.segments.push_back(std::move(segment));
  }
  return curve;
}

}  // namespace

MeasuredFile read_afmformats_hdf5(const std::filesystem::path& path,
                                  const CalibrationOverride& overrides) {
  // The library's own error printing would add lines to standard error; the message says it.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) refuse(path, "HDF5 cannot open it (truncated or damaged?)");
  const std::vector<std::string> names = group_names(file.get());
  if (names.empty()) {
    refuse(path, "no curve groups '0', '1', ...: not an HDF5 file in afmformats' layout");
  }
  MeasuredFile result;
  result.path = path;
  result.format = "hdf5";
  for (const std::string& name : names) {
    try {
      result.curves.push_back(read_group(path, file.get(), name, overrides));
    } catch (const MeasuredFileError& error) {
      if (names.size() == 1) throw;
      result.curves.push_back(ForceCurve{.label = name, .unreadable = error.what()});
    }
  }
  return result;
}

}  // namespace mdrsim::measured
