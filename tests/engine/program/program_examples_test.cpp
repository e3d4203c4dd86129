// The example loading programs of scenes/programs/ run through the mdrsim binary and compared
// with the continuum references of engine/reference/program_reference.
//
// Tolerances. Every scene runs N = 4000 springs over the largest radius a_max it reaches, at
// spacing h = a_max/(N a0). The row's force is a right Riemann sum of (1/2) int (d - 3 x^2) dx,
// off by up to (3/4) h a^2 F0, and its contact radius moves by whole springs, which moves the
// force by |dF/da| h and a fold's depth by O(h^2). So forces [F0], depths and tangential
// displacements [d0] are held to 2 h (1 + a_max^2), radii [a0] to 2 h. A stage's work is held
// to that force bound times the depth the stage travels [F0 d0]; the program's, a signed sum
// whose errors largely cancel between loading and unloading over the same springs, to
// 3 h sum |W_stage| with the reference's stage works. The engine's errors measure at most a
// third of these bounds (several above a sixth), and one spring (h) in the radii.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <string_view>

#include "engine/reference/friction_reference.hpp"
#include "engine/reference/program_reference.hpp"
#include "profiles/parabolic_profile.hpp"
#include "tests/support/run_command.hpp"

namespace pr = mdrsim::program_reference;
using nlohmann::json;

namespace {

// Every example: R = 1 cm, E* = G* = 1 MPa (E = 1 MPa, nu = 0), dgamma = 0.05 J/m^2, 4000 springs.
constexpr double kRadius = 0.01;
constexpr double kModulus = 1.0e6;
constexpr double kWorkOfAdhesion = 0.05;
constexpr double kSprings = 4000.0;

/// The paper's scales (eq. 17).
struct Scales {
  static constexpr double pi = std::numbers::pi;
  double force = 1.5 * pi * kRadius * kWorkOfAdhesion;  ///< F0 [N]
  double radius = std::cbrt(9.0 * pi * kRadius * kRadius * kWorkOfAdhesion / (8.0 * kModulus));
  double depth = std::cbrt(3.0 * pi * pi * kRadius * kWorkOfAdhesion * kWorkOfAdhesion /
                           (64.0 * kModulus * kModulus));
  double work() const { return force * depth; }  ///< F0 d0 [J]
};

/// The bounds of the header comment for a program whose largest radius is a_max [a0].
struct Tolerance {
  double largest_radius;
  double spacing() const { return largest_radius / kSprings; }
  double value() const { return 2.0 * spacing() * (1.0 + largest_radius * largest_radius); }
  double radius() const { return 2.0 * spacing(); }
  /// A stage's work: the force bound over the depth it travels [d0].
  double stage_work(double travel) const { return value() * travel; }
  /// The program's: the stage works' relative errors, largely cancelling between loading and
  /// unloading over the same springs, bounded by 3 h sum |W_stage| [F0 d0].
  double total_work(double gross_stage_work) const { return 3.0 * spacing() * gross_stage_work; }
};

/// j[key] if j is an object holding it, else null: the checks then say what is missing.
json member(const json& j, const char* key) {
  return j.is_object() && j.contains(key) ? j[key] : json();
}

/// The JSON result of `mdrsim run scenes/programs/NAME.toml`, or null (with a failure) if the
/// run failed or printed no JSON.
/// `extra`: options after the scene's path (--set ...).
json run_example(const std::string& name, const std::string& extra = "") {
  const auto r = mdrsim::test::run_mdrsim("run scenes/programs/" + name + ".toml " + extra +
                                          " --json - --log-level off");
  EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  json result = json::parse(r.out, nullptr, false);
  if (result.is_discarded() || !result.is_object()) {
    ADD_FAILURE() << name << ": standard output is no JSON object: " << r.out.substr(0, 400)
                  << "\nstandard error: " << r.err.substr(0, 400);
    return json();
  }
  return result;
}

/// The stage named `name`, or null.
json stage(const json& result, std::string_view name) {
  if (result.contains("stages") && result["stages"].is_array()) {
    for (const auto& s : result["stages"]) {
      if (s.is_object() && s.value("name", "") == name) return s;
    }
  }
  ADD_FAILURE() << "no stage \"" << name << "\" in " << member(result, "stages").dump();
  return json();
}

/// The jump of `kind` in stage `name` that changes the most springs (the cascade of the
/// instability, whatever smaller records the engine keeps beside it), or null.
json biggest_jump(const json& result, std::string_view name, std::string_view kind) {
  json best;
  if (result.contains("jumps") && result["jumps"].is_array()) {
    for (const auto& j : result["jumps"]) {
      if (!j.is_object() || j.value("stage", "") != name || j.value("kind", "") != kind) continue;
      if (best.is_null() ||
          std::abs(j.value("springs", 0.0)) > std::abs(best.value("springs", 0.0))) {
        best = j;
      }
    }
  }
  if (best.is_null()) ADD_FAILURE() << "no jump \"" << kind << "\" in stage \"" << name << "\"";
  return best;
}

/// Compares the SI field `field` of `state`, divided by `scale` (named `unit`), with `want`.
void expect_field(const json& state, const char* field, double want, double scale, const char* unit,
                  double tol, const std::string& where) {
  if (!state.is_object() || !state.contains(field) || !state[field].is_number()) {
    ADD_FAILURE() << where << ": no number \"" << field << "\" in " << state.dump();
    return;
  }
  const double got = state[field].get<double>() / scale;
  EXPECT_NEAR(got, want, tol) << where << "." << field << " [" << unit << "]: mdrsim " << got
                              << ", continuum reference " << want << ", tolerance " << tol
                              << " (SI: mdrsim " << state[field].get<double>() << ", reference "
                              << want * scale << ")";
}

/// Compares the fields of a state object (critical, after, end) with a reference state.
void expect_state(const json& state, const pr::State& want, const Tolerance& tol,
                  const std::string& where) {
  const Scales k;
  expect_field(state, "normal_force", want.normal_force, k.force, "F0", tol.value(), where);
  expect_field(state, "indentation", want.indentation, k.depth, "d0", tol.value(), where);
  expect_field(state, "contact_radius", want.contact_radius, k.radius, "a0", tol.radius(), where);
  expect_field(state, "tangential_displacement", want.tangential_displacement, k.depth, "d0",
               tol.value(), where);
  expect_field(state, "tangential_force", want.tangential_force, k.force, "F0", tol.value(), where);
}

void expect_work(const json& work, double want, double tol, const std::string& where) {
  const Scales k;
  expect_field(work, "normal", want, k.work(), "F0 d0", tol, where + ".work");
}

void expect_lost_at(const json& result, std::string_view last_stage, const pr::State& critical,
                    const Tolerance& tol) {
  EXPECT_EQ(result.value("status", ""), "instability");
  expect_state(member(result, "critical"), critical, tol, "critical");
  expect_state(member(biggest_jump(result, last_stage, "out"), "critical"), critical, tol,
               std::string("jump out of ") + std::string(last_stage) + ".critical");
}

}  // namespace

// ---- (a) ----

TEST(ProgramExamples, ReversibleJkrCycleJumpsInAtMinusEightNinthsAndDissipatesWhateverTheDepth) {
  const auto want = pr::reversible_jkr_cycle(3.0);
  const Tolerance tol{want.approach_end.contact_radius};
  const json result = run_example("jkr_cycle_reversible");
  ASSERT_TRUE(result.is_object());
  const json in = biggest_jump(result, "approach", "in");
  expect_state(member(in, "after"), want.jump_in_after, tol, "jump in.after");
  expect_field(member(in, "critical"), "indentation", 0.0, Scales{}.depth, "d0", tol.value(),
               "jump in.critical");
  expect_state(member(stage(result, "approach"), "end"), want.approach_end, tol, "approach.end");
  expect_lost_at(result, "retract", want.retract_critical, tol);
  const double approach_work =
      pr::jkr_branch_work(want.jump_in_after.contact_radius, want.approach_end.contact_radius);
  const double retract_work =
      pr::jkr_branch_work(want.approach_end.contact_radius, want.retract_critical.contact_radius);
  const double gross = std::abs(approach_work) + std::abs(retract_work);
  const double fold_depth = -want.retract_critical.indentation;
  expect_work(member(stage(result, "approach"), "work"), approach_work, tol.stage_work(3.0),
              "approach");
  expect_work(member(stage(result, "retract"), "work"), retract_work,
              tol.stage_work(3.0 + fold_depth), "retract");
  expect_work(member(result, "work"), want.dissipated_work, tol.total_work(gross),
              "the cycle (0.935503 F0 |d_c|)");
}

// ---- (b) ----

TEST(ProgramExamples, GlueOnTouchJkrCycleDissipatesTwoThirdsF0DmaxPlusFourFortyFifthsF0Dc) {
  const auto want = pr::glue_on_touch_cycle(3.0);
  const Tolerance tol{want.max_radius};
  const json result = run_example("jkr_cycle_glue_on_touch");
  ASSERT_TRUE(result.is_object());
  for (const auto& j : member(result, "jumps")) {
    EXPECT_FALSE(j.is_object() && j.value("kind", "") == "in")
        << "gluing on touch has no jump-in: " << j.dump();
  }
  expect_state(member(stage(result, "approach"), "end"), want.load_end, tol, "approach.end");
  expect_lost_at(result, "retract", want.retract_critical, tol);
  const double retract_work = want.dissipated_work - want.loading_work;
  const double gross = std::abs(want.loading_work) + std::abs(retract_work);
  const double fold_depth = -want.retract_critical.indentation;
  expect_work(member(stage(result, "approach"), "work"), want.loading_work, tol.stage_work(3.0),
              "approach");
  expect_work(member(stage(result, "retract"), "work"), retract_work,
              tol.stage_work(3.0 + fold_depth), "retract");
  expect_work(member(result, "work"), pr::claimed_glue_on_touch_dissipation(3.0),
              tol.total_work(gross), "the cycle");
}

// ---- (c) ----

TEST(ProgramExamples, ShearRampAtHeldForceEndsOnTheFixedLoadEnvelope) {
  const auto want = pr::shear_ramp_at_held_force(2.0, -0.5);
  const Tolerance tol{2.0};
  const json result = run_example("shear_ramp_fixed_load");
  ASSERT_TRUE(result.is_object());
  expect_state(member(stage(result, "unload"), "end"), want.start, tol, "unload.end");
  expect_lost_at(result, "shear", want.critical, tol);
}

TEST(ProgramExamples, ShearRampAtHeldDepthEndsOnTheFixedGripsEnvelope) {
  const auto want = pr::shear_ramp_at_held_indentation(2.0, -1.0);
  const Tolerance tol{2.0};
  const json result = run_example("shear_ramp_fixed_grips");
  ASSERT_TRUE(result.is_object());
  expect_state(member(stage(result, "unload"), "end"), want.start, tol, "unload.end");
  expect_lost_at(result, "shear", want.critical, tol);
  // The paper's eq. 35 at the simulated tangential force.
  const json critical = member(result, "critical");
  if (critical.contains("tangential_force")) {
    const double fx = critical["tangential_force"].get<double>() / Scales{}.force;
    expect_field(critical, "normal_force", fx * fx / 4.0 - 5.0 / 9.0, Scales{}.force, "F0",
                 tol.value(), "critical on eq. 35");
  }
}

// ---- (d) ----

TEST(ProgramExamples, InclinedPullEndsAtTheFoldOfTheBoundaryEquation) {
  const auto want = pr::inclined_pull(2.0);
  ASSERT_EQ(want.end, pr::InclinedPull::End::fold);
  ASSERT_TRUE(want.contact_lost);
  const Tolerance tol{std::sqrt(2.0 / 3.0)};
  const json result = run_example("inclined_pull_45");
  ASSERT_TRUE(result.is_object());
  expect_lost_at(result, "inclined-pull", want.critical, tol);
}

// ---- (e) ----

class ReloadExample : public ::testing::TestWithParam<bool> {};

TEST_P(ReloadExample, StageEndsPullOffAndWorkFollowTheReference) {
  const bool rebinding = GetParam();
  const auto want = pr::reload_program(12.0, 3.0, 6.0, rebinding);
  const Tolerance tol{want.glued_radius};
  const json result = run_example(rebinding ? "reload_rebinding_true" : "reload_rebinding_false");
  ASSERT_TRUE(result.is_object());
  const Scales k;
  const char* names[] = {"load", "unload", "reload", "unload-again", "pull-off"};
  const double fold_depth = -want.pull_off_critical.indentation;
  const double travel[] = {12.0, 9.0, 9.0, 6.0, 6.0 + fold_depth};  // d0
  double gross = 0.0;
  for (const double w : want.stage_work) gross += std::abs(w);
  for (int i = 0; i < 5; ++i) {
    const json s = stage(result, names[i]);
    if (i < 4) {
      expect_field(member(s, "end"), "normal_force", want.stage_end_force[i], k.force, "F0",
                   tol.value(), std::string(names[i]) + ".end");
    }
    expect_work(member(s, "work"), want.stage_work[i], tol.stage_work(travel[i]), names[i]);
  }
  expect_lost_at(result, "pull-off", want.pull_off_critical, tol);
  expect_work(member(result, "work"), want.work, tol.total_work(gross), "the program");
}

INSTANTIATE_TEST_SUITE_P(Rebinding, ReloadExample, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "True" : "False"; });

// The second unloads part by 0.61 F0 at d3 (2.708 F0 without rebinding, 2.095 F0 with it).
TEST(ProgramExamples, SecondUnloadDependsOnRebinding) {
  const double off = pr::reload_program(12.0, 3.0, 6.0, false).stage_end_force[3];
  const double on = pr::reload_program(12.0, 3.0, 6.0, true).stage_end_force[3];
  const json a = run_example("reload_rebinding_false");
  const json b = run_example("reload_rebinding_true");
  ASSERT_TRUE(a.is_object() && b.is_object());
  const auto end_force = [](const json& r) {
    const json end = member(stage(r, "unload-again"), "end");
    return end.is_object() ? end.value("normal_force", NAN) / Scales{}.force : NAN;
  };
  EXPECT_NEAR(end_force(a) - end_force(b), off - on, 2.0 * Tolerance{2.0}.value())
      << "without rebinding " << end_force(a) << " F0, with it " << end_force(b) << " F0";
}

TEST(ProgramExamples, FrettingCycleDissipatesTheMindlinDeresiewiczLoopEnergy) {
  // docs/friction.md: F_z = 1 mN, mu = 0.5, u_m = 1 um on the sphere of every example. The
  // closed forms at the continuum's d for F_z; the row's d under the fixed load and its sums over
  // springs are each off by O(1/N): W within 4/N = 1e-3 of itself, F_x(u_m) within 4/N of mu F_z
  // (observed: 9e-5 and 6e-5).
  const json r = run_example("fretting_parabola");
  constexpr double kMu = 0.5;
  constexpr double kForce = 1e-3;
  constexpr double kAmplitude = 1e-6;
  const double a = std::cbrt(3.0 * kForce * kRadius / (4.0 * kModulus));
  const mdrsim::ParabolicProfile profile(kRadius);
  const mdrsim::friction_reference::CattaneoMindlin cm(profile, kModulus, kModulus, kMu,
                                                       a * a / kRadius);
  const double closed = cm.loop_energy(kAmplitude);
  double work = 0.0;
  double dissipated = 0.0;
  for (const char* name : {"unload", "reload"}) {
    work += member(member(stage(r, name), "work"), "tangential").get<double>();
    dissipated += member(member(stage(r, name), "work"), "dissipated_by_friction").get<double>();
  }
  EXPECT_NEAR(work, closed, 4.0 / kSprings * closed);
  EXPECT_NEAR(dissipated, work, 1e-12 * closed);  // a closed cycle: all of it dissipated
  const double loaded = member(member(stage(r, "load"), "end"), "tangential_force").get<double>();
  EXPECT_NEAR(loaded, cm.loading_force(kAmplitude), 4.0 / kSprings * kMu * kForce);
  const double reloaded =
      member(member(stage(r, "reload"), "end"), "tangential_force").get<double>();
  EXPECT_EQ(reloaded, loaded);  // the cycle closes on the loading curve's end (Masing)
}

TEST(ProgramExamples, PullOffAfterShearLetsTheGlueGoWhereThePapersPathDoes) {
  // docs/friction.md "Pull-off after shear": sheared to u = 1e-5 m (0.78 u_c) with d held, the
  // glue is whole with the stretch u on every spring, so without friction (mu = 0) the
  // retraction is the paper's path with u held: Fig. 3a's shorthand, answered here on the
  // continuum route at rtol 1e-10. At this u the glue lets go while the contact is still
  // pressed (the critical force is compressive) and nothing ever pulls: no peak adhesion. The
  // row's critical force within 3/N of the unsheared pull-off force (observed: 1.3/N), its
  // contact radius within one spacing. With the example's mu = 1, friction holds part of each
  // pressed spring's stretch, so the glue holds on further: its critical force lies below the
  // path's, still compressive.
  const json program = run_example("pull_off_after_shear", "--set friction.coefficient=0.0");
  const json with_friction = run_example("pull_off_after_shear");
  const auto path = mdrsim::test::run_mdrsim(
      "run scenes/fig3a_fixed_grips.toml --set loading.tangential.displacement=1e-5 --set "
      "'solver={method=\"continuum\"}' --set 'discretization={rtol=1e-10}' --json - "
      "--log-level off");
  ASSERT_EQ(path.exit_code, 0) << path.err;
  const json reference = json::parse(path.out, nullptr, false);
  ASSERT_TRUE(reference.is_object());
  EXPECT_EQ(member(program, "status"), "instability");
  EXPECT_EQ(member(reference, "status"), "instability");
  EXPECT_TRUE(member(program, "peak_adhesion").is_null());
  EXPECT_TRUE(member(reference, "peak_adhesion").is_null());
  const json critical = member(program, "critical");
  const json expected = member(reference, "critical");
  ASSERT_TRUE(critical.is_object() && expected.is_object());
  const double force = member(expected, "normal_force").get<double>();
  EXPECT_GT(force, 0.0);  // pressed: the glue lets go before the contact pulls
  constexpr double kRowSprings = 2000.0;
  const double unsheared = 2.356194490192345e-3;  // the path's pull-off force at u = 0 [N]
  EXPECT_NEAR(member(critical, "normal_force").get<double>(), force, 3.0 / kRowSprings * unsheared);
  const double glued_radius = 5.209397078678047e-4;
  EXPECT_NEAR(member(critical, "contact_radius").get<double>(),
              member(expected, "contact_radius").get<double>(), glued_radius / kRowSprings);
  const double held = member(member(with_friction, "critical"), "normal_force").get<double>();
  EXPECT_GT(held, 0.0);
  EXPECT_LT(held, force - 3.0 / kRowSprings * unsheared);
}
