// docs: the shorthand is a program. Each shorthand scene, written as its three stages
// (preload: press to the preload depth; tangential: hold the normal axis under its pull-off
// control and ramp u_x; pull-off: lower the normal held value until separation), gives the
// same status and critical point on the same row of springs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/model/snapshot_fields.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The scene text with its [loading] table replaced by `loading`.
std::string with_loading(const std::string& text, const std::string& loading) {
  const std::size_t begin = text.find("[loading]");
  const std::size_t end = text.find("\n[", begin + 1);
  return text.substr(0, begin) + loading + text.substr(end);
}

struct Case {
  const char* scene;
  const char* control;
  double pull_rate;  ///< the pull-off stage's `by` per unit of its parameter [m or N]
  double tangential_displacement;
};

class ShorthandAsProgram : public ::testing::TestWithParam<Case> {};

TEST_P(ShorthandAsProgram, GivesTheSameCriticalPoint) {
  const Case c = GetParam();
  const std::string path = std::string(MDRSIM_SOURCE_DIR) + "/scenes/" + c.scene;
  const Registries& registries = Registries::builtin();
  const Scene shorthand = SceneDocument::from_file(path).build(registries);
  const std::string tangential =
      c.tangential_displacement != 0.0
          ? fmt::format("tangential = {{ control = \"fixed-grips\", to = {:.17g} }}\n",
                        c.tangential_displacement)
          : std::string();
  const std::string loading = fmt::format(
      "[loading]\n"
      "[[loading.stage]]\nname = \"preload\"\nnormal = {{ control = \"fixed-grips\", to = "
      "{:.17g} }}\n"
      "[[loading.stage]]\nname = \"tangential\"\nnormal = {{ control = \"{}\" }}\n{}"
      "[[loading.stage]]\nname = \"pull-off\"\nnormal = {{ by = {} }}\nuntil = \"separation\"\n",
      shorthand.preload_depth, c.control, tangential, c.pull_rate);
  const Scene program =
      SceneDocument::from_text(with_loading(read_file(path), loading), "program.toml")
          .build(registries);

  const RunResult a = run_scene(shorthand, {});
  const RunResult b = run_scene(program, {});
  EXPECT_EQ(to_string(a.status), std::string(to_string(b.status)));
  ASSERT_TRUE(a.critical && b.critical);
  EXPECT_EQ(a.critical->springs_in_contact, b.critical->springs_in_contact);
  for (const SnapshotField& f : kSnapshotFields) {
    const double x = (*a.critical).*f.member;
    const double y = (*b.critical).*f.member;
    // The rows agree to the rounding of their outermost spring (g(a_g) against the depth).
    EXPECT_NEAR(y, x, 1e-10 * std::abs(x) + 1e-300) << f.name;
  }
  ASSERT_TRUE(a.peak && b.peak);
  EXPECT_NEAR(b.peak->normal_force, a.peak->normal_force, 1e-10 * std::abs(a.peak->normal_force));
  // Both report the same stages, jumps and work (docs: "every run, shorthand included").
  ASSERT_EQ(a.stages.size(), 3u);
  ASSERT_EQ(b.stages.size(), 3u);
  EXPECT_EQ(b.stages[0].end.springs_in_contact, b.springs);  // the finest row, all pressed
  const auto near = [](double x, double y, double scale) {
    return std::abs(x - y) <= 1e-9 * scale + 1e-300;
  };
  ASSERT_TRUE(a.work && b.work);
  const double work_scale = std::abs(a.stages[0].work.normal);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.stages[i].name, b.stages[i].name);
    EXPECT_EQ(a.stages[i].end.springs_in_contact, b.stages[i].end.springs_in_contact) << i;
    EXPECT_TRUE(near(a.stages[i].end.normal_force, b.stages[i].end.normal_force,
                     std::abs(a.stages[0].end.normal_force)))
        << a.stages[i].name << ": " << a.stages[i].end.normal_force << " against "
        << b.stages[i].end.normal_force;
    EXPECT_TRUE(near(a.stages[i].work.normal, b.stages[i].work.normal, work_scale))
        << a.stages[i].name << ": " << a.stages[i].work.normal << " J against "
        << b.stages[i].work.normal << " J";
    EXPECT_TRUE(near(a.stages[i].work.tangential, b.stages[i].work.tangential, work_scale))
        << a.stages[i].name;
  }
  ASSERT_EQ(a.jumps.size(), b.jumps.size());
  for (std::size_t i = 0; i < a.jumps.size(); ++i) {
    EXPECT_EQ(a.jumps[i].springs, b.jumps[i].springs) << i;
    EXPECT_EQ(a.jumps[i].by_shear, b.jumps[i].by_shear) << i;
    EXPECT_TRUE(near(a.jumps[i].critical.normal_force, b.jumps[i].critical.normal_force,
                     std::abs(a.critical->normal_force)));
  }
}

INSTANTIATE_TEST_SUITE_P(
    PaperScenes, ShorthandAsProgram,
    ::testing::Values(Case{"fig2_fixed_grips.toml", "fixed-grips", -1e-5, 0.0},
                      Case{"fig2_fixed_load.toml", "fixed-load", -1e-2, 0.0},
                      Case{"fig3a_fixed_grips.toml", "fixed-grips", -1e-5, 2.2614848269449475e-6},
                      Case{"fig3a_fixed_load.toml", "fixed-load", -1e-2, 2.2614848269449475e-6},
                      Case{"cone_fixed_grips.toml", "fixed-grips", -1e-5, 0.0},
                      Case{"sphere_fixed_load.toml", "fixed-load", -1e-2, 0.0}),
    [](const auto& info) {
      std::string name = info.param.scene;
      name = name.substr(0, name.find('.'));
      return name;
    });

}  // namespace
}  // namespace mdrsim
