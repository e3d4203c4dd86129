// The subcommands of mdrsim: options as parsed, and the functions that carry them out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mdrsim::cli {

struct RunOptions {
  std::string scene;
  std::vector<std::string> sets;       ///< KEY=VALUE
  std::string json;                    ///< path, "-" or empty (print a summary)
  std::string trajectory;              ///< CSV path or empty
  std::int64_t trajectory_stride = 1;  ///< every K-th ordinary row (trajectory_stride.hpp)
  std::int64_t samples = 1000;         ///< continuum route: branch points of --trajectory
  bool plan = false;                   ///< print the route plan and exit
};

struct SweepOptions {
  std::string scene;
  std::vector<std::string> vary;  ///< KEY=VALUES, one per varied key (docs/sweeps.md)
  std::vector<std::string> link;  ///< KEY=VALUES varied with a --vary key, not as a product
  /// For each --link, how many --vary came before it on the command line (it joins the axis
  /// of the last of them); empty: every --link follows the last --vary.
  std::vector<std::size_t> link_after;
  std::vector<std::string> where;  ///< conditions a row must pass to be run
  std::string design;              ///< grid (default), random or latin
  std::string samples;             ///< a random design's sample count, as given
  std::string seed;                ///< a random design's seed, as given
  std::vector<std::string> sets;
  std::string csv = "-";
  int threads = 1;
  std::string shard;    ///< I/N, or empty for all rows
  bool resume = false;  ///< finish the CSV at `csv` rather than start it again
  bool force = false;   ///< replace a CSV already at `csv` (else a non-empty file is refused)
};

struct MergeOptions {
  std::string out;                  ///< path or "-"
  std::vector<std::string> shards;  ///< the shard CSVs, in any order
};

struct FitOptions {
  std::vector<std::string> curves;  ///< measured files
  std::string tip;                  ///< SPEC's tip text
  std::string model = "hertz";
  double poisson_ratio = 0.5;
  std::string segment = "approach";
  std::string range;               ///< FROM:TO [m] of indentation, or empty
  std::vector<std::string> fixes;  ///< NAME=VALUE
  std::string json;                ///< path, "-" or empty
  std::string csv;                 ///< path, "-" or empty
  std::string plot;                ///< PNG path or empty
  int threads = 1;                 ///< curves fitted in parallel
  std::string shard;               ///< "I/N": files I, I+N, ... of `curves`; empty: all
  bool resume = false;             ///< skip the curves already in the CSV at `csv`
};

/// Each returns the process exit code; bad input throws SceneError or UsageError.
int run_command(const RunOptions& options);
int sweep_command(const SweepOptions& options);
int merge_command(const MergeOptions& options);
/// `mdrsim fit`: Hertz, DMT or JKR fitted to measured force curves (docs/afm.md).
int fit_command(const FitOptions& options);
/// `mdrsim list`: the registered parts with their keys and units, on standard output.
int list_command();

}  // namespace mdrsim::cli
