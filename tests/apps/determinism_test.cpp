// Determinism: the same scene gives byte-identical output on every run and with any thread count.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The JSON text with the value of wall_time_s replaced by a marker; fails the test if the field
/// is missing, so that the comparison below is never vacuous.
std::string without_wall_time(const std::string& json) {
  static const std::regex wall_time(R"("wall_time_s": [-+.eE0-9]+)");
  EXPECT_TRUE(std::regex_search(json, wall_time)) << json;
  return std::regex_replace(json, wall_time, R"("wall_time_s": <removed>)");
}

std::vector<std::string> example_scenes() {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(fs::path(MDRSIM_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".toml")
      out.push_back("scenes/" + entry.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Nothing in a run depends on time, addresses or thread scheduling: the same scene and flags
// must give the same bytes. The only exception docs allows is wall_time_s. Checked on every
// example scene and on variants that take other code paths (stepping with halvings, a root
// search for the let-go, a compliant machine, a held tangential force).
TEST(Determinism, SameSceneTwiceGivesByteIdenticalJson) {
  std::vector<std::string> runs;
  for (const auto& scene : example_scenes()) {
    runs.push_back(scene);
    runs.push_back(scene + " --set solver.method=stepping --set 'discretization={springs=500}'");
    runs.push_back(scene +
                   " --set detachment.criterion=mode-dependent --set detachment.lambda=0.3");
  }
  runs.push_back(
      "scenes/fig2_fixed_load.toml --set 'loading.normal={ control = \"compliant\", stiffness = "
      "50.0 }' --set 'loading.tangential={ control = \"fixed-load\", force = 1e-3 }'");
  ASSERT_GE(runs.size(), 4u);
  for (const auto& args : runs) {
    const auto first = run_mdrsim("run " + args + " --json - --log-level off");
    const auto second = run_mdrsim("run " + args + " --json - --log-level off");
    ASSERT_EQ(first.exit_code, 0) << args << ": " << first.err;
    ASSERT_EQ(second.exit_code, 0) << args << ": " << second.err;
    EXPECT_EQ(without_wall_time(first.out), without_wall_time(second.out)) << args;
  }
}

// The trajectory CSV has no time column: the whole file must repeat byte for byte.
TEST(Determinism, SameSceneTwiceGivesByteIdenticalTrajectory) {
  const std::string dir = make_temp_dir();
  for (const char* method : {"event", "stepping"}) {
    std::vector<std::string> files;
    for (int i = 0; i < 2; ++i) {
      const std::string csv = fmt::format("{}/{}{}.csv", dir, method, i);
      const auto r =
          run_mdrsim(fmt::format("run scenes/fig2_fixed_grips.toml --set solver.method={} --set "
                                 "'discretization={{springs=300}}' "
                                 "--trajectory {} --log-level off",
                                 method, csv));
      ASSERT_EQ(r.exit_code, 0) << r.err;
      files.push_back(slurp(csv));
    }
    EXPECT_GT(files[0].size(), 1000u) << method;
    EXPECT_EQ(files[0], files[1]) << method;
  }
  fs::remove_all(dir);
}

// A sweep's runs are independent and written in input order: one thread and several threads
// must give the same CSV, byte for byte (the CSV has no time column). 12 values, so that two
// and five threads interleave differently.
TEST(Determinism, SweepWithOneThreadEqualsSweepWithSeveral) {
  const std::string dir = make_temp_dir();
  const std::string sweep =
      "sweep scenes/fig3a_fixed_grips.toml --vary loading.tangential.displacement=0:9e-6:12 "
      "--set discretization.springs=2000 --log-level off";
  std::vector<std::string> csvs;
  for (const int threads : {1, 2, 5}) {
    const std::string csv = fmt::format("{}/threads{}.csv", dir, threads);
    const auto r = run_mdrsim(fmt::format("{} --threads {} --csv {}", sweep, threads, csv));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    csvs.push_back(slurp(csv));
  }
  // The identity line, the header and 12 rows.
  EXPECT_EQ(std::count(csvs[0].begin(), csvs[0].end(), '\n'), 14);
  EXPECT_EQ(csvs[0], csvs[1]);
  EXPECT_EQ(csvs[0], csvs[2]);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mdrsim::test
