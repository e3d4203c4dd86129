// Appends each event's state to the columns; stage names are stored once.
#include "python/src/trajectory_recorder.hpp"

#include <string_view>

namespace mdrsim::python {

void TrajectoryRecorder::on_event(const Event& e) {
  if (e.kind == EventKind::finished) return;
  TrajectoryColumns& c = columns_;
  const std::string_view stage = stage_name(e);
  if (c.stage_names.empty() || c.stage_names.back() != stage) {
    std::size_t index = 0;
    while (index < c.stage_names.size() && c.stage_names[index] != stage) ++index;
    if (index == c.stage_names.size()) c.stage_names.emplace_back(stage);
    c.stage.push_back(static_cast<std::int32_t>(index));
  } else {
    c.stage.push_back(static_cast<std::int32_t>(c.stage_names.size() - 1));
  }
  const ContactSnapshot& s = e.state;
  c.event.push_back(e.kind);
  c.in_cascade.push_back(e.in_cascade ? 1 : 0);
  c.normal_control.push_back(s.normal_control);
  c.indentation.push_back(s.indentation);
  c.normal_force.push_back(s.normal_force);
  c.contact_radius.push_back(s.contact_radius);
  c.tangential_displacement.push_back(s.tangential_displacement);
  c.tangential_force.push_back(s.tangential_force);
  c.springs_in_contact.push_back(s.springs_in_contact);
}

}  // namespace mdrsim::python
