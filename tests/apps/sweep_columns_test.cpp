// What a sweep row says about its run: the springs it used (rtol picks them), its
// preload state, its warning count and its work, each equal to what `mdrsim run --json` says of the
// same scene; and its log lines name the row they belong to.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

/// The CSV rows of a sweep on standard output, each as {column: text}.
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& csv) {
  const auto lines = lines_of(csv);
  EXPECT_GE(lines.size(), 2u) << csv;
  if (lines.size() < 2) return {};
  const auto columns = fields_of(lines[1]);
  std::vector<std::map<std::string, std::string>> rows;
  for (std::size_t i = 2; i < lines.size(); ++i) {
    const auto fields = fields_of(lines[i]);
    EXPECT_EQ(fields.size(), columns.size()) << lines[i];
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < columns.size() && k < fields.size(); ++k) {
      row[columns[k]] = fields[k];
    }
    rows.push_back(row);
  }
  return rows;
}

/// The JSON of `mdrsim run SCENE --set SET --json -`.
nlohmann::json run_json(const std::string& scene, const std::string& set) {
  const auto r = run_mdrsim(fmt::format("run {} --set {} --json - --log-level off", scene, set));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

/// A number's text in the CSV read back, to compare with the JSON's double exactly.
double number(const std::string& text) { return std::stod(text); }

TEST(SweepColumns, SpringsUsedAreTheRunsAndVaryWithRtol) {
  // The glue-on-touch cycle needs 2048 springs for 1e-2 and 4096 for 1e-3 (its peak is not
  // located between springs, so the rows go on doubling).
  const std::string scene = "scenes/programs/jkr_cycle_glue_on_touch.toml";
  const auto r = run_mdrsim(
      fmt::format("sweep {} --vary discretization.rtol=1e-2,1e-3 --log-level off", scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    const auto json = run_json(scene, "discretization.rtol=" + row.at("discretization.rtol"));
    EXPECT_EQ(row.at("springs"), std::to_string(json.at("springs").get<long long>()));
    EXPECT_EQ(json.at("resolution").at("rows").back(), json.at("springs"));
    EXPECT_EQ(row.at("warnings"),
              std::to_string(json.value("warnings", nlohmann::json::array()).size()));
    // A program has no preload state: its columns are empty, not zero.
    EXPECT_EQ(row.at("glued_radius"), "");
    EXPECT_EQ(row.at("preload_depth"), "");
    EXPECT_EQ(row.at("preload_force"), "");
  }
  EXPECT_NE(rows[0].at("springs"), rows[1].at("springs"));
}

TEST(SweepColumns, PreloadStateIsTheRunsForEachPreloadForce) {
  // Preloads by force: the glued radius and depth follow from it (JKR), as run reports them.
  const std::string scene = "scenes/fig2_fixed_load.toml";
  const auto r = run_mdrsim(fmt::format(
      "sweep {} --vary loading.preload.force=1e-3,2e-2 --set discretization.springs=500 "
      "--log-level off",
      scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    const auto json = run_json(scene, "loading.preload.force=" + row.at("loading.preload.force") +
                                          " --set discretization.springs=500");
    const auto& preload = json.at("preload");
    EXPECT_EQ(number(row.at("glued_radius")), preload.at("glued_radius").get<double>());
    EXPECT_EQ(number(row.at("preload_depth")), preload.at("depth").get<double>());
    EXPECT_EQ(number(row.at("preload_force")), preload.at("force").get<double>());
    EXPECT_EQ(row.at("springs"), std::to_string(json.at("springs").get<std::int64_t>()));
  }
  // A larger preload glues a larger contact.
  EXPECT_LT(number(rows[0].at("glued_radius")), number(rows[1].at("glued_radius")));
}

TEST(SweepColumns, FrictionColumnsAreTheRunsAndZeroWithoutFriction) {
  // The pull-off after shear, sheared past the glue's break (u = 2e-5 m > u_c) and below it,
  // with mu = 1 and mu = 0 (no friction: nothing slides, no frictional work).
  const std::string scene = "scenes/programs/pull_off_after_shear.toml";
  const auto r = run_mdrsim(fmt::format(
      "sweep {} --vary loading.stage.2.tangential.to=5e-6,2e-5 --vary friction.coefficient=0,1 "
      "--log-level off",
      scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    const std::string sets =
        "loading.stage.2.tangential.to=" + row.at("loading.stage.2.tangential.to") +
        " --set friction.coefficient=" + row.at("friction.coefficient");
    const auto json = run_json(scene, sets);
    EXPECT_EQ(row.at("status"), json.at("status").get<std::string>()) << sets;
    EXPECT_EQ(row.at("sliding"), json.value("sliding", false) ? "true" : "false") << sets;
    const double friction =
        json.at("work").value("dissipated_by_friction", 0.0);  // absent without friction
    EXPECT_EQ(number(row.at("dissipated_by_friction")), friction) << sets;
    if (json.contains("critical")) {
      EXPECT_EQ(row.at("springs_sliding"),
                std::to_string(json.at("critical").value("springs_sliding", 0)))
          << sets;
    } else {
      EXPECT_EQ(row.at("springs_sliding"), "") << sets;
    }
  }
  // Past the break under mu = 1 the pressed springs slide and dissipate; with mu = 0 nothing.
  EXPECT_GT(number(rows[3].at("dissipated_by_friction")), 0.0);
  EXPECT_EQ(number(rows[2].at("dissipated_by_friction")), 0.0);
  // Without [friction] in any row the columns are not there.
  const auto plain = run_mdrsim(
      "sweep scenes/fig2_fixed_grips.toml --vary discretization.springs=100,200 --log-level off");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("sliding"), std::string::npos);
}

TEST(SweepColumns, WorkColumnsAreTheRunsJsonWork) {
  // A fretting cycle at two friction coefficients on 400 springs: each row's total work per
  // axis and its frictional part are the JSON's of the same run, to the bit (both print the
  // shortest text that reads back as the same double).
  const std::string scene = "scenes/programs/fretting_parabola.toml";
  const auto r = run_mdrsim(
      fmt::format("sweep {} --vary friction.coefficient=0.3,0.5 --set discretization.springs=400 "
                  "--log-level off",
                  scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto header = fields_of(lines_of(r.out).at(1));
  ASSERT_GE(header.size(), 2u);
  EXPECT_EQ(header[header.size() - 2], "work_normal");
  EXPECT_EQ(header.back(), "work_tangential");
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    const std::string sets = "friction.coefficient=" + row.at("friction.coefficient") +
                             " --set discretization.springs=400";
    const auto work = run_json(scene, sets).at("work");
    EXPECT_EQ(number(row.at("work_normal")), work.at("normal").get<double>()) << sets;
    EXPECT_EQ(number(row.at("work_tangential")), work.at("tangential").get<double>()) << sets;
    EXPECT_EQ(number(row.at("dissipated_by_friction")),
              work.at("dissipated_by_friction").get<double>())
        << sets;
    EXPECT_GT(number(row.at("dissipated_by_friction")), 0.0) << sets;
  }
  // The shorthand without friction has no program and no work: no work columns.
  const auto plain = run_mdrsim(
      "sweep scenes/fig2_fixed_grips.toml --vary discretization.springs=100,200 --log-level off");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("work_normal"), std::string::npos);
}

TEST(SweepColumns, TimesDissipationsAreTheRunsJsonWork) {
  // A rate sweep of the rate law (continuum route) and a relaxing bulk's press and withdrawal
  // at two relaxation times: each row's dissipation is the JSON's `work` of the same run, to
  // the bit, in the last column; the work columns before it.
  struct Sweep {
    std::string scene, vary, set, column;
  };
  for (const Sweep& s :
       {Sweep{"scenes/viscoelastic/rate_law_parabola.toml", "loading.stage.2.speed=1e-9:1e-6:4:log",
              "", "dissipated_at_front"},
        Sweep{"scenes/viscoelastic/lee_radok_parabola.toml", "material.relaxation.1.time=0.1,1.0",
              "discretization.springs=100", "dissipated_by_bulk"}}) {
    const std::string sets = s.set.empty() ? "" : " --set " + s.set;
    const auto r =
        run_mdrsim(fmt::format("sweep {} --vary {}{} --log-level off", s.scene, s.vary, sets));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto header = fields_of(lines_of(r.out).at(1));
    ASSERT_GE(header.size(), 3u);
    EXPECT_EQ(header[header.size() - 3], "work_normal");
    EXPECT_EQ(header.back(), s.column);
    const std::string other =
        s.column == "dissipated_by_bulk" ? "dissipated_at_front" : "dissipated_by_bulk";
    EXPECT_EQ(r.out.find(other), std::string::npos) << s.scene;
    const std::string key = s.vary.substr(0, s.vary.find('='));
    const auto rows = csv_rows(r.out);
    ASSERT_FALSE(rows.empty());
    double last = 0.0;
    for (const auto& row : rows) {
      const std::string set = key + "=" + row.at(key) + sets;
      const auto work = run_json(s.scene, set).at("work");
      EXPECT_EQ(number(row.at(s.column)), work.at(s.column).get<double>()) << set;
      EXPECT_EQ(number(row.at("work_normal")), work.at("normal").get<double>()) << set;
      EXPECT_GT(number(row.at(s.column)), 0.0) << set;
      EXPECT_NE(number(row.at(s.column)), last) << set;
      last = number(row.at(s.column));
    }
  }
}

TEST(SweepLogs, WarningsNameTheirRowAndAreCounted) {
  // 20 springs do not resolve the critical point: every row warns once, at debug in a sweep.
  const auto r = run_mdrsim(
      "sweep scenes/fig3a_fixed_grips.toml --vary loading.tangential.displacement=0,4e-6 "
      "--vary detachment.criterion=mode-mixed,stress --set 'discretization={springs=20}' "
      "--threads 2 --log-level debug");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string> labels{
      "row 0 of 4 (loading.tangential.displacement=0, detachment.criterion=mode-mixed): ",
      "row 1 of 4 (loading.tangential.displacement=0, detachment.criterion=stress): ",
      "row 2 of 4 (loading.tangential.displacement=4e-06, detachment.criterion=mode-mixed): ",
      "row 3 of 4 (loading.tangential.displacement=4e-06, detachment.criterion=stress): "};
  const auto err = lines_of(r.err);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::size_t labelled = 0;
    for (const std::string& line : err) {
      if (line.rfind("[debug] " + labels[i], 0) == 0) ++labelled;
    }
    EXPECT_EQ(std::to_string(labelled), rows[i].at("warnings")) << labels[i] << "\n" << r.err;
    EXPECT_EQ(rows[i].at("warnings"), "1") << r.err;
  }
  for (const std::string& line : err) {
    EXPECT_TRUE(line.rfind("[debug] row ", 0) == 0 || line.rfind("[info] sweep: ", 0) == 0 ||
                line.rfind("[warning] sweep: 4 runs warned: 4 x 'the critical point has only "
                           "...'",
                           0) == 0)
        << line;
  }
}

TEST(SweepLogs, AtTheDefaultLevelOneLineCountsTheRunsWarnings) {
  // 20 rows that each warn: no line of a run at the default level (info), one line counting
  // their warnings by kind, and the CSV keeps each row's count.
  const auto r = run_mdrsim(
      "sweep scenes/fig3a_fixed_grips.toml --vary loading.tangential.displacement=0:4e-6:20 "
      "--set 'discretization={springs=20}' --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 20u);
  for (const auto& row : rows) EXPECT_EQ(row.at("warnings"), "1");
  const auto err = lines_of(r.err);
  ASSERT_EQ(err.size(), 2u) << r.err;
  EXPECT_EQ(err[0], "[warning] sweep: 20 runs warned: 20 x 'the critical point has only ...'");
  EXPECT_EQ(err[1].rfind("[info] sweep: 20 rows on 2 threads in ", 0), 0u) << err[1];
}

TEST(SweepLogs, ShardRowsKeepTheirIndexInTheWholeGrid) {
  const auto r = run_mdrsim(
      "sweep scenes/fig3a_fixed_grips.toml --vary loading.tangential.displacement=0,2e-6,4e-6 "
      "--set 'discretization={springs=20}' --shard 1/2 --log-level debug");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("[debug] row 1 of 3 (loading.tangential.displacement=2e-06): "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("row 0 of 3"), std::string::npos) << r.err;
}

TEST(SweepLogs, ARunAloneIsNotLabelled) {
  const auto r = run_mdrsim(
      "run scenes/fig3a_fixed_grips.toml --set 'discretization={springs=20}' --log-level warn");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("[warning] the critical point has only", 0), 0u) << r.err;
}

}  // namespace
}  // namespace mdrsim::test
