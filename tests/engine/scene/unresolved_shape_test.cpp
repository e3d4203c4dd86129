// A scene whose finest row cannot follow the profile's shortest feature is refused at the
// profile's type, with the springs it would need; one that can runs. A shorthand is refused as
// it is read, a program by its run (its rows span the largest contact, which its pilot finds).
#include <gtest/gtest.h>

#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"

namespace mdrsim::test {
namespace {

/// A wavy sphere glued at 5.2e-4 m, ripple `wavelength`, with `discretization`'s keys.
std::string wavy(const std::string& wavelength, const std::string& discretization) {
  return "[material]\neffective_modulus = 1.0e2\nwork_of_adhesion = 0.05\n[profile]\n"
         "type = \"wavy\"\nradius = 0.01\namplitude = 1e-6\nwavelength = " +
         wavelength +
         "\n[loading]\npreload = { contact_radius = 5.2e-4 }\nnormal = { control = "
         "\"fixed-load\" }\n[discretization]\n" +
         discretization + "[solver]\nmethod = \"event\"\n";
}

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "scene.toml").build(registries);
}

// 2000 springs across 5.2e-4 m: spacing 2.6e-7 m, so a ripple needs at least 1.04e-6 m (four
// spacings); under Richardson the finest row has 4000 springs, under rtol 2^25.
TEST(UnresolvedShape, ARippleFinerThanFourSpacingsIsRefused) {
  EXPECT_THROW_MSG(build(wavy("1.0e-6", "springs = 2000\n")), SceneError,
                   "scene.toml:5:8: profile.type: the shape varies on 1e-06 m, less than 4 "
                   "spacings of the finest row (2.6e-07 m: the glued radius 0.00052 m over 2000 "
                   "springs): the springs cannot follow it; give at least 2.08e+03 springs, or a "
                   "longer wavelength");
  EXPECT_NO_THROW(build(wavy("1.05e-6", "springs = 2000\n")));
  EXPECT_NO_THROW(build(wavy("1.0e-6", "springs = 2000\nextrapolation = \"richardson\"\n")));
  EXPECT_NO_THROW(build(wavy("1.0e-9", "rtol = 1e-6\n")));
  EXPECT_THROW(build(wavy("1.0e-11", "rtol = 1e-6\n")), SceneError);
}

/// A wavy sphere pressed under fixed grips to 2e-5 m (a contact of about 4.5e-4 m) and pulled
/// off, on a row of 2000 springs.
std::string wavy_program(const std::string& wavelength) {
  return "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n[profile]\n"
         "type = \"wavy\"\nradius = 0.01\namplitude = 1e-7\nwavelength = " +
         wavelength +
         "\n[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = "
         "2e-5 }\n[[loading.stage]]\nname = \"pull\"\nnormal = { by = -1e-4 }\nuntil = "
         "\"separation\"\n[discretization]\nsprings = 2000\n";
}

TEST(UnresolvedShape, AProgramWhoseRowsCannotFollowTheRippleIsRefusedByItsRun) {
  const Scene fine = build(wavy_program("1e-8"));  // read: its rows' radius is not known yet
  std::string why;
  try {
    run_scene(fine, {});
  } catch (const SceneError& e) {
    why = e.what();
  }
  EXPECT_EQ(why.rfind("scene.toml:5:8: profile.type: the shape varies on 1e-08 m, less than 4 "
                      "spacings of the finest row (",
                      0),
            0U)
      << why;
  EXPECT_NE(why.find("m: the largest contact radius 0.000"), std::string::npos) << why;
  // A ripple of 5e-5 m has some 50 springs per wavelength: it runs, to the contact's loss.
  const RunResult coarse = run_scene(build(wavy_program("5e-5")), {});
  EXPECT_EQ(coarse.stages.size(), 2U);
  EXPECT_EQ(coarse.stages.back().end.springs_in_contact, 0);
}

}  // namespace
}  // namespace mdrsim::test
