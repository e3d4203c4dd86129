// work_of_adhesion and approach_work_of_adhesion as a table (inline or CSV) or a sinusoid: read
// into the material, bad tables refused with file, line, key and radius.
#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

// The [material] table's adhesion keys follow on line 5.
constexpr std::string_view kHead = R"(title = "adhesion by radius"
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
)";
constexpr std::string_view kTail = R"(
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
name = "press"
normal = { control = "fixed-grips", to = 1e-6 }
)";

Scene build(std::string_view material, const std::string& name = "scene.toml") {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(std::string(kHead) + std::string(material) + std::string(kTail),
                                  name)
      .build(registries);
}

TEST(AdhesionInput, ReadsATableAndASinusoid) {
  const Scene table =
      build("work_of_adhesion = { r = [0.0, 1e-4, 1e-4, 2e-4], value = [0.05, 0.08, 0.02, 0.02] }");
  const Material& m = table.material;
  ASSERT_TRUE(m.work_of_adhesion_by_radius);
  EXPECT_EQ(m.work_of_adhesion, 0.05);  // the scale value: the table's at r = 0
  EXPECT_EQ(m.work_of_adhesion_at(0.5e-4), 0.065);
  EXPECT_EQ(m.work_of_adhesion_at(1e-4), 0.02);  // a step: the outer value at its radius
  EXPECT_EQ(m.work_of_adhesion_at(1.0), 0.02);   // constant beyond the ends
  EXPECT_EQ(m.approach_work_of_adhesion, 0.0);
  EXPECT_FALSE(m.approach_work_of_adhesion_by_radius);

  const Scene sinusoid = build(
      "work_of_adhesion = { mean = 0.05, amplitude = 0.2, wavelength = 1e-4 }\n"
      "approach_work_of_adhesion = { mean = 0.05, amplitude = 0.2, wavelength = 1e-4 }");
  EXPECT_EQ(sinusoid.material.work_of_adhesion, 0.05);  // the mean
  EXPECT_DOUBLE_EQ(sinusoid.material.work_of_adhesion_at(0.25e-4), 0.06);
  EXPECT_DOUBLE_EQ(sinusoid.material.approach_work_of_adhesion_at(0.75e-4), 0.04);
  // The resolved scene keeps the form.
  EXPECT_EQ(sinusoid.resolved->at("material").at("work_of_adhesion").at("amplitude"), 0.2);
}

TEST(AdhesionInput, ReadsACsvTable) {
  const auto dir = std::filesystem::temp_directory_path() / "mdrsim_adhesion_input_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "w.csv") << "r,value\n0,0.05\n# a tougher ring\n1e-4,0.08\n2e-4,0.05\n";
  std::ofstream(dir / "bad.csv") << "r,value\n0,0.05\n1e-4,0.08\n0.5e-4,0.05\n";
  const std::string good = (dir / "w.csv").string();
  const Scene scene = build("work_of_adhesion = { file = \"" + good + "\" }");
  EXPECT_EQ(scene.material.work_of_adhesion_at(1e-4), 0.08);
  EXPECT_EQ(scene.material.work_of_adhesion_at(1.5e-4), 0.065);
  const std::string bad = (dir / "bad.csv").string();
  EXPECT_THROW_MSG(build("work_of_adhesion = { file = \"" + bad + "\" }"), SceneError,
                   "scene.toml:5:29: material.work_of_adhesion.file: line 4 of '" + bad +
                       "': r[2] = 5e-05 is below r[1] = 0.0001: expected radii in increasing "
                       "order");
  std::filesystem::remove_all(dir);
}

TEST(AdhesionInput, RefusesBadTablesAtTheirKeyAndRadius) {
  EXPECT_THROW_MSG(
      build("work_of_adhesion = { r = [0.0, 2e-4, 1e-4], value = [0.05, 0.08, 0.05] }"), SceneError,
      "scene.toml:5:26: material.work_of_adhesion.r: r[2] = 0.0001 is below r[1] = 0.0002: "
      "expected radii in increasing order");
  EXPECT_THROW_MSG(build("work_of_adhesion = { r = [0.0, 1e-4], value = [0.05, -0.08] }"),
                   SceneError,
                   "scene.toml:5:47: material.work_of_adhesion.value: value[1] = -0.08 at r = "
                   "0.0001 is not a finite work of adhesion >= 0");
  EXPECT_THROW_MSG(
      build("work_of_adhesion = { r = [0.0, 1e-4, 1e-4, 1e-4], value = [0.05, 0.08, 0.05, 0.1] }"),
      SceneError,
      "scene.toml:5:26: material.work_of_adhesion.r: r[1] = r[2] = r[3] = 0.0001: a radius at "
      "most twice (a step)");
  EXPECT_THROW_MSG(build("work_of_adhesion = { mean = 0.05, amplitude = 1.5, wavelength = 1e-4 }"),
                   SceneError,
                   "scene.toml:5:47: material.work_of_adhesion.amplitude = 1.5 is outside [0, 1]");
  EXPECT_THROW_MSG(build("work_of_adhesion = { men = 0.05 }"), SceneError,
                   "scene.toml:5:22: material.work_of_adhesion.men: unknown key; did you mean "
                   "'mean'? (known: amplitude, file, mean, r, value, wavelength)");
  EXPECT_THROW_MSG(
      build("work_of_adhesion = { mean = 0.05, amplitude = 0.5, wavelength = 1e-4, r = [0.0] }"),
      SceneError,
      "scene.toml:5:29: material.work_of_adhesion.mean: give a table (r and value, or file) or a "
      "sinusoid (mean, amplitude, wavelength), not both");
}

TEST(AdhesionInput, RefusesAnApproachAboveTheRecedingValueAtItsRadius) {
  EXPECT_THROW_MSG(build("work_of_adhesion = 0.05\napproach_work_of_adhesion = { r = [0.0, 1e-4], "
                         "value = [0.0, 0.06] }"),
                   SceneError,
                   "scene.toml:6:29: material.approach_work_of_adhesion: dgamma_a = 0.06 is above "
                   "work_of_adhesion's dgamma = 0.05 at r = 0.0001 m (0 <= dgamma_a <= dgamma at "
                   "every radius)");
  // A sinusoid dips below its mean: a uniform dgamma_a = mean exceeds it a quarter wave in
  // (found on the grid of 64 points per wavelength).
  const std::string message = thrown_message<SceneError>([] {
    build(
        "work_of_adhesion = { mean = 0.05, amplitude = 0.2, wavelength = 1e-4 }\n"
        "approach_work_of_adhesion = 0.05");
  });
  EXPECT_NE(message.find("material.approach_work_of_adhesion: dgamma_a = 0.05 is above"),
            std::string::npos)
      << message;
}

TEST(AdhesionInput, TheContinuumRouteRefusesAVaryingWorkOfAdhesion) {
  EXPECT_THROW_MSG(build("work_of_adhesion = { mean = 0.05, amplitude = 0.2, wavelength = 1e-4 }"
                         "\n[solver]\nmethod = \"continuum\""),
                   SceneError,
                   "scene.toml:7:10: solver.method: a work of adhesion that varies with the radius "
                   "pins and releases the front at every change (several folds), and the "
                   "continuum route follows one fold only; use method = \"event\" "
                   "(docs/continuum.md)");
}

}  // namespace
}  // namespace mdrsim::test
