// SceneDocument::to_toml: the values, overrides applied, as TOML that reads back to the same
// document and scene, from TOML and from JSON alike.
#include "engine/scene/scene_document.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "engine/scene/registries.hpp"

namespace mdrsim::test {
namespace {

constexpr std::string_view kScene = R"(# a comment, not kept
title = "to_toml"
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.2e-4 }
normal = { control = "fixed-load" }
[discretization]
springs = 100
)";

TEST(SceneDocumentToToml, ReadsBackToTheSameValuesWithTheOverrides) {
  SceneDocument document = SceneDocument::from_text(kScene, "a.toml");
  document.set_value("material.poisson_ratio", "0.3");
  document.set_value("discretization.rtol", "1e-3");  // replaces springs (exclusive keys)
  const std::string text = document.to_toml();
  EXPECT_NE(text.find("poisson_ratio = "), std::string::npos) << text;
  EXPECT_NE(text.find("rtol = "), std::string::npos) << text;
  EXPECT_EQ(text.find("springs"), std::string::npos) << text;
  EXPECT_EQ(text.find("comment"), std::string::npos) << text;
  const SceneDocument again = SceneDocument::from_text(text, "b.toml");
  EXPECT_EQ(again.to_toml(), text);
  const Scene a = document.build(Registries::builtin());
  const Scene b = again.build(Registries::builtin());
  EXPECT_EQ(a.title, b.title);
  // Numbers are written with 17 digits: they read back to the same doubles.
  EXPECT_EQ(b.material.effective_modulus, 1.0e6 / (1.0 - 0.3 * 0.3));  // E/(1 - nu^2)
  EXPECT_EQ(a.material.effective_modulus, b.material.effective_modulus);
  EXPECT_EQ(b.discretization.rtol, 1e-3);
}

TEST(SceneDocumentToToml, JsonBecomesToml) {
  const SceneDocument json = SceneDocument::from_scene_text(
      R"({"scene": {"material": {"effective_modulus": 1e6, "work_of_adhesion": 0.05},
          "profile": {"type": "parabolic", "radius": 0.01},
          "loading": {"preload": {"depth": 2e-5}}, "discretization": {"springs": 100}}})",
      "result.json");
  const SceneDocument toml = SceneDocument::from_text(json.to_toml(), "x.toml");
  EXPECT_EQ(toml.to_toml(), json.to_toml());
  EXPECT_NE(json.to_toml().find("springs = 100\n"), std::string::npos);  // still a whole number
}

}  // namespace
}  // namespace mdrsim::test
