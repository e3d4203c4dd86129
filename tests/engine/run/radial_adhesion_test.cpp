// A work of adhesion that varies with the radius (docs/scene.md): its uniform limits equal the
// number to the bit, and a step of dgamma pins the receding front over the closed-form interval
// of depths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <regex>
#include <string>

#include <fmt/format.h>

#include "engine/output/result_json.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

/// The result's JSON without what may differ between equal runs: the time, the resolved scene
/// (which echoes the scene's own spelling of dgamma) and the material's words on dgamma(r).
nlohmann::ordered_json comparable(const std::string& text) {
  const Scene scene = test::build_scene_text(text);
  nlohmann::ordered_json j = result_to_json(scene, run_scene(scene, {}));
  j.erase("wall_time_s");
  j.erase("scene");
  j["material"].erase("work_of_adhesion_by_radius");
  j["material"].erase("approach_work_of_adhesion_by_radius");
  return j;
}

/// `text` with its `work_of_adhesion = 0.05` (and approach) given as a table and a sinusoid
/// of amplitude 0.
void expect_uniform_limits_equal_the_number(const std::string& text) {
  const nlohmann::ordered_json number = comparable(text);
  const std::regex value(R"((^|\n)(approach_)?work_of_adhesion = ([0-9.e-]+))");
  const std::string table = std::regex_replace(
      text, value, "$1$2work_of_adhesion = { r = [0.0, 1e-4], value = [$3, $3] }");
  const std::string sinusoid = std::regex_replace(
      text, value, "$1$2work_of_adhesion = { mean = $3, amplitude = 0.0, wavelength = 3e-5 }");
  ASSERT_NE(table, text);
  EXPECT_EQ(comparable(table), number) << table;
  EXPECT_EQ(comparable(sinusoid), number) << sinusoid;
}

constexpr const char* kMaterial = R"(
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
)";

TEST(RadialAdhesion, UniformLimitsEqualTheNumberOnThePapersPath) {
  // Fig. 3a (fixed load, a held u_x, mode-mixed) with Richardson; the stress criterion under
  // fixed grips; Hutchinson-Suo with lambda = 0.4 (its table scaled by dgamma(a)).
  for (const std::string tail : {
           R"([profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.209397078678047e-4 }
tangential = { control = "fixed-grips", displacement = 2.2614848269449475e-6 }
normal = { control = "fixed-load" }
[detachment]
criterion = "mode-mixed"
[discretization]
springs = 2000
extrapolation = "richardson"
)",
           R"([profile]
type = "sphere"
radius = 0.01
[loading]
preload = { contact_radius = 5e-4 }
tangential = { control = "fixed-grips", displacement = 1e-6 }
normal = { control = "fixed-grips" }
[detachment]
criterion = "stress"
[discretization]
springs = 1000
)",
           R"([profile]
type = "cone"
slope_angle_deg = 10.0
[loading]
preload = { contact_radius = 5e-4 }
tangential = { control = "fixed-load", force = 1e-4 }
normal = { control = "fixed-load" }
[detachment]
criterion = "mode-dependent"
lambda = 0.4
[discretization]
rtol = 1e-5
[solver]
method = "event"
)"}) {
    SCOPED_TRACE(tail);
    expect_uniform_limits_equal_the_number(std::string(kMaterial) + tail);
  }
}

TEST(RadialAdhesion, UniformLimitsEqualTheNumberInPrograms) {
  // The reversible JKR cycle (dgamma_a = dgamma: the advancing front's limit from the table
  // too) and a glue-on-touch cycle at rtol, whose row sizes come from the frame's search (on
  // the row: rtol alone takes the continuum route for the number, and the row for a table).
  expect_uniform_limits_equal_the_number(std::string(kMaterial) +
                                         R"(approach_work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
name = "approach"
normal = { control = "fixed-grips", to = 6.7844544808348425e-6 }
[[loading.stage]]
name = "retract"
normal = { control = "fixed-grips", by = -1.0e-6 }
until = "separation"
[discretization]
springs = 2000
)");
  expect_uniform_limits_equal_the_number(std::string(kMaterial) + R"([profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
name = "press"
normal = { control = "fixed-load", to = 1e-3 }
[[loading.stage]]
name = "pull"
normal = { control = "fixed-load", by = -1.0 }
until = "separation"
[discretization]
rtol = 1e-4
[solver]
method = "event"
)");
}

// A tougher core: dgamma_in for r < b, dgamma_out beyond (a step of the table at b). The
// receding front (glued on touch out to a_max > b, then retracted under fixed grips) reaches
// b where the springs beyond b let go, d = g(b) - sqrt(2 pi b dgamma_out / E*), and stays
// pinned there until the first spring inside lets go with dgamma_in,
// d = g(b) - sqrt(2 pi b dgamma_in / E*). Both branches are stable here: b lies above the
// fixed-grips folds (c R^2 / 16)^(1/3) of either uniform branch, c = 2 pi dgamma / E*.
TEST(RadialAdhesion, AStepPinsTheRecedingFrontOverTheClosedFormInterval) {
  const double e_star = 1e6, radius = 0.01, b = 2.5e-4, inner = 0.2, outer = 0.05;
  const double a_max = 4e-4;
  const int springs = 4000;
  const auto limit = [&](double w) { return std::sqrt(2.0 * std::numbers::pi * b * w / e_star); };
  const double g_b = b * b / radius;
  const double d_reach = g_b - limit(outer);  // the front arrives at b
  const double d_leave = g_b - limit(inner);  // and leaves it
  for (const double w : {inner, outer}) {
    ASSERT_GT(b, std::cbrt(2.0 * std::numbers::pi * w / e_star * radius * radius / 16.0));
  }
  const double width = d_reach - d_leave;
  // Each probe's depth, and where the front must be: beyond b, pinned at b, inside b. The
  // margin (1 % of the interval) is ~20 times the depth a front moves over one spacing.
  struct Probe {
    double depth;
    int where;  // +1 beyond b, 0 at b, -1 inside
  };
  const double margin = 0.01 * width;
  const Probe probes[] = {{d_reach + margin, +1},
                          {d_reach - margin, 0},
                          {0.5 * (d_reach + d_leave), 0},
                          {d_leave + margin, 0},
                          {d_leave - margin, -1}};
  std::string text =
      fmt::format(R"(
[material]
effective_modulus = {}
work_of_adhesion = {{ r = [0.0, {b}, {b}], value = [{}, {}, {}] }}
[profile]
type = "parabolic"
radius = {}
[[loading.stage]]
name = "press"
normal = {{ control = "fixed-grips", to = {} }}
)",
                  e_star, inner, inner, outer, radius, a_max * a_max / radius, fmt::arg("b", b));
  for (std::size_t i = 0; i < std::size(probes); ++i) {
    text += fmt::format(
        "[[loading.stage]]\nname = \"probe{}\"\nnormal = {{ control = "
        "\"fixed-grips\", to = {:.17g} }}\n",
        i, probes[i].depth);
  }
  text += fmt::format("[discretization]\nsprings = {}\n", springs);
  const Scene scene = test::build_scene_text(text);
  const RunResult r = run_scene(scene, {});
  ASSERT_EQ(r.stages.size(), std::size(probes) + 1);
  const double dx = a_max / springs;
  for (std::size_t i = 0; i < std::size(probes); ++i) {
    const double a = r.stages[i + 1].end.contact_radius;
    SCOPED_TRACE(fmt::format("probe {} at d = {:.6e} m: a = {:.9e} m, b = {:.9e} m", i,
                             probes[i].depth, a, b));
    switch (probes[i].where) {
      case +1:
        EXPECT_GT(a, b + dx);
        break;
      case 0:
        EXPECT_LE(a, b);
        EXPECT_GT(a, b - 1.5 * dx);
        break;
      default:
        EXPECT_LT(a, b - 1.5 * dx);
    }
  }
}

// The shorthand's pull-off with a tougher core, dgamma_in = 0.5 inside b = 2e-4 and 0.05
// outside, glued at 4e-4 (R = 1 cm, E* = 1 MPa). Under a fixed load the outer branch folds at
// a^3 = 9 c_out R^2 / 16 (F = -1.5 pi dgamma_out R): the front jumps in, is caught pinned at b
// (F = E* (2 b d - 2 b^3 / (3R)) rises with d: stable) and holds until the first spring inside
// lets go at d = g(b) - sqrt(2 pi b dgamma_in / E*); the inner branch is unstable there (b
// lies below its fold (c_in R^2 / 16)^(1/3)), so that is the pull-off under either control.
// The row pins at the last spring inside b: within 3/N (measured 6e-4 at N = 4000, 2.5/N).
TEST(RadialAdhesion, ATougherCoreCatchesTheFixedLoadJumpAndSetsThePullOff) {
  const double e_star = 1e6, radius = 0.01, b = 2e-4, inner = 0.5, outer = 0.05;
  const double d_leave = b * b / radius - std::sqrt(2.0 * std::numbers::pi * b * inner / e_star);
  const double expected = e_star * (2.0 * b * d_leave - 2.0 * b * b * b / (3.0 * radius));
  ASSERT_LT(b, std::cbrt(2.0 * std::numbers::pi * inner / e_star * radius * radius / 16.0));
  for (const std::string control : {"fixed-load", "fixed-grips"}) {
    for (const int n : {4000, 16000}) {
      SCOPED_TRACE(fmt::format("{} at N = {}", control, n));
      const Scene scene = test::build_scene_text(fmt::format(R"(
[material]
effective_modulus = {}
work_of_adhesion = {{ r = [0.0, {b}, {b}], value = [{}, {}, {}] }}
[profile]
type = "parabolic"
radius = {}
[loading]
preload = {{ contact_radius = 4e-4 }}
normal = {{ control = "{}" }}
[discretization]
springs = {}
)",
                                                             e_star, inner, inner, outer, radius,
                                                             control, n, fmt::arg("b", b)));
      const RunResult r = run_scene(scene, {});
      ASSERT_TRUE(r.critical.has_value());
      EXPECT_EQ(r.status, RunStatus::instability);
      EXPECT_NEAR(r.critical->normal_force / expected, 1.0, 3.0 / n);
      EXPECT_NEAR(r.critical->indentation / d_leave, 1.0, 3.0 / n);
    }
  }
}

}  // namespace
}  // namespace mdrsim
