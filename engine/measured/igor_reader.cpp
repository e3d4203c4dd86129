// Igor binary waves, version 5 (Igor Pro technical note PTN003): a 64-byte BinHeader5, a
// 320-byte WaveHeader5, the data column by column, then the formula, the note and the
// dimension labels, each as long as the BinHeader5 says.
#include "engine/measured/igor_reader.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/base/text.hpp"
#include "engine/measured/measured_error.hpp"

namespace mdrsim::measured {
namespace {

constexpr std::size_t kBinHeaderSize = 64;
constexpr std::size_t kWaveHeaderSize = 320;
constexpr std::size_t kLabelSize = 32;  // MAX_DIM_LABEL_CHARS + 1

/// Reads little- or big-endian numbers from the file's bytes.
class Bytes {
 public:
  Bytes(const std::string& data, bool little) : data_(data), little_(little) {}

  template <typename T>
  T at(std::size_t offset) const {
    std::array<unsigned char, sizeof(T)> raw;
    std::memcpy(raw.data(), data_.data() + offset, sizeof(T));
    if (little_ != (std::endian::native == std::endian::little))
      std::reverse(raw.begin(), raw.end());
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    return value;
  }

 private:
  const std::string& data_;
  bool little_;
};

/// The note's "Key: value" lines (Asylum separates them by carriage returns).
std::map<std::string, std::string, std::less<>> note_entries(std::string_view note) {
  std::map<std::string, std::string, std::less<>> entries;
  std::size_t pos = 0;
  while (pos < note.size()) {
    std::size_t end = note.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = note.size();
    const std::string_view line = note.substr(pos, end - pos);
    const std::size_t colon = line.find(':');
    if (colon != std::string_view::npos) {
      entries.emplace(std::string(trim_blanks(line.substr(0, colon))),
                      std::string(trim_blanks(line.substr(colon + 1))));
    }
    pos = end + 1;
  }
  return entries;
}

std::optional<double> note_number(const std::map<std::string, std::string, std::less<>>& note,
                                  std::string_view key) {
  const auto found = note.find(key);
  if (found == note.end()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(found->second.c_str(), &end);
  if (end == found->second.c_str() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// Comma-separated numbers ("0,1008,2015", "NaN,1,-1,"), NaN where a field is not a number.
std::vector<double> number_list(std::string_view text) {
  std::vector<double> values;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find(',', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string field(trim_blanks(text.substr(pos, end - pos)));
    if (!field.empty()) {
      char* stop = nullptr;
      const double value = std::strtod(field.c_str(), &stop);
      values.push_back(stop == field.c_str() ? std::nan("") : value);
    }
    pos = end + 1;
  }
  return values;
}

std::optional<Calibrated> from_note(const std::map<std::string, std::string, std::less<>>& note,
                                    const char* key) {
  const auto value = note_number(note, key);
  if (!value) return std::nullopt;
  return Calibrated{*value, std::string("note '") + key + "'"};
}

}  // namespace

MeasuredFile read_igor(const std::filesystem::path& path, const CalibrationOverride& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, "cannot be opened ({})", system_reason(errno));
  const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (data.size() < 2) refuse(path, "truncated: {} bytes, not even an Igor header", data.size());
  const bool little = static_cast<unsigned char>(data[0]) != 0;
  const Bytes bytes(data, little);
  const auto version = bytes.at<std::int16_t>(0);
  if (version != 5) {
    refuse(path, "Igor binary wave version {} is not read (only version 5)", version);
  }
  if (data.size() < kBinHeaderSize + kWaveHeaderSize) {
    refuse(path, "truncated: {} bytes, the headers alone take {}", data.size(),
           kBinHeaderSize + kWaveHeaderSize);
  }
  std::uint16_t checksum = 0;
  for (std::size_t i = 0; i < kBinHeaderSize + kWaveHeaderSize; i += 2) {
    checksum = static_cast<std::uint16_t>(checksum + bytes.at<std::uint16_t>(i));
  }
  if (checksum != 0) refuse(path, "the Igor headers' checksum does not add up (damaged file)");

  // Sizes and counts are signed 32-bit in the file: a negative one is a damaged header. Below
  // 2^31 each, their sums and products below cannot overflow 64 bits.
  const auto size_at = [&](std::size_t offset, const char* what) {
    const auto value = bytes.at<std::int32_t>(offset);
    if (value < 0) refuse(path, "the Igor header's {} is {} (damaged file)", what, value);
    return static_cast<std::size_t>(value);
  };
  const std::size_t wave_size = size_at(4, "wave size");
  const std::size_t formula_size = size_at(8, "formula size");
  const std::size_t note_size = size_at(12, "note size");
  const std::size_t data_units_size = size_at(16, "units size");
  std::size_t dim_units_size = 0;
  for (std::size_t d = 0; d < 4; ++d) dim_units_size += size_at(20 + 4 * d, "units size");
  const std::size_t label_size_rows = size_at(36, "label size");
  const std::size_t label_size_columns = size_at(40, "label size");

  const std::size_t wave = kBinHeaderSize;
  const std::size_t points = size_at(wave + 12, "point count");
  const auto type = bytes.at<std::int16_t>(wave + 16);
  const std::size_t rows = size_at(wave + 68, "row count");
  const std::size_t columns = std::max<std::size_t>(1, size_at(wave + 72, "column count"));
  if (bytes.at<std::int32_t>(wave + 76) > 1) refuse(path, "a wave of more than two dimensions");
  if (rows * columns != points) {
    refuse(path, "{} rows x {} columns but {} points (damaged header)", rows, columns, points);
  }
  std::size_t width = 0;
  switch (type) {
    case 2:
      width = 4;
      break;  // NT_FP32
    case 4:
      width = 8;
      break;  // NT_FP64
    case 0x08:
    case 0x48:
      width = 1;
      break;
    case 0x10:
    case 0x50:
      width = 2;
      break;
    case 0x20:
    case 0x60:
      width = 4;
      break;
    default:
      refuse(path, "Igor number type {:#x} is not read (real numbers only)", type);
  }
  const std::size_t values_at = kBinHeaderSize + kWaveHeaderSize;
  const std::size_t note_at = kBinHeaderSize + wave_size + formula_size;
  const std::size_t labels_at =
      note_at + note_size + data_units_size + dim_units_size + label_size_rows;
  if (wave_size < kWaveHeaderSize + points * width ||
      data.size() < labels_at + label_size_columns) {
    refuse(path, "truncated: {} bytes, the headers promise {}", data.size(),
           labels_at + label_size_columns);
  }
  const auto value = [&](std::size_t i) -> double {
    const std::size_t at = values_at + i * width;
    switch (type) {
      case 2:
        return bytes.at<float>(at);
      case 4:
        return bytes.at<double>(at);
      case 0x08:
        return bytes.at<std::int8_t>(at);
      case 0x48:
        return bytes.at<std::uint8_t>(at);
      case 0x10:
        return bytes.at<std::int16_t>(at);
      case 0x50:
        return bytes.at<std::uint16_t>(at);
      case 0x20:
        return bytes.at<std::int32_t>(at);
      default:
        return bytes.at<std::uint32_t>(at);
    }
  };
  // Column labels: the first label of the dimension names the dimension itself.
  std::vector<std::string> labels;
  const std::size_t label_count = label_size_columns / kLabelSize;
  for (std::size_t l = label_count > columns ? label_count - columns : 0; l < label_count; ++l) {
    const char* text = data.data() + labels_at + l * kLabelSize;
    labels.emplace_back(text, strnlen(text, kLabelSize));
  }
  const auto column_of =
      [&](std::initializer_list<const char*> names) -> std::optional<std::size_t> {
    for (const char* name : names) {
      const auto found = std::find(labels.begin(), labels.end(), name);
      if (found != labels.end()) return static_cast<std::size_t>(found - labels.begin());
    }
    return std::nullopt;
  };
  const auto note = note_entries(std::string_view(data).substr(note_at, note_size));

  const auto piezo = column_of({"Raw", "Height"});
  const auto measured = column_of({"ZSnsr", "ZSensor"});
  const auto deflection = column_of({"Defl", "Deflection"});
  if ((!piezo && !measured) || !deflection) {
    refuse(path,
           "no force curve in the wave: it needs a height column (Raw, Height, ZSnsr or "
           "ZSensor) and a deflection column (Defl or Deflection); its columns are '{}'",
           join_names(labels));
  }
  const auto column_values = [&](std::optional<std::size_t> c, double sign, std::size_t begin,
                                 std::size_t end) {
    std::vector<double> values;
    if (!c) return values;
    values.reserve(end - begin);
    for (std::size_t i = begin; i < end; ++i) values.push_back(sign * value(*c * rows + i));
    return values;
  };

  ForceCurve curve;
  curve.calibration.sensitivity = from_note(note, "InvOLS");
  curve.calibration.spring_constant = from_note(note, "SpringConstant");
  curve.calibration.approach_speed = from_note(note, "ApproachVelocity");
  curve.calibration.retract_speed = from_note(note, "RetractVelocity");
  if (overrides.sensitivity)
    curve.calibration.sensitivity = Calibrated{*overrides.sensitivity, "override"};
  if (overrides.spring_constant) {
    curve.calibration.spring_constant = Calibrated{*overrides.spring_constant, "override"};
  }
  const std::optional<double> rate = note_number(note, "NumPtsPerSec");

  // "Indexes: 0,1008,2015" ends each segment at an index (the first entry is the start) and
  // "Direction: NaN,1,-1," says which way it moves: 1 towards the sample, -1 away, 0 a pause.
  std::vector<double> ends =
      note.contains("Indexes") ? number_list(note.find("Indexes")->second) : std::vector<double>{};
  std::vector<double> directions = note.contains("Direction")
                                       ? number_list(note.find("Direction")->second)
                                       : std::vector<double>{};
  if (ends.size() < 2) {
    ends = {0.0, static_cast<double>(rows) - 1.0};
    directions = {std::nan(""), 1.0};
  }
  for (std::size_t s = 1; s < ends.size(); ++s) {
    const double first = s == 1 ? ends[0] : ends[s - 1] + 1.0;
    const double last = ends[s];
    if (!(first >= 0.0 && last >= first - 1.0 && last < static_cast<double>(rows))) {
      refuse(path, "note 'Indexes' segment {} [{}, {}] lies outside the wave's {} rows", s, first,
             last, rows);
    }
    const auto begin = static_cast<std::size_t>(first);
    const auto end = static_cast<std::size_t>(last + 1.0);
    const double direction = s < directions.size() ? directions[s] : std::nan("");
    Segment segment;
    segment.kind = direction > 0.0   ? SegmentKind::approach
                   : direction < 0.0 ? SegmentKind::retract
                                     : SegmentKind::pause;
    segment.name = segment_kind_name(segment.kind);
    // Asylum's heights grow towards the sample; afmformats' sign has them shrink.
    segment.piezo_height = column_values(piezo, -1.0, begin, end);
    segment.measured_height = column_values(measured, -1.0, begin, end);
    segment.deflection = column_values(deflection, 1.0, begin, end);
    if (rate && *rate > 0.0) {
      for (std::size_t i = begin; i < end; ++i)
        segment.time.push_back(static_cast<double>(i) / *rate);
    }
    curve.segments.push_back(std::move(segment));
  }
  MeasuredFile result;
  result.path = path;
  result.format = "igor";
  result.curves.push_back(std::move(curve));
  return result;
}

}  // namespace mdrsim::measured
