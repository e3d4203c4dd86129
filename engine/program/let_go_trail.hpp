// The let-gos that began a stage's last cascades: the branch next to a program row's shear-off,
// whose fold above a_s gives that shear-off its status margin (status_margin.hpp).
#pragma once

#include <array>
#include <cstdint>

#include "detachment/criterion.hpp"
#include "engine/program/program_cascade.hpp"
#include "engine/program/program_front.hpp"
#include "engine/program/program_row.hpp"

namespace mdrsim {

class LetGoTrail {
 public:
  void clear() { size_ = 0; }

  /// Spring k of `row` lets go at tangential stretch `stretch_x` [m] in `cascade` (before the
  /// cascade counts it), broken at rest where `by_shear`. Only a stage that lowers the normal
  /// held value at a still tangential one peels along one branch of that value, with one
  /// stretch on the glue.
  void note(Cascade& cascade, const ProgramRow& row, const StageLine& line,
            const DetachmentCriterion& criterion, std::int64_t k, double stretch_x, bool by_shear) {
    if (!(line.normal.rate < 0.0) || line.tangential.rate != 0.0 || !row.one_offset()) return;
    if (cascade.changes == 0 && !by_shear) {
      if (size_ == 3) {
        trail_[0] = trail_[1];
        trail_[1] = trail_[2];
        --size_;
      }
      trail_[size_++] = {k, row.normal().held};
      return;
    }
    if (cascade.changes == 1 && by_shear && cascade.first == Change::let_go &&
        !cascade.first_by_shear && size_ == 3) {
      note_shear_off(cascade, row, criterion, k, stretch_x);
    }
  }

 private:
  /// Spring K = k + 1 let go by its stretch and spring k breaks at rest right after it: the
  /// row's shear-off, whose branch may fold above a_s within a spacing of spring K.
  void note_shear_off(Cascade& cascade, const ProgramRow& row, const DetachmentCriterion& criterion,
                      std::int64_t k, double stretch_x);

  struct LetGoPoint {
    std::int64_t spring;
    double control;  ///< the held normal value
  };
  std::array<LetGoPoint, 3> trail_{};
  int size_ = 0;
};

}  // namespace mdrsim
