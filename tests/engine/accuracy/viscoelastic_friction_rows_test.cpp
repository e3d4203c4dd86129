// Richardson on the viscoelastic row with friction: the tangential work and friction's share of
// it are combined across the rows and estimated as the normal work is, against a reference made
// apart from the combination (two plain rows of 4000 and 8000 springs extrapolated by their
// own O(1/N) difference).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

RunResult run_sheared_relaxing(const std::string& discretization) {
  const std::string name = "pull_off_after_shear_relaxing.toml";
  std::ifstream in(std::string(MDRSIM_SOURCE_DIR) + "/scenes/viscoelastic/" + name);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::string springs_line = "springs = 2000";
  const auto at = text.find(springs_line);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.replace(at, springs_line.size(), discretization);
  const Scene scene = SceneDocument::from_text(text, name).build(Registries::builtin());
  return run_scene(scene, {});
}

TEST(ViscoelasticFrictionRows, RichardsonCombinesTheTangentialWorkAndFriction) {
  // The plain rows' works converge as c / N (their differences halve as N doubles), so
  // 2 W(8000) - W(4000) is the limit to O(1/N^2): about 1e-13 of 3.7e-7 J here (the differences
  // halve to 4 digits).
  const RunResult fine = run_sheared_relaxing("springs = 8000");
  const RunResult half = run_sheared_relaxing("springs = 4000");
  ASSERT_TRUE(fine.work && half.work);
  const double friction_reference = 2.0 * fine.work->friction - half.work->friction;
  const double tangential_reference = 2.0 * fine.work->tangential - half.work->tangential;
  const RunResult r = run_sheared_relaxing("springs = 250\nextrapolation = \"richardson\"");
  ASSERT_TRUE(r.work && r.accuracy.work_error_estimate);
  const AxisWork& estimate = *r.accuracy.work_error_estimate;
  const double friction_error = std::abs(r.work->friction - friction_reference);
  const double tangential_error = std::abs(r.work->tangential - tangential_reference);
  fmt::print(
      "Richardson at 250 springs: friction {:.10e} J, error {:.2e} (estimate {:.2e}); tangential "
      "{:.10e} J, error {:.2e} (estimate {:.2e})\n",
      r.work->friction, friction_error, estimate.friction, r.work->tangential, tangential_error,
      estimate.tangential);
  // The reference's own error (~1e-13 J) is far below the estimates (~1e-11 J).
  EXPECT_LE(friction_error, estimate.friction);
  EXPECT_LE(tangential_error, estimate.tangential);
  // The combination removes the plain row's c / N: closer than the finest row alone.
  const RunResult plain = run_sheared_relaxing("springs = 500");
  ASSERT_TRUE(plain.work);
  EXPECT_LT(friction_error, std::abs(plain.work->friction - friction_reference) / 10.0);
  EXPECT_LT(tangential_error, std::abs(plain.work->tangential - tangential_reference) / 10.0);
}

}  // namespace
}  // namespace mdrsim
