// A sweep's design: the product grid of its axes, or N samples drawn uniformly (random) or one
// per stratum of every axis (Latin hypercube), reproducible from a seed on any machine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mdrsim::cli {

struct SweepDesign {
  enum class Kind { grid, random, latin };

  Kind kind = Kind::grid;
  std::uint64_t samples = 0;  ///< a random or Latin design's sample count
  std::uint64_t seed = 0;

  bool drawn() const { return kind != Kind::grid; }
  static constexpr std::uint64_t kMaxSamples = 100'000'000;
  /// A Latin hypercube keeps one permutation of its samples per axis in memory.
  static constexpr std::uint64_t kMaxLatinSamples = 10'000'000;
};

/// --design NAME, --samples N, --seed S as given (an empty text: not given); throws
/// UsageError naming the flag: an unknown design, samples or a seed without a random
/// design, a random design without --samples, a count or seed that is not a whole number.
SweepDesign parse_design(const std::string& kind, const std::string& samples,
                         const std::string& seed);
/// "grid", "random", "latin".
const char* to_string(SweepDesign::Kind kind);

/// The draws t in [0, 1) of a random design, one per sample and axis. random: SplitMix64 of
/// (seed, axis, sample), its top 53 bits. latin: sample i of axis a lies in stratum p_a(i) of
/// the axis' N equal strata, [p/N, (p+1)/N), p_a a permutation of 0..N-1 shuffled
/// (Fisher-Yates) from the seed, at a uniform draw inside the stratum.
class DesignDraws {
 public:
  DesignDraws() = default;
  DesignDraws(const SweepDesign& design, std::size_t axes);

  double draw(std::uint64_t sample, std::size_t axis) const;

 private:
  SweepDesign design_;
  std::vector<std::vector<std::uint32_t>> strata_;  ///< latin: p_a(i) per axis
};

/// SplitMix64's output function: a 64-bit mix with every input bit reaching every output bit.
std::uint64_t splitmix64(std::uint64_t z);

}  // namespace mdrsim::cli
