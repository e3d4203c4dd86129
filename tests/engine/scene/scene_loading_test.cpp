// Bad scene input: every key docs defines, each way it can be wrong, with the exact message.
#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

// The scene every case mutates; the line numbers in the messages below refer to it.
constexpr std::string_view kScene =
    R"(title = "test scene"
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.0e-4 }
tangential = { control = "fixed-grips", displacement = 0.0 }
normal = { control = "fixed-load" }
[detachment]
criterion = "mode-mixed"
[discretization]
springs = 100
[solver]
method = "event"
)";

/// `text` with the one occurrence of `from` replaced by `to`.
std::string replaced(std::string text, std::string_view from, std::string_view to) {
  const auto at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
    throw std::logic_error(fmt::format("'{}' is not in the test scene exactly once", from));
  }
  return text.replace(at, from.size(), to);
}

/// kScene with the one occurrence of `from` replaced by `to`.
std::string scene_with(std::string_view from, std::string_view to) {
  return replaced(std::string(kScene), from, to);
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Lists and help texts that come from the registries, so that a newly registered part does
// not break these tests.
const Registries& registries() {
  static const Registries r = Registries::builtin();
  return r;
}
std::string profiles() { return join(registries().profiles.names()); }
std::string criteria() { return join(registries().criteria.names()); }
std::string controllers() { return join(registries().controllers.names()); }
template <class Registry>
std::string help(const Registry& registry, std::string_view part, std::string_view key) {
  for (const auto& spec : registry.find(part)->parameters) {
    if (spec.key == key) return spec.help;
  }
  throw std::logic_error("no such parameter");
}

/// Whether `message` starts with `prefix`; for messages that end in computed numbers.
::testing::AssertionResult starts_with(const std::string& message, const std::string& prefix) {
  if (message.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "[" << message << "] does not start with [" << prefix << "]";
}

constexpr const char* kMaterialKeys =
    "adhesive_stress, approach_work_of_adhesion, effective_modulus, effective_shear_modulus, "
    "grading, maugis_parameter, poisson_ratio, relaxation, work_of_adhesion, youngs_modulus";
constexpr const char* kRootKeys =
    "detachment, discretization, friction, loading, material, profile, solver, title";

struct BadScene {
  std::string name;     ///< test name
  std::string from;     ///< text of kScene
  std::string to;       ///< its replacement
  std::string message;  ///< the exact SceneError text
};

void PrintTo(const BadScene& c, std::ostream* os) { *os << c.name; }

class BadSceneTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, FailsWithTheExactMessage) {
  const BadScene& c = GetParam();
  const std::string text = scene_with(c.from, c.to);
  EXPECT_THROW_MSG(build_scene_text(text), SceneError, c.message) << text;
}

std::string case_name(const ::testing::TestParamInfo<BadScene>& info) { return info.param.name; }

// ---- title and the root table ----

std::vector<BadScene> root_cases() {
  return {
      {"TitleNumber", R"(title = "test scene")", "title = 3",
       "test.toml:1:9: title: expected a string, got 3"},
      {"TitleArray", R"(title = "test scene")", R"(title = ["a"])",
       "test.toml:1:9: title: expected a string, got an array"},
      {"TitleTable", R"(title = "test scene")", "title = { text = \"a\" }",
       "test.toml:1:9: title: expected a string, got a table"},
      {"TitleTypo", R"(title = "test scene")", R"(tittle = "test scene")",
       fmt::format("test.toml:1:1: tittle: unknown key; did you mean 'title'? (known: {})",
                   kRootKeys)},
      {"UnknownTopLevelTable", "[solver]", "[solvr]",
       fmt::format("test.toml:17:2: solvr: unknown key; did you mean 'solver'? (known: {})",
                   kRootKeys)},
      {"KeyWithNewlineIsEscaped", R"(title = "test scene")", R"("a\nb" = 1)",
       fmt::format("test.toml:1:1: a\\nb: unknown key (known: {})", kRootKeys)},
      {"MissingMaterial",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n", "",
       "test.toml: material: missing, expected a table"},
      {"MaterialIsAValue",
       "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n",
       "material = 3\n", "test.toml:2:12: material: expected a table, got 3"},
      {"MissingProfile", "[profile]\ntype = \"parabolic\"\nradius = 0.01\n", "",
       "test.toml: profile: missing, expected a table"},
      {"MissingLoading",
       "[loading]\npreload = { contact_radius = 5.0e-4 }\ntangential = { control = "
       "\"fixed-grips\", displacement = 0.0 }\nnormal = { control = \"fixed-load\" }\n",
       "", "test.toml: loading: missing, expected a table"},
  };
}
INSTANTIATE_TEST_SUITE_P(Root, BadSceneTest, ::testing::ValuesIn(root_cases()), case_name);

// ---- [material] ----

std::vector<BadScene> material_cases() {
  const std::string e_help = "Young's modulus E [Pa], > 0; or give effective_modulus";
  return {
      {"YoungsModulusMissing", "youngs_modulus = 1.0e6\n", "",
       "test.toml:2:1: material.youngs_modulus: missing, expected a number (" + e_help + ")"},
      {"YoungsModulusString", "youngs_modulus = 1.0e6", R"(youngs_modulus = "1e6")",
       R"(test.toml:3:18: material.youngs_modulus: expected a number, got string "1e6")"},
      {"YoungsModulusMultilineString", "youngs_modulus = 1.0e6",
       "youngs_modulus = \"\"\"1.0e6\n\"\"\"",
       R"(test.toml:3:18: material.youngs_modulus: expected a number, got string "1.0e6\n")"},
      {"YoungsModulusArray", "youngs_modulus = 1.0e6", "youngs_modulus = [1.0e6]",
       "test.toml:3:18: material.youngs_modulus: expected a number, got an array"},
      {"YoungsModulusTable", "youngs_modulus = 1.0e6", "youngs_modulus = { value = 1.0e6 }",
       "test.toml:3:18: material.youngs_modulus: expected a number, got a table"},
      {"YoungsModulusBoolean", "youngs_modulus = 1.0e6", "youngs_modulus = true",
       "test.toml:3:18: material.youngs_modulus: expected a number, got true"},
      {"YoungsModulusDate", "youngs_modulus = 1.0e6", "youngs_modulus = 2024-01-01",
       "test.toml:3:18: material.youngs_modulus: expected a number, got a date or time"},
      {"YoungsModulusNegative", "youngs_modulus = 1.0e6", "youngs_modulus = -1.0e6",
       "test.toml:3:18: material.youngs_modulus = -1000000 is outside (0, inf)"},
      {"YoungsModulusZero", "youngs_modulus = 1.0e6", "youngs_modulus = 0",
       "test.toml:3:18: material.youngs_modulus = 0 is outside (0, inf)"},
      {"YoungsModulusNan", "youngs_modulus = 1.0e6", "youngs_modulus = nan",
       "test.toml:3:18: material.youngs_modulus = nan is not a finite number"},
      {"YoungsModulusInf", "youngs_modulus = 1.0e6", "youngs_modulus = inf",
       "test.toml:3:18: material.youngs_modulus = inf is not a finite number"},
      {"YoungsModulusMinusInf", "youngs_modulus = 1.0e6", "youngs_modulus = -inf",
       "test.toml:3:18: material.youngs_modulus = -inf is not a finite number"},
      {"YoungsModulusTypo", "youngs_modulus = 1.0e6", "youngs_modulu = 1.0e6",
       fmt::format("test.toml:3:1: material.youngs_modulu: unknown key; did you mean "
                   "'youngs_modulus'? (known: {})",
                   kMaterialKeys)},
      {"PoissonRatioAboveHalf", "poisson_ratio = 0.0", "poisson_ratio = 0.7",
       "test.toml:4:17: material.poisson_ratio = 0.7 is outside (-1, 0.5]"},
      {"PoissonRatioMinusOne", "poisson_ratio = 0.0", "poisson_ratio = -1",
       "test.toml:4:17: material.poisson_ratio = -1 is outside (-1, 0.5]"},
      {"PoissonRatioString", "poisson_ratio = 0.0", "poisson_ratio = \"0.3\"",
       R"(test.toml:4:17: material.poisson_ratio: expected a number, got string "0.3")"},
      {"PoissonRatioNan", "poisson_ratio = 0.0", "poisson_ratio = nan",
       "test.toml:4:17: material.poisson_ratio = nan is not a finite number"},
      {"PoissonRatioMissing", "poisson_ratio = 0.0\n", "",
       "test.toml:2:1: material.poisson_ratio: missing, expected a number (Poisson's ratio nu in "
       "(-1, 0.5])"},
      {"PoissonRatioTypo", "poisson_ratio = 0.0", "poisson = 0.0",
       fmt::format("test.toml:4:1: material.poisson: unknown key; did you mean 'poisson_ratio'? "
                   "(known: {})",
                   kMaterialKeys)},
      {"WorkOfAdhesionNegative", "work_of_adhesion = 0.05", "work_of_adhesion = -0.01",
       "test.toml:5:20: material.work_of_adhesion = -0.01 is outside [0, inf)"},
      {"WorkOfAdhesionInf", "work_of_adhesion = 0.05", "work_of_adhesion = +inf",
       "test.toml:5:20: material.work_of_adhesion = inf is not a finite number"},
      {"WorkOfAdhesionArray", "work_of_adhesion = 0.05", "work_of_adhesion = [0.05]",
       "test.toml:5:20: material.work_of_adhesion: expected a number, got an array"},
      {"WorkOfAdhesionString", "work_of_adhesion = 0.05", "work_of_adhesion = \"sticky\"",
       R"(test.toml:5:20: material.work_of_adhesion: expected a number, got string "sticky")"},
      {"WorkOfAdhesionTypo", "work_of_adhesion = 0.05", "work_of_adhesio = 0.05",
       fmt::format("test.toml:5:1: material.work_of_adhesio: unknown key; did you mean "
                   "'work_of_adhesion'? (known: {})",
                   kMaterialKeys)},
      {"EffectiveShearModulusString", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = 1.0e6\neffective_shear_modulus = \"soft\"",
       R"(test.toml:4:27: material.effective_shear_modulus: expected a number, got string "soft")"},
      {"WorkOfAdhesionMissing", "work_of_adhesion = 0.05\n", "",
       "test.toml:2:1: material.work_of_adhesion: missing, expected a number (work of adhesion "
       "dgamma [J/m^2], >= 0)"},
      {"BothFormsGiven", "poisson_ratio = 0.0", "poisson_ratio = 0.0\neffective_modulus = 1.0e6",
       "test.toml:5:21: material.effective_modulus: give youngs_modulus and poisson_ratio, or "
       "effective_modulus (and effective_shear_modulus), not both"},
      {"BothFormsGivenShear", "poisson_ratio = 0.0",
       "poisson_ratio = 0.0\neffective_shear_modulus = 1.0e6",
       "test.toml:5:27: material.effective_shear_modulus: give youngs_modulus and poisson_ratio, "
       "or effective_modulus (and effective_shear_modulus), not both"},
      {"EffectiveModulusMissing", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_shear_modulus = 1.0e6",
       "test.toml:2:1: material.effective_modulus: missing, expected a number (E* [Pa], > 0)"},
      {"EffectiveModulusZero", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = 0.0",
       "test.toml:3:21: material.effective_modulus = 0 is outside (0, inf)"},
      {"EffectiveModulusString", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = \"big\"",
       R"(test.toml:3:21: material.effective_modulus: expected a number, got string "big")"},
      {"EffectiveModulusNan", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = nan",
       "test.toml:3:21: material.effective_modulus = nan is not a finite number"},
      {"EffectiveShearModulusNegative", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = 1.0e6\neffective_shear_modulus = -1.0",
       "test.toml:4:27: material.effective_shear_modulus = -1 is outside (0, inf)"},
      {"EffectiveShearModulusInf", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = 1.0e6\neffective_shear_modulus = inf",
       "test.toml:4:27: material.effective_shear_modulus = inf is not a finite number"},
      {"EffectiveModulusTypo", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "effective_modulus = 1.0e6\neffective_shear = 1.0e6",
       fmt::format("test.toml:4:1: material.effective_shear: unknown key; did you mean "
                   "'effective_shear_modulus'? (known: {})",
                   kMaterialKeys)},
      {"ModuliOverflow", "youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
       "youngs_modulus = 1.0e308\npoisson_ratio = -0.999",
       "test.toml:2:1: material: youngs_modulus = 1e+308 and poisson_ratio = -0.999 give E* = "
       "inf Pa, G* = inf Pa; expected finite positive moduli"},
  };
}
INSTANTIATE_TEST_SUITE_P(Material, BadSceneTest, ::testing::ValuesIn(material_cases()), case_name);

// ---- [profile] ----

std::vector<BadScene> profile_cases() {
  const std::string radius_help = help(registries().profiles, "parabolic", "radius");
  return {
      {"TypeMissing", "type = \"parabolic\"\n", "",
       fmt::format("test.toml:6:1: profile.type: missing, expected a string (one of: {})",
                   profiles())},
      {"TypeNumber", "type = \"parabolic\"", "type = 2",
       "test.toml:7:8: profile.type: expected a string, got 2"},
      {"TypeWithNewlineIsEscaped", "type = \"parabolic\"", "type = \"\"\"para\nbolic\"\"\"",
       fmt::format(
           R"(test.toml:7:8: profile.type: unknown 'para\nbolic'; did you mean 'parabolic'? (known: {}))",
           profiles())},
      {"TypeArray", "type = \"parabolic\"", "type = [\"parabolic\"]",
       "test.toml:7:8: profile.type: expected a string, got an array"},
      {"TypeUnknown", "type = \"parabolic\"", "type = \"parabola\"",
       fmt::format(
           "test.toml:7:8: profile.type: unknown 'parabola'; did you mean 'parabolic'? (known: {})",
           profiles())},
      {"RadiusMissing", "radius = 0.01\n", "",
       fmt::format("test.toml:6:1: profile.radius: missing, expected a number ({})", radius_help)},
      {"RadiusNegative", "radius = 0.01", "radius = -0.01",
       "test.toml:8:10: profile.radius = -0.01 is outside (0, inf)"},
      {"RadiusString", "radius = 0.01", "radius = \"1 cm\"",
       R"(test.toml:8:10: profile.radius: expected a number, got string "1 cm")"},
      {"RadiusNan", "radius = 0.01", "radius = -nan",
       "test.toml:8:10: profile.radius = nan is not a finite number"},
      {"RadiusTable", "radius = 0.01", "radius = { value = 0.01 }",
       "test.toml:8:10: profile.radius: expected a number, got a table"},
      {"RadiusTypo", "radius = 0.01", "radiuss = 0.01",
       "test.toml:8:1: profile.radiuss: unknown key; did you mean 'radius'? (known: radius, type)"},
  };
}
INSTANTIATE_TEST_SUITE_P(Profile, BadSceneTest, ::testing::ValuesIn(profile_cases()), case_name);

// ---- [loading] ----

constexpr const char* kPreload = "preload = { contact_radius = 5.0e-4 }";
constexpr const char* kTangential =
    R"(tangential = { control = "fixed-grips", displacement = 0.0 })";
constexpr const char* kNormal = R"(normal = { control = "fixed-load" })";
constexpr const char* kExactlyOne =
    "loading.preload: give exactly one of depth [m], force [N] or contact_radius [m]";

std::vector<BadScene> loading_cases() {
  const std::string stiffness_help = help(registries().controllers, "compliant", "stiffness");
  return {
      {"Typo", kPreload, std::string(kPreload) + "\nprelod = 1",
       "test.toml:11:1: loading.prelod: unknown key; did you mean 'preload'? (known: normal, "
       "preload, tangential)"},
      // preload
      {"PreloadMissing", std::string(kPreload) + "\n", "",
       "test.toml:9:1: loading.preload: missing, expected a table"},
      {"PreloadIsANumber", kPreload, "preload = 5.0e-4",
       "test.toml:10:11: loading.preload: expected a table, got 0.0005"},
      {"PreloadEmpty", kPreload, "preload = {}", fmt::format("test.toml:10:11: {}", kExactlyOne)},
      {"PreloadTwoQuantities", kPreload, "preload = { depth = 1.0e-5, force = 0.01 }",
       fmt::format("test.toml:10:11: {}", kExactlyOne)},
      {"PreloadThreeQuantities", kPreload,
       "preload = { depth = 1.0e-5, force = 0.01, contact_radius = 5.0e-4 }",
       fmt::format("test.toml:10:11: {}", kExactlyOne)},
      {"PreloadTypo", kPreload, "preload = { contact_radiu = 5.0e-4 }",
       "test.toml:10:13: loading.preload.contact_radiu: unknown key; did you mean "
       "'contact_radius'? (known: contact_radius, "
       "depth, force)"},
      {"PreloadDepthZero", kPreload, "preload = { depth = 0.0 }",
       "test.toml:10:21: loading.preload.depth = 0 is outside (0, inf)"},
      {"PreloadDepthString", kPreload, "preload = { depth = \"deep\" }",
       R"(test.toml:10:21: loading.preload.depth: expected a number, got string "deep")"},
      {"PreloadDepthNan", kPreload, "preload = { depth = nan }",
       "test.toml:10:21: loading.preload.depth = nan is not a finite number"},
      {"PreloadForceNegative", kPreload, "preload = { force = -0.01 }",
       "test.toml:10:21: loading.preload.force = -0.01 is outside (0, inf)"},
      {"PreloadForceInf", kPreload, "preload = { force = inf }",
       "test.toml:10:21: loading.preload.force = inf is not a finite number"},
      {"PreloadForceArray", kPreload, "preload = { force = [0.01] }",
       "test.toml:10:21: loading.preload.force: expected a number, got an array"},
      {"PreloadContactRadiusZero", kPreload, "preload = { contact_radius = 0 }",
       "test.toml:10:30: loading.preload.contact_radius = 0 is outside (0, inf)"},
      {"PreloadContactRadiusBoolean", kPreload, "preload = { contact_radius = false }",
       "test.toml:10:30: loading.preload.contact_radius: expected a number, got false"},
      // tangential
      {"TangentialIsANumber", kTangential, "tangential = 0.0",
       "test.toml:11:14: loading.tangential: expected a table, got 0"},
      {"TangentialControlMissing", kTangential, "tangential = { displacement = 0.0 }",
       fmt::format("test.toml:11:14: loading.tangential.control: missing, expected a string "
                   "(one of: {})",
                   controllers())},
      {"TangentialControlNumber", kTangential, "tangential = { control = 1, displacement = 0.0 }",
       "test.toml:11:26: loading.tangential.control: expected a string, got 1"},
      {"TangentialControlUnknown", kTangential,
       R"(tangential = { control = "fixed-grip", displacement = 0.0 })",
       fmt::format("test.toml:11:26: loading.tangential.control: unknown 'fixed-grip'; did you "
                   "mean 'fixed-grips'? (known: {})",
                   controllers())},
      {"TangentialDisplacementMissing", kTangential, R"(tangential = { control = "fixed-grips" })",
       "test.toml:11:14: loading.tangential.displacement: missing, expected a number (the held "
       "displacement [m])"},
      {"TangentialDisplacementString", kTangential,
       R"(tangential = { control = "fixed-grips", displacement = "1 um" })",
       R"(test.toml:11:56: loading.tangential.displacement: expected a number, got string "1 um")"},
      {"TangentialDisplacementNan", kTangential,
       R"(tangential = { control = "fixed-grips", displacement = nan })",
       "test.toml:11:56: loading.tangential.displacement = nan is not a finite number"},
      {"TangentialDisplacementTypo", kTangential,
       R"(tangential = { control = "fixed-grips", displacment = 0.0 })",
       "test.toml:11:41: loading.tangential.displacment: unknown key; did you mean 'displacement'? "
       "(known: control, "
       "displacement, force)"},
      {"TangentialForceUnderFixedGrips", kTangential,
       R"(tangential = { control = "fixed-grips", force = 0.0 })",
       "test.toml:11:49: loading.tangential.force: control = \"fixed-grips\" holds displacement, "
       "not force"},
      {"TangentialDisplacementUnderFixedLoad", kTangential,
       R"(tangential = { control = "fixed-load", displacement = 0.0 })",
       "test.toml:11:55: loading.tangential.displacement: control = \"fixed-load\" holds force, "
       "not displacement"},
      {"TangentialForceMissing", kTangential, R"(tangential = { control = "fixed-load" })",
       "test.toml:11:14: loading.tangential.force: missing, expected a number (the held force "
       "[N])"},
      {"TangentialForceString", kTangential,
       R"(tangential = { control = "fixed-load", force = "1 N" })",
       R"(test.toml:11:48: loading.tangential.force: expected a number, got string "1 N")"},
      {"TangentialForceInf", kTangential,
       R"(tangential = { control = "fixed-load", force = -inf })",
       "test.toml:11:48: loading.tangential.force = -inf is not a finite number"},
      // normal
      {"NormalMissing", std::string(kNormal) + "\n", "",
       "test.toml:9:1: loading.normal: missing, expected a table"},
      {"NormalIsAString", kNormal, R"(normal = "fixed-load")",
       R"(test.toml:12:10: loading.normal: expected a table, got string "fixed-load")"},
      {"NormalControlMissing", kNormal, "normal = {}",
       fmt::format("test.toml:12:10: loading.normal.control: missing, expected a string "
                   "(one of: {})",
                   controllers())},
      {"NormalControlUnknown", kNormal, R"(normal = { control = "fixed_load" })",
       fmt::format("test.toml:12:22: loading.normal.control: unknown 'fixed_load'; did you mean "
                   "'fixed-load'? (known: {})",
                   controllers())},
      {"NormalControlTable", kNormal, "normal = { control = { name = \"fixed-load\" } }",
       "test.toml:12:22: loading.normal.control: expected a string, got a table"},
      {"NormalHoldsNoValue", kNormal, R"(normal = { control = "fixed-load", force = 0.0 })",
       "test.toml:12:36: loading.normal.force: unknown key (known: control)"},
      {"NormalStiffnessNotCompliant", kNormal,
       R"(normal = { control = "fixed-load", stiffness = 10.0 })",
       "test.toml:12:48: loading.normal.stiffness: applies to control = \"compliant\" only"},
      {"NormalStiffnessMissing", kNormal, R"(normal = { control = "compliant" })",
       fmt::format("test.toml:12:10: loading.normal.stiffness: missing, expected a number ({})",
                   stiffness_help)},
      {"NormalStiffnessZero", kNormal, R"(normal = { control = "compliant", stiffness = 0 })",
       "test.toml:12:47: loading.normal.stiffness = 0 is outside (0, inf)"},
      {"NormalStiffnessString", kNormal,
       R"(normal = { control = "compliant", stiffness = "stiff" })",
       R"(test.toml:12:47: loading.normal.stiffness: expected a number, got string "stiff")"},
      {"NormalStiffnessInf", kNormal, R"(normal = { control = "compliant", stiffness = inf })",
       "test.toml:12:47: loading.normal.stiffness = inf is not a finite number"},
      {"NormalStiffnessTypo", kNormal, R"(normal = { control = "compliant", stifness = 10.0 })",
       "test.toml:12:35: loading.normal.stifness: unknown key; did you mean 'stiffness'? (known: "
       "control, stiffness)"},
  };
}
INSTANTIATE_TEST_SUITE_P(Loading, BadSceneTest, ::testing::ValuesIn(loading_cases()), case_name);

// ---- [detachment], [discretization], [solver] ----

std::vector<BadScene> detachment_cases() {
  const std::string lambda_help = help(registries().criteria, "mode-dependent", "lambda");
  return {
      {"CriterionUnknown", "criterion = \"mode-mixed\"", "criterion = \"stres\"",
       fmt::format("test.toml:14:13: detachment.criterion: unknown 'stres'; did you mean 'stress'? "
                   "(known: {})",
                   criteria())},
      {"CriterionNumber", "criterion = \"mode-mixed\"", "criterion = 20",
       "test.toml:14:13: detachment.criterion: expected a string, got 20"},
      {"CriterionTypo", "criterion = \"mode-mixed\"", "criterio = \"stress\"",
       "test.toml:14:1: detachment.criterio: unknown key; did you mean 'criterion'? (known: "
       "criterion, front_speed_law)"},
      {"LambdaMissing", "criterion = \"mode-mixed\"", "criterion = \"mode-dependent\"",
       fmt::format("test.toml:13:1: detachment.lambda: missing, expected a number ({})",
                   lambda_help)},
      {"LambdaAboveOne", "criterion = \"mode-mixed\"",
       "criterion = \"mode-dependent\"\nlambda = 1.5",
       "test.toml:15:10: detachment.lambda = 1.5 is outside [0, 1]"},
      {"LambdaNegative", "criterion = \"mode-mixed\"",
       "criterion = \"mode-dependent\"\nlambda = -0.1",
       "test.toml:15:10: detachment.lambda = -0.1 is outside [0, 1]"},
      {"LambdaNan", "criterion = \"mode-mixed\"", "criterion = \"mode-dependent\"\nlambda = nan",
       "test.toml:15:10: detachment.lambda = nan is not a finite number"},
      {"LambdaString", "criterion = \"mode-mixed\"",
       "criterion = \"mode-dependent\"\nlambda = \"half\"",
       R"(test.toml:15:10: detachment.lambda: expected a number, got string "half")"},
      {"LambdaTypo", "criterion = \"mode-mixed\"", "criterion = \"mode-dependent\"\nlamda = 0.5",
       "test.toml:15:1: detachment.lamda: unknown key; did you mean 'lambda'? (known: criterion, "
       "front_speed_law, lambda)"},
      {"LambdaWithOtherCriterion", "criterion = \"mode-mixed\"",
       "criterion = \"mode-mixed\"\nlambda = 0.5",
       "test.toml:15:10: detachment.lambda: applies to criterion = \"mode-dependent\" only"},
      {"LambdaWithDefaultCriterion", "criterion = \"mode-mixed\"", "lambda = 0.5",
       "test.toml:14:10: detachment.lambda: applies to criterion = \"mode-dependent\" only"},
  };
}
INSTANTIATE_TEST_SUITE_P(Detachment, BadSceneTest, ::testing::ValuesIn(detachment_cases()),
                         case_name);

std::vector<BadScene> discretization_cases() {
  return {
      {"SpringsZero", "springs = 100", "springs = 0",
       "test.toml:16:11: discretization.springs = 0 is outside [1, 1000000000]"},
      {"SpringsTooMany", "springs = 100", "springs = 1e10",
       "test.toml:16:11: discretization.springs = 10000000000 is outside [1, 1000000000]"},
      {"SpringsFraction", "springs = 100", "springs = 100.5",
       "test.toml:16:11: discretization.springs = 100.5 is not a whole number"},
      {"SpringsString", "springs = 100", "springs = \"100\"",
       R"(test.toml:16:11: discretization.springs: expected a whole number, got string "100")"},
      {"SpringsNan", "springs = 100", "springs = nan",
       "test.toml:16:11: discretization.springs = nan is not a finite number"},
      {"SpringsArray", "springs = 100", "springs = [100]",
       "test.toml:16:11: discretization.springs: expected a whole number, got an array"},
      {"SpringsTypo", "springs = 100", "spring = 100",
       "test.toml:16:1: discretization.spring: unknown key; did you mean 'springs'? (known: "
       "extrapolation, rtol, springs)"},
      {"RtolTooLoose", "springs = 100", "rtol = 0.5",
       "test.toml:16:8: discretization.rtol = 0.5 is outside [1e-12, 0.1]"},
      {"RtolString", "springs = 100", "rtol = \"tight\"",
       R"(test.toml:16:8: discretization.rtol: expected a number, got string "tight")"},
      {"RtolAndSprings", "springs = 100", "springs = 100\nrtol = 1e-3",
       "test.toml:17:8: discretization.rtol: give springs or rtol, not both"},
      {"ExtrapolationUnknown", "springs = 100", "extrapolation = \"aitken\"",
       "test.toml:16:17: discretization.extrapolation: unknown 'aitken' (known: none, richardson)"},
  };
}
INSTANTIATE_TEST_SUITE_P(Discretization, BadSceneTest, ::testing::ValuesIn(discretization_cases()),
                         case_name);

constexpr const char* kStepping = "method = \"stepping\"";

std::vector<BadScene> solver_cases() {
  return {
      {"MethodUnknown", "method = \"event\"", "method = \"events\"",
       "test.toml:18:10: solver.method: unknown 'events'; did you mean 'event'? (known: event, "
       "stepping, continuum)"},
      {"MethodNumber", "method = \"event\"", "method = 1",
       "test.toml:18:10: solver.method: expected a string, got 1"},
      {"MethodTypo", "method = \"event\"", "mehtod = \"event\"",
       "test.toml:18:1: solver.mehtod: unknown key; did you mean 'method'? (known: max_events, "
       "max_events_per_spring, max_halvings, max_steps, method, step)"},
      {"StepWithEvent", "method = \"event\"", "method = \"event\"\nstep = 1e-6",
       "test.toml:19:8: solver.step: applies to method = \"stepping\" only"},
      {"StepWithDefaultMethod", "method = \"event\"", "step = 1e-6",
       "test.toml:18:8: solver.step: applies to method = \"stepping\" only"},
      {"MaxHalvingsWithEvent", "method = \"event\"", "method = \"event\"\nmax_halvings = 3",
       "test.toml:19:16: solver.max_halvings: applies to method = \"stepping\" only"},
      {"MaxStepsWithEvent", "method = \"event\"", "method = \"event\"\nmax_steps = 3",
       "test.toml:19:13: solver.max_steps: applies to method = \"stepping\" only"},
      {"StepZero", "method = \"event\"", std::string(kStepping) + "\nstep = 0.0",
       "test.toml:19:8: solver.step = 0 is outside (0, inf)"},
      {"StepNan", "method = \"event\"", std::string(kStepping) + "\nstep = nan",
       "test.toml:19:8: solver.step = nan is not a finite number"},
      {"StepString", "method = \"event\"", std::string(kStepping) + "\nstep = \"small\"",
       R"(test.toml:19:8: solver.step: expected a number, got string "small")"},
      {"StepTypo", "method = \"event\"", std::string(kStepping) + "\nsteps = 1e-6",
       "test.toml:19:1: solver.steps: unknown key; did you mean 'step'? (known: max_events, "
       "max_events_per_spring, max_halvings, max_steps, method, step)"},
      {"MaxHalvingsNegative", "method = \"event\"", std::string(kStepping) + "\nmax_halvings = -1",
       "test.toml:19:16: solver.max_halvings = -1 is outside [0, 60]"},
      {"MaxHalvingsTooMany", "method = \"event\"", std::string(kStepping) + "\nmax_halvings = 61",
       "test.toml:19:16: solver.max_halvings = 61 is outside [0, 60]"},
      {"MaxHalvingsFraction", "method = \"event\"", std::string(kStepping) + "\nmax_halvings = 2.5",
       "test.toml:19:16: solver.max_halvings = 2.5 is not a whole number"},
      {"MaxHalvingsString", "method = \"event\"", std::string(kStepping) + "\nmax_halvings = \"3\"",
       R"(test.toml:19:16: solver.max_halvings: expected a whole number, got string "3")"},
      {"MaxStepsZero", "method = \"event\"", std::string(kStepping) + "\nmax_steps = 0",
       "test.toml:19:13: solver.max_steps = 0 is outside [1, 1000000000000000]"},
      {"MaxStepsString", "method = \"event\"", std::string(kStepping) + "\nmax_steps = \"many\"",
       R"(test.toml:19:13: solver.max_steps: expected a whole number, got string "many")"},
      {"MaxStepsFraction", "method = \"event\"", std::string(kStepping) + "\nmax_steps = 10.5",
       "test.toml:19:13: solver.max_steps = 10.5 is not a whole number"},
      {"MaxStepsTooMany", "method = \"event\"", std::string(kStepping) + "\nmax_steps = 1e16",
       "test.toml:19:13: solver.max_steps = 1e+16 is outside [1, 1000000000000000]"},
      {"MaxStepsInf", "method = \"event\"", std::string(kStepping) + "\nmax_steps = inf",
       "test.toml:19:13: solver.max_steps = inf is not a finite number"},
      // The event limits hold under either row method, and only there.
      {"MaxEventsZero", "method = \"event\"", "method = \"event\"\nmax_events = 0",
       "test.toml:19:14: solver.max_events = 0 is outside [1, 1000000000000000]"},
      {"MaxEventsTooMany", "method = \"event\"", std::string(kStepping) + "\nmax_events = 1e16",
       "test.toml:19:14: solver.max_events = 1e+16 is outside [1, 1000000000000000]"},
      {"MaxEventsFraction", "method = \"event\"", "max_events = 10.5",
       "test.toml:18:14: solver.max_events = 10.5 is not a whole number"},
      {"MaxEventsString", "method = \"event\"", "max_events = \"many\"",
       R"(test.toml:18:14: solver.max_events: expected a whole number, got string "many")"},
      {"MaxEventsWithContinuum", "method = \"event\"", "method = \"continuum\"\nmax_events = 10",
       "test.toml:19:14: solver.max_events: applies to method = \"event\" or \"stepping\" only"},
      {"MaxEventsPerSpringZero", "method = \"event\"", "max_events_per_spring = 0",
       "test.toml:18:25: solver.max_events_per_spring = 0 is outside [1, 1000000000]"},
      {"MaxEventsPerSpringTooMany", "method = \"event\"", "max_events_per_spring = 2e9",
       "test.toml:18:25: solver.max_events_per_spring = 2000000000 is outside [1, 1000000000]"},
      {"MaxEventsPerSpringFraction", "method = \"event\"", "max_events_per_spring = 0.5",
       "test.toml:18:25: solver.max_events_per_spring = 0.5 is outside [1, 1000000000]"},
      {"MaxEventsPerSpringWithContinuum", "method = \"event\"",
       "method = \"continuum\"\nmax_events_per_spring = 8",
       "test.toml:19:25: solver.max_events_per_spring: applies to method = \"event\" or "
       "\"stepping\" only"},
  };
}
INSTANTIATE_TEST_SUITE_P(Solver, BadSceneTest, ::testing::ValuesIn(solver_cases()), case_name);

// ---- malformed TOML ----

std::vector<BadScene> malformed_cases() {
  return {
      {"UnterminatedString", R"(title = "test scene")", R"(title = "test scene)",
       "test.toml:1:20: malformed TOML: error while parsing string: unescaped control characters "
       "other than TAB (U+0009) are explicitly prohibited"},
      {"DuplicateKey", "poisson_ratio = 0.0", "poisson_ratio = 0.0\npoisson_ratio = 0.3",
       "test.toml:5:17: malformed TOML: error while parsing key-value pair: cannot redefine "
       "existing floating-point 'poisson_ratio'"},
      {"DuplicateTable", "[solver]", "[material]",
       "test.toml:17:1: malformed TOML: error while parsing table header: cannot redefine "
       "existing table 'material'"},
      {"MissingValue", "radius = 0.01", "radius =",
       R"(test.toml:8:9: malformed TOML: error while parsing key-value pair: expected value, saw '\n')"},
      {"InvalidUtf8", R"(title = "test scene")", "title = \"\xff\xfe\"",
       "test.toml:1:9: malformed TOML: encountered invalid utf-8 sequence"},
      {"NulByteInAString", R"(title = "test scene")", std::string("title = \"a\0b\"", 12),
       "test.toml:1:11: malformed TOML: error while parsing string: unescaped control characters "
       "other than TAB (U+0009) are explicitly prohibited"},
      {"UnclosedInlineTable", kNormal, R"(normal = { control = "fixed-load")",
       R"(test.toml:12:34: malformed TOML: error while parsing inline table: expected key or closing '}', saw '\n')"},
  };
}

// ---- numbers TOML reads but a double (or a 64-bit whole number) cannot hold ----
// toml++ refuses them as "could not be interpreted as a value"; they name their key as every
// other bad value does, at the column where the number begins.

std::vector<BadScene> beyond_range_cases() {
  return {
      {"Float", "radius = 0.01", "radius = 1e400",
       "test.toml:8:10: profile.radius = 1e400 is beyond the range of a double (largest 1.8e308)"},
      {"NegativeWithUnderscores", "radius = 0.01", "radius = -1_0e4_00",
       "test.toml:8:10: profile.radius = -1_0e4_00 is beyond the range of a double (largest "
       "1.8e308)"},
      {"MalformedStaysMalformed", kPreload, "preload = { contact_radius = 5e-4e0 }",
       "test.toml:10:34: malformed TOML: error while parsing floating-point: expected "
       "decimal digit, saw 'e'"},
      {"InInlineTableValue", kPreload, "preload = { contact_radius = 2e308 }",
       "test.toml:10:30: loading.preload.contact_radius = 2e308 is beyond the range of a double "
       "(largest 1.8e308)"},
      {"InArray", "work_of_adhesion = 0.05",
       "work_of_adhesion = { r = [0.0, 1e500, 2e-3], value = [0.05, 0.05, 0.06] }",
       "test.toml:5:32: material.work_of_adhesion.r[1] = 1e500 is beyond the range of a double "
       "(largest 1.8e308)"},
      {"TheFirstOfTwo", "springs = 100", "springs = 100\nrtol = 1e999\nx = 2e999",
       "test.toml:17:8: discretization.rtol = 1e999 is beyond the range of a double (largest "
       "1.8e308)"},
      {"WholeNumber", "springs = 100", "springs = 99999999999999999999",
       "test.toml:16:11: discretization.springs = 99999999999999999999 is beyond the range of a "
       "64-bit whole number"},
  };
}
INSTANTIATE_TEST_SUITE_P(BeyondRange, BadSceneTest, ::testing::ValuesIn(beyond_range_cases()),
                         case_name);

// ---- numbers written nonzero that a double reads as zero ----
// toml++ reads 1e-400 as 0 without a word; a work of adhesion typed with one digit too many in
// its exponent would silently turn the adhesion off. Written zeros (0.0e-500) stay zeros.

std::vector<BadScene> underflow_cases() {
  return {
      {"Float", "work_of_adhesion = 0.05", "work_of_adhesion = 1e-400",
       "test.toml:5:20: material.work_of_adhesion = 1e-400 is too small for a double (it would "
       "read as 0; the smallest is 4.9e-324)"},
      {"InArray", "work_of_adhesion = 0.05",
       "work_of_adhesion = { r = [0.0, 1e-3, 2e-3], value = [0.05, -5_0e-4_00, 0.06] }",
       "test.toml:5:60: material.work_of_adhesion.value[1] = -5_0e-4_00 is too small for a "
       "double (it would read as 0; the smallest is 4.9e-324)"},
  };
}
INSTANTIATE_TEST_SUITE_P(Underflow, BadSceneTest, ::testing::ValuesIn(underflow_cases()),
                         case_name);

TEST(GoodScene, AWrittenZeroWithAHugeNegativeExponentIsZero) {
  EXPECT_EQ(build_scene_text(scene_with("work_of_adhesion = 0.05",
                                        "work_of_adhesion = 0.05\n"
                                        "approach_work_of_adhesion = 0.0e-500"))
                .material.approach_work_of_adhesion_at(0.0),
            0.0);
}

TEST(BadScene, ANumberBeyondADoubleInAnArrayOfTablesNamesTheStage) {
  const std::string program = R"([material]
effective_modulus = 1.0e6
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
normal = { control = "fixed-grips", to = 2.0e-5 }
[[loading.stage]]
normal = { by = -1e400 }
)";
  EXPECT_THROW_MSG(SceneDocument::from_text(program, "test.toml"), SceneError,
                   "test.toml:10:17: loading.stage.2.normal.by = -1e400 is beyond the range of a "
                   "double (largest 1.8e308)");
}
INSTANTIATE_TEST_SUITE_P(Malformed, BadSceneTest, ::testing::ValuesIn(malformed_cases()),
                         case_name);

// ---- good scenes: the cases above fail for their own reason, not the base scene's ----

TEST(GoodScene, BaseSceneBuilds) { EXPECT_NO_THROW(build_scene_text(std::string(kScene))); }

TEST(GoodScene, OptionalKeysMayBeLeftOut) {
  EXPECT_EQ(build_scene_text(scene_with(R"(title = "test scene")", "")).title, "");
  const Scene defaults = build_scene_text(
      scene_with("[detachment]\ncriterion = \"mode-mixed\"\n[discretization]\nsprings = 100\n"
                 "[solver]\nmethod = \"event\"\n",
                 ""));
  EXPECT_EQ(defaults.criterion_name, "mode-mixed");
  EXPECT_EQ(defaults.springs, 2000);
  EXPECT_TRUE(defaults.solver.method == SolverMethod::event);
  EXPECT_FALSE(build_scene_text(scene_with(std::string(kTangential) + "\n", "")).tangential);
}

TEST(GoodScene, EveryPreloadFormAndEffectiveModuli) {
  EXPECT_NO_THROW(build_scene_text(scene_with(kPreload, "preload = { depth = 1.0e-5 }")));
  EXPECT_NO_THROW(build_scene_text(scene_with(kPreload, "preload = { force = 0.01 }")));
  const Scene scene =
      build_scene_text(scene_with("youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
                                  "effective_modulus = 2.0e6\neffective_shear_modulus = 1.5e6"));
  EXPECT_EQ(scene.material.effective_modulus, 2.0e6);
  EXPECT_EQ(scene.material.effective_shear_modulus, 1.5e6);
  const Scene e_only = build_scene_text(
      scene_with("youngs_modulus = 1.0e6\npoisson_ratio = 0.0", "effective_modulus = 2.0e6"));
  EXPECT_EQ(e_only.material.effective_shear_modulus, 2.0e6);  // docs: G* defaults to E*
}

TEST(GoodScene, WholeFloatsAreWholeNumbersAndSteppingKeysApply) {
  const Scene scene = build_scene_text(
      replaced(scene_with("springs = 100", "springs = 1e3"), "method = \"event\"",
               "method = \"stepping\"\nstep = 1e-4\nmax_halvings = 0\nmax_steps = 5"));
  EXPECT_EQ(scene.springs, 1000);
  EXPECT_TRUE(scene.solver.method == SolverMethod::stepping);
  EXPECT_EQ(scene.solver.step, 1e-4);
  EXPECT_EQ(scene.solver.max_halvings, 0);
  EXPECT_EQ(scene.solver.max_steps, 5);
}

TEST(GoodScene, BoundaryValuesAreInside) {
  EXPECT_NO_THROW(build_scene_text(scene_with("poisson_ratio = 0.0", "poisson_ratio = 0.5")));
  EXPECT_NO_THROW(
      build_scene_text(scene_with("work_of_adhesion = 0.05", "work_of_adhesion = 0.0")));
  EXPECT_NO_THROW(build_scene_text(
      scene_with("criterion = \"mode-mixed\"", "criterion = \"mode-dependent\"\nlambda = 0")));
  EXPECT_NO_THROW(build_scene_text(
      scene_with("criterion = \"mode-mixed\"", "criterion = \"mode-dependent\"\nlambda = 1")));
}

// ---- cases that need more than one substitution ----

TEST(BadScene, PreloadThatOverflowsIsRefused) {
  EXPECT_TRUE(starts_with(thrown_message<SceneError>([] {
                            build_scene_text(scene_with(kPreload, "preload = { depth = 1e300 }"));
                          }),
                          "test.toml:10:11: loading.preload: the preload overflows ("));
}

/// kScene with the table `block` removed and `value_line` as its second line, where a value
/// belongs to the root table.
std::string root_value(std::string_view block, std::string_view value_line) {
  return replaced(scene_with(block, ""), "[material]", std::string(value_line) + "\n[material]");
}

TEST(BadScene, ValuesWhereTablesAreExpected) {
  EXPECT_THROW_MSG(build_scene_text(root_value("[profile]\ntype = \"parabolic\"\nradius = 0.01\n",
                                               "profile = \"parabolic\"")),
                   SceneError,
                   R"(test.toml:2:11: profile: expected a table, got string "parabolic")");
  EXPECT_THROW_MSG(build_scene_text(root_value("[detachment]\ncriterion = \"mode-mixed\"\n",
                                               "detachment = \"mode-mixed\"")),
                   SceneError,
                   R"(test.toml:2:14: detachment: expected a table, got string "mode-mixed")");
  EXPECT_THROW_MSG(
      build_scene_text(root_value("[discretization]\nsprings = 100\n", "discretization = 100")),
      SceneError, "test.toml:2:18: discretization: expected a table, got 100");
  EXPECT_THROW_MSG(
      build_scene_text(root_value("[solver]\nmethod = \"event\"\n", "solver = [\"event\"]")),
      SceneError, "test.toml:2:10: solver: expected a table, got an array");
}

TEST(BadScene, PreloadAsAHeaderTable) {
  // [loading.preload] at the end: a table with a header of its own, still checked.
  EXPECT_THROW_MSG(
      build_scene_text(scene_with(std::string(kPreload) + "\n", "") + "[loading.preload]\n"),
      SceneError, "test.toml:18:1: " + std::string(kExactlyOne));
  EXPECT_NO_THROW(build_scene_text(scene_with(std::string(kPreload) + "\n", "") +
                                   "[loading.preload]\ndepth = 1.0e-5\n"));
}

TEST(BadScene, UnterminatedStringAtTheEndOfTheFile) {
  EXPECT_THROW_MSG(build_scene_text(std::string(kScene) + "x = \"abc"), SceneError,
                   "test.toml:19:9: malformed TOML: error while parsing string: encountered "
                   "end-of-file");
}

TEST(BadScene, InRangeValuesThatOverflowTheRunAreRefused) {
  // Each value passes its own range; together they would give NaN or infinity in the result.
  EXPECT_THROW_MSG(
      build_scene_text(scene_with(
          kTangential, R"(tangential = { control = "fixed-grips", displacement = 1e308 })")),
      SceneError,
      "test.toml:11:56: loading.tangential.displacement = 1e+308 overflows the tangential force "
      "of the glued contact");
  EXPECT_THROW_MSG(
      build_scene_text(
          scene_with("youngs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05",
                     "effective_modulus = 5e-324\neffective_shear_modulus = 1\n"
                     "work_of_adhesion = 0")),
      SceneError,
      "test.toml:10:11: loading.preload: the contact stiffnesses 2 E* a = 0 N/m and 2 G* a = "
      "0.001 N/m at contact radius 0.0005 m are not finite and positive");
  EXPECT_TRUE(starts_with(
      thrown_message<SceneError>([] {
        build_scene_text(
            scene_with(kNormal, R"(normal = { control = "compliant", stiffness = 5e-324 })"));
      }),
      "test.toml:12:10: loading.normal: control = \"compliant\" is degenerate with these values "
      "(constraint a_u = 1, a_F = inf m/N against a contact stiffness of "));
}

TEST(BadScene, EmptyTextHasNoMaterial) {
  EXPECT_THROW_MSG(build_scene_text(""), SceneError,
                   "test.toml: material: missing, expected a table");
}

// A held tangential force in range whose dimensionless value F_x/F0 overflows (F0 = 2.4e-3 N
// here): the run would report F_x/F0 = inf, so the reader refuses it at its key, like the held
// displacement above (before, `mdrsim run` ended in an internal error, exit 1).
TEST(BadScene, TangentialForceWhoseDimensionlessValueOverflowsIsRefused) {
  EXPECT_THROW_MSG(
      build_scene_text(
          scene_with(kTangential, R"(tangential = { control = "fixed-load", force = 1e308 })")),
      SceneError,
      "test.toml:11:48: loading.tangential.force = 1e+308 overflows F/F0 (the JKR scale is "
      "0.0023561944901923453 N)");
}

// The same for the preload: a force in range whose F/F0 overflows would give F/F0 = inf in the
// result (found by the fuzzer; `mdrsim run` exits 1), so the reader refuses it at its key.
TEST(BadScene, PreloadForceWhoseDimensionlessValueOverflowsIsRefused) {
  EXPECT_THROW_MSG(
      build_scene_text(scene_with(kPreload, "preload = { force = 2.1e306 }")), SceneError,
      "test.toml:10:21: loading.preload.force = 2.1e+306 overflows F/F0 (the JKR scale is "
      "0.0023561944901923453 N)");
}

TEST(BadScene, ArrayOfTablesWhereATableIsExpected) {
  const std::string text =
      scene_with("[solver]\nmethod = \"event\"\n", "[[solver]]\nmethod = \"event\"\n");
  EXPECT_THROW_MSG(build_scene_text(text), SceneError,
                   "test.toml:17:1: solver: expected a table, got an array");
}

TEST(BadScene, UnknownKeyIsReportedBeforeAMissingOne) {
  // The typo, not the missing youngs_modulus, is what the user must fix.
  EXPECT_THROW_MSG(build_scene_text(scene_with("youngs_modulus = 1.0e6\npoisson_ratio = 0.0",
                                               "poisson_ratio = 0.0\nyoungs_modulu = 1.0e6")),
                   SceneError,
                   fmt::format("test.toml:4:1: material.youngs_modulu: unknown key; did you mean "
                               "'youngs_modulus'? (known: {})",
                               kMaterialKeys));
}

TEST(BadScene, LongStringValueIsCutShort) {
  const std::string text =
      scene_with("type = \"parabolic\"", "type = \"" + std::string(200, 'x') + "\"");
  EXPECT_THROW_MSG(build_scene_text(text), SceneError,
                   fmt::format("test.toml:7:8: profile.type: unknown '{}...' (known: {})",
                               std::string(80, 'x'), profiles()));
}

// ---- --set and --vary through the document ----

SceneDocument document() { return SceneDocument::from_text(kScene, "test.toml"); }

TEST(SetValue, OutOfRangeNamesTheFlag) {
  SceneDocument d = document();
  d.set_value("material.poisson_ratio", "0.7");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   "--set: material.poisson_ratio = 0.7 is outside (-1, 0.5]");
}

TEST(SetValue, UnknownKeyNamesTheFlag) {
  SceneDocument d = document();
  d.set_value("material.youngs_modulu", "1e6");
  EXPECT_THROW_MSG(
      d.build(registries()), SceneError,
      fmt::format(
          "--set: material.youngs_modulu: unknown key; did you mean 'youngs_modulus'? (known: {})",
          kMaterialKeys));
}

TEST(SetValue, UnknownKeyInsideASetTableNamesTheFlag) {
  SceneDocument d = document();
  d.set_value("loading.normal", R"({ control = "compliant", stifness = 1 })");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   "--set: loading.normal.stifness: unknown key; did you mean 'stiffness'? (known: "
                   "control, stiffness)");
}

TEST(SetValue, BareWordIsAString) {
  SceneDocument d = document();
  d.set_value("material.youngs_modulus", "stiff");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   R"(--set: material.youngs_modulus: expected a number, got string "stiff")");
  SceneDocument good = document();
  good.set_value("loading.normal.control", " fixed-grips ");
  EXPECT_EQ(good.build(registries()).normal.control, "fixed-grips");
}

TEST(SetValue, NonFiniteIsRefused) {
  SceneDocument d = document();
  d.set_value("profile.radius", "inf");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   "--set: profile.radius = inf is not a finite number");
}

TEST(SetValue, MissingKeyInASetTableNamesTheFlag) {
  SceneDocument d = document();
  d.set_value("material", "{}");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   "--set: material.work_of_adhesion: missing, expected a number (work of "
                   "adhesion dgamma [J/m^2], >= 0)");
}

TEST(SetValue, BadKeysAndValues) {
  SceneDocument d = document();
  EXPECT_THROW_MSG(d.set_value("", "1"), SceneError,
                   "--set: '' is not a dotted scene key like material.poisson_ratio");
  EXPECT_THROW_MSG(d.set_value("material..poisson_ratio", "1"), SceneError,
                   "--set: 'material..poisson_ratio' is not a dotted scene key like "
                   "material.poisson_ratio");
  EXPECT_THROW_MSG(d.set_value("material.", "1"), SceneError,
                   "--set: 'material.' is not a dotted scene key like material.poisson_ratio");
  EXPECT_THROW_MSG(d.set_value("title.text", "1"), SceneError,
                   "--set: title.text: 'title' is not a table");
  EXPECT_THROW_MSG(d.set_value("material.poisson_ratio", ""), SceneError,
                   "--set: material.poisson_ratio: the value is empty");
  EXPECT_THROW_MSG(d.set_value("material.poisson_ratio", "0.1\nyoungs_modulus = 1"), SceneError,
                   "--set: material.poisson_ratio: the value must be one line of text");
  // None of the refused values changed the document.
  EXPECT_NO_THROW(d.build(registries()));
}

TEST(SetNumber, VaryValueOutOfRangeNamesTheFlag) {
  SceneDocument d = document();
  d.set_number("material.poisson_ratio", 0.7, "--vary");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   "--vary: material.poisson_ratio = 0.7 is outside (-1, 0.5]");
  SceneDocument springs = document();
  springs.set_number("discretization.springs", 2.5, "--vary");
  EXPECT_THROW_MSG(springs.build(registries()), SceneError,
                   "--vary: discretization.springs = 2.5 is not a whole number");
  SceneDocument title = document();
  title.set_number("title", 1.0, "--vary");
  EXPECT_THROW_MSG(title.build(registries()), SceneError,
                   "--vary: title: expected a string, got 1");
}

TEST(SceneDocumentCopy, KeepsLinesAndFlags) {
  // A sweep builds copies of the document; toml++ drops source regions on copy.
  SceneDocument base =
      SceneDocument::from_text(scene_with("radius = 0.01", "radius = -0.01"), "test.toml");
  base.set_value("material.poisson_ratio", "0.3");
  const SceneDocument copy = base;
  EXPECT_THROW_MSG(copy.build(registries()), SceneError,
                   "test.toml:8:10: profile.radius = -0.01 is outside (0, inf)");
  SceneDocument assigned = document();
  assigned = base;
  assigned.set_value("profile.radius", "0.01");
  assigned.set_number("discretization.springs", 0, "--vary");
  const SceneDocument copy_of_copy = assigned;
  EXPECT_THROW_MSG(copy_of_copy.build(registries()), SceneError,
                   "--vary: discretization.springs = 0 is outside [1, 1000000000]");
}

TEST(SceneFile, MissingFile) {
  const std::string path = make_temp_dir() + "/none.toml";
  EXPECT_THROW_MSG(SceneDocument::from_file(path), SceneError,
                   path + ": cannot read the scene file (no such file or directory)");
}

TEST(SceneFile, Directory) {
  const std::string dir = make_temp_dir();
  EXPECT_THROW_MSG(SceneDocument::from_file(dir), SceneError,
                   dir + ": cannot read the scene file (it is a directory)");
  std::filesystem::remove_all(dir);
}

TEST(SceneFile, LinesAreThoseOfTheFile) {
  const std::string dir = make_temp_dir();
  const std::string path = dir + "/scene.toml";
  std::ofstream(path) << scene_with("poisson_ratio = 0.0", "poisson_ratio = 0.7");
  EXPECT_THROW_MSG(SceneDocument::from_file(path).build(registries()), SceneError,
                   path + ":4:17: material.poisson_ratio = 0.7 is outside (-1, 0.5]");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mdrsim::test
