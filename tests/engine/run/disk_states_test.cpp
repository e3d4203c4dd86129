// The disk check on a run's reported states: the JSON's disk_valid per state and at the top,
// and the warning, on a wavy sphere whose ripple re-contacts outside the preload's disk.
#include "engine/run/disk_states.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "engine/model/disk_validity.hpp"
#include "engine/output/result_json.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

/// Fig. 2's fixed-grips pull-off from 2 a0 on a wavy sphere of ripple amplitude A.
std::string wavy_scene(double amplitude) {
  return fmt::format(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"wavy\"\nradius = 0.01\namplitude = {}\nwavelength = 1e-4\n"
      "[loading]\npreload = {{ contact_radius = 5.209397078678047e-4 }}\n"
      "normal = {{ control = \"fixed-grips\" }}\n"
      "[discretization]\nsprings = 2000\n",
      amplitude);
}

// A = 1e-6 m (A k^2 R = 39): at the preload (a = 5.2e-4 m) the next trough of the ripple
// touches the surface outside the disk. The preload's state fails, the critical point (a
// smaller disk) passes; the state flags are the check's own verdicts, state by state.
TEST(DiskStates, AStrongRippleRecontactsOutsideThePreloadDisk) {
  const Scene scene = test::build_scene_text(wavy_scene(1e-6));
  const RunResult r = run_scene(scene, {});
  ASSERT_EQ(r.status, RunStatus::instability);
  EXPECT_FALSE(r.disk_valid);
  ASSERT_FALSE(r.stages.empty());
  const ContactSnapshot& preload = r.stages.front().end;
  EXPECT_FALSE(preload.disk_valid);
  EXPECT_EQ(preload.disk_valid,
            check_disk(*scene.profile, scene.material.effective_modulus, preload.contact_radius,
                       preload.indentation, preload.contact_radius)
                .valid);
  ASSERT_TRUE(r.critical.has_value());
  EXPECT_EQ(r.critical->disk_valid,
            check_disk(*scene.profile, scene.material.effective_modulus, r.critical->contact_radius,
                       r.critical->indentation, r.critical->contact_radius)
                .valid);
  bool warned = false;
  for (const std::string& w : r.warnings) {
    warned = warned || w.find("the contact is not one disk") != std::string::npos;
  }
  EXPECT_TRUE(warned);
  const auto j = result_to_json(scene, r);
  EXPECT_EQ(j["disk_valid"], false);
  EXPECT_EQ(j["stages"][0]["end"]["disk_valid"], false);
  EXPECT_EQ(j["critical"]["disk_valid"], r.critical->disk_valid);
}

// A gentle ripple (A k^2 R = 0.39, f and g rise) stays one disk: no warning.
TEST(DiskStates, AGentleRippleIsOneDisk) {
  const RunResult r = run_scene(test::build_scene_text(wavy_scene(1e-8)), {});
  EXPECT_TRUE(r.disk_valid);
  for (const std::string& w : r.warnings) {
    EXPECT_EQ(w.find("not one disk"), std::string::npos) << w;
  }
}

}  // namespace
}  // namespace mdrsim
