// The slip keys of a row's sticking springs: the first to slip along +x and along -x, flat.
#include "engine/program/slip_keys.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>

namespace mdrsim {

void SlipKeys::insert(std::int64_t i, double forward, double backward) {
  if (i < 1) throw std::logic_error("SlipKeys::insert: spring index below 1");
  forward_.insert(i, forward);
  // Negated exactly: the largest (key, i) is the least (-key, i) with ties to the larger i.
  backward_.insert(i, -backward);
}

void SlipKeys::erase(std::int64_t i) {
  if (!forward_.contains(i)) return;
  forward_.erase(i);
  backward_.erase(i);
}

SlipKey SlipKeys::forward_first() const {
  const std::int64_t i = forward_.least();
  if (i == 0) return {std::numeric_limits<double>::infinity(), 0};
  return {forward_.key(i), i};
}

SlipKey SlipKeys::backward_last() const {
  const std::int64_t i = backward_.least();
  if (i == 0) return {-std::numeric_limits<double>::infinity(), 0};
  return {-backward_.key(i), i};
}

std::vector<SlipKeys::Side::Run>::iterator SlipKeys::Side::run_after(std::int64_t i) {
  return std::upper_bound(runs_.begin(), runs_.end(), i,
                          [](std::int64_t j, const Run& run) { return j < run.first; });
}

std::vector<SlipKeys::Side::Run>::const_iterator SlipKeys::Side::run_after(std::int64_t i) const {
  return std::upper_bound(runs_.begin(), runs_.end(), i,
                          [](std::int64_t j, const Run& run) { return j < run.first; });
}

bool SlipKeys::Side::contains(std::int64_t i) const {
  if (i < 1 || static_cast<std::size_t>(i) > keys_.size()) return false;
  if (tree_) return nodes_[leaves_ + static_cast<std::size_t>(i - 1)] == i;
  if (runs_.empty() || runs_.back().last < i) return false;
  const auto after = run_after(i);
  return after != runs_.begin() && std::prev(after)->last >= i;
}

void SlipKeys::Side::insert(std::int64_t i, double key) {
  if (contains(i)) throw std::logic_error("SlipKeys::insert: spring already in");
  if (static_cast<std::size_t>(i) > keys_.size()) keys_.resize(static_cast<std::size_t>(i));
  keys_[static_cast<std::size_t>(i - 1)] = key;
  ++size_;
  if (tree_) {
    if (static_cast<std::size_t>(i) > leaves_) build_tree(i);
    update_tree(i, i);
    return;
  }
  insert_in_runs(i);
  if (runs_.size() > max_runs_) build_tree(static_cast<std::int64_t>(keys_.size()));
}

void SlipKeys::Side::insert_in_runs(std::int64_t i) {
  // A row touches its next spring past every member: no search then.
  const auto after = runs_.empty() || runs_.back().last < i ? runs_.end() : run_after(i);
  Run* left =
      after != runs_.begin() && std::prev(after)->last == i - 1 ? &*std::prev(after) : nullptr;
  Run* right = after != runs_.end() && after->first == i + 1 ? &*after : nullptr;
  // A member joins a run at an end where it keeps the run's order.
  const auto fits_after = [&](const Run& run) {
    return run.order == 0 || (run.order > 0 ? less(run.last, i) : less(i, run.last));
  };
  const auto fits_before = [&](const Run& run) {
    return run.order == 0 || (run.order > 0 ? less(i, run.first) : less(run.first, i));
  };
  if (left != nullptr && fits_after(*left)) {
    if (left->order == 0) left->order = less(i - 1, i) ? 1 : -1;
    left->last = i;
    // It may join the two runs into one.
    if (right != nullptr && (right->order == 0 || right->order == left->order) &&
        (left->order > 0 ? less(i, i + 1) : less(i + 1, i))) {
      left->last = right->last;
      runs_.erase(after);
    }
  } else if (right != nullptr && fits_before(*right)) {
    if (right->order == 0) right->order = less(i, i + 1) ? 1 : -1;
    right->first = i;
  } else {
    runs_.insert(after, Run{i, i, 0});
  }
  if (least_ == 0 || less(i, least_)) least_ = i;
}

void SlipKeys::Side::erase(std::int64_t i) {
  --size_;
  if (tree_) {
    update_tree(i, 0);
    if (size_ == 0) {
      tree_ = false;
      nodes_ = {};
      leaves_ = 0;
    }
    return;
  }
  erase_from_runs(i);
  if (runs_.size() > max_runs_) build_tree(static_cast<std::int64_t>(keys_.size()));
}

void SlipKeys::Side::erase_from_runs(std::int64_t i) {
  const auto at = std::prev(run_after(i));
  Run& run = *at;
  if (run.first == run.last) {
    runs_.erase(at);
  } else if (i == run.first || i == run.last) {
    if (i == run.first) {
      ++run.first;
    } else {
      --run.last;
    }
    if (run.first == run.last) run.order = 0;
  } else {
    // Either side of i stays in order.
    const Run high{i + 1, run.last, i + 1 == run.last ? 0 : run.order};
    run.last = i - 1;
    if (run.first == run.last) run.order = 0;
    runs_.insert(std::next(at), high);
  }
  if (i == least_) {
    least_ = 0;
    for (const Run& r : runs_) least_ = better(least_, least_of(r));
  }
}

void SlipKeys::Side::build_tree(std::int64_t top) {
  std::size_t leaves = std::max<std::size_t>(leaves_, 64);
  while (leaves < static_cast<std::size_t>(top)) leaves *= 2;
  std::vector<std::int64_t> nodes(2 * leaves, 0);
  if (tree_) {
    std::copy(nodes_.begin() + static_cast<std::ptrdiff_t>(leaves_), nodes_.end(),
              nodes.begin() + static_cast<std::ptrdiff_t>(leaves));
  } else {
    for (const Run& run : runs_)
      for (std::int64_t j = run.first; j <= run.last; ++j)
        nodes[leaves + static_cast<std::size_t>(j - 1)] = j;
    runs_.clear();
  }
  for (std::size_t p = leaves - 1; p >= 1; --p) nodes[p] = better(nodes[2 * p], nodes[2 * p + 1]);
  nodes_ = std::move(nodes);
  leaves_ = leaves;
  tree_ = true;
  least_ = nodes_[1];
}

void SlipKeys::Side::update_tree(std::int64_t i, std::int64_t value) {
  std::size_t p = leaves_ + static_cast<std::size_t>(i - 1);
  nodes_[p] = value;
  // A node whose least member stays the same leaves every node above it the same (a member
  // leaves every node it was least of when it goes: its keys never change while it is in).
  for (p /= 2; p >= 1; p /= 2) {
    const std::int64_t least = better(nodes_[2 * p], nodes_[2 * p + 1]);
    if (least == nodes_[p]) break;
    nodes_[p] = least;
  }
  least_ = nodes_[1];
}

}  // namespace mdrsim
