// CSV rows at full precision, so that plots and checks see the engine's own numbers.
#include "engine/output/trajectory_csv.hpp"

#include <fmt/ostream.h>

namespace mdrsim {

TrajectoryCsvWriter::TrajectoryCsvWriter(std::ostream& out, bool friction)
    : out_(&out), friction_(friction) {
  *out_ << "stage,event,in_cascade,indentation,normal_force,contact_radius,tangential_displacement,"
           "tangential_force,springs_in_contact"
        << (friction_ ? ",sliding\n" : "\n");
}

void TrajectoryCsvWriter::on_event(const Event& e) {
  if (e.kind == EventKind::finished) return;
  const ContactSnapshot& s = e.state;
  if (e.kind == EventKind::sample) {  // the continuum route counts no springs
    fmt::print(*out_, "{},{},0,{},{},{},{},{},\n", stage_name(e), to_string(e.kind), s.indentation,
               s.normal_force, s.contact_radius, s.tangential_displacement, s.tangential_force);
    return;
  }
  fmt::print(*out_, "{},{},{},{},{},{},{},{},{}", stage_name(e), to_string(e.kind),
             e.in_cascade ? 1 : 0, s.indentation, s.normal_force, s.contact_radius,
             s.tangential_displacement, s.tangential_force, s.springs_in_contact);
  if (friction_) fmt::print(*out_, ",{}", s.springs_sliding);
  *out_ << '\n';
}

}  // namespace mdrsim
