// JSON scene input: a result's `scene` or a scene object, and the messages for bad JSON.
#include "engine/scene/json_scene.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <nlohmann/json.hpp>
#include <string>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

constexpr const char* kScene = R"({
  "material": {"effective_modulus": 1000000.0, "work_of_adhesion": 0.05},
  "profile": {"type": "parabolic", "radius": 0.01},
  "loading": {"stage": [
    {"normal": {"control": "fixed-grips", "to": 2e-05}},
    {"normal": {"by": -2e-05}, "until": "separation"}]},
  "discretization": {"springs": 100}
})";

Scene build(const std::string& text) {
  return SceneDocument::from_scene_text(text, "r.json").build(Registries::builtin());
}

TEST(JsonScene, IsToldFromTomlByItsFirstCharacter) {
  EXPECT_TRUE(is_json_text(" \n\t{}"));
  EXPECT_FALSE(is_json_text("title = \"{\""));
  EXPECT_FALSE(is_json_text(""));
}

TEST(JsonScene, ObjectsAreTablesAndArraysOfObjectsArraysOfTables) {
  const Scene scene = build(kScene);
  ASSERT_TRUE(scene.program.has_value());
  EXPECT_EQ(scene.program->stages.size(), 2u);
  EXPECT_EQ(scene.springs, 100);
}

TEST(JsonScene, AResultGivesItsScene) {
  const std::string result =
      std::string(R"({"status": "instability", "springs": 7, "scene": )") + kScene + "}";
  EXPECT_EQ(build(result).springs, 100);
}

TEST(JsonScene, SetWorksOnItAsOnToml) {
  SceneDocument d = SceneDocument::from_scene_text(kScene, "r.json");
  d.set_value("discretization.rtol", "1e-3");
  const SceneDocument copy = d;  // re-parses the JSON
  EXPECT_EQ(copy.build(Registries::builtin()).discretization.rtol, 1e-3);
}

TEST(JsonScene, BadInputNamesTheFile) {
  EXPECT_THROW_MSG(build("{\"material\": }"), SceneError,
                   "r.json: malformed JSON: parse error at line 1, column 14: syntax error while "
                   "parsing value - unexpected '}'; expected '[', '{', or a literal");
  // A number beyond a double (found by the fuzzer: nlohmann throws out_of_range, not
  // parse_error, for it).
  EXPECT_THROW_MSG(build(R"({"material": {"youngs_modulus": 1e999}})"), SceneError,
                   "r.json: malformed JSON: number overflow parsing '1e999'");
  EXPECT_THROW_MSG(build(R"({"scene": 3})"), SceneError,
                   "r.json: scene: expected an object (the scene of a result)");
  EXPECT_THROW_MSG(build(R"({"title": null})"), SceneError,
                   "r.json: title: null is not a scene value");
  EXPECT_THROW_MSG(build(R"({"discretization": {"springs": 18446744073709551615}})"), SceneError,
                   "r.json: discretization.springs: 18446744073709551615 is too large a whole "
                   "number");
  // Far deeper than a scene: refused before the conversion could exhaust the stack.
  const std::string deep =
      "{\"title\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::string message = thrown_message<SceneError>([&] { build(deep); });
  EXPECT_EQ(message.rfind("r.json: title[0][0]", 0), 0u) << message;
  EXPECT_NE(message.find(": nested deeper than 16 levels"), std::string::npos) << message;
  // Keys and values are checked as in TOML; JSON has no line numbers to give.
  nlohmann::json typo = nlohmann::json::parse(kScene);
  typo["material"]["poisson"] = 0.3;
  EXPECT_THROW_MSG(build(typo.dump()), SceneError,
                   "r.json: material.poisson: unknown key; did you mean 'poisson_ratio'? (known: "
                   "adhesive_stress, approach_work_of_adhesion, effective_modulus, "
                   "effective_shear_modulus, grading, maugis_parameter, poisson_ratio, relaxation, "
                   "work_of_adhesion, "
                   "youngs_modulus)");
}

}  // namespace
}  // namespace mdrsim::test
