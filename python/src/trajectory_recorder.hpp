// The trajectory in memory within a row budget, one column per quantity, for NumPy to take
// over without a copy.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/events/observer.hpp"

namespace mdrsim::python {

/// The rows of the trajectory CSV (engine/events/trajectory_csv.hpp) as columns.
struct TrajectoryColumns {
  std::vector<std::string> stage_names;  ///< distinct stage names, in order of appearance
  std::vector<std::int32_t> stage;       ///< index into stage_names
  std::vector<EventKind> event;
  std::vector<std::uint8_t> in_cascade;         ///< 1 inside a jump: NumPy reads it as bool
  std::vector<double> normal_control;           ///< [m or N]
  std::vector<double> indentation;              ///< [m]
  std::vector<double> normal_force;             ///< [N]
  std::vector<double> contact_radius;           ///< [m]
  std::vector<double> tangential_displacement;  ///< [m]
  std::vector<double> tangential_force;         ///< [N]
  std::vector<std::int64_t> springs_in_contact;
  std::uint64_t rows_seen = 0;  ///< the rows the run gave, held or not
  /// 1 when every row is held; else every `stride`-th ordinary row is (a power of two).
  std::uint64_t stride = 1;
};

/// Every event but `finished`, as the CSV writer has them, at most `row_budget` rows held:
/// - kept always: the first and the last row and the rows of kind preload, tangential,
///   stage_end and instability (a few per stage);
/// - kept while the budget allows, then thinned: a cascade's ends (the rows on either side of
///   a change of in_cascade) and `jump` rows, ranked above
/// - the ordinary rows (detached, glued, touched, lifted, step, halved).
/// When the rows held pass the budget, every other row of the lowest rank still thinnable is
/// dropped and its stride doubled, so that the rows held stay evenly spaced among the rows of
/// their rank and the memory is O(budget), whatever the length of the run.
class TrajectoryRecorder final : public Observer {
 public:
  explicit TrajectoryRecorder(std::uint64_t row_budget);
  void on_event(const Event& event) override;
  bool wants(EventKind kind) const override { return kind != EventKind::finished; }
  /// The rows held, in order; the recorder is spent.
  TrajectoryColumns take();

 private:
  struct Row {
    std::int32_t stage;
    EventKind event;
    std::uint8_t in_cascade;
    std::uint8_t rank;  ///< 0 ordinary, 1 a cascade's end or a jump, 2 always kept
    ContactSnapshot state;
  };
  static constexpr int kThinned = 2;  ///< ranks 0 and 1 are thinned

  std::int32_t stage_index(const Event& event);
  void commit(const Row& row);
  void append(const Row& row, std::uint64_t ordinal);
  void thin();

  std::uint64_t budget_;
  TrajectoryColumns columns_;
  std::vector<std::uint8_t> rank_;      ///< per row held
  std::vector<std::uint64_t> ordinal_;  ///< per row held: its place among the rows of its rank
  std::array<std::uint64_t, kThinned> offered_{};  ///< rows of each thinned rank so far
  std::array<std::uint64_t, kThinned> stride_{1, 1};
  std::array<std::uint64_t, kThinned> held_{};
  Row pending_{};  ///< the last row, held back until the next tells whether it ends a cascade
  bool has_pending_ = false;
};

}  // namespace mdrsim::python
