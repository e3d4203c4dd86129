// The fold of a program row's shear-off from the let-gos that led to it.
#include "engine/program/let_go_trail.hpp"

#include "engine/result/status_margin.hpp"

namespace mdrsim {

void LetGoTrail::note_shear_off(Cascade& cascade, const ProgramRow& row,
                                const DetachmentCriterion& criterion, std::int64_t k,
                                double stretch_x) {
  const auto& [outer2, outer, boundary] = trail_;  // springs K + 2, K + 1, K
  if (boundary.spring != k + 1 || outer.spring != k + 2 || outer2.spring != k + 3) return;
  cascade.fold_above_shear_off = program_fold_above_shear_off(
      criterion, stretch_x, row.position(k),
      {row.position(k + 1), row.position(k + 2), row.position(k + 3)},
      {boundary.control, outer.control, outer2.control}, row.spacing());
}

}  // namespace mdrsim
