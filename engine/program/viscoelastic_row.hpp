// A program's row of viscoelastic springs under normal fixed grips without adhesion: the
// indentation moves linearly in time stage by stage, a spring is pressed from the moment the
// indenter reaches it until its load falls to zero (Ting), and a free spring creeps back and
// may be met again (docs/viscoelastic.md).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/base/material.hpp"

namespace mdrsim {

/// The springs: i = 1..N at x_i = i dx with images g(x_i), each of stiffness 2 E*(t) dx (both
/// halves of the foundation), E*(t) = E* + sum_j E_j* exp(-t / tau_j).
struct ViscoelasticRowSprings {
  double relaxed_modulus;        ///< E* [Pa] > 0
  std::vector<PronyTerm> terms;  ///< the Prony terms, plane strain
  double spacing;                ///< dx [m]
  std::vector<double> images;    ///< g(x_i) [m], i = 1..N
};

/// A stretch of the program during which the indentation moves at one rate.
struct DriveSegment {
  double duration;  ///< [s] >= 0
  double rate;      ///< d' [m/s]; 0: a hold
};

/// The row's state at one time.
struct ViscoelasticRowSample {
  double time;            ///< [s]
  double depth;           ///< d [m]
  double force;           ///< F [N], positive pressing
  double contact_radius;  ///< the outermost pressed spring's x [m]; 0 without contact
  std::int64_t pressed;   ///< springs pressed
};

struct ViscoelasticRowRun {
  /// The states at the requested times, in their order.
  std::vector<ViscoelasticRowSample> samples;
  /// When the last pressed spring let go, the contact being lost [s]; none if it never was
  /// after being made, or was made again.
  std::optional<double> separation_time;
  std::int64_t touches = 0;   ///< springs met by the indenter (fresh or free)
  std::int64_t releases = 0;  ///< springs whose load fell to zero
};

/// Runs the segments from d = 0, t = 0 (every spring at rest), reporting at `sample_times`
/// (ascending, within the segments' span). Events (a touch, a release) are located exactly in
/// time, one spring's next event at a time in a queue: between events nothing loops over the
/// springs (the pressed springs' arms are summed per term by SharedDriveArms).
ViscoelasticRowRun run_viscoelastic_row(const ViscoelasticRowSprings& springs,
                                        std::span<const DriveSegment> segments,
                                        std::span<const double> sample_times);

}  // namespace mdrsim
