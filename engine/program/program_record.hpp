// What a program reports of its path as it runs: each stage's end and work, each jump, the
// total work; the program loop (program_runner.cpp) hands it the states, it keeps the records.
#pragma once

#include <cstdint>
#include <string>

#include "engine/program/program_cascade.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

class ProgramRecord {
 public:
  explicit ProgramRecord(RunResult& result) : result_(&result) {}

  /// The jump of a cascade of two or more changes, with the row it left: springs in contact
  /// and glued after it; the caller adds where it lands (after, end, located states).
  JumpRecord& add_jump(const Cascade& cascade, std::int64_t in_contact_after,
                       std::int64_t glued_after);
  /// Ends the stage under way at `end`, with its work [J], which joins the total.
  StageRecord& end_stage(const std::string& name, const ContactSnapshot& end, const AxisWork& work);
  /// The total work of the stages ended so far.
  const AxisWork& total_work() const { return total_work_; }

 private:
  RunResult* result_;
  AxisWork total_work_;
};

}  // namespace mdrsim
