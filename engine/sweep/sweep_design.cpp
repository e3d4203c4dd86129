// Random and Latin hypercube designs: counter-based draws, so that any row is drawn on its own
// (a shard, a resumed sweep) and every machine draws the same.
#include "engine/sweep/sweep_design.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string_view>
#include <utility>

#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

/// Streams of draws: the uniform draws of a sample, and the shuffles of a Latin design.
constexpr std::uint64_t kUniformStream = 0;
constexpr std::uint64_t kShuffleStream = 1;

/// The top 53 bits of a 64-bit draw as a double in [0, 1).
double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1p-53; }

std::uint64_t draw_bits(std::uint64_t seed, std::uint64_t stream, std::uint64_t axis,
                        std::uint64_t sample) {
  return splitmix64(splitmix64(splitmix64(splitmix64(seed) ^ stream) ^ axis) ^ sample);
}

}  // namespace

std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

const char* to_string(SweepDesign::Kind kind) {
  switch (kind) {
    case SweepDesign::Kind::random:
      return "random";
    case SweepDesign::Kind::latin:
      return "latin";
    case SweepDesign::Kind::grid:
      break;
  }
  return "grid";
}

SweepDesign parse_design(const std::string& kind, const std::string& samples,
                         const std::string& seed) {
  SweepDesign design;
  if (kind == "random") {
    design.kind = SweepDesign::Kind::random;
  } else if (kind == "latin") {
    design.kind = SweepDesign::Kind::latin;
  } else if (!kind.empty() && kind != "grid") {
    throw UsageError(
        fmt::format("--design: unknown '{}' (known: grid, latin, random)", printable(kind)));
  }
  if (!design.drawn()) {
    if (!samples.empty()) {
      throw UsageError(
          "--samples: a grid has the rows of its --vary values (--samples belongs "
          "to --design random or latin)");
    }
    if (!seed.empty()) {
      throw UsageError("--seed: a grid draws nothing (--seed belongs to --design random or latin)");
    }
    return design;
  }
  const std::uint64_t most = design.kind == SweepDesign::Kind::latin ? SweepDesign::kMaxLatinSamples
                                                                     : SweepDesign::kMaxSamples;
  if (samples.empty()) {
    throw UsageError(fmt::format("--samples: --design {} needs --samples N", kind));
  }
  if (!read_whole_number(samples, design.samples) || design.samples < 1 || design.samples > most) {
    throw UsageError(fmt::format("--samples: '{}' is not a whole number from 1 to {} (--design {})",
                                 printable(samples), most, kind));
  }
  if (!seed.empty() && !read_whole_number(seed, design.seed)) {
    throw UsageError(fmt::format("--seed: '{}' is not a whole number from 0 to {}", printable(seed),
                                 UINT64_MAX));
  }
  return design;
}

DesignDraws::DesignDraws(const SweepDesign& design, std::size_t axes) : design_(design) {
  if (design.kind != SweepDesign::Kind::latin) return;
  const auto n = static_cast<std::uint32_t>(design.samples);
  strata_.resize(axes);
  for (std::size_t a = 0; a < axes; ++a) {
    std::vector<std::uint32_t>& p = strata_[a];
    p.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) p[i] = i;
    for (std::uint32_t i = n; i-- > 1;) {
      // The bias of a 64-bit draw taken modulo at most 1e7 is below 1e-12.
      const auto j = static_cast<std::uint32_t>(draw_bits(design.seed, kShuffleStream, a, i) %
                                                (static_cast<std::uint64_t>(i) + 1));
      std::swap(p[i], p[j]);
    }
  }
}

double DesignDraws::draw(std::uint64_t sample, std::size_t axis) const {
  const double u = unit(draw_bits(design_.seed, kUniformStream, axis, sample));
  if (design_.kind != SweepDesign::Kind::latin) return u;
  const auto n = static_cast<double>(design_.samples);
  const double stratum = strata_[axis][sample];
  const double lo = stratum / n;
  const double hi = (stratum + 1.0) / n;
  const double t = lo + u * (hi - lo);
  return t < hi ? t : std::nextafter(hi, lo);  // rounding may reach the next stratum's start
}

}  // namespace mdrsim::cli
