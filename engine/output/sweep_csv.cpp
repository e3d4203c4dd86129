// Formatting sweep rows and reading sweep CSVs back, for --resume and merge.
#include "engine/output/sweep_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <fstream>

#include "engine/base/text.hpp"
#include "engine/model/snapshot_fields.hpp"
#include "engine/output/result_json.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr std::size_t kHeadBytes = 64 * 1024;

template <class T>
void append_field(fmt::memory_buffer& out, const std::optional<T>& value) {
  out.push_back(',');
  if (value) fmt::format_to(std::back_inserter(out), "{}", *value);
}

}  // namespace

std::string identity_line(const SweepIdentity& id) {
  return fmt::format("# mdrsim sweep: scene {:016x}, grid {:016x}, rows {}, shard {}/{}\n",
                     id.scene, id.grid, id.rows, id.shard.index, id.shard.count);
}

std::optional<SweepIdentity> parse_identity_line(std::string_view line) {
  if (line.size() > 200) return std::nullopt;
  const std::string text(line);
  SweepIdentity id;
  unsigned long long scene = 0, grid = 0, rows = 0, index = 0, count = 0;
  if (std::sscanf(text.c_str(),
                  "# mdrsim sweep: scene %16llx, grid %16llx, rows %llu, shard %llu/%llu", &scene,
                  &grid, &rows, &index, &count) != 5) {
    return std::nullopt;
  }
  id = {scene, grid, rows, {index, count}};
  // Only the exact form is one: no signs, spaces or leading zeros that sscanf lets through.
  if (count == 0 || index >= count || identity_line(id) != text + "\n") return std::nullopt;
  return id;
}

std::uint64_t scene_hash(std::string_view scene_bytes, const std::vector<std::string>& sets) {
  std::uint64_t h = fnv1a(scene_bytes);
  for (const std::string& set : sets) {
    h = fnv1a(std::string_view("\0", 1), h);
    h = fnv1a(set, h);
  }
  return h;
}

std::string csv_header(const SweepGrid& grid, SweepColumns columns) {
  const bool dimensionless = columns.dimensionless;
  std::string out = "status,stop_reason";
  for (const VarySpec& spec : grid.keys()) out += "," + spec.key;
  for (const SnapshotField& f : kSnapshotFields) out += std::string(",") + f.name;
  out += ",springs_in_contact";
  if (dimensionless) {
    for (const SnapshotField& f : kSnapshotFields) out += std::string(",dimensionless_") + f.name;
  }
  out += ",peak_normal_force";
  if (dimensionless) out += ",dimensionless_peak_normal_force";
  out += ",tangential_strength,critical_error_estimate";
  out += ",springs,glued_radius,preload_depth,preload_force,warnings,disk_valid";
  // Friction (docs/friction.md): the critical state's sliding springs and stick radius,
  // whether the contact slid away, and the frictional work of the whole run.
  if (columns.friction) out += ",springs_sliding,stick_radius,sliding,dissipated_by_friction";
  // A program's total work per axis (the JSON's `work`), last so that the columns before keep
  // their places.
  if (columns.work) out += ",work_normal,work_tangential";
  // What the dashpots and the rate law's front dissipated over the run (the JSON's `work`).
  if (columns.bulk) out += ",dissipated_by_bulk";
  if (columns.front) out += ",dissipated_at_front";
  return out + "\n";
}

// The status and its stop reason (empty but for step-limit) lead each row, and a run without a
// critical point leaves the critical columns empty, so that no plot mistakes it for one.
std::string csv_row(const std::vector<VaryValue>& values, const Scene& scene, const RunResult& r,
                    SweepColumns columns) {
  const bool dimensionless = columns.dimensionless;
  fmt::memory_buffer out;
  const auto s = dimensionless_scales(scene);
  fmt::format_to(std::back_inserter(out), "{},{}", to_string(r.status),
                 r.stop_reason ? to_string(*r.stop_reason) : "");
  for (std::size_t k = 0; k < values.size(); ++k) {
    out.push_back(',');
    const std::string& text = values[k].text;
    out.append(text.data(), text.data() + text.size());
  }
  const auto critical = [&](const SnapshotField& f, double scale) -> std::optional<double> {
    if (!r.critical) return std::nullopt;
    return *r.critical.*f.member / scale;
  };
  for (const SnapshotField& f : kSnapshotFields) append_field(out, critical(f, 1.0));
  append_field(
      out, r.critical ? std::optional<std::int64_t>(r.critical->springs_in_contact) : std::nullopt);
  if (dimensionless) {
    for (const SnapshotField& f : kSnapshotFields) {
      append_field(out, s ? critical(f, scale_of(*s, f.scale)) : std::nullopt);
    }
  }
  append_field(out, r.peak ? std::optional<double>(r.peak->normal_force) : std::nullopt);
  if (dimensionless) {
    append_field(
        out, s && r.peak ? std::optional<double>(r.peak->normal_force / s->force) : std::nullopt);
  }
  append_field(out, r.tangential_strength);
  append_field(out, r.accuracy.critical_error_estimate);
  // What the row ran: its finest row of springs (rtol picks it) and its preload state (a
  // program has none); then the number of warnings it logged, which a plot should not hide.
  append_field(out, std::optional<std::int64_t>(r.springs));
  const auto preload = [&](double value) {
    return scene.shorthand() ? std::optional<double>(value) : std::nullopt;
  };
  append_field(out, preload(scene.glued_radius));
  append_field(out, preload(scene.preload_depth));
  append_field(out, preload(scene.preload_force));
  append_field(out, std::optional<std::size_t>(r.warnings.size()));
  const std::string_view disk = r.disk_valid ? ",true" : ",false";
  out.append(disk.data(), disk.data() + disk.size());
  if (columns.friction) {
    // A row without friction (mu = 0 in a varied coefficient) slides nowhere: 0, and no work.
    const bool rubs = scene.friction.has_value();
    append_field(
        out, r.critical ? std::optional<std::int64_t>(r.critical->springs_sliding) : std::nullopt);
    append_field(out, r.critical ? std::optional<double>(r.critical->stick_radius) : std::nullopt);
    const std::string_view sliding = r.sliding ? ",true" : ",false";
    out.append(sliding.data(), sliding.data() + sliding.size());
    append_field(
        out, rubs && r.work ? std::optional<double>(r.work->friction) : std::optional<double>(0.0));
  }
  if (columns.work) {
    // A run without work (a scene without a program in a varied grid) leaves them empty.
    append_field(out, r.work ? std::optional<double>(r.work->normal) : std::nullopt);
    append_field(out, r.work ? std::optional<double>(r.work->tangential) : std::nullopt);
  }
  // A row whose scene lacks the key (a varied grid of scenes with and without it) leaves its
  // column empty, as a row without work does.
  if (columns.bulk) {
    const bool relaxes = scene.material.relaxes() && r.work;
    append_field(out, relaxes ? std::optional<double>(r.work->bulk) : std::nullopt);
  }
  if (columns.front) {
    const bool law = scene.front_speed_law.has_value() && r.work;
    append_field(out, law ? std::optional<double>(r.work->front) : std::nullopt);
  }
  out.push_back('\n');
  return fmt::to_string(out);
}

SweepFile read_sweep_file(const std::string& path, const std::string& who) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw UsageError(
        fmt::format("{}: cannot read '{}' ({})", who, printable(path), system_reason(errno)));
  }
  SweepFile file;
  std::uint64_t lines = 0;
  std::string line;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    const std::size_t n = static_cast<std::size_t>(in.gcount());
    if (file.head.size() < kHeadBytes) {
      file.head.append(buffer, std::min(n, kHeadBytes - file.head.size()));
    }
    for (std::size_t i = 0; i < n; ++i) {
      const char c = buffer[i];
      if (lines < 2) line += c;
      if (c != '\n') continue;
      ++lines;
      file.complete_bytes = file.size + i + 1;
      if (lines == 1) file.first_line = line.substr(0, line.size() - 1);
      if (lines == 2) file.header = line;
      if (lines <= 2) line.clear();
    }
    file.size += n;
  }
  if (in.bad()) {
    throw UsageError(fmt::format("{}: cannot read '{}' (read error)", who, printable(path)));
  }
  file.rows = lines > 2 ? lines - 2 : 0;
  return file;
}

}  // namespace mdrsim::cli
