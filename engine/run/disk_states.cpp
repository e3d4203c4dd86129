// The disk check over a run's reported states.
#include "engine/run/disk_states.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "engine/model/disk_validity.hpp"

namespace mdrsim {

void check_disk_states(const Scene& scene, RunResult& result) {
  const Profile& profile = *scene.profile;
  if (profile.proves_one_disk()) return;
  const double modulus = scene.material.effective_modulus;
  const bool adhesive = scene.material.adhesive();
  struct Worst {
    std::string state;
    DiskValidity check;
  };
  std::optional<Worst> worst;
  int invalid = 0;
  const auto check = [&](ContactSnapshot& s, const std::string& name) {
    const double a = s.contact_radius;
    if (!(a > 0.0) || !std::isfinite(a) || !std::isfinite(s.indentation)) return;
    // The pressure must not pull where springs in contact are not glued: beyond the glued
    // radius (all of the contact without adhesion; none of it where all are glued).
    const double unglued_from =
        !adhesive ? 0.0 : (s.glued_radius >= 0.0 ? std::min(s.glued_radius, a) : a);
    const DiskValidity c = check_disk(profile, modulus, a, s.indentation, unglued_from);
    s.disk_valid = c.valid;
    if (c.valid) return;
    ++invalid;
    // The worst relative to its state's zero (of a gap or a pressure).
    if (!worst || c.worst / c.zero < worst->check.worst / worst->check.zero) {
      worst = Worst{name, c};
    }
  };
  if (result.critical) check(*result.critical, "the critical point");
  if (result.peak) check(*result.peak, "the peak adhesion");
  for (StageRecord& stage : result.stages)
    check(stage.end, fmt::format("the end of stage '{}'", stage.name));
  for (std::size_t i = 0; i < result.jumps.size(); ++i) {
    JumpRecord& jump = result.jumps[i];
    check(jump.critical, fmt::format("the critical point of jump {}", i + 1));
    if (jump.end == JumpEnd::state)
      check(jump.after, fmt::format("the state after jump {}", i + 1));
  }
  if (!worst) return;
  result.disk_valid = false;
  const bool gap = worst->check.violation == DiskValidity::Violation::gap;
  result.warnings.push_back(fmt::format(
      "the contact is not one disk at {} state(s): worst at {}, where {} at r = {:.6g} m ({} "
      "{:.3g} {}); the MDR's answer does not hold there",
      invalid, worst->state,
      gap ? "the surface touches the indenter again outside the contact"
          : "the pressure pulls where springs are not glued",
      worst->check.worst_radius.value_or(0.0), gap ? "gap" : "pressure", worst->check.worst,
      gap ? "m" : "Pa"));
}

}  // namespace mdrsim
