// The sweep CSV: its identity line, header and rows, and what a sweep CSV on disk holds.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"
#include "engine/sweep/sweep_grid.hpp"

namespace mdrsim::cli {

/// What a sweep CSV is a sweep of: its first line, `# mdrsim sweep: scene S, grid G, rows M,
/// shard I/N` (S and G as 16 hex digits, M the rows of the whole grid).
struct SweepIdentity {
  std::uint64_t scene = 0;  ///< FNV-1a of the scene file's bytes and the --set texts
  std::uint64_t grid = 0;   ///< SweepGrid::hash()
  std::uint64_t rows = 0;
  Shard shard;

  bool operator==(const SweepIdentity&) const = default;
};

/// The identity line, with its newline.
std::string identity_line(const SweepIdentity& identity);
/// A line (without its newline) read back; nullopt unless it is exactly an identity line.
std::optional<SweepIdentity> parse_identity_line(std::string_view line);

/// FNV-1a of the scene file's bytes, then of a NUL byte and the text of each --set in turn.
std::uint64_t scene_hash(std::string_view scene_bytes, const std::vector<std::string>& sets);

/// The columns a sweep adds where some row has them: dimensionless (the rows' JKR scales)
/// friction, a program's total work, and the dissipations of time: a relaxing bulk's
/// (material.relaxation) and the rate law's front's (detachment.front_speed_law)
/// (docs/sweeps.md "Rows").
struct SweepColumns {
  bool dimensionless = false;
  bool friction = false;
  bool work = false;
  bool bulk = false;
  bool front = false;
};

/// The header line, with its newline: status, stop_reason, the varied keys, the run's fields.
std::string csv_header(const SweepGrid& grid, SweepColumns columns);
/// One row, with its newline; `values` are the row's, one per key (SweepGrid::values).
std::string csv_row(const std::vector<VaryValue>& values, const Scene& scene,
                    const RunResult& result, SweepColumns columns);

/// A sweep CSV as found on disk: complete lines end in a newline; a last line without one
/// is torn (the writer was killed during it).
struct SweepFile {
  std::string first_line;            ///< without its newline; empty when there is none
  std::string header;                ///< the second line, with its newline; empty when incomplete
  std::uint64_t rows = 0;            ///< complete lines after the header
  std::uint64_t complete_bytes = 0;  ///< the bytes up to and with the last newline
  std::uint64_t size = 0;
  std::string head;  ///< the first min(size, 64 KiB) bytes, to compare a torn start with
};

/// Reads the file at `path`; throws UsageError "WHO: cannot read 'PATH' (why)".
SweepFile read_sweep_file(const std::string& path, const std::string& who);

}  // namespace mdrsim::cli
