// The clock of a loading program (docs/programs.md "Time"): each state's time is its stage's
// start plus its stage parameter times the stage's seconds per unit of it, on every route that
// runs programs; without relaxation or a rate law the clock changes no number.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <toml++/toml.h>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "engine/output/result_json.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/program_reader.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"

namespace mdrsim {
namespace {

// R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2; pressed (glue on touch) to kDepth, held, then
// retracted until separation.
constexpr double kDepth = 2.0e-5;  // [m]
constexpr double kSpeed = 4.0e-6;  // the approach's speed [m/s]: it lasts kDepth / kSpeed = 5 s
constexpr double kHold = 3.0;      // the hold [s]
constexpr double kBy = -1.0e-5;    // the retraction per unit of its parameter [m]
constexpr double kPerUnit = 7.0;   // the retraction's seconds per unit of its parameter [s]
constexpr double kRetractSpeed = 2.0e-6;  // [m/s]: |kBy| / kRetractSpeed = 5 s per unit

/// The scene; `approach`, `hold` and `retract` are each stage's time key line (or "").
std::string scene_text(const std::string& approach, const std::string& hold,
                       const std::string& retract, const std::string& method = "event",
                       const std::string& material = "") {
  return fmt::format(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n{}"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"approach\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
      "{}\n"
      "[[loading.stage]]\nname = \"hold\"\n{}\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = {{ by = {} }}\nuntil = \"separation\"\n"
      "{}\n"
      "{}[solver]\nmethod = \"{}\"\n",
      material, kDepth, approach, hold, kBy, retract,
      // The continuum route has no springs to give.
      method == "event" ? "[discretization]\nsprings = 1000\n" : "", method);
}

std::string timed_scene(const std::string& method = "event", const std::string& material = "") {
  return scene_text(fmt::format("speed = {}", kSpeed), fmt::format("duration = {}", kHold),
                    fmt::format("duration = {}", kPerUnit), method, material);
}

/// Finite-range adhesion, which the continuum route runs as a Dugdale program.
constexpr const char* kDugdale = "maugis_parameter = 1.0\n";

/// The retraction's parameter of a state under fixed grips: its indentation's change over kBy.
double retract_parameter(const ContactSnapshot& s) { return (s.indentation - kDepth) / kBy; }

/// `start_depth`: the indentation the program starts at (0, or -h0 where a cohesive zone first
/// reaches the surface).
void expect_hand_times(const RunResult& r, double per_unit, double start_depth = 0.0) {
  ASSERT_EQ(r.stages.size(), 3u);
  // The approach lasts |D - d_start| / V, computed so in the engine (one quotient): exact from
  // d = 0; from -h0, to the rounding of h0 (1e-12 relative).
  const double approach_end = (kDepth - start_depth) / kSpeed;
  if (start_depth == 0.0) {
    EXPECT_DOUBLE_EQ(r.stages[0].end.time, 5.0);
    EXPECT_EQ(r.stages[0].end.time, approach_end);
  } else {
    EXPECT_NEAR(r.stages[0].end.time, approach_end, 1e-12 * approach_end);
  }
  // The hold's parameter runs 0..1 over its duration: one sum, exact.
  EXPECT_EQ(r.stages[1].end.time, r.stages[0].end.time + kHold);
  ASSERT_TRUE(r.critical.has_value());
  // t = start + per_unit * s, s from the critical indentation; the engine's s is the held
  // value's own parameter, which the indentation gives back to a few ulps (1e-12 relative).
  const double start = r.stages[1].end.time;
  const double s = retract_parameter(*r.critical);
  EXPECT_GT(s, 0.0);
  EXPECT_NEAR(r.critical->time, start + per_unit * s, 1e-12 * (start + per_unit * s));
  // The retraction's end is the loss of contact: the jump's, at the critical point's time.
  ASSERT_FALSE(r.jumps.empty());
  const JumpRecord& out = r.jumps.back();
  EXPECT_EQ(out.critical.time, r.critical->time);
  EXPECT_EQ(out.after.time, out.critical.time);  // a jump takes no time
  EXPECT_GE(r.stages[2].end.time, r.critical->time);
  // The peak: in the retraction, or (a cohesive zone's jump-in) in the approach.
  ASSERT_TRUE(r.peak.has_value());
  EXPECT_LE(r.peak->time, r.critical->time);
  const double peak_time = r.peak->time >= start ? start + per_unit * retract_parameter(*r.peak)
                                                 : (r.peak->indentation - start_depth) / kSpeed;
  EXPECT_NEAR(r.peak->time, peak_time, 1e-12 * r.critical->time);
}

TEST(ProgramClock, RampAtASpeedHoldAndRetractionUntilSeparationOnTheRow) {
  expect_hand_times(run_scene(test::build_scene_text(timed_scene()), {}), kPerUnit);
}

TEST(ProgramClock, SpeedUntilSeparationIsTimePerUnitByOverSpeed) {
  const RunResult r =
      run_scene(test::build_scene_text(scene_text(fmt::format("speed = {}", kSpeed),
                                                  fmt::format("duration = {}", kHold),
                                                  fmt::format("speed = {}", kRetractSpeed))),
                {});
  expect_hand_times(r, std::abs(kBy) / kRetractSpeed);
}

TEST(ProgramClock, ContinuumRouteGivesTheSameTimes) {
  expect_hand_times(run_scene(test::build_scene_text(timed_scene("continuum")), {}), kPerUnit);
}

// A Dugdale program starts where the zone first reaches the surface, d = -h0 = -dgamma /
// sigma_0, with sigma_0 = (lambda / 2) (pi dgamma K^2 / R)^(1/3), K = 4 E* / 3 (docs/maugis.md).
TEST(ProgramClock, DugdaleProgramGivesTheSameTimes) {
  const double k = 4.0 * 1e6 / 3.0;
  const double sigma0 = 0.5 * std::cbrt(std::numbers::pi * 0.05 * k * k / 0.01);
  expect_hand_times(run_scene(test::build_scene_text(timed_scene("continuum", kDugdale)), {}),
                    kPerUnit, -0.05 / sigma0);
}

// Durations label time and change no number: every state of the untimed run is the timed
// run's, bit for bit, with time 0.
TEST(ProgramClock, DurationsChangeNoNumber) {
  for (const auto& [method, material] : {std::pair<std::string, std::string>{"event", ""},
                                         {"continuum", ""},
                                         {"continuum", kDugdale}}) {
    const RunResult timed = run_scene(test::build_scene_text(timed_scene(method, material)), {});
    const RunResult plain =
        run_scene(test::build_scene_text(scene_text("", "", "", method, material)), {});
    ASSERT_TRUE(timed.critical && plain.critical) << method;
    EXPECT_EQ(plain.critical->time, 0.0);
    EXPECT_EQ(timed.critical->normal_force, plain.critical->normal_force) << method;
    EXPECT_EQ(timed.critical->indentation, plain.critical->indentation) << method;
    ASSERT_EQ(timed.stages.size(), plain.stages.size());
    for (std::size_t k = 0; k < timed.stages.size(); ++k) {
      EXPECT_EQ(timed.stages[k].end.normal_force, plain.stages[k].end.normal_force);
      EXPECT_EQ(timed.stages[k].work.normal, plain.stages[k].work.normal);
    }
    ASSERT_TRUE(timed.work && plain.work);
    EXPECT_EQ(timed.work->normal, plain.work->normal);
  }
}

TEST(ProgramClock, JsonHasTimeOnlyForATimedProgram) {
  const Scene timed_scene_built = test::build_scene_text(timed_scene());
  const auto timed = result_to_json(timed_scene_built, run_scene(timed_scene_built, {}));
  EXPECT_TRUE(timed["critical"].contains("time"));
  EXPECT_TRUE(timed["peak_adhesion"].contains("time"));
  EXPECT_EQ(timed["stages"][0]["start_time"].get<double>(), 0.0);
  EXPECT_EQ(timed["stages"][1]["start_time"].get<double>(),
            timed["stages"][0]["end_time"].get<double>());
  EXPECT_EQ(timed["stages"][1]["end_time"].get<double>(), kDepth / kSpeed + kHold);
  EXPECT_EQ(timed["stages"][2]["end_time"].get<double>(),
            timed["stages"][2]["end"]["time"].get<double>());
  for (const auto& jump : timed["jumps"]) {
    EXPECT_EQ(jump["critical"]["time"], jump["after"]["time"]);
  }
  const Scene plain_scene = test::build_scene_text(scene_text("", "", ""));
  const auto plain = result_to_json(plain_scene, run_scene(plain_scene, {}));
  EXPECT_FALSE(plain["critical"].contains("time"));
  EXPECT_FALSE(plain["stages"][0].contains("start_time"));
  EXPECT_FALSE(plain["stages"][0]["end"].contains("time"));
}

// A fixed load that loses the contact ends its stage there, at the critical point's time:
// F(s) = F0 + (F1 - F0) s over the stage, so t = start + T (F_c - F0) / (F1 - F0).
TEST(ProgramClock, AFixedLoadLossEndsTheStageAtItsTime) {
  constexpr double kPull = -5.0e-3;  // below -F0 = -3 pi dgamma R / 2 = -2.36e-3 N
  constexpr double kPress = 2.0, kPull_s = 10.0;
  const std::string text = fmt::format(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
      "duration = {}\n"
      "[[loading.stage]]\nname = \"pull\"\nnormal = {{ control = \"fixed-load\", to = {} }}\n"
      "duration = {}\n"
      "[discretization]\nsprings = 1000\n",
      kDepth, kPress, kPull, kPull_s);
  const RunResult r = run_scene(test::build_scene_text(text), {});
  ASSERT_TRUE(r.critical.has_value());
  ASSERT_EQ(r.stages.size(), 2u);
  const double f0 = r.stages[0].end.normal_force;
  const double s = (r.critical->normal_force - f0) / (kPull - f0);
  EXPECT_GT(s, 0.0);
  EXPECT_LT(s, 1.0);
  // The held force is the stage's parameter to rounding (1e-12 relative).
  EXPECT_NEAR(r.critical->time, kPress + kPull_s * s, 1e-12 * (kPress + kPull_s));
  EXPECT_EQ(r.stages[1].end.time, r.critical->time);
}

// The readers of the time keys of the material and the criterion call this with their key:
// a stand-in key here, on a timed program, an untimed one and the shorthand (no program).
TEST(ProgramClock, TimeKeysNeedATimedProgram) {
  const toml::table doc = toml::parse("[material]\nrelaxation = 1\n");
  const TomlReader material(*doc["material"].as_table(), "material", "scene.toml", ".");
  const Scene timed = test::build_scene_text(timed_scene());
  const Scene plain = test::build_scene_text(scene_text("", "", ""));
  EXPECT_NO_THROW(require_timed_program(material, "relaxation", &*timed.program));
  const char* message =
      "scene.toml:2:14: material.relaxation: a program whose every stage has duration or speed "
      "is needed with material.relaxation";
  EXPECT_THROW_MSG(require_timed_program(material, "relaxation", &*plain.program), SceneError,
                   message);
  EXPECT_THROW_MSG(require_timed_program(material, "relaxation", nullptr), SceneError, message);
}

}  // namespace
}  // namespace mdrsim
