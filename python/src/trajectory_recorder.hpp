// The trajectory in memory within a row budget; its columns, made when Python asks for them,
// for NumPy to take over without a copy.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/events/observer.hpp"
#include "engine/model/snapshot_fields.hpp"

namespace mdrsim::python {

/// The rows of the trajectory CSV (engine/output/trajectory_csv.hpp) as columns.
struct TrajectoryColumns {
  std::vector<std::string> stage_names;  ///< distinct stage names, in order of appearance
  std::vector<std::int32_t> stage;       ///< index into stage_names
  std::vector<EventKind> event;
  std::vector<std::uint8_t> in_cascade;  ///< 1 inside a jump: NumPy reads it as bool
  std::vector<double> normal_control;    ///< [m or N]
  /// The state's fields in kTrajectoryFields' order (engine/model/snapshot_fields.hpp) [SI].
  std::array<std::vector<double>, kTrajectoryFields.size()> state;
  std::vector<std::int64_t> springs_in_contact;
  std::vector<std::int64_t> springs_sliding;  ///< the CSV's `sliding` (docs/friction.md)
  std::vector<double> cohesive_radius;        ///< the CSV's `cohesive_radius` [m] (docs/maugis.md)
  std::vector<double> time;                   ///< the CSV's `time` [s] (docs/programs.md "Time")
};

struct TrajectoryRow {
  ContactSnapshot state;
  std::uint64_t ordinal;  ///< its place among the rows of its rank
  std::int32_t stage;     ///< index into the stage names
  EventKind event;
  std::uint8_t in_cascade;
  std::uint8_t rank;  ///< 0 ordinary, 1 a cascade's end or a jump, 2 always kept
};

/// Rows in blocks of kRows (90 KiB), taken from and given back to a pool of blocks shared by
/// all runs: a run grows its trajectory without the copies of a growing vector and, once the
/// pool is warm, without page faults (each 6 us on this host, 200 for a run of 10,000
/// springs), which also serialise threads in the kernel: two threads with trajectories ran
/// slower than one.
class RowBlocks {
 public:
  static constexpr std::size_t kRows = 1024;
  RowBlocks() = default;
  RowBlocks(RowBlocks&& other) noexcept;
  RowBlocks& operator=(RowBlocks&& other) noexcept;
  RowBlocks(const RowBlocks&) = delete;
  RowBlocks& operator=(const RowBlocks&) = delete;
  ~RowBlocks();
  std::size_t size() const { return size_; }
  TrajectoryRow& operator[](std::size_t i) { return blocks_[i / kRows][i % kRows]; }
  const TrajectoryRow& operator[](std::size_t i) const { return blocks_[i / kRows][i % kRows]; }
  void push_back(const TrajectoryRow& row);
  /// Keeps the first n rows.
  void shrink_to(std::size_t n);

 private:
  std::vector<std::unique_ptr<TrajectoryRow[]>> blocks_;
  std::size_t size_ = 0;
};

/// What a run recorded.
struct TrajectoryRows {
  std::vector<std::string> stage_names;
  RowBlocks rows;
  std::uint64_t rows_seen = 0;  ///< the rows the run gave, held or not
  /// 1 when every row is held; else every `stride`-th ordinary row is (a power of two).
  std::uint64_t stride = 1;

  TrajectoryColumns columns() const;
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
  TrajectoryRows take();

 private:
  static constexpr int kThinned = 2;  ///< ranks 0 and 1 are thinned

  std::int32_t stage_index(const Event& event);
  void commit(TrajectoryRow row);
  void thin();

  std::uint64_t budget_;
  TrajectoryRows out_;
  std::array<std::uint64_t, kThinned> offered_{};  ///< rows of each thinned rank so far
  std::array<std::uint64_t, kThinned> stride_{1, 1};
  std::array<std::uint64_t, kThinned> held_{};
  TrajectoryRow
      pending_{};  ///< the last row, held back until the next tells whether it ends a cascade
  bool has_pending_ = false;
};

}  // namespace mdrsim::python
