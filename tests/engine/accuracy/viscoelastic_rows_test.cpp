// Richardson and rtol on the viscoelastic row, run by `mdrsim run`'s path (run_scene) on the
// scenes of scenes/viscoelastic/, against references written apart from the engine: Lee-Radok's
// force at the end of the press and Ting's separation time (tests/support/lee_radok), and the
// pull-off of a relaxed adhesive parabola, the least of F(a) = 4 E_inf a^3 / (3R) -
// sqrt(8 pi a^3 dgamma E_0) (tests/engine/program/viscoelastic_adhesion_test.cpp derives it):
// a = (9 pi R^2 dgamma E_0 / (8 E_inf^2))^(1/3), F = -(3/2) pi R dgamma E_0 / E_inf.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "tests/support/lee_radok.hpp"

namespace mdrsim {
namespace {

// scenes/viscoelastic/lee_radok_parabola.toml's numbers (its comments), plane-strain moduli.
const test::StandardLinearSolid kLeeRadokSolid{1.0e6, 9.0e6, 0.1};
const test::ParabolaRamp kLeeRadokRamp{0.01, 1.0e-4, 0.2};

// scenes/viscoelastic/adhesive_relaxed_pull_off.toml's numbers.
constexpr double kPullOffRadius = 0.01;    // R [m]
constexpr double kPullOffRelaxed = 1.0e6;  // E*_inf [Pa]
constexpr double kPullOffGlassy = 1.0e7;   // E*_0 [Pa]
constexpr double kPullOffDgamma = 0.05;    // [J/m^2]

/// -(3/2) pi R dgamma E_0 / E_inf [N].
double relaxed_pull_off() {
  return -1.5 * std::numbers::pi * kPullOffRadius * kPullOffDgamma * kPullOffGlassy /
         kPullOffRelaxed;
}

std::string viscoelastic_scene_text(const std::string& name) {
  std::ifstream in(std::string(MDRSIM_SOURCE_DIR) + "/scenes/viscoelastic/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The scene `name` with its [discretization] table's springs line `springs_line` replaced by
/// `discretization`.
RunResult run_viscoelastic_scene(const std::string& name, const std::string& springs_line,
                                 const std::string& discretization) {
  std::string text = viscoelastic_scene_text(name);
  const auto at = text.find(springs_line);
  EXPECT_NE(at, std::string::npos) << name;
  if (at != std::string::npos) text.replace(at, springs_line.size(), discretization);
  const Scene scene = SceneDocument::from_text(text, name).build(Registries::builtin());
  return run_scene(scene, {});
}

RunResult run_lee_radok(const std::string& discretization) {
  return run_viscoelastic_scene("lee_radok_parabola.toml", "springs = 400", discretization);
}

RunResult run_relaxed_pull_off(const std::string& discretization) {
  return run_viscoelastic_scene("adhesive_relaxed_pull_off.toml", "springs = 200", discretization);
}

std::string richardson_with(std::int64_t springs) {
  return fmt::format("springs = {}\nextrapolation = \"richardson\"", springs);
}

// Lee-Radok's force at the end of the press and Ting's separation time: Richardson's values
// within their estimates at every N (the estimate must bound the error, not just by luck at
// one N), and closer to the references than the plain row of the finest springs (2N): the row's
// c / N is removed.
TEST(ViscoelasticRows, RichardsonOnLeeRadokAndTingWithinItsEstimate) {
  const double tm = kLeeRadokRamp.turn_time;
  const double force = test::lee_radok_force(kLeeRadokSolid, kLeeRadokRamp, tm);
  const double separation = test::ting_separation_time(kLeeRadokSolid, kLeeRadokRamp);
  for (const std::int64_t n : {100, 200, 400, 800}) {
    const RunResult r = run_lee_radok(richardson_with(n));
    const RunResult plain = run_lee_radok(fmt::format("springs = {}", 2 * n));
    ASSERT_EQ(r.stages.size(), 2u);
    ASSERT_EQ(plain.stages.size(), 2u);
    EXPECT_EQ(r.accuracy.route, Accuracy::Route::richardson);
    EXPECT_EQ(r.status, RunStatus::no_instability);
    const StageRecord& press = r.stages[0];
    const StageRecord& withdraw = r.stages[1];
    ASSERT_TRUE(press.normal_force_error_estimate && withdraw.time_error_estimate);
    const double force_error = std::abs(press.end.normal_force - force);
    const double time_error = std::abs(withdraw.end.time - separation);
    const double plain_force_error = std::abs(plain.stages[0].end.normal_force - force);
    const double plain_time_error = std::abs(plain.stages[1].end.time - separation);
    fmt::print(
        "N {:4}: press force error {:.2e} (estimate {:.2e}, plain 2N {:.2e}); separation error "
        "{:.2e} s (estimate {:.2e}, plain 2N {:.2e})\n",
        n, force_error / force, *press.normal_force_error_estimate / force,
        plain_force_error / force, time_error, *withdraw.time_error_estimate, plain_time_error);
    EXPECT_LE(force_error, *press.normal_force_error_estimate) << n;
    EXPECT_LE(time_error, *withdraw.time_error_estimate) << n;
    EXPECT_LT(force_error, plain_force_error / 10.0) << n;
    EXPECT_LT(time_error, plain_time_error / 10.0) << n;
    // The energy terms are combined as the works are: each stage's balance still closes to
    // rounding (1e-12 of its work: sums over the springs of terms of its size).
    for (const StageRecord& stage : r.stages) {
      const EnergyBalance& e = *stage.energy;
      EXPECT_EQ(e.machine_work, stage.work.normal);
      EXPECT_NEAR(e.machine_work, e.stored_change + e.dissipated_by_bulk,
                  1e-12 * std::abs(e.machine_work));
    }
  }
}

// The relaxed pull-off (the scene's peak tension) against the continuum's least force.
TEST(ViscoelasticRows, RichardsonOnTheRelaxedPullOffWithinItsEstimate) {
  const double reference = relaxed_pull_off();
  for (const std::int64_t n : {100, 200, 400, 800}) {
    const RunResult r = run_relaxed_pull_off(richardson_with(n));
    const RunResult plain = run_relaxed_pull_off(fmt::format("springs = {}", 2 * n));
    ASSERT_TRUE(r.peak && plain.peak);
    ASSERT_TRUE(r.accuracy.peak_error_estimate);
    const double error = std::abs(r.peak->normal_force - reference);
    const double plain_error = std::abs(plain.peak->normal_force - reference);
    fmt::print("N {:4}: pull-off error {:.2e} (estimate {:.2e}, plain 2N {:.2e})\n", n,
               error / std::abs(reference), *r.accuracy.peak_error_estimate / std::abs(reference),
               plain_error / std::abs(reference));
    EXPECT_LE(error, *r.accuracy.peak_error_estimate) << n;
    EXPECT_LT(error, plain_error / 10.0) << n;
    // The critical point sits on the same spring of every row: it stays the finest row's and
    // is not covered, nor are the stage end times, which end at it.
    ASSERT_TRUE(r.critical && plain.critical);
    EXPECT_EQ(r.critical->normal_force, plain.critical->normal_force);
    EXPECT_FALSE(r.accuracy.critical_error_estimate.has_value());
    EXPECT_EQ(r.accuracy.covers,
              (std::vector<std::string>{"peak_adhesion.normal_force", "stages.end.normal_force",
                                        "stages.work", "work"}));
  }
}

// rtol doubles the rows from 256 springs until every estimate meets it: Lee-Radok's force at
// the end of the press, Ting's separation time and the relaxed pull-off within rtol of their
// references (relative) at 1e-3, 1e-5 and 1e-7.
TEST(ViscoelasticRows, RtolMeetsTheReferences) {
  const double tm = kLeeRadokRamp.turn_time;
  const double force = test::lee_radok_force(kLeeRadokSolid, kLeeRadokRamp, tm);
  const double separation = test::ting_separation_time(kLeeRadokSolid, kLeeRadokRamp);
  const double pull_off = relaxed_pull_off();
  for (const double rtol : {1e-3, 1e-5, 1e-7}) {
    const std::string discretization = fmt::format("rtol = {}", rtol);
    const RunResult lee_radok = run_lee_radok(discretization);
    const RunResult relaxed = run_relaxed_pull_off(discretization);
    EXPECT_TRUE(lee_radok.accuracy.rtol_met) << rtol;
    EXPECT_TRUE(relaxed.accuracy.rtol_met) << rtol;
    ASSERT_EQ(lee_radok.stages.size(), 2u);
    ASSERT_TRUE(relaxed.peak);
    const double force_error = std::abs(lee_radok.stages[0].end.normal_force - force) / force;
    const double time_error = std::abs(lee_radok.stages[1].end.time - separation) / separation;
    const double pull_off_error =
        std::abs(relaxed.peak->normal_force - pull_off) / std::abs(pull_off);
    fmt::print(
        "rtol {:g}: Lee-Radok {} springs, press force error {:.2e}, separation error {:.2e}; "
        "relaxed pull-off {} springs, error {:.2e}\n",
        rtol, lee_radok.springs, force_error, time_error, relaxed.springs, pull_off_error);
    EXPECT_LT(force_error, rtol);
    EXPECT_LT(time_error, rtol);
    EXPECT_LT(pull_off_error, rtol);
  }
}

// The scenes of scenes/viscoelastic/ with a relaxing bulk run at the fuzzer's rtol cap, 1e-3,
// with rtol met, in well under a second each (measured: about 20 ms).
TEST(ViscoelasticRows, ScenesRunAtTheFuzzCapQuickly) {
  for (const auto& [name, springs] :
       {std::pair<std::string, std::string>{"lee_radok_parabola.toml", "springs = 400"},
        {"adhesive_relaxed_pull_off.toml", "springs = 200"}}) {
    const RunResult r = run_viscoelastic_scene(name, springs, "rtol = 1e-3");
    EXPECT_TRUE(r.accuracy.rtol_met) << name;
    EXPECT_LT(r.wall_time_s, 1.0) << name;
  }
}

}  // namespace
}  // namespace mdrsim
