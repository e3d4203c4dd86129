// mdrsim fit over maps and many files: the same output on any number of threads, the grid
// cells in the CSV, an undetermined modulus, shards with --resume, and --plot.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

using mdrsim::test::make_temp_dir;
using mdrsim::test::run_mdrsim;

namespace {

const std::string kMap = "tests/data/afm/fmt-jpk-fd_map-data-reference-points.jpk-force-map";
const std::string kQi = "tests/data/afm/fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data";
const std::string kSpot3 = "tests/data/afm/fmt-jpk-fd_spot3-0192.jpk-force";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> fields(1);
    for (const char c : line) {
      if (c == ',') {
        fields.emplace_back();
      } else {
        fields.back() += c;
      }
    }
    rows.push_back(fields);
  }
  return rows;
}

TEST(FitMap, OneAndTwoThreadsGiveIdenticalJsonAndCsv) {
  // Bad curves among them: the map's index/109 retract has no modulus to find, its index/129
  // and the QI file's index/1 do not converge; each keeps its status and the rest are fitted.
  const std::string args = "fit " + kMap + " " + kQi + " " + kSpot3 +
                           " --tip parabolic:radius=1e-5 --model dmt --segment retract ";
  std::string outputs[2];
  for (int t = 0; t < 2; ++t) {
    const auto json = run_mdrsim(args + "--threads " + std::to_string(t + 1) + " --json -");
    const auto csv = run_mdrsim(args + "--threads " + std::to_string(t + 1) + " --csv -");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    outputs[t] = json.out + csv.out;
  }
  EXPECT_EQ(outputs[0], outputs[1]);
  const auto all = nlohmann::json::parse(outputs[0].substr(0, outputs[0].find("file,curve")));
  ASSERT_EQ(all.size(), 8U);
  EXPECT_EQ(all[0]["curve"], "index/109");
  EXPECT_EQ(all[0]["status"], "not-converged");
  EXPECT_EQ(all[4]["status"], "not-converged");
  EXPECT_EQ(all[2]["status"], "fitted");
  EXPECT_EQ(all[7]["status"], "fitted");
}

TEST(FitMap, CsvGivesThePositionAndTheGridCell) {
  const auto result =
      run_mdrsim("fit " + kMap + " " + kQi + " --tip parabolic:radius=1e-5 --csv -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto rows = csv_rows(result.out);
  ASSERT_EQ(rows.size(), 8U);
  EXPECT_EQ(
      std::vector<std::string>(rows[0].begin(), rows[0].begin() + 8),
      (std::vector<std::string>{"file", "curve", "x", "y", "index", "column", "row", "status"}));
  // The map is 25 x 25 cells of 20 um, back and forth: index 109 is row 4 (even, left to
  // right) column 9; index 129 row 5 (odd, right to left) column 24 - 4 = 20.
  EXPECT_EQ(std::vector<std::string>(rows[1].begin() + 4, rows[1].begin() + 7),
            (std::vector<std::string>{"109", "9", "4"}));
  EXPECT_EQ(std::vector<std::string>(rows[2].begin() + 4, rows[2].begin() + 7),
            (std::vector<std::string>{"129", "20", "5"}));
  EXPECT_EQ(std::stod(rows[1][2]), -0.0012197656250000001);
  // The QI grid (128 x 128 over 10 um): its first curves are its first cells.
  EXPECT_EQ(std::vector<std::string>(rows[7].begin() + 4, rows[7].begin() + 7),
            (std::vector<std::string>{"3", "3", "0"}));
}

TEST(FitMap, AModulusTheCurveDoesNotDetermineIsNotFitted) {
  // JKR on the map's index/109 retract: the fit ends with the contact point below every sample
  // (E = 2.6e13 +- 3e19 Pa): no sample is indented, E is not known.
  const auto result = run_mdrsim("fit " + kMap +
                                 " --tip parabolic:radius=1e-5 --model jkr --segment retract "
                                 "--json -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto all = nlohmann::json::parse(result.out);
  ASSERT_EQ(all.size(), 3U);
  EXPECT_EQ(all[0]["status"], "not-converged");
  EXPECT_EQ(all[0]["message"], "undetermined: no sample is indented past the contact point");
  EXPECT_EQ(all[2]["status"], "fitted");
}

TEST(FitMap, ACurveTheModelRefusesKeepsItsStatusAndTheMapGoesOn) {
  // DMT with a 5 um sphere on the map's index/109 retract: a trial indents the sphere past its
  // radius, which its profile refuses (an exception that used to end the whole command).
  const auto result = run_mdrsim(
      "fit " + kMap + " --tip sphere:radius=5e-6 --model dmt --segment retract --json -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto all = nlohmann::json::parse(result.out);
  ASSERT_EQ(all.size(), 3U);
  EXPECT_EQ(all[0]["status"], "not-converged");
  EXPECT_EQ(all[0]["message"], "the model failed: the preload depth is out of the profile's reach");
  EXPECT_EQ(all[0]["youngs_modulus"]["value"], 0.0);
  EXPECT_EQ(all[2]["status"], "fitted");
}

TEST(FitMap, ShardsWithResumeFinishTheCsvOfOneRun) {
  const std::string dir = make_temp_dir();
  const std::string files = kMap + " " + kQi + " " + kSpot3 + " --tip parabolic:radius=1e-5 ";
  const auto whole = run_mdrsim("fit " + files + "--csv " + dir + "/whole.csv");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const std::string expected = slurp(dir + "/whole.csv");

  // Shard 0 of 2 takes the files 0 and 2; the run without a shard fits only what is missing.
  const std::string csv = dir + "/resumed.csv";
  const auto first = run_mdrsim("fit " + files + "--shard 0/2 --resume --csv " + csv);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(csv_rows(slurp(csv)).size(), 1U + 3U + 1U);
  // A run killed in the middle of a row leaves it torn: cut the last row short.
  const std::string partial = slurp(csv);
  std::ofstream(csv, std::ios::binary) << partial.substr(0, partial.size() - 20);
  const auto second = run_mdrsim("fit " + files + "--resume --csv " + csv);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.err.find("fit: 5 curves of 3 files"), std::string::npos) << second.err;
  EXPECT_NE(second.err.find("(3 were in the CSV already)"), std::string::npos) << second.err;
  // The torn row is fitted again: the CSV is byte for byte the one of a run in one piece.
  EXPECT_EQ(slurp(csv), expected);
  const auto again = run_mdrsim("fit " + files + "--resume --csv " + csv);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(slurp(csv), expected);

  const auto other = run_mdrsim("fit " + files + "--model dmt --resume --csv " + csv);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_EQ(other.err,
            "--resume: '" + csv + "' holds fits of --model hertz; this run is --model dmt\n");
  const auto stdout_csv = run_mdrsim("fit " + files + "--resume --csv -");
  EXPECT_EQ(stdout_csv.exit_code, 2);
  EXPECT_EQ(stdout_csv.err, "--resume: needs --csv PATH (the CSV it finishes)\n");
  std::filesystem::remove_all(dir);
}

bool has_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0 ||
         std::system("python3 -c 'import matplotlib' > /dev/null 2>&1") == 0;
}

TEST(FitMap, PlotWritesAPngForOneCurveAndForAMap) {
  if (!has_matplotlib()) GTEST_SKIP() << "no python3 with matplotlib";
  const std::string dir = make_temp_dir();
  const auto one =
      run_mdrsim("fit " + kSpot3 + " --tip parabolic:radius=1e-5 --plot " + dir + "/one.png");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto map = run_mdrsim("fit " + kMap + " --tip parabolic:radius=1e-5 --model dmt --plot " +
                              dir + "/map.png --csv " + dir + "/map.csv");
  ASSERT_EQ(map.exit_code, 0) << map.err;
  for (const char* png : {"/one.png", "/map.png"}) {
    const std::string bytes = slurp(dir + png);
    ASSERT_GT(bytes.size(), 1000U) << png;
    EXPECT_EQ(bytes.substr(1, 3), "PNG") << png;
  }
  std::filesystem::remove_all(dir);
}

TEST(FitMap, PlotWithoutMatplotlibRefusesBeforeFitting) {
  setenv("MDRSIM_PYTHON", "/bin/false", 1);
  const auto result =
      run_mdrsim("fit " + kSpot3 + " --tip parabolic:radius=1e-5 --plot /nonexistent/x.png");
  unsetenv("MDRSIM_PYTHON");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            "--plot: needs python3 with matplotlib (tried /bin/false; install python3-matplotlib "
            "or set MDRSIM_PYTHON)\n");
  EXPECT_EQ(result.out, "");
}

}  // namespace
