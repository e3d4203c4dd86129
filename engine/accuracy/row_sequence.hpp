// Rows of doubling springs over one radius, combined plainly or by Richardson, with estimates.
#pragma once

#include <optional>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

/// What a sequence combines: the critical point or the peak adhesive force of each row.
enum class Target { critical, peak };

/// Rows of N, 2N, 4N, ... springs across the same radius. Each row's value Q_j is its end
/// located between springs (fold_refinement.hpp), whose error is C/N_j + O(1/N_j^2).
/// - Plain: Q_j, with error estimate 2 max(|Q_j - Q_{j-1}|, |Q_{j-1} - Q_{j-2}|/2): the first
///   difference is C/N_j itself, and the factor 2 and the earlier difference guard against
///   two rows that agree by chance.
/// - Richardson: R_j = 2 Q_j - Q_{j-1}, with estimate 2 max(|R_j - R_{j-1}|,
///   |R_{j-1} - R_{j-2}|/2): for order p the difference is (2^p - 1) times R_j's error, 3
///   times at p = 2; the factor 2 covers the irregular O(dx^2) part of a fold or shear-off
///   located between springs, which made the plain difference fall short by 1.5x in the
///   random set.
/// Where dgamma(r) jumps or bends within a few spacings of a row's end (rough radii), the
/// row's let-go values lambda(n) are not smooth there: the parabola that locates the end
/// between springs spans the jump (and misses by a fixed fraction of it at every
/// resolution), and the front pins at the step, so that the plain value's error is a
/// sawtooth S dx frac(step / dx) in the spacing. Such a sequence takes every row's plain end,
/// refuses Richardson, and its estimate adds 2 S dx_j to the plain one, S the largest slope
/// |Q_i - Q_k| / |a_i - a_k| between its rows (the branch the pinned ends lie on).
class RowSequence {
 public:
  explicit RowSequence(Target target) : target_(target) {}

  /// The same rows, read for another target.
  RowSequence(Target target, std::vector<RunResult> rows)
      : target_(target), rows_(std::move(rows)) {}

  /// The radii [m] where the rows' dgamma is not smooth, sorted (rough_radii(material)).
  RowSequence& with_rough_radii(std::vector<double> radii) {
    rough_radii_ = std::move(radii);
    return *this;
  }
  /// A sequence of no rows with the same target and rough radii.
  RowSequence emptied() const {
    RowSequence out(target_);
    out.rough_radii_ = rough_radii_;
    return out;
  }

  Target target() const { return target_; }
  void add(RunResult row) { rows_.push_back(std::move(row)); }
  const std::vector<RunResult>& rows() const { return rows_; }
  bool empty() const { return rows_.empty(); }
  const RunResult& last() const { return rows_.back(); }
  std::int64_t next_springs() const { return 2 * rows_.back().springs; }

  /// Whether row j has a value between springs (every row must, for either route).
  bool usable() const;
  std::optional<ContactSnapshot> value(Accuracy::Route route) const;
  std::optional<double> estimate(Accuracy::Route route) const;
  /// Whether some row ends within a few spacings of a rough radius: the plain route only.
  bool rough() const;

 private:
  bool ends_near_rough_radius(std::size_t j) const;
  const ContactSnapshot* plain_end(std::size_t j) const;
  double pinned_front_bound() const;
  const ContactSnapshot* between_springs(std::size_t j) const;
  double q(std::size_t j) const { return between_springs(j)->normal_force; }
  double r(std::size_t j) const { return 2.0 * q(j) - q(j - 1); }

  Target target_;
  std::vector<RunResult> rows_;
  std::vector<double> rough_radii_;
};

/// The radii [m] where dgamma(r) or dgamma_a(r) jumps or bends: their tables' points (none
/// for a sinusoid or a uniform value).
std::vector<double> rough_radii(const Material& material);

/// Whether the sequence's value by `route` is within rtol of its estimate, relative.
bool meets(const RowSequence& seq, Accuracy::Route route, double rtol);

/// The route predicted to meet rtol with the fewest springs: the plain row's error falls
/// like 1/N, the extrapolated one's like 1/N^2.
Accuracy::Route cheaper_route(const RowSequence& seq, double rtol);

/// 2 fine - coarse, field by field; springs in contact from `fine`.
ContactSnapshot extrapolate(const ContactSnapshot& coarse, const ContactSnapshot& fine);

}  // namespace mdrsim
