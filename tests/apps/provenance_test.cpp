// The JSON result says what produced it: the resolved scene, the version, the
// material, the preload, the scales and the rows; and its scene, run again, gives the same
// numbers, for a shorthand scene and a program, from a result file or its scene alone.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/events/program_version.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// A result without its wall time, the one field that differs between two runs.
nlohmann::json timeless(nlohmann::json j) {
  j.erase("wall_time_s");
  return j;
}

class Provenance : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_temp_dir(); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  /// `mdrsim run ARGS --json PATH`: its result.
  nlohmann::json run(const std::string& args, const std::string& name) {
    const auto r = run_mdrsim(fmt::format("run {} --json {} --log-level off", args, path(name)));
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    return read_json(path(name));
  }
  std::string dir_;
};

TEST_F(Provenance, TheJsonCarriesWhatProducedIt) {
  const nlohmann::json j =
      run("scenes/cone_fixed_load.toml --set discretization.springs=20000 --set "
          "material.work_of_adhesion=0.04",
          "r.json");
  EXPECT_EQ(j["mdrsim_version"], program_version());
  EXPECT_EQ(j["mdrsim_version"], "0.1.0");
  const nlohmann::json scene = nlohmann::json::parse(R"({
    "title": "Cone of 10 degrees, pulled off under fixed-load",
    "material": {"youngs_modulus": 1000000.0, "poisson_ratio": 0.0, "work_of_adhesion": 0.04,
                 "approach_work_of_adhesion": 0.0},
    "profile": {"type": "cone", "slope_angle_deg": 10.0},
    "loading": {"preload": {"contact_radius": 2e-05}, "normal": {"control": "fixed-load"}},
    "detachment": {"criterion": "mode-mixed"},
    "discretization": {"springs": 20000},
    "solver": {"method": "event", "max_events": 1000000000000000,
               "max_events_per_spring": 64}})");
  EXPECT_EQ(j["scene"], scene) << j["scene"].dump(2);
  EXPECT_EQ(j["material"]["effective_modulus"], 1e6);
  EXPECT_EQ(j["material"]["effective_shear_modulus"], 1e6);
  EXPECT_EQ(j["material"]["work_of_adhesion"], 0.04);
  EXPECT_EQ(j["preload"]["glued_radius"], 2e-5);
  // g(a) = (pi/2) tan(10 deg) a at a = 20 um; F = E* (pi/2) tan(theta) a^2 (Sneddon).
  EXPECT_NEAR(j["preload"]["depth"].get<double>(), 5.539475472233828e-06, 1e-20);
  EXPECT_NEAR(j["preload"]["force"].get<double>(), 1.1078950944467656e-4, 1e-18);
  EXPECT_EQ(j["scales"]["basis"].get<std::string>().rfind("cone: ", 0), 0u);
  EXPECT_EQ(j["resolution"], nlohmann::json::parse(R"({"route": "row", "rows": [20000]})"));
}

TEST_F(Provenance, RtolNamesItsRoute) {
  const nlohmann::json j =
      run("scenes/fig2_fixed_load.toml --set discretization.rtol=1e-6", "r.json");
  // rtol replaces springs; the scene's extrapolation stays and picks the Richardson route.
  EXPECT_EQ(j["scene"]["discretization"],
            nlohmann::json::parse(R"({"extrapolation": "richardson", "rtol": 1e-06})"));
  EXPECT_EQ(j["accuracy"]["route"], "richardson");
  EXPECT_EQ(j["resolution"]["route"], j["accuracy"]["route"]);
  EXPECT_EQ(j["resolution"]["rows"], j["accuracy"]["rows"]);
}

TEST_F(Provenance, TabulatedFilesAreAbsolute) {
  const nlohmann::json j = run("scenes/tabulated_cone_fixed_load.toml", "r.json");
  const fs::path file = j["scene"]["profile"]["file"].get<std::string>();
  EXPECT_TRUE(file.is_absolute()) << file;
  EXPECT_TRUE(fs::equivalent(file, fs::path(MDRSIM_SOURCE_DIR) / "scenes/tabulated_cone.csv"));
}

TEST_F(Provenance, ATabulatedResultRerunsAfterItsCsvIsGone) {
  // The result's scene embeds the table: moving or deleting the CSV does not stop a rerun.
  fs::copy_file(fs::path(MDRSIM_SOURCE_DIR) / "scenes/tabulated_cone.csv", path("t.csv"));
  std::ifstream in(fs::path(MDRSIM_SOURCE_DIR) / "scenes/tabulated_cone_fixed_load.toml");
  std::string text(std::istreambuf_iterator<char>(in), {});
  const std::string file = "file = \"tabulated_cone.csv\"";
  text.replace(text.find(file), file.size(), "file = \"t.csv\"");
  std::ofstream(path("scene.toml")) << text;
  const nlohmann::json first = run(path("scene.toml"), "r.json");
  EXPECT_EQ(first["scene"]["profile"]["table"]["r"].size(), 51u);  // the CSV's 51 points
  fs::remove(path("t.csv"));
  const auto r = run_mdrsim(
      fmt::format("run {} --json {} --log-level warn", path("r.json"), path("again.json")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, fmt::format("[warning] {}: profile.file '{}' is gone; running the table "
                               "embedded in the result\n",
                               path("r.json"), path("t.csv")));
  const nlohmann::json again = read_json(path("again.json"));
  EXPECT_EQ(again["critical"], first["critical"]);
  EXPECT_EQ(again["peak_adhesion"], first["peak_adhesion"]);
}

// The scene of r.json run again gives identical numbers, from the result file
// itself and from its scene alone, for shorthand scenes (one under --set, one with a table
// file) and loading programs.
TEST_F(Provenance, ItsSceneRunAgainGivesIdenticalNumbers) {
  const std::vector<std::string> scenes = {
      "scenes/fig3a_fixed_grips.toml --set loading.tangential.displacement=4.5e-6",
      "scenes/tangential_force_fixed_load.toml --set discretization.rtol=1e-5",
      "scenes/tabulated_cone_fixed_load.toml",
      "scenes/power_law_fixed_grips.toml --set solver.method=stepping --set "
      "discretization.springs=500",
      "scenes/programs/jkr_cycle_reversible.toml",
      "scenes/programs/shear_ramp_fixed_load.toml --set discretization.rtol=1e-4",
      "scenes/programs/reload_rebinding_true.toml",
  };
  for (const std::string& args : scenes) {
    const nlohmann::json first = run(args, "r.json");
    const nlohmann::json again = run(path("r.json"), "again.json");
    EXPECT_EQ(timeless(again), timeless(first)) << args;
    std::ofstream(path("scene.json")) << first["scene"].dump(2);
    const nlohmann::json alone = run(path("scene.json"), "alone.json");
    EXPECT_EQ(timeless(alone), timeless(first)) << args;
  }
}

TEST_F(Provenance, AProgramsJsonHasNoPreload) {
  const nlohmann::json j = run("scenes/programs/jkr_cycle_reversible.toml", "r.json");
  EXPECT_FALSE(j.contains("preload"));
  EXPECT_EQ(j["scene"]["loading"]["rebinding"], false);
  EXPECT_EQ(j["scene"]["loading"]["stage"].size(), 2u);
}

}  // namespace
}  // namespace mdrsim::test
