// Appends each event's state to the rows, thinning them to the row budget.
#include "python/src/trajectory_recorder.hpp"

#include <algorithm>
#include <mutex>
#include <string_view>
#include <utility>

namespace mdrsim::python {
namespace {

std::uint8_t rank_of(EventKind kind) {
  switch (kind) {
    case EventKind::preload_reached:
    case EventKind::tangential_applied:
    case EventKind::stage_end:
    case EventKind::instability:
      return 2;
    case EventKind::jump:
      return 1;
    default:
      return 0;
  }
}

/// Blocks given back, for the next runs: at most kPooled (46 MB, the trajectories of 48 runs
/// of 10,000 springs held at once and freed: malloc would hand that memory back to the system
/// and the next batch would fault it in again), one lock per block.
class BlockPool {
 public:
  static constexpr std::size_t kPooled = 512;
  using Block = std::unique_ptr<TrajectoryRow[]>;

  Block get() {
    {
      const std::lock_guard lock(mutex_);
      if (!free_.empty()) {
        Block block = std::move(free_.back());
        free_.pop_back();
        return block;
      }
    }
    return std::make_unique_for_overwrite<TrajectoryRow[]>(RowBlocks::kRows);
  }

  void give_back(Block block) {
    const std::lock_guard lock(mutex_);
    if (free_.size() < kPooled) free_.push_back(std::move(block));
  }

 private:
  std::mutex mutex_;
  std::vector<Block> free_;
};

/// Never freed: results may be freed after static destructors have run.
BlockPool& pool() {
  static auto* p = new BlockPool;
  return *p;
}

}  // namespace

RowBlocks::RowBlocks(RowBlocks&& other) noexcept
    : blocks_(std::move(other.blocks_)), size_(std::exchange(other.size_, 0)) {
  other.blocks_.clear();
}

RowBlocks& RowBlocks::operator=(RowBlocks&& other) noexcept {
  if (this != &other) {
    shrink_to(0);
    blocks_ = std::move(other.blocks_);
    size_ = std::exchange(other.size_, 0);
    other.blocks_.clear();
  }
  return *this;
}

RowBlocks::~RowBlocks() { shrink_to(0); }

void RowBlocks::push_back(const TrajectoryRow& row) {
  if (size_ == blocks_.size() * kRows) blocks_.push_back(pool().get());
  (*this)[size_++] = row;
}

void RowBlocks::shrink_to(std::size_t n) {
  size_ = std::min(size_, n);
  const std::size_t needed = (size_ + kRows - 1) / kRows;
  while (blocks_.size() > needed) {
    pool().give_back(std::move(blocks_.back()));
    blocks_.pop_back();
  }
}

TrajectoryColumns TrajectoryRows::columns() const {
  TrajectoryColumns c;
  c.stage_names = stage_names;
  const std::size_t n = rows.size();
  c.stage.resize(n);
  c.event.resize(n);
  c.in_cascade.resize(n);
  c.normal_control.resize(n);
  for (std::vector<double>& column : c.state) column.resize(n);
  c.springs_in_contact.resize(n);
  c.springs_sliding.resize(n);
  c.cohesive_radius.resize(n);
  c.time.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const TrajectoryRow& row = rows[i];
    const ContactSnapshot& s = row.state;
    c.stage[i] = row.stage;
    c.event[i] = row.event;
    c.in_cascade[i] = row.in_cascade;
    c.normal_control[i] = s.normal_control;
    for (std::size_t j = 0; j < kTrajectoryFields.size(); ++j) {
      c.state[j][i] = s.*kTrajectoryFields[j].member;
    }
    c.springs_in_contact[i] = s.springs_in_contact;
    c.springs_sliding[i] = s.springs_sliding;
    c.cohesive_radius[i] = s.cohesive_radius;
    c.time[i] = s.time;
  }
  return c;
}

TrajectoryRecorder::TrajectoryRecorder(std::uint64_t row_budget)
    : budget_(std::max<std::uint64_t>(row_budget, 1)) {}

std::int32_t TrajectoryRecorder::stage_index(const Event& e) {
  std::vector<std::string>& names = out_.stage_names;
  const std::string_view stage = stage_name(e);
  if (!names.empty() && names.back() == stage) return static_cast<std::int32_t>(names.size() - 1);
  std::size_t index = 0;
  while (index < names.size() && names[index] != stage) ++index;
  if (index == names.size()) names.emplace_back(stage);
  return static_cast<std::int32_t>(index);
}

void TrajectoryRecorder::on_event(const Event& e) {
  if (e.kind == EventKind::finished) return;
  ++out_.rows_seen;
  TrajectoryRow row{.state = e.state,
                    .ordinal = 0,
                    .stage = stage_index(e),
                    .event = e.kind,
                    .in_cascade = static_cast<std::uint8_t>(e.in_cascade ? 1 : 0),
                    .rank = rank_of(e.kind)};
  if (!has_pending_) {
    row.rank = 2;  // the first row
  } else {
    if (row.in_cascade != pending_.in_cascade) {
      // A cascade begins or ends between the two: both are its ends.
      pending_.rank = std::max<std::uint8_t>(pending_.rank, 1);
      row.rank = std::max<std::uint8_t>(row.rank, 1);
    }
    commit(pending_);
  }
  pending_ = row;
  has_pending_ = true;
}

void TrajectoryRecorder::commit(TrajectoryRow row) {
  if (row.rank >= kThinned) {
    out_.rows.push_back(row);
    return;
  }
  row.ordinal = offered_[row.rank]++;
  // Strides are powers of two.
  if ((row.ordinal & (stride_[row.rank] - 1)) != 0) return;
  out_.rows.push_back(row);
  ++held_[row.rank];
  if (out_.rows.size() > budget_) thin();
}

void TrajectoryRecorder::thin() {
  // Held rows of a rank are the multiples of its stride among its ordinals, all of them: with
  // two or more held, doubling the stride drops at least one, so the loop ends.
  RowBlocks& rows = out_.rows;
  while (rows.size() > budget_) {
    int r = 0;
    while (r < kThinned && held_[static_cast<std::size_t>(r)] < 2) ++r;
    if (r == kThinned) return;  // only rows kept always: a budget below the stage count
    const auto rank = static_cast<std::size_t>(r);
    stride_[rank] *= 2;
    std::size_t kept = 0;
    std::uint64_t held = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const TrajectoryRow& row = rows[i];
      if (row.rank != r) {
        rows[kept++] = row;
      } else if ((row.ordinal & (stride_[rank] - 1)) == 0) {
        rows[kept++] = row;
        ++held;
      }
    }
    rows.shrink_to(kept);
    held_[rank] = held;
  }
}

TrajectoryRows TrajectoryRecorder::take() {
  if (has_pending_) {
    pending_.rank = 2;  // the last row
    commit(pending_);
    has_pending_ = false;
  }
  out_.stride = stride_[0];
  return std::move(out_);
}

}  // namespace mdrsim::python
