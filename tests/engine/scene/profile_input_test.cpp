// Bad profile input exits 2 with one exact line: each way a profile's
// keys, a table or its CSV file can be wrong, and the preload that a profile cannot carry.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

// Line numbers in the messages refer to this frame: the profile's keys start on line 6.
constexpr const char* kHead =
    "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
    "[profile]\n";

std::string scene_with(const std::string& profile,
                       const std::string& preload = "contact_radius = 1e-4") {
  return std::string(kHead) + profile + "[loading]\npreload = { " + preload +
         " }\nnormal = { control = \"fixed-load\" }\n";
}

struct BadProfile {
  std::string name;
  std::string profile;
  std::string message;
  std::string preload = "contact_radius = 1e-4";
};

const std::string kTable = "type = \"tabulated\"\n";

void PrintTo(const BadProfile& c, std::ostream* os) { *os << c.name; }

std::vector<BadProfile> cases() {
  return {
      {"ExponentZero", "type = \"power_law\"\ncoefficient = 0.8\nexponent = 0\n",
       "test.toml:8:12: profile.exponent = 0 is outside (0, inf)"},
      {"ExponentNegative", "type = \"power_law\"\ncoefficient = 0.8\nexponent = -1.5\n",
       "test.toml:8:12: profile.exponent = -1.5 is outside (0, inf)"},
      {"CoefficientZero", "type = \"power_law\"\ncoefficient = 0\nexponent = 2\n",
       "test.toml:7:15: profile.coefficient = 0 is outside (0, inf)"},
      {"ConeFlat", "type = \"cone\"\nslope_angle_deg = 0\n",
       "test.toml:7:19: profile.slope_angle_deg = 0 is outside (0, 90)"},
      {"ConeUpright", "type = \"cone\"\nslope_angle_deg = 90\n",
       "test.toml:7:19: profile.slope_angle_deg = 90 is outside (0, 90)"},
      {"ConeBeyondUpright", "type = \"cone\"\nslope_angle_deg = 120\n",
       "test.toml:7:19: profile.slope_angle_deg = 120 is outside (0, 90)"},
      {"SphereRadiusNegative", "type = \"sphere\"\nradius = -1e-3\n",
       "test.toml:7:10: profile.radius = -0.001 is outside (0, inf)"},
      {"PunchKeyOnCone", "type = \"cone\"\nslope_angle_deg = 10\nradius = 1\n",
       "test.toml:8:10: profile.radius: applies to type = \"flat_punch\" or \"parabolic\" or "
       "\"sphere\" or \"wavy\" only"},
      {"TableRadiiNotIncreasing", kTable + "r = [0, 1e-4, 1e-4, 3e-4]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:7:5: profile.r: r[2] = 0.0001 is not above the previous r = 0.0001; r must "
       "increase"},
      {"TableRadiiDecreasing", kTable + "r = [0, 2e-4, 1e-4, 3e-4]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:7:5: profile.r: r[2] = 0.0001 is not above the previous r = 0.0002; r must "
       "increase"},
      {"TableGapNegative", kTable + "r = [0, 1e-4, 2e-4, 3e-4]\nf = [0, 1e-6, -2e-6, 3e-6]\n",
       "test.toml:8:15: profile.f[2] = -2e-06 is outside [0, inf)"},
      {"TableRadiusNegative", kTable + "r = [0, -1e-4, 2e-4, 3e-4]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:7:9: profile.r[1] = -0.0001 is outside [0, inf)"},
      {"TableTooFewPoints", kTable + "r = [0, 1e-4, 2e-4]\nf = [0, 1e-6, 2e-6]\n",
       "test.toml:7:5: profile.r: has 3 points, expected at least 4"},
      {"TableEmpty", kTable + "r = []\nf = []\n",
       "test.toml:7:5: profile.r: has 0 points, expected at least 4"},
      {"TableNotFromTheTip", kTable + "r = [1e-5, 1e-4, 2e-4, 3e-4]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:7:5: profile.r: r[0] = 1e-05 is not 0: the table starts at the tip"},
      {"TableGapAtTheTip", kTable + "r = [0, 1e-4, 2e-4, 3e-4]\nf = [1e-7, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:8:5: profile.f: f[0] = 1e-07 is not 0: the gap is 0 at the tip"},
      {"TableLengthsDiffer", kTable + "r = [0, 1e-4, 2e-4, 3e-4]\nf = [0, 1e-6, 2e-6]\n",
       "test.toml:8:5: profile.f: has 3 values for 4 radii r, expected one per r"},
      {"TableWithoutGaps", kTable + "r = [0, 1e-4, 2e-4, 3e-4]\n",
       "test.toml:5:1: profile.f: missing, expected r = [...] and f = [...] (radii and gaps "
       "[m]), or file = \"table.csv\""},
      {"TableWithoutAnything", kTable,
       "test.toml:5:1: profile.r: missing, expected r = [...] and f = [...] (radii and gaps "
       "[m]), or file = \"table.csv\""},
      {"TableAndFile", kTable + "file = \"x.csv\"\nr = [0, 1e-4, 2e-4, 3e-4]\n",
       "test.toml:7:8: profile.file: give file or the arrays r and f, not both"},
      {"TableGapNotANumber", kTable + "r = [0, 1e-4, 2e-4, 3e-4]\nf = [0, 1e-6, 2e-6, \"3e-6\"]\n",
       "test.toml:8:21: profile.f[3]: expected a number, got string \"3e-6\""},
      {"TableRadiiNotAnArray", kTable + "r = \"0, 1e-4\"\nf = [0, 1e-6]\n",
       "test.toml:7:5: profile.r: expected an array of numbers, got string \"0, 1e-4\""},
      // Preloads a profile cannot carry.
      {"SphereGluedAtItsEdge", "type = \"sphere\"\nradius = 1e-4\n",
       "test.toml:9:30: loading.preload.contact_radius = 0.0001 is at the profile's edge, where "
       "its image diverges"},
      {"TableGluedBeyondItsEnd", kTable + "r = [0, 2e-5, 4e-5, 6e-5]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:10:30: loading.preload.contact_radius = 0.0001 is beyond the profile's edge at "
       "6e-05"},
      {"TablePressedBeyondItsEnd",
       kTable + "r = [0, 2e-5, 4e-5, 6e-5]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:10:21: loading.preload.depth = 0.001 is beyond the profile's reach: its image "
       "is g = 4.71239e-06 m at its edge r = 6e-05 m",
       "depth = 1e-3"},
      {"TableLoadedBeyondItsEnd", kTable + "r = [0, 2e-5, 4e-5, 6e-5]\nf = [0, 1e-6, 2e-6, 3e-6]\n",
       "test.toml:10:21: loading.preload.force = 10 is beyond the profile's reach: "
       "0.000282743 N press it in up to its edge r = 6e-05 m",
       "force = 10.0"},
      {"PunchGluedOffItsEdge", "type = \"flat_punch\"\nradius = 2e-4\n",
       "test.toml:9:30: loading.preload.contact_radius = 0.0001 differs from the profile's fixed "
       "contact radius 0.0002"},
  };
}

}  // namespace

class BadProfileTest : public ::testing::TestWithParam<BadProfile> {};

TEST_P(BadProfileTest, FailsWithTheExactMessage) {
  const BadProfile& c = GetParam();
  EXPECT_THROW_MSG(build_scene_text(scene_with(c.profile, c.preload)), SceneError, c.message);
}

INSTANTIATE_TEST_SUITE_P(Profiles, BadProfileTest, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

/// A scene in a temporary folder with a CSV table beside it.
class CsvTable : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_temp_dir(); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  std::string scene(const std::string& csv_name) {
    return write("scene.toml", scene_with(kTable + "file = \"" + csv_name + "\"\n"));
  }
  std::string dir_;
};

// A table from a file: its problems name the file's line, at the scene's `file` key.
TEST_F(CsvTable, ProblemsNameTheLineOfTheFile) {
  const std::string where = "scene.toml:7:8: profile.file: ";
  const std::string csv = std::filesystem::path(dir_ + "/t.csv").lexically_normal().string();
  const auto build = [&] {
    return thrown_message<SceneError>([&] {
      SceneDocument::from_text(scene_with(kTable + "file = \"t.csv\"\n"), "scene.toml", dir_)
          .build(Registries::builtin());
    });
  };
  const auto message = [&](const std::string& text) {
    write("t.csv", text);
    return build();
  };
  EXPECT_EQ(message("0,0\n1e-4,-1e-6\n2e-4,1e-6\n3e-4,3e-6\n"),
            where + "line 2 of '" + csv + "': f = -1e-06 is outside [0, inf)");
  EXPECT_EQ(message("# comment\n0,0\n2e-4,1e-6\n1e-4,2e-6\n3e-4,3e-6\n"),
            where + "line 4 of '" + csv +
                "': r = 0.0001 is not above the previous r = 0.0002; r must increase");
  EXPECT_EQ(message("0,0\n1e-4,1e-6\n2e-4,2e-6\n"),
            where + "'" + csv + "' has 3 points, expected at least 4");
  EXPECT_EQ(message("0,0\n1e-4 2e-6\n"),
            where + "line 2 of '" + csv + "': expected two numbers r,f, got \"1e-4 2e-6\"");
  EXPECT_EQ(message("0,0,0\n"),
            where + "line 1 of '" + csv + "': expected two numbers r,f, got \"0,0,0\"");
  std::filesystem::remove(dir_ + "/t.csv");
  EXPECT_EQ(build(), where + "cannot read '" + csv + "': No such file or directory");
}

// Through the binary: exit code 2, the one line on standard error, nothing on standard out.
TEST_F(CsvTable, TheCommandExitsTwoWithTheLine) {
  write("t.csv", "r,f\n0,0\n1e-4,2e-6\n2e-4,-1e-6\n3e-4,3e-6\n");
  const std::string path = scene("t.csv");
  const CommandResult r = run_mdrsim("run '" + path + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, path + ":7:8: profile.file: line 4 of '" +
                       std::filesystem::path(dir_ + "/t.csv").lexically_normal().string() +
                       "': f = -1e-06 is outside [0, inf)\n");
  const std::string cone =
      write("cone.toml", scene_with("type = \"cone\"\nslope_angle_deg = 90\n"));
  const CommandResult c = run_mdrsim("run '" + cone + "'");
  EXPECT_EQ(c.exit_code, 2);
  EXPECT_EQ(c.err, cone + ":7:19: profile.slope_angle_deg = 90 is outside (0, 90)\n");
  const CommandResult e =
      run_mdrsim("run scenes/power_law_fixed_load.toml --set profile.exponent=0");
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_EQ(e.err, "--set: profile.exponent = 0 is outside (0, inf)\n");
}

}  // namespace mdrsim::test
