// The disk check on a run's reported states: the JSON's disk_valid per state and at the top,
// and the warning, on a wavy sphere whose ripple re-contacts outside the preload's disk.
#include "engine/run/disk_states.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "engine/model/disk_validity.hpp"
#include "engine/output/result_json.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "profiles/tabulated_profile.hpp"

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

/// A 200-point table of a sphere of radius 1 cm out to 6 mm, optionally with point 60 raised
/// by five times its second difference (the table's one concave point).
ProfileTable sphere_table(bool bumped) {
  ProfileTable t;
  for (int i = 0; i < 200; ++i) {
    const double r = 6e-3 * i / 199.0;
    t.radii.push_back(r);
    t.gaps.push_back(0.01 - std::sqrt(0.01 * 0.01 - r * r));
  }
  if (bumped) t.gaps[60] += 5.0 * (t.gaps[61] - 2.0 * t.gaps[60] + t.gaps[59]);
  return t;
}

/// The profile `shape` claiming that it proves one disk, whatever it is.
struct ClaimsOneDisk final : Profile {
  const Profile& inner;
  explicit ClaimsOneDisk(const Profile& p) : inner(p) {}
  double shape(double r) const override { return inner.shape(r); }
  double mdr_image(double x) const override { return inner.mdr_image(x); }
  double outer_radius() const override { return inner.outer_radius(); }
  bool proves_one_disk() const override { return true; }
};

// The skip is as good as its proof: a table that proves one disk (the sphere's) passes the
// check at every state tried, pressed and stretched; a table with one concave point does not
// prove it, is checked, and the check finds the surface touching again outside a contact
// whose edge stands at the foot of the raised point (a = 1.812 mm, d = g(a): the gap dips to
// -6e-11 m, 1e-9 of the depth being 3e-13 m). The same profile claiming one disk is skipped.
TEST(DiskStates, TheSkipFollowsTheProfilesProof) {
  const TabulatedProfile sphere(sphere_table(false));
  ASSERT_TRUE(sphere.proves_one_disk());
  for (const double a : {1e-5, 1e-4, 5e-4, 1.8e-3, 4e-3, 5.9e-3}) {
    for (const double stretch : {0.0, 1e-3 * sphere.mdr_image(a), 0.5 * sphere.mdr_image(a)}) {
      SCOPED_TRACE(fmt::format("a {} stretch {}", a, stretch));
      EXPECT_TRUE(check_disk(sphere, 1e6, a, sphere.mdr_image(a) - stretch, a).valid);
    }
  }

  const auto bumped = std::make_shared<const TabulatedProfile>(sphere_table(true));
  ASSERT_FALSE(bumped->proves_one_disk());
  Scene scene = test::build_scene_text(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\npreload = { contact_radius = 5e-4 }\nnormal = { control = \"fixed-grips\" }\n");
  scene.profile = bumped;
  RunResult r;
  ContactSnapshot edge;
  edge.contact_radius = 1.81221e-3;
  edge.indentation = bumped->mdr_image(edge.contact_radius);
  edge.glued_radius = edge.contact_radius;
  r.critical = edge;
  check_disk_states(scene, r);
  EXPECT_FALSE(r.disk_valid);
  EXPECT_FALSE(r.critical->disk_valid);

  const ClaimsOneDisk claims(*bumped);
  scene.profile = std::shared_ptr<const Profile>(&claims, [](const Profile*) {});
  r.critical = edge;
  r.disk_valid = true;
  r.warnings.clear();
  check_disk_states(scene, r);
  EXPECT_TRUE(r.disk_valid);
  EXPECT_TRUE(r.critical->disk_valid);
}

// With adhesion the pressure is checked where springs in contact are not glued. A wavy sphere
// (A = 1 um, wavelength 100 um) glued on touch to d = 30 um, retracted to d = 0 (the front
// recedes to 3.95e-4 m) and pressed back to 30 um without rebinding: the same contact as the
// first press (a = 5.18e-4 m), but the ring outside 3.95e-4 m is pressed unglued, and over the
// ripple's falling flank there the MDR pressure pulls (-1.35e4 Pa at r = 4.51e-4 m, computed
// apart with scipy's quadrature of p(r) = (E*/pi) [(d - g(a)) / sqrt(a^2 - r^2) + int_r^a
// g'(x) / sqrt(x^2 - r^2) dx]): the glued first press is one disk, the pressed-back one is not.
TEST(DiskStates, PressedBackUngluedSpringsMustNotPull) {
  const Scene scene = test::build_scene_text(R"(
[material]
effective_modulus = 1e6
work_of_adhesion = 0.05
[profile]
type = "wavy"
radius = 0.01
amplitude = 1e-6
wavelength = 1e-4
[[loading.stage]]
name = "press"
normal = { control = "fixed-grips", to = 3e-5 }
[[loading.stage]]
name = "retract"
normal = { control = "fixed-grips", to = 0.0 }
[[loading.stage]]
name = "repress"
normal = { control = "fixed-grips", to = 3e-5 }
[discretization]
springs = 2000
)");
  const RunResult r = run_scene(scene, {});
  ASSERT_EQ(r.stages.size(), 3u);
  const ContactSnapshot& press = r.stages[0].end;
  const ContactSnapshot& repress = r.stages[2].end;
  ASSERT_EQ(press.springs_in_contact, repress.springs_in_contact);
  EXPECT_EQ(press.glued_radius, press.contact_radius);
  EXPECT_NEAR(repress.glued_radius, 3.953e-4, 1e-7);
  EXPECT_TRUE(press.disk_valid);
  EXPECT_FALSE(repress.disk_valid);
  // The check at the glued radius finds the pull; at the contact's edge (all glued) none.
  const DiskValidity ring = check_disk(*scene.profile, 1e6, repress.contact_radius,
                                       repress.indentation, repress.glued_radius);
  EXPECT_EQ(ring.violation, DiskValidity::Violation::pressure);
  ASSERT_TRUE(ring.worst_radius.has_value());
  // scipy, on 60 radii across the ring: -13488.5 Pa at 4.5125e-4 m.
  EXPECT_NEAR(*ring.worst_radius, 4.5125e-4, 2e-6);
  EXPECT_NEAR(ring.worst / -13488.5, 1.0, 1e-3);
  EXPECT_TRUE(check_disk(*scene.profile, 1e6, repress.contact_radius, repress.indentation,
                         repress.contact_radius)
                  .valid);
}

}  // namespace
}  // namespace mdrsim
