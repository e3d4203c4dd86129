// The trajectory in memory, one column per quantity, for NumPy to take over without a copy.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/events/observer.hpp"

namespace mdrsim::python {

/// The rows of the trajectory CSV (engine/events/trajectory_csv.hpp) as columns.
struct TrajectoryColumns {
  std::vector<std::string> stage_names;  ///< distinct stage names, in order of appearance
  std::vector<std::int32_t> stage;       ///< index into stage_names
  std::vector<EventKind> event;
  std::vector<std::uint8_t> in_cascade;         ///< 1 inside a jump: NumPy reads it as bool
  std::vector<double> normal_control;           ///< [m or N]
  std::vector<double> indentation;              ///< [m]
  std::vector<double> normal_force;             ///< [N]
  std::vector<double> contact_radius;           ///< [m]
  std::vector<double> tangential_displacement;  ///< [m]
  std::vector<double> tangential_force;         ///< [N]
  std::vector<std::int64_t> springs_in_contact;
};

/// Every event but `finished`, as the CSV writer has them.
class TrajectoryRecorder final : public Observer {
 public:
  void on_event(const Event& event) override;
  bool wants(EventKind kind) const override { return kind != EventKind::finished; }
  TrajectoryColumns& columns() { return columns_; }

 private:
  TrajectoryColumns columns_;
};

}  // namespace mdrsim::python
