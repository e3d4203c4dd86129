// CSV rows at full precision, so that plots and checks see the engine's own numbers.
#include "engine/output/trajectory_csv.hpp"

#include <fmt/ostream.h>

#include <cstddef>

#include "engine/model/snapshot_fields.hpp"

namespace mdrsim {

TrajectoryCsvWriter::TrajectoryCsvWriter(std::ostream& out, bool friction, bool cohesive, bool time)
    : out_(&out), friction_(friction), cohesive_(cohesive), time_(time) {
  *out_ << "stage,event,in_cascade";
  for (const SnapshotField& f : kTrajectoryFields) *out_ << ',' << f.name;
  *out_ << ",springs_in_contact" << (friction_ ? ",sliding" : "")
        << (cohesive_ ? ",cohesive_radius" : "") << (time_ ? ",time\n" : "\n");
}

void TrajectoryCsvWriter::on_event(const Event& e) {
  if (e.kind == EventKind::finished) return;
  const ContactSnapshot& s = e.state;
  // One format string per row: a join or a call per field writes a long trajectory slower.
  static_assert(kTrajectoryFields.size() == 5, "one {} per field in the rows below");
  const auto field = [&s](std::size_t i) { return s.*kTrajectoryFields[i].member; };
  if (e.kind == EventKind::sample) {  // the continuum route counts no springs
    fmt::print(*out_, "{},{},0,{},{},{},{},{},", stage_name(e), to_string(e.kind), field(0),
               field(1), field(2), field(3), field(4));
    if (friction_) *out_ << ',';
    if (cohesive_) fmt::print(*out_, ",{}", s.cohesive_radius);
    if (time_) fmt::print(*out_, ",{}", s.time);
    *out_ << '\n';
    return;
  }
  fmt::print(*out_, "{},{},{},{},{},{},{},{},{}", stage_name(e), to_string(e.kind),
             e.in_cascade ? 1 : 0, field(0), field(1), field(2), field(3), field(4),
             s.springs_in_contact);
  if (friction_) fmt::print(*out_, ",{}", s.springs_sliding);
  if (cohesive_) fmt::print(*out_, ",{}", s.cohesive_radius);
  if (time_) fmt::print(*out_, ",{}", s.time);
  *out_ << '\n';
}

}  // namespace mdrsim
