// The records of a program's path: jumps from their cascades, stage ends with their work.
#include "engine/program/program_record.hpp"

namespace mdrsim {

JumpRecord& ProgramRecord::add_jump(const Cascade& cascade, std::int64_t in_contact_after,
                                    std::int64_t glued_after) {
  JumpRecord jump;
  jump.stage = cascade.stage->name;
  jump.springs = in_contact_after - cascade.in_contact;
  jump.glued_springs = glued_after - cascade.glued;
  jump.critical = cascade.before;
  jump.by_shear = cascade.second_by_shear;
  result_->jumps.push_back(jump);
  return result_->jumps.back();
}

StageRecord& ProgramRecord::end_stage(const std::string& name, const ContactSnapshot& end,
                                      const AxisWork& work) {
  result_->stages.push_back({name, end, work});
  total_work_ += work;
  return result_->stages.back();
}

}  // namespace mdrsim
