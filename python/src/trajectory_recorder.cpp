// Appends each event's state to the columns, thinning them to the row budget.
#include "python/src/trajectory_recorder.hpp"

#include <algorithm>
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

/// Keeps the entries i of `column` for which keep[i]; returns nothing, resizes.
template <class T>
void keep_where(std::vector<T>& column, const std::vector<std::uint8_t>& keep) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < column.size(); ++i) {
    if (keep[i]) column[out++] = std::move(column[i]);
  }
  column.resize(out);
}

}  // namespace

TrajectoryRecorder::TrajectoryRecorder(std::uint64_t row_budget)
    : budget_(std::max<std::uint64_t>(row_budget, 1)) {}

std::int32_t TrajectoryRecorder::stage_index(const Event& e) {
  std::vector<std::string>& names = columns_.stage_names;
  const std::string_view stage = stage_name(e);
  if (!names.empty() && names.back() == stage) return static_cast<std::int32_t>(names.size() - 1);
  std::size_t index = 0;
  while (index < names.size() && names[index] != stage) ++index;
  if (index == names.size()) names.emplace_back(stage);
  return static_cast<std::int32_t>(index);
}

void TrajectoryRecorder::on_event(const Event& e) {
  if (e.kind == EventKind::finished) return;
  ++columns_.rows_seen;
  Row row{.stage = stage_index(e),
          .event = e.kind,
          .in_cascade = static_cast<std::uint8_t>(e.in_cascade ? 1 : 0),
          .rank = rank_of(e.kind),
          .state = e.state};
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

void TrajectoryRecorder::commit(const Row& row) {
  if (row.rank >= kThinned) {
    append(row, 0);
    return;
  }
  const std::uint64_t ordinal = offered_[row.rank]++;
  // Strides are powers of two.
  if ((ordinal & (stride_[row.rank] - 1)) != 0) return;
  append(row, ordinal);
  ++held_[row.rank];
  if (columns_.event.size() > budget_) thin();
}

void TrajectoryRecorder::append(const Row& row, std::uint64_t ordinal) {
  TrajectoryColumns& c = columns_;
  const ContactSnapshot& s = row.state;
  c.stage.push_back(row.stage);
  c.event.push_back(row.event);
  c.in_cascade.push_back(row.in_cascade);
  c.normal_control.push_back(s.normal_control);
  c.indentation.push_back(s.indentation);
  c.normal_force.push_back(s.normal_force);
  c.contact_radius.push_back(s.contact_radius);
  c.tangential_displacement.push_back(s.tangential_displacement);
  c.tangential_force.push_back(s.tangential_force);
  c.springs_in_contact.push_back(s.springs_in_contact);
  rank_.push_back(row.rank);
  ordinal_.push_back(ordinal);
}

void TrajectoryRecorder::thin() {
  // Held rows of a rank are the multiples of its stride among its ordinals, all of them: with
  // two or more held, doubling the stride drops at least one, so the loop ends.
  while (columns_.event.size() > budget_) {
    int r = 0;
    while (r < kThinned && held_[static_cast<std::size_t>(r)] < 2) ++r;
    if (r == kThinned) return;  // only rows kept always: a budget below the stage count
    const auto rank = static_cast<std::size_t>(r);
    stride_[rank] *= 2;
    std::vector<std::uint8_t> keep(rank_.size());
    for (std::size_t i = 0; i < rank_.size(); ++i) {
      keep[i] = rank_[i] != r || (ordinal_[i] & (stride_[rank] - 1)) == 0;
    }
    TrajectoryColumns& c = columns_;
    keep_where(c.stage, keep);
    keep_where(c.event, keep);
    keep_where(c.in_cascade, keep);
    keep_where(c.normal_control, keep);
    keep_where(c.indentation, keep);
    keep_where(c.normal_force, keep);
    keep_where(c.contact_radius, keep);
    keep_where(c.tangential_displacement, keep);
    keep_where(c.tangential_force, keep);
    keep_where(c.springs_in_contact, keep);
    keep_where(ordinal_, keep);
    keep_where(rank_, keep);
    held_[rank] = static_cast<std::uint64_t>(std::count(rank_.begin(), rank_.end(), r));
  }
}

TrajectoryColumns TrajectoryRecorder::take() {
  if (has_pending_) {
    pending_.rank = 2;  // the last row
    commit(pending_);
    has_pending_ = false;
  }
  columns_.stride = stride_[0];
  rank_ = {};
  ordinal_ = {};
  return std::move(columns_);
}

}  // namespace mdrsim::python
