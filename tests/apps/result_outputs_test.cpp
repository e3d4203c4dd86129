// What run and sweep print for each status: no critical point that was never an equilibrium.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

using mdrsim::test::run_mdrsim;

namespace {

// JKR: R = 1 cm, E* = 1 MPa, dgamma = 0.05, glued at 2 a0. The glue holds a tangential
// displacement below sqrt(2 pi a_g dgamma / G*) = 1.28e-5 m at a_g.
constexpr const char* kScene = R"(
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.209397078678047e-4 }
tangential = { control = "fixed-grips", displacement = 0.0 }
normal = { control = "fixed-grips" }
[discretization]
springs = 2000
)";

class ResultOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = mdrsim::test::make_temp_dir();
    scene_ = dir_ + "/scene.toml";
    std::ofstream(scene_) << kScene;
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  nlohmann::json run_json(const std::string& sets) {
    const auto r = run_mdrsim(fmt::format("run {} {} --json - --log-level off", scene_, sets));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
  std::string dir_;
  std::string scene_;
};

/// The rows of a CSV, past a sweep's identity line (# mdrsim sweep: ...).
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind('#', 0) == 0) continue;
    std::vector<std::string> fields;
    std::string field;
    std::istringstream cells(line);
    while (std::getline(cells, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

}  // namespace

// A fixed-grips JKR pull-off: the jump at -5/9 F0, the peak adhesive force -F0 at a0
// (1.5/N with 2000 springs: within 2e-3).
TEST_F(ResultOutputs, InstabilityHasItsCriticalPointAndThePeak) {
  const nlohmann::json j = run_json("");
  EXPECT_EQ(j["status"], "instability");
  EXPECT_NEAR(j["dimensionless"]["normal_force"].get<double>(), -5.0 / 9.0, 2e-3);
  EXPECT_NEAR(j["peak_adhesion"]["dimensionless"]["normal_force"].get<double>(), -1.0, 2e-3);
  EXPECT_NEAR(j["peak_adhesion"]["dimensionless"]["contact_radius"].get<double>(), 1.0, 2e-3);
  EXPECT_TRUE(j["warnings"].empty());
  EXPECT_FALSE(j.contains("accuracy"));
  const auto r = run_mdrsim(fmt::format("run {} --log-level off", scene_));
  EXPECT_NE(r.out.find("\npeak adhesion: F = "), std::string::npos) << r.out;
}

// Beyond the glue's limit the tangential load breaks it as it is applied: no equilibrium, no
// critical point, but the strength sqrt(8 pi G* a_g^3 dgamma) = sqrt(32) F0.
TEST_F(ResultOutputs, ShearOffAtApplicationReportsTheStrength) {
  const nlohmann::json j = run_json("--set loading.tangential.displacement=2e-5");
  EXPECT_EQ(j["status"], "shear-off");
  EXPECT_FALSE(j.contains("critical"));
  EXPECT_FALSE(j.contains("dimensionless"));
  EXPECT_NEAR(j["dimensionless_tangential_strength"].get<double>(), std::sqrt(32.0), 1e-9);
  const auto r = run_mdrsim(
      fmt::format("run {} --set loading.tangential.displacement=2e-5 --log-level off", scene_));
  EXPECT_NE(r.out.find("critical: none: the tangential load broke the glue as it was applied\n"),
            std::string::npos)
      << r.out;
}

// The step limit: exit 0, a warning on standard error and in the JSON, no critical point.
TEST_F(ResultOutputs, StepLimitWarnsAndHasNoCriticalPoint) {
  const std::string sets =
      "--set 'solver={method=\"stepping\",step=1e-30,max_steps=100}' --set "
      "discretization.springs=100";
  const auto r = run_mdrsim(fmt::format("run {} {} --json -", scene_, sets));
  EXPECT_EQ(r.exit_code, 0);
  const std::string warning =
      "the stepping method reached solver.max_steps = 100 before the contact was lost: there is "
      "no critical point";
  EXPECT_NE(r.err.find("[warning] " + warning), std::string::npos) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "step-limit");
  EXPECT_FALSE(j.contains("critical"));
  EXPECT_EQ(j["warnings"], nlohmann::json::array({warning}));
}

// rtol's JSON says how it got there (on the row: method = "event" named; rtol alone takes
// the continuum route).
TEST_F(ResultOutputs, RtolReportsItsRouteRowsAndEstimate) {
  const nlohmann::json j =
      run_json("--set 'discretization={rtol=1e-6}' --set 'solver={method=\"event\"}'");
  const auto& a = j["accuracy"];
  EXPECT_EQ(a["route"], "richardson");
  EXPECT_EQ(a["rtol_met"], true);
  EXPECT_EQ(j["springs"], a["rows"].back());
  const double force = std::abs(j["critical"]["normal_force"].get<double>());
  EXPECT_LE(a["critical_error_estimate"].get<double>(), 1e-6 * force);
  EXPECT_NEAR(j["dimensionless"]["normal_force"].get<double>(), -5.0 / 9.0, 1e-6 * 5.0 / 9.0);
}

// A sweep across the glue's limit: the status leads every row, and the rows that sheared off
// as the load was applied leave the critical columns empty.
TEST_F(ResultOutputs, SweepRowsWithoutCriticalPointLeaveItEmpty) {
  const auto r = run_mdrsim(fmt::format(
      "sweep {} --vary loading.tangential.displacement=1e-5:2e-5:3 --csv - --log-level off",
      scene_));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0][0], "status");
  EXPECT_EQ(rows[0][1], "stop_reason");
  EXPECT_EQ(rows[0][2], "loading.tangential.displacement");
  const std::size_t columns = rows[0].size();
  std::size_t strength = 0;
  for (std::size_t c = 0; c < columns; ++c) {
    if (rows[0][c] == "tangential_strength") strength = c;
  }
  ASSERT_GT(strength, 0u);
  EXPECT_EQ(rows[1][0], "instability");
  EXPECT_TRUE(rows[1][1].empty());  // a stop reason is step-limit's alone
  EXPECT_FALSE(rows[1][3].empty());
  EXPECT_TRUE(rows[1][strength].empty());
  for (const std::size_t i : {2u, 3u}) {
    ASSERT_EQ(rows[i].size(), columns);
    EXPECT_EQ(rows[i][0], "shear-off");
    for (std::size_t c = 3; c < strength; ++c) {
      if (rows[0][c].find("peak") == std::string::npos) {
        EXPECT_TRUE(rows[i][c].empty()) << rows[0][c];
      }
    }
    EXPECT_FALSE(rows[i][strength].empty());
  }
}

// A smooth peel (power law n = 0.5, normal-only, fixed grips: d(a) falls like sqrt(a) to 0):
// no critical point, and rtol says how deep it looked for a fold.
TEST_F(ResultOutputs, SmoothPeelUnderRtolSaysHowDeepItLooked) {
  const auto r = run_mdrsim(
      "run scenes/power_law_fixed_grips.toml --set profile.coefficient=0.01 --set "
      "profile.exponent=0.5 --set detachment.criterion=normal-only --set "
      "'discretization={rtol=1e-4}' --log-level off");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("status: no-instability"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("accuracy: no fold down to the last spring at a = "), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("critical: none: the contact peeled off smoothly, nothing jumped\n"),
            std::string::npos)
      << r.out;
}

// A cone with adhesion glued on touch: the approach jumps in (the advancing limit sqrt(x)
// outgrows g(x) = (pi/2) tan(theta) x near the apex, to x = 8 dgamma/(pi E* tan^2) = 4 a_c),
// but the fixed-grips fold of the retract, a_c = 2 dgamma/(pi E* tan^2(theta)) = 1.7e-8 m, lies
// below the first spring (dx = 3.4e-8 m), so the peel ends smoothly. The summary lists the
// jump-in and must not say that nothing jumped.
TEST_F(ResultOutputs, SmoothPeelAfterAJumpInDoesNotSayNothingJumped) {
  const std::string scene = dir_ + "/jump_in.toml";
  std::ofstream(scene) << R"([material]
effective_modulus = 1.0e6
work_of_adhesion = 1e-3
approach_work_of_adhesion = 1e-3
[profile]
type = "cone"
slope_angle_deg = 11.0
[[loading.stage]]
name = "press"
normal = { control = "fixed-grips", to = 5e-6 }
[[loading.stage]]
name = "pull"
normal = { control = "fixed-grips", by = -1e-5 }
until = "separation"
[discretization]
springs = 500
)";
  const auto r = run_mdrsim("run " + scene + " --log-level off");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("status: no-instability"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("jump in in stage press"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nothing jumped"), std::string::npos) << r.out;
  EXPECT_NE(
      r.out.find("critical: none: the contact peeled off smoothly at its end (no jump lost it)"),
      std::string::npos)
      << r.out;
}

// A force that is zero because no spring holds is computed as -0 (a sum of negative terms
// over no springs); the summary prints 0, never "F = -0 N".
TEST_F(ResultOutputs, TheSummaryPrintsNoNegativeZero) {
  const auto r = run_mdrsim("run scenes/programs/jkr_cycle_reversible.toml --log-level off");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("stage retract: ends at d = -4.70408e-06 m, F = 0 N, ux = 0 m, Fx = 0 N"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("to d = -4.70408e-06 m, F = 0 N (0 springs)"), std::string::npos) << r.out;
  for (const char* negative_zero : {"-0 ", "-0,", "-0)", "-0\n"}) {
    EXPECT_EQ(r.out.find(negative_zero), std::string::npos) << negative_zero << "\n" << r.out;
  }
}

// A plain row says that its O(1/N) error is not estimated; the shipped Fig. 2 scene
// extrapolates and prints its estimate instead.
TEST_F(ResultOutputs, APlainRowSaysItsErrorIsNotEstimated) {
  const auto plain = run_mdrsim(
      "run scenes/fig2_fixed_load.toml --set 'discretization={springs=1000}' --log-level off");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(plain.out.find("accuracy: plain row of 1000 springs; its discretization error (O(1/N)) "
                           "is not estimated"),
            std::string::npos)
      << plain.out;
  const auto extrapolated = run_mdrsim(
      "run scenes/fig2_fixed_load.toml --set discretization.springs=1000 --log-level off");
  ASSERT_EQ(extrapolated.exit_code, 0) << extrapolated.err;
  EXPECT_EQ(extrapolated.out.find("plain row"), std::string::npos) << extrapolated.out;
  EXPECT_NE(extrapolated.out.find("accuracy: richardson over rows of 500, 1000, 2000 springs"),
            std::string::npos)
      << extrapolated.out;
}

// The viscoelastic row the same: its plain row says its error is not estimated; its rows,
// contact lost at zero force (no critical point, no peak) or with the glue, print the rows
// they ran, and with a critical point located between springs its estimate.
TEST_F(ResultOutputs, TheViscoelasticRowSaysWhatItsRowsEstimate) {
  const auto plain = run_mdrsim("run scenes/viscoelastic/lee_radok_parabola.toml --log-level off");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(plain.out.find("accuracy: plain row of 400 springs; its discretization error (O(1/N)) "
                           "is not estimated"),
            std::string::npos)
      << plain.out;
  const auto extrapolated = run_mdrsim(
      "run scenes/viscoelastic/lee_radok_parabola.toml --set "
      "discretization.extrapolation=richardson --log-level off");
  ASSERT_EQ(extrapolated.exit_code, 0) << extrapolated.err;
  EXPECT_NE(extrapolated.out.find("accuracy: richardson over rows of 100, 200, 400, 800 springs"),
            std::string::npos)
      << extrapolated.out;
  const auto adhesive = run_mdrsim(
      "run scenes/viscoelastic/adhesive_relaxed_pull_off.toml --set "
      "discretization.extrapolation=richardson --log-level off");
  ASSERT_EQ(adhesive.exit_code, 0) << adhesive.err;
  EXPECT_NE(adhesive.out.find("accuracy: richardson over rows of 50, 100, 200, 400 springs across "
                              "0.0015 m; critical force error estimate"),
            std::string::npos)
      << adhesive.out;
}
