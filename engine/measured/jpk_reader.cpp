// JPK force files: zip archives of Java properties and big-endian channel data with conversion
// sets (volts -> distance -> force for the deflection, volts -> nominal -> calibrated for the
// piezo height).
#include "engine/measured/jpk_reader.hpp"

#include <zip.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "engine/measured/java_properties.hpp"
#include "engine/measured/measured_error.hpp"

namespace mdrsim::measured {
namespace {

/// The archive, open for reading, with the names of its entries.
class ZipArchive {
 public:
  explicit ZipArchive(const std::filesystem::path& path) : path_(path) {
    int code = 0;
    archive_ = zip_open(path.c_str(), ZIP_RDONLY, &code);
    if (archive_ == nullptr) {
      zip_error_t error;
      zip_error_init_with_code(&error, code);
      const std::string reason = zip_error_strerror(&error);
      zip_error_fini(&error);
      refuse(path_, "not a readable zip archive, as a JPK file is ({}; truncated?)",
             lowercase(reason));
    }
    const zip_int64_t count = zip_get_num_entries(archive_, 0);
    for (zip_int64_t i = 0; i < count; ++i) {
      const char* name = zip_get_name(archive_, static_cast<zip_uint64_t>(i), 0);
      if (name != nullptr) names_.insert(name);
    }
  }
  ZipArchive(const ZipArchive&) = delete;
  ZipArchive& operator=(const ZipArchive&) = delete;
  ~ZipArchive() { zip_discard(archive_); }

  bool has(const std::string& name) const { return names_.contains(name); }
  /// Whether any entry's name starts with `folder`.
  bool has_under(const std::string& folder) const {
    const auto it = names_.lower_bound(folder);
    return it != names_.end() && it->starts_with(folder);
  }
  const std::set<std::string>& names() const { return names_; }

  std::string read(const std::string& name) const {
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat(archive_, name.c_str(), 0, &stat) != 0 || (stat.valid & ZIP_STAT_SIZE) == 0) {
      refuse(path_, "{}: missing from the archive", name);
    }
    // A damaged directory can claim any size; no JPK entry comes near a gigabyte.
    if (stat.size > (zip_uint64_t{1} << 30)) {
      refuse(path_, "{}: {} bytes claimed (damaged archive?)", name, stat.size);
    }
    zip_file_t* file = zip_fopen(archive_, name.c_str(), 0);
    if (file == nullptr) refuse(path_, "{}: {}", name, lowercase(zip_strerror(archive_)));
    std::string bytes(static_cast<std::size_t>(stat.size), '\0');
    const zip_int64_t got = zip_fread(file, bytes.data(), bytes.size());
    // A damaged entry shows at its end: the CRC is checked once all of it has been read.
    char probe = 0;
    const zip_int64_t extra = got < 0 ? 0 : zip_fread(file, &probe, 1);
    std::string reason = got < 0 || extra < 0 ? lowercase(zip_file_strerror(file)) : "";
    zip_fclose(file);
    if (!reason.empty()) refuse(path_, "{}: {}", name, reason);
    if (got != static_cast<zip_int64_t>(bytes.size())) {
      refuse(path_, "{}: {} of {} bytes could be read", name, got, bytes.size());
    }
    return bytes;
  }

 private:
  static std::string lowercase(std::string text) {
    // "Not a zip archive" continues a message; "CRC error" keeps its capitals.
    if (text.size() > 1 && std::islower(static_cast<unsigned char>(text[1]))) {
      text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    }
    return text;
  }

  std::filesystem::path path_;
  zip_t* archive_ = nullptr;
  std::set<std::string> names_;
};

/// The series types whose header holds a curve's position (force maps and QI).
constexpr std::string_view kSeriesTypes[] = {"force-scan-series", "quantitative-imaging-series"};
constexpr std::string_view kMapTypes[] = {"force-scan-map", "quantitative-imaging-map"};

/// Replaces each "head.mediator.*=N" key by the shared-data keys "mediator.N.rest", as
/// "head.rest" (JPK writes what every curve shares once, in shared-data/header.properties).
void substitute_shared(Properties& properties, const Properties& shared) {
  std::vector<std::pair<std::string, std::string>> links;
  for (const auto& [key, value] : properties) {
    if (key.size() > 2 && key.ends_with(".*")) links.emplace_back(key, value);
  }
  for (const auto& [key, value] : links) {
    const std::string stem = key.substr(0, key.size() - 2);  // head.mediator
    const std::size_t dot = stem.rfind('.');
    if (dot == std::string::npos) continue;
    const std::string head = stem.substr(0, dot);
    const std::string prefix = stem.substr(dot + 1) + "." + value + ".";
    for (auto it = shared.lower_bound(prefix); it != shared.end() && it->first.starts_with(prefix);
         ++it) {
      properties.try_emplace(head + "." + it->first.substr(prefix.size()), it->second);
    }
  }
}

/// A number that is present and not NaN (JPK writes NaN for settings it does not use).
std::optional<double> finite_number(const Properties& properties, const std::string& key) {
  const auto value = property_number(properties, key);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

/// The value of the first of `keys` present.
std::optional<std::string> first_text(const Properties& properties,
                                      std::initializer_list<std::string> keys) {
  for (const std::string& key : keys) {
    if (auto value = property_text(properties, key)) return value;
  }
  return std::nullopt;
}

/// The first of `keys` present as a finite number.
std::optional<double> first_number(const Properties& properties,
                                   std::initializer_list<std::string> keys) {
  for (const std::string& key : keys) {
    if (const auto value = finite_number(properties, key)) return value;
  }
  return std::nullopt;
}

/// One step of a conversion set: value = multiplier * (value of the base slot) + offset.
struct Scaling {
  double multiplier = 1.0;
  double offset = 0.0;
};

/// What the user overrides: the step into `slot` of `channel` becomes (multiplier, 0) from `base`.
struct SlotOverride {
  std::string_view channel;
  std::string_view slot;
  std::string_view base;
  double multiplier = 0.0;
};

/// The channel's conversion from its raw volts to `slot`, steps in the order they apply, or
/// nullopt when the slot is not defined (a calibration the file does not have).
std::optional<std::vector<Scaling>> conversion_to(const Properties& properties,
                                                  const std::string& channel, std::string slot,
                                                  const std::vector<SlotOverride>& overrides) {
  const std::string set = "channel." + channel + ".conversion-set";
  const std::string base = property_text(properties, set + ".conversions.base").value_or("volts");
  std::vector<Scaling> steps;
  for (int depth = 0; slot != base; ++depth) {
    if (depth > 8) return std::nullopt;
    const auto override_it = std::find_if(overrides.begin(), overrides.end(), [&](const auto& o) {
      return o.channel == channel && o.slot == slot;
    });
    if (override_it != overrides.end()) {
      steps.push_back({override_it->multiplier, 0.0});
      slot = std::string(override_it->base);
      continue;
    }
    const std::string conversion = set + ".conversion." + slot;
    if (property_text(properties, conversion + ".defined") != "true") return std::nullopt;
    const auto multiplier = finite_number(properties, conversion + ".scaling.multiplier");
    const auto offset = finite_number(properties, conversion + ".scaling.offset");
    const auto from = property_text(properties, conversion + ".base-calibration-slot");
    if (!multiplier || !from) return std::nullopt;
    steps.push_back({*multiplier, offset.value_or(0.0)});
    slot = *from;
  }
  std::reverse(steps.begin(), steps.end());
  return steps;
}

/// The slot's unit ("m", "N"), as the conversion set names it.
std::string slot_unit(const Properties& properties, const std::string& channel,
                      const std::string& slot) {
  const std::string scaling =
      "channel." + channel + ".conversion-set.conversion." + slot + ".scaling.unit";
  return property_text(properties, scaling + ".unit")
      .value_or(property_text(properties, scaling).value_or(""));
}

/// The channel's samples in its raw unit (volts): the encoder's integers times its multiplier
/// plus its offset, or big-endian floats where the channel has no encoder.
std::vector<double> raw_channel(const std::filesystem::path& path, const std::string& entry,
                                const std::string& bytes, const Properties& properties,
                                const std::string& channel) {
  // Keys of the segment's own header carry ".data."; those taken from shared-data do not.
  const auto text = [&](const std::string& rest) {
    return first_text(properties,
                      {"channel." + channel + ".data." + rest, "channel." + channel + "." + rest});
  };
  const auto number = [&](const std::string& rest) {
    return first_number(
        properties, {"channel." + channel + ".data." + rest, "channel." + channel + "." + rest});
  };
  const std::string encoder = text("encoder.type").value_or("");
  const std::string type = text("type").value_or("");
  std::size_t width = 0;
  bool is_signed = true;
  bool is_float = false;
  if (encoder == "signedshort" || encoder == "unsignedshort") {
    width = 2;
    is_signed = encoder == "signedshort";
  } else if (encoder == "signedinteger" || encoder == "unsignedinteger") {
    width = 4;
    is_signed = encoder == "signedinteger";
  } else if (encoder == "signedlong" || encoder == "unsignedlong") {
    width = 8;
    is_signed = encoder == "signedlong";
  } else if (encoder.empty() && (type == "float" || type == "float-data")) {
    width = 4;
    is_float = true;
  } else if (encoder.empty() && (type == "double" || type == "double-data")) {
    width = 8;
    is_float = true;
  } else {
    refuse(path, "{}: unknown data encoding '{}'", entry, encoder.empty() ? type : encoder);
  }
  if (bytes.size() % width != 0) {
    refuse(path, "{}: {} bytes is not a whole number of {}-byte samples", entry, bytes.size(),
           width);
  }
  const double multiplier = is_float ? 1.0 : number("encoder.scaling.multiplier").value_or(1.0);
  const double offset = is_float ? 0.0 : number("encoder.scaling.offset").value_or(0.0);
  std::vector<double> values(bytes.size() / width);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint64_t word = 0;
    for (std::size_t b = 0; b < width; ++b) word = (word << 8) | data[i * width + b];
    double value = 0.0;
    if (is_float && width == 4) {
      value = std::bit_cast<float>(static_cast<std::uint32_t>(word));
    } else if (is_float) {
      value = std::bit_cast<double>(word);
    } else if (is_signed) {
      const unsigned shift = static_cast<unsigned>(64 - 8 * width);
      value = static_cast<double>(static_cast<std::int64_t>(word << shift) >> shift);
    } else {
      value = static_cast<double>(word);
    }
    values[i] = value * multiplier + offset;
  }
  return values;
}

/// A curve's folder in the archive: "" for a single curve, "index/N/" in a map.
struct CurveFolder {
  std::string label;
  std::string prefix;
};

std::vector<CurveFolder> curve_folders(const ZipArchive& archive,
                                       const std::filesystem::path& path) {
  const auto& names = archive.names();
  const bool single = std::any_of(names.begin(), names.end(),
                                  [](const std::string& n) { return n.starts_with("segments/"); });
  if (single) return {{"", ""}};
  std::set<long> indices;
  for (const std::string& name : names) {
    if (!name.starts_with("index/")) continue;
    const std::size_t slash = name.find('/', 6);
    if (slash == std::string::npos || slash == 6) continue;
    const std::string digits = name.substr(6, slash - 6);
    if (digits.size() <= 9 &&
        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      indices.insert(std::stol(digits));
    }
  }
  if (indices.empty()) {
    refuse(path, "no segments/ or index/ folder: a zip archive, but not a JPK force file");
  }
  std::vector<CurveFolder> folders;
  for (const long index : indices) {
    folders.push_back({"index/" + std::to_string(index), "index/" + std::to_string(index) + "/"});
  }
  return folders;
}

SegmentKind segment_kind(const std::filesystem::path& path, const std::string& where,
                         const std::string& style) {
  if (style == "extend") return SegmentKind::approach;
  if (style == "retract") return SegmentKind::retract;
  if (style == "pause") return SegmentKind::pause;
  refuse(path, "{}: unknown segment style '{}' (known: extend, retract, pause)", where, style);
}

/// The channel's samples in `slot` (unit `unit`), or empty when the file cannot give them.
std::vector<double> channel_in(const std::vector<double>& volts, const Properties& properties,
                               const std::string& channel, const std::string& slot,
                               const std::string& unit,
                               const std::vector<SlotOverride>& overrides) {
  const auto steps = conversion_to(properties, channel, slot, overrides);
  if (!steps) return {};
  const bool overridden = std::any_of(overrides.begin(), overrides.end(), [&](const auto& o) {
    return o.channel == channel && o.slot == slot;
  });
  if (!overridden && slot_unit(properties, channel, slot) != unit) return {};
  std::vector<double> values = volts;
  for (const Scaling& step : *steps) {
    for (double& v : values) v = step.multiplier * v + step.offset;
  }
  return values;
}

struct ChannelFile {
  std::string channel;
  std::string entry;
};

/// The first of `candidates` that the segment has a data file for.
std::optional<ChannelFile> find_channel(const ZipArchive& archive, const Properties& properties,
                                        const std::string& folder,
                                        std::initializer_list<const char*> candidates) {
  for (const char* channel : candidates) {
    const std::string name =
        property_text(properties, std::string("channel.") + channel + ".data.file.name")
            .value_or(std::string("channels/") + channel + ".dat");
    if (archive.has(folder + name)) return ChannelFile{channel, folder + name};
  }
  return std::nullopt;
}

Calibration calibration_of(const Properties& properties, const CalibrationOverride& overrides) {
  Calibration calibration;
  const std::string set = "channel.vDeflection.conversion-set.conversion.";
  const auto defined = [&](const std::string& slot) {
    return property_text(properties, set + slot + ".defined") == "true";
  };
  if (overrides.sensitivity) {
    calibration.sensitivity = Calibrated{*overrides.sensitivity, "override"};
  } else if (const auto value = finite_number(properties, set + "distance.scaling.multiplier");
             value && defined("distance")) {
    calibration.sensitivity = Calibrated{*value, set + "distance.scaling.multiplier"};
  }
  if (overrides.spring_constant) {
    calibration.spring_constant = Calibrated{*overrides.spring_constant, "override"};
  } else if (const auto value = finite_number(properties, set + "force.scaling.multiplier");
             value && defined("force")) {
    calibration.spring_constant = Calibrated{*value, set + "force.scaling.multiplier"};
  }
  return calibration;
}

/// The piezo's speed over a segment: |z-start - z-end| / duration of its settings.
std::optional<Calibrated> segment_speed(const Properties& properties) {
  const std::string settings = "force-segment-header.settings.segment-settings.";
  const auto start = finite_number(properties, settings + "z-start");
  const auto end = finite_number(properties, settings + "z-end");
  const auto duration = finite_number(properties, settings + "duration");
  if (!start || !end || !duration || *duration <= 0.0) return std::nullopt;
  return Calibrated{std::abs(*start - *end) / *duration, settings + "z-start, z-end and duration"};
}

ForceCurve read_curve(const ZipArchive& archive, const std::filesystem::path& path,
                      const CurveFolder& folder, const Properties& general,
                      const Properties& shared, const CalibrationOverride& overrides) {
  ForceCurve curve;
  curve.label = folder.label;
  const std::string header = folder.prefix + "header.properties";
  const Properties curve_properties =
      archive.has(header) ? parse_properties(archive.read(header)) : general;
  for (const std::string_view series : kSeriesTypes) {
    const std::string head = std::string(series) + ".header.";
    const auto x = finite_number(curve_properties, head + "position.x");
    const auto y = finite_number(curve_properties, head + "position.y");
    if (x && y) {
      const auto index = finite_number(curve_properties, head + "position-index");
      const bool whole = index && std::abs(*index) < 1e9;
      curve.position = MapPosition{*x, *y, whole ? std::lround(*index) : 0};
      break;
    }
  }
  std::vector<SlotOverride> slot_overrides;
  if (overrides.sensitivity) {
    slot_overrides.push_back({"vDeflection", "distance", "volts", *overrides.sensitivity});
  }
  if (overrides.spring_constant) {
    slot_overrides.push_back({"vDeflection", "force", "distance", *overrides.spring_constant});
  }
  double start_time = 0.0;
  for (int number = 0;; ++number) {
    const std::string segment_folder = folder.prefix + "segments/" + std::to_string(number) + "/";
    const std::string segment_header = segment_folder + "segment-header.properties";
    if (!archive.has(segment_header)) {
      if (archive.has_under(segment_folder)) refuse(path, "{}: missing", segment_header);
      break;
    }
    Properties properties = parse_properties(archive.read(segment_header));
    properties.insert(curve_properties.begin(), curve_properties.end());
    substitute_shared(properties, shared);
    properties.insert(general.begin(), general.end());

    Segment segment;
    const std::string where = folder.prefix + "segments/" + std::to_string(number);
    const std::string style =
        first_text(properties, {"force-segment-header.settings.style",
                                "force-segment-header.settings.segment-settings.style"})
            .value_or("");
    segment.kind = segment_kind(path, where, style);
    segment.name =
        first_text(properties, {"force-segment-header.name.name",
                                "force-segment-header.settings.segment-settings.identifier.name"})
            .value_or(style);
    const auto points = finite_number(properties, "force-segment-header.num-points");
    if (!points || *points < 0.0 || *points > 1e9) {
      refuse(path, "{}: no force-segment-header.num-points between 0 and 1e9", where);
    }
    const auto count = static_cast<std::size_t>(std::lround(*points));

    const auto read_volts = [&](const ChannelFile& file) {
      std::vector<double> volts =
          raw_channel(path, file.entry, archive.read(file.entry), properties, file.channel);
      if (volts.size() != count) {
        refuse(path, "{}: {} samples, the segment header says {}", file.entry, volts.size(), count);
      }
      return volts;
    };
    if (const auto height =
            find_channel(archive, properties, segment_folder, {"height", "head-height"})) {
      const std::vector<double> volts = read_volts(*height);
      segment.piezo_height = channel_in(volts, properties, height->channel, "calibrated", "m", {});
      if (segment.piezo_height.empty()) {
        segment.piezo_height = channel_in(volts, properties, height->channel, "nominal", "m", {});
      }
    }
    if (const auto measured =
            find_channel(archive, properties, segment_folder,
                         {"strainGaugeHeight", "capacitiveSensorHeight", "measuredHeight"})) {
      segment.measured_height =
          channel_in(read_volts(*measured), properties, measured->channel, "nominal", "m", {});
    }
    if (const auto deflection =
            find_channel(archive, properties, segment_folder, {"vDeflection"})) {
      const std::vector<double> volts = read_volts(*deflection);
      segment.deflection =
          channel_in(volts, properties, "vDeflection", "distance", "m", slot_overrides);
      segment.force = channel_in(volts, properties, "vDeflection", "force", "N", slot_overrides);
    }
    const double duration =
        finite_number(properties, "force-segment-header.duration").value_or(0.0);
    if (duration > 0.0) {
      segment.time.resize(count);
      for (std::size_t i = 0; i < count; ++i) {
        segment.time[i] =
            start_time + duration * static_cast<double>(i) / static_cast<double>(count);
      }
      start_time += duration;
    }
    if (number == 0) curve.calibration = calibration_of(properties, overrides);
    if (segment.kind == SegmentKind::approach && !curve.calibration.approach_speed) {
      curve.calibration.approach_speed = segment_speed(properties);
    }
    if (segment.kind == SegmentKind::retract && !curve.calibration.retract_speed) {
      curve.calibration.retract_speed = segment_speed(properties);
    }
    curve.segments.push_back(std::move(segment));
  }
  return curve;
}

}  // namespace

MeasuredFile read_jpk(const std::filesystem::path& path, const std::string& format,
                      const CalibrationOverride& overrides) {
  const ZipArchive archive(path);
  const std::vector<CurveFolder> folders = curve_folders(archive, path);
  const Properties general = archive.has("header.properties")
                                 ? parse_properties(archive.read("header.properties"))
                                 : Properties{};
  if (folders.size() == 1 && folders.front().prefix.empty() && general.empty()) {
    refuse(path, "no header.properties: a zip archive, but not a JPK force file");
  }
  const Properties shared = archive.has("shared-data/header.properties")
                                ? parse_properties(archive.read("shared-data/header.properties"))
                                : Properties{};
  MeasuredFile file;
  file.path = path;
  file.format = format;
  for (const std::string_view map : kMapTypes) {
    const std::string grid = std::string(map) + ".position-pattern.grid.";
    const auto columns = finite_number(general, grid + "ilength");
    const auto rows = finite_number(general, grid + "jlength");
    if (columns && rows && *columns >= 0.0 && *rows >= 0.0 && *columns < 1e9 && *rows < 1e9) {
      file.grid = MapGrid{std::lround(*columns),
                          std::lround(*rows),
                          finite_number(general, grid + "ulength").value_or(0.0),
                          finite_number(general, grid + "vlength").value_or(0.0),
                          finite_number(general, grid + "xcenter").value_or(0.0),
                          finite_number(general, grid + "ycenter").value_or(0.0)};
      break;
    }
  }
  for (const CurveFolder& folder : folders) {
    try {
      file.curves.push_back(read_curve(archive, path, folder, general, shared, overrides));
    } catch (const MeasuredFileError& error) {
      if (folders.size() == 1) throw;
      file.curves.push_back(ForceCurve{.label = folder.label, .unreadable = error.what()});
    }
  }
  return file;
}

}  // namespace mdrsim::measured
