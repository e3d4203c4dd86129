// mdrsim fit on the command line: the JSON and CSV of the real JPK curve, the refusals (exit 2,
// one line) and a map whose bad curve gets its status.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.hpp"

using mdrsim::test::run_mdrsim;

namespace {

constexpr const char* kSpot3 = "tests/data/afm/fmt-jpk-fd_spot3-0192.jpk-force";

TEST(FitCommand, HertzOnTheJpkCurveAsJson) {
  const auto result = run_mdrsim(std::string("fit ") + kSpot3 +
                                 " --tip parabolic:radius=1e-5 --poisson-ratio 0.5 "
                                 "--fix baseline_slope=0 --json -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto all = nlohmann::json::parse(result.out);
  ASSERT_EQ(all.size(), 1U);
  const auto& fit = all[0];
  EXPECT_EQ(fit["status"], "fitted");
  EXPECT_EQ(fit["model"], "hertz");
  EXPECT_EQ(fit["segment"], "approach");
  EXPECT_EQ(fit["tip_position_from"], "measured_height");
  // nanite's value (tests/test_indent.py), 1e-3 relative as in the engine's test.
  EXPECT_NEAR(fit["youngs_modulus"]["value"].get<double>(), 14741.96, 14.74);
  EXPECT_GT(fit["youngs_modulus"]["standard_error"].get<double>(), 0.0);
  EXPECT_EQ(fit["baseline_slope"]["fixed"], true);
  EXPECT_EQ(fit["baseline_slope"]["value"].get<double>(), 0.0);
  EXPECT_EQ(fit["points"], 2000);
  EXPECT_NEAR(fit["calibration"]["spring_constant"]["value"].get<double>(), 0.043493666407368466,
              1e-15);
}

TEST(FitCommand, CsvHasOneRowPerCurveOfAMap) {
  const auto result = run_mdrsim(
      "fit tests/data/afm/fmt-jpk-fd_map-data-reference-points.jpk-force-map "
      "--tip sphere:radius=5e-6 --csv -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  int lines = 0;
  for (const char c : result.out) lines += c == '\n';
  EXPECT_EQ(lines, 4) << result.out;  // header + 3 curves
  EXPECT_EQ(result.out.rfind("file,curve,x,y,index,column,row,status,youngs_modulus,", 0), 0U);
  EXPECT_EQ(result.out.find("nan"), std::string::npos);
}

TEST(FitCommand, RefusesWithOneLine) {
  const struct {
    std::string args;
    std::string message;
  } cases[] = {
      {std::string("fit ") + kSpot3 + " --tip cone:half_angle_deg=20 --model maugis",
       "--model maugis: not for a cone (the Maugis parameter needs a tip radius: parabolic or "
       "sphere; use --model jkr)\n"},
      {std::string("fit ") + kSpot3 +
           " --tip parabolic:radius=1e-5 --model jkr --fix "
           "maugis_parameter=1",
       "--fix maugis_parameter: not a parameter of --model jkr\n"},
      {std::string("fit ") + kSpot3 +
           " --tip parabolic:radius=1e-5 --model auto --fix "
           "maugis_parameter=0",
       "--fix maugis_parameter: must be > 0\n"},
      {std::string("fit ") + kSpot3 + " --tip cone:half_angle_deg=20 --model dmt",
       "--model dmt: not for a cone (its DMT adhesion depends on the attraction's range; use "
       "--model jkr)\n"},
      {std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --model foo",
       "--model foo: unknown (known: hertz, dmt, jkr, maugis, auto)\n"},
      {std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --fix work_of_adhesion=1",
       "--fix work_of_adhesion: not a parameter of --model hertz\n"},
      {std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --fix youngs=1",
       "--fix youngs: unknown (known: youngs_modulus, work_of_adhesion, "
       "approach_work_of_adhesion, maugis_parameter, contact_point, baseline_offset, "
       "baseline_slope, spring_constant, sensitivity)\n"},
      {std::string("fit ") + kSpot3 +
           " --tip parabolic:radius=1e-5 --model jkr --fix approach_work_of_adhesion=0.1",
       "--fix approach_work_of_adhesion: only with --segment both\n"},
      {std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --model auto --segment both",
       "--segment both: not with --model auto (approach and retract are fitted together by "
       "hertz, dmt, jkr and maugis)\n"},
      {std::string("fit ") + kSpot3 + " --tip blunt:radius=1",
       "--tip: 'blunt:radius=1' is not a tip (known: parabolic:radius=R, sphere:radius=R, "
       "cone:half_angle_deg=A, pyramid:half_angle_deg=A, a scene file FILE.toml)\n"},
      {std::string("fit ") + kSpot3 + " --tip pyramid:half_angle_deg=35 --model dmt",
       "--model dmt: not for a pyramid (its DMT adhesion depends on the attraction's range; use "
       "--model jkr)\n"},
      {std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --range 1e-7",
       "--range: '1e-7' is not FROM:TO (indentations in m)\n"},
      {std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --range 2e-7:1e-7",
       "--range 2e-7:1e-7: FROM must be below TO\n"},
      {"fit tests/data/afm/fmt-jpk-fd_single-modified_2023.jpk-force --tip "
       "parabolic:radius=1e-5",
       "tests/data/afm/fmt-jpk-fd_single-modified_2023.jpk-force: segment extend-cellhesion200: no "
       "spring "
       "constant to turn the deflection into a force (give --fix spring_constant=K [N/m])\n"},
      {"fit tests/data/afm/README.md --tip parabolic:radius=1e-5",
       "tests/data/afm/README.md: unknown kind of file '.md' (known: .jpk-force, "
       ".jpk-force-map, .jpk-qi-data, .jpk-qi-series, .h5, .hdf5, .ibw, .csv, .tsv, .txt)\n"},
  };
  for (const auto& c : cases) {
    const auto result = run_mdrsim(c.args);
    EXPECT_EQ(result.exit_code, 2) << c.args;
    EXPECT_EQ(result.err, c.message) << c.args;
    EXPECT_EQ(result.out, "") << c.args;
  }
}

TEST(FitCommand, JkrOnTheIgorRetractAsJson) {
  const auto result = run_mdrsim(
      "fit tests/data/afm/fmt-igor-fd_SiN_FD_plot.ibw --tip parabolic:radius=1e-5 --model jkr "
      "--segment retract --json -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto fit = nlohmann::json::parse(result.out)[0];
  EXPECT_EQ(fit["status"], "fitted");
  EXPECT_EQ(fit["model"], "jkr");
  EXPECT_EQ(fit["segment"], "retract");
  EXPECT_GT(fit["work_of_adhesion"]["value"].get<double>(), 0.0);
  EXPECT_GT(fit["work_of_adhesion"]["standard_error"].get<double>(), 0.0);
  // JKR's fixed-load pull-off of the paraboloid, (3/2) pi w R, to the branch's sampling.
  EXPECT_NEAR(fit["adhesion_force"]["fitted"].get<double>(),
              1.5 * M_PI * fit["work_of_adhesion"]["value"].get<double>() * 1e-5,
              1e-4 * fit["adhesion_force"]["fitted"].get<double>());
  EXPECT_GT(fit["adhesion_force"]["measured"].get<double>(), 0.0);

  const auto held = run_mdrsim(
      "fit tests/data/afm/fmt-igor-fd_SiN_FD_plot.ibw --tip parabolic:radius=1e-5 --model dmt "
      "--segment retract --fix work_of_adhesion=0.001 --csv -");
  ASSERT_EQ(held.exit_code, 0) << held.err;
  EXPECT_NE(held.out.find(",dmt,0.001,0,"), std::string::npos) << held.out;
}

// auto: the Maugis fit and the model its lambda picks, with the reason, in JSON, CSV and the
// summary; a held lambda is held.
TEST(FitCommand, AutoNamesThePickedModelAndWhy) {
  const std::string base =
      "fit tests/data/afm/fmt-igor-fd_SiN_FD_plot.ibw --tip parabolic:radius=1e-5 --segment "
      "retract ";
  const auto result = run_mdrsim(base + "--model auto --json -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto fit = nlohmann::json::parse(result.out)[0];
  EXPECT_EQ(fit["status"], "fitted");
  EXPECT_EQ(fit["model"], "auto");
  const double lambda = fit["maugis_parameter"]["value"].get<double>();
  const std::string picked = lambda < 0.1 ? "dmt" : lambda > 5 ? "jkr" : "maugis";
  EXPECT_EQ(fit["auto"]["picked"], picked);
  EXPECT_EQ(fit["auto"]["reason"].get<std::string>().rfind("auto: lambda = ", 0), 0U);
  EXPECT_NE(fit["auto"]["reason"].get<std::string>().find("-> " + picked), std::string::npos);

  const auto summary = run_mdrsim(base + "--model auto");
  ASSERT_EQ(summary.exit_code, 0) << summary.err;
  EXPECT_NE(summary.out.find("(auto: lambda = "), std::string::npos) << summary.out;

  const auto held = run_mdrsim(base + "--model maugis --fix maugis_parameter=0.5 --csv -");
  ASSERT_EQ(held.exit_code, 0) << held.err;
  EXPECT_NE(held.out.find("maugis_parameter,maugis_parameter_error,auto_model,warnings\n"),
            std::string::npos)
      << held.out;
  EXPECT_NE(held.out.find(",0.5,0,,"), std::string::npos) << held.out;
}

// The warnings of a fit the engine cannot vouch for: the cell's retract under JKR (the tethers'
// pull, which no model here holds, is taken as the contact branch) in the JSON's list, the
// CSV's column and a text line after the fit's; the Hertz approach of nanite's case has none.
TEST(FitCommand, AFitItCannotVouchForCarriesWarnings) {
  const std::string base = std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 ";
  const auto hertz = run_mdrsim(base + "--json -");
  ASSERT_EQ(hertz.exit_code, 0) << hertz.err;
  EXPECT_EQ(nlohmann::json::parse(hertz.out)[0]["warnings"], nlohmann::json::array());

  const auto json = run_mdrsim(base + "--model jkr --segment retract --json -");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto fit = nlohmann::json::parse(json.out)[0];
  EXPECT_EQ(fit["status"], "fitted");
  const auto& warnings = fit["warnings"];
  ASSERT_EQ(warnings.size(), 2U) << warnings;
  EXPECT_EQ(warnings[0].get<std::string>().rfind("short baseline: ", 0), 0U) << warnings;
  EXPECT_EQ(warnings[1].get<std::string>().rfind("the model does not describe the curve", 0), 0U)
      << warnings;

  const auto csv = run_mdrsim(base + "--model jkr --segment retract --csv -");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  const std::string joined = warnings[0].get<std::string>() + "; " + warnings[1].get<std::string>();
  // The cell is quoted: the warnings hold commas.
  EXPECT_NE(csv.out.find(",\"" + joined + "\"\n"), std::string::npos) << csv.out;

  const auto text = run_mdrsim(base + "--model jkr --segment retract");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::string where = std::string(kSpot3) + ": ";
  EXPECT_EQ(text.out.rfind(where + "fitted E = ", 0), 0U) << text.out;
  EXPECT_NE(text.out.find("\n" + where + "warning: " + warnings[0].get<std::string>() + "\n" +
                          where + "warning: " + warnings[1].get<std::string>() + "\n"),
            std::string::npos)
      << text.out;
}

// A sphere of 5 um pressed past its reach by the map's curves (DMT's Hertz force there has no
// contact radius): each curve gets not-converged with the reason and the map goes on, for every
// adhesive model, not an internal error.
TEST(FitCommand, ASpherePressedPastItsReachIsNotConverged) {
  for (const char* model : {"dmt", "jkr", "maugis", "auto"}) {
    const auto result = run_mdrsim(
        std::string("fit tests/data/afm/fmt-jpk-fd_map-data-reference-points.jpk-force-map "
                    "--tip sphere:radius=5e-6 --segment retract --json - --model ") +
        model);
    ASSERT_EQ(result.exit_code, 0) << model << ": " << result.err;
    const auto all = nlohmann::json::parse(result.out);
    ASSERT_EQ(all.size(), 3U);
    for (const auto& fit : all) {
      EXPECT_TRUE(fit["status"] == "not-converged" || fit["status"] == "fitted") << fit.dump();
      // auto names a model only for a fitted lambda.
      EXPECT_EQ(fit.contains("auto"), fit["status"] == "fitted" && std::string(model) == "auto");
    }
  }
}

TEST(FitCommand, SpringConstantGivenFitsTheDeflectionOnlyFile) {
  const auto result = run_mdrsim(
      "fit tests/data/afm/fmt-jpk-fd_single-modified_2023.jpk-force --tip parabolic:radius=1e-5 "
      "--fix spring_constant=0.05 --json -");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto all = nlohmann::json::parse(result.out);
  EXPECT_EQ(all[0]["calibration"]["spring_constant"]["source"], "override");
}

/// Writes `text` to NAME in a fresh temporary folder; returns its path.
std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = mdrsim::test::make_temp_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// A bad tip file: exit 2 and one line naming the file, line, column and key.
TEST(FitCommand, BadTipFileNamesTheFileAndKey) {
  const std::string tip = temp_file("tip.toml", "[profile]\ntype = \"sphere\"\nradus = 1e-5\n");
  const auto result = run_mdrsim(std::string("fit ") + kSpot3 + " --tip " + tip);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, tip +
                            ":3:1: profile.radus: unknown key; did you mean 'radius'? (known: "
                            "radius, type)\n");
}

// A scene file's paraboloid fits as `parabolic:radius=` does, to the last digit; the pyramid's
// output says it is approximate.
TEST(FitCommand, SceneTipAndPyramid) {
  const std::string tip =
      temp_file("tip.toml",
                "[material]\nyoungs_modulus = 1\n[profile]\ntype = \"parabolic\"\nradius = 1e-5\n");
  const auto scene = run_mdrsim(std::string("fit ") + kSpot3 + " --tip " + tip + " --json -");
  const auto plain =
      run_mdrsim(std::string("fit ") + kSpot3 + " --tip parabolic:radius=1e-5 --json -");
  ASSERT_EQ(scene.exit_code, 0) << scene.err;
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto a = nlohmann::json::parse(scene.out)[0], b = nlohmann::json::parse(plain.out)[0];
  EXPECT_EQ(a["youngs_modulus"], b["youngs_modulus"]);
  EXPECT_EQ(a["contact_point"], b["contact_point"]);
  EXPECT_EQ(a["tip"], tip + " (parabolic)");

  const auto pyramid =
      run_mdrsim(std::string("fit ") + kSpot3 + " --tip pyramid:half_angle_deg=35 --json -");
  ASSERT_EQ(pyramid.exit_code, 0) << pyramid.err;
  const auto p = nlohmann::json::parse(pyramid.out)[0];
  EXPECT_EQ(p["status"], "fitted");
  EXPECT_EQ(p["tip_approximation"],
            "approximate: the four-sided pyramid as the cone of equal cross-section area, half "
            "angle 38.3122 deg");
  EXPECT_NE(pyramid.err.find("approximate"), std::string::npos) << pyramid.err;
}

// --range keeps the samples whose indentation from the contact point lies in FROM:TO: a Hertz
// curve (paraboloid R = 10 um, E = 10 kPa) whose sample stiffens past 200 nm (a substrate: E
// doubles there) gives 10 kPa when fitted to 200 nm only, and not when fitted whole.
TEST(FitCommand, RangeRestrictsTheFittedIndentation) {
  const double r = 1e-5, e = 1e4 / 0.75, contact = 5e-6, knee = 2e-7;
  std::string table = "tip_position [m],force [N],segment\n";
  for (int i = 0; i < 1500; ++i) {
    const double d = 6e-7 * (i / 1499.0) - 6e-7 * 0.5;
    double f = d > 0 ? 4.0 / 3.0 * e * std::sqrt(r) * std::pow(d, 1.5) : 0.0;
    if (d > knee) f += 4.0 / 3.0 * e * std::sqrt(r) * std::pow(d - knee, 1.5);
    table += fmt::format("{},{},approach\n", contact - d, f);
  }
  const std::string curve = temp_file("stiffening.csv", table);
  const auto whole = run_mdrsim("fit " + curve + " --tip parabolic:radius=1e-5 --json -");
  const auto part =
      run_mdrsim("fit " + curve + " --tip parabolic:radius=1e-5 --range=-3e-7:2e-7 --json -");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  ASSERT_EQ(part.exit_code, 0) << part.err;
  const auto w = nlohmann::json::parse(whole.out)[0], p = nlohmann::json::parse(part.out)[0];
  EXPECT_GT(w["youngs_modulus"]["value"].get<double>(), 1.1e4);
  // Noise-free and exact inside the range: the minimiser's tolerance.
  EXPECT_NEAR(p["youngs_modulus"]["value"].get<double>(), 1e4, 1e-6 * 1e4);
  EXPECT_NEAR(p["contact_point"]["value"].get<double>(), contact, 1e-13);
  // Samples from 300 nm above contact to 200 nm in: 5/6 of the 1500.
  EXPECT_NEAR(p["points"].get<double>(), 1250, 2);
  EXPECT_EQ(p["range"], nlohmann::json::parse("[-3e-7, 2e-7]"));
}

// --segment both on the Igor curve of a stiff sample: one E and contact point, both works of
// adhesion, the hysteresis energy; the hysteresis is the same whatever segment is fitted.
TEST(FitCommand, BothSegmentsOnTheIgorCurve) {
  const std::string base =
      "fit tests/data/afm/fmt-igor-fd_SiN_FD_plot.ibw --tip parabolic:radius=1e-5 --json - ";
  const auto both = run_mdrsim(base + "--model jkr --segment both");
  ASSERT_EQ(both.exit_code, 0) << both.err;
  const auto f = nlohmann::json::parse(both.out)[0];
  EXPECT_EQ(f["segment"], "both");
  EXPECT_EQ(f["status"], "fitted") << f;
  EXPECT_GT(f["work_of_adhesion"]["value"].get<double>(), 0.0);
  EXPECT_GT(f["approach_work_of_adhesion"]["value"].get<double>(), 0.0);
  EXPECT_EQ(f["points"], 1009 + 1007);
  ASSERT_TRUE(f["hysteresis_energy"].is_number());
  const auto approach = run_mdrsim(base);
  ASSERT_EQ(approach.exit_code, 0) << approach.err;
  EXPECT_EQ(nlohmann::json::parse(approach.out)[0]["hysteresis_energy"], f["hysteresis_energy"]);
  const auto hertz = run_mdrsim(base + "--segment both");
  ASSERT_EQ(hertz.exit_code, 0) << hertz.err;
  EXPECT_EQ(nlohmann::json::parse(hertz.out)[0].count("approach_work_of_adhesion"), 0U);
}

}  // namespace
