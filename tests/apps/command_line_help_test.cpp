// What a new user meets: --version, `list` from the registries, help naming the parts, a
// scene on standard input, --set that replaces siblings and names a split inline table, paths
// relative to where they were typed, and the moduli warning.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/scene/registries.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = "scenes/fig2_fixed_load.toml";

/// Exit code 2, exactly `message` as the one line on stderr, nothing on stdout.
::testing::AssertionResult bad_input(const CommandResult& r, const std::string& message) {
  if (r.exit_code == 2 && r.err == message + "\n" && r.out.empty()) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "exit code " << r.exit_code << "\nstderr: [" << r.err << "]\nwant:   [" << message
         << "\n]\nstdout: [" << r.out << "]";
}

TEST(CommandLine, Version) {
  const auto r = run_mdrsim("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "mdrsim 0.1.0\n");
}

// A missing or unknown command: tests/apps/cli_test.cpp, MissingOrUnknownSubcommand.

TEST(CommandLine, ListNamesEveryRegisteredPartWithItsKeys) {
  const auto r = run_mdrsim("list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto registries = Registries::builtin();
  const auto check = [&](const auto& registry) {
    for (const std::string& name : registry.names()) {
      const auto* entry = registry.find(name);
      EXPECT_NE(r.out.find(fmt::format("  {}: {}", name, entry->summary)), std::string::npos)
          << name;
      for (const ParameterSpec& spec : entry->parameters) {
        EXPECT_NE(r.out.find(fmt::format("      {} = ", spec.key)), std::string::npos) << spec.key;
        EXPECT_NE(r.out.find(spec.help), std::string::npos) << spec.help;
      }
    }
  };
  check(registries.profiles);
  check(registries.criteria);
  check(registries.controllers);
  EXPECT_NE(r.out.find("      slope_angle_deg = number: angle theta between flank and surface "
                       "[degrees]; in (0, 90)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  fixed-load: holds the force on its axis (holds its axis's force [N])\n"),
            std::string::npos)
      << r.out;
}

TEST(CommandLine, RunHelpNamesTheParts) {
  const auto r = run_mdrsim("run --help");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto registries = Registries::builtin();
  for (const auto& names :
       {registries.profiles.names(), registries.criteria.names(), registries.controllers.names()}) {
    for (const std::string& name : names) EXPECT_NE(r.out.find(name), std::string::npos) << name;
  }
  EXPECT_NE(r.out.find("- reads standard input"), std::string::npos) << r.out;
}

TEST(CommandLine, SceneOnStandardInput) {
  const auto file = run_mdrsim(fmt::format("run {} --json - --log-level off", kScene));
  const auto piped = run_mdrsim("run - --json - --log-level off", kScene);
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  auto a = nlohmann::json::parse(file.out);
  auto b = nlohmann::json::parse(piped.out);
  a.erase("wall_time_s");
  b.erase("wall_time_s");
  EXPECT_EQ(a, b);
  // A result on standard input reruns its scene.
  const std::string dir = make_temp_dir();
  std::ofstream(dir + "/r.json") << file.out;
  const auto rerun = run_mdrsim("run - --json - --log-level off", dir + "/r.json");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  auto c = nlohmann::json::parse(rerun.out);
  c.erase("wall_time_s");
  EXPECT_EQ(c, a);
  std::ofstream(dir + "/bad.toml")
      << "[material]\nwork_of_adhesion = 0.05\npoisson_ratio = 0\nyoungs_modulus = -1\n";
  EXPECT_TRUE(bad_input(run_mdrsim("run -", dir + "/bad.toml"),
                        "<stdin>:4:18: material.youngs_modulus = -1 is outside (0, inf)"));
  fs::remove_all(dir);
}

TEST(CommandLine, SetReplacesExclusiveSiblings) {
  const auto r = run_mdrsim(
      fmt::format("run {} --set discretization.rtol=1e-4 --set loading.preload.force=1e-3 --json - "
                  "--log-level off",
                  kScene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // rtol replaces springs, its exclusive sibling; the scene's extrapolation stays.
  EXPECT_EQ(j["scene"]["discretization"],
            nlohmann::json::parse(R"({"extrapolation": "richardson", "rtol": 0.0001})"));
  EXPECT_EQ(j["scene"]["loading"]["preload"], nlohmann::json::parse(R"({"force": 0.001})"));
  EXPECT_EQ(j["preload"]["force"], 1e-3);
}

TEST(CommandLine, SetNamesAnInlineTableTheShellSplit) {
  // What the shell passes for --set loading.normal={ control = "fixed-grips" }, unquoted.
  EXPECT_TRUE(bad_input(
      run_mdrsim(
          fmt::format("run {} --set 'loading.normal={{' control = fixed-grips '}}'", kScene)),
      "--set: loading.normal: '{' is not a whole TOML inline table: unquoted, the shell splits a "
      "value at spaces, expands {a,b} and drops quotes; quote the whole KEY=VALUE, as in --set "
      "'loading.normal={ ... }'"));
  // And for --set material={effective_modulus=1e6,work_of_adhesion=0.05}: brace expansion.
  EXPECT_TRUE(bad_input(
      run_mdrsim(fmt::format("run {} --set material=effective_modulus=1e6 --set "
                             "material=work_of_adhesion=0.05",
                             kScene)),
      "--set: material: 'effective_modulus=1e6' is a piece of an inline table: unquoted, the "
      "shell splits a value at spaces, expands {a,b} and drops quotes; quote the whole "
      "KEY=VALUE, as in --set 'material={ ... }'"));
}

TEST(CommandLine, SetPathsAreRelativeToTheWorkingDirectory) {
  // The scene lives in a folder without the table; the table is at scenes/ of the working
  // directory (the source folder), where the user typed its path.
  const std::string dir = make_temp_dir();
  fs::copy_file(fs::path(MDRSIM_SOURCE_DIR) / kScene, dir + "/scene.toml");
  const auto r = run_mdrsim(fmt::format(
      "run {}/scene.toml --set 'profile={{ type = \"tabulated\", file = "
      "\"scenes/tabulated_cone.csv\" }}' --set loading.preload.contact_radius=1e-5 --json - "
      "--log-level off",
      dir));
  fs::remove_all(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["scene"]["profile"]["file"],
            std::string(MDRSIM_SOURCE_DIR) + "/scenes/tabulated_cone.csv");
}

TEST(CommandLine, ModuliOutsideTheIsotropicRangeWarn) {
  const auto r = run_mdrsim(fmt::format(
      "run {} --set 'material={{ effective_modulus = 1e6, effective_shear_modulus = 1e7, "
      "work_of_adhesion = 0.05 }}' --set discretization.springs=1000 --json - --log-level warn",
      kScene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string warning =
      "--set: material.effective_shear_modulus: G*/E* = 10 is outside [2/3, 4/3], the range of "
      "an isotropic half-space (G*/E* = 2(1-nu)/(2-nu), -1 < nu <= 0.5)";
  EXPECT_EQ(r.err, "[warning] " + warning + "\n");
  EXPECT_EQ(nlohmann::json::parse(r.out)["warnings"], nlohmann::json::array({warning}));
}

}  // namespace
}  // namespace mdrsim::test
