// The Maugis-Dugdale spring row from scene text through run_scene against the continuum route of
// the same scene: rows converging at first order as their estimates say, Richardson and rtol
// meeting the continuum's numbers, and the same statuses.
#include "engine/accuracy/dugdale_rows.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/accuracy/row_sequence.hpp"
#include "engine/events/event_recorder.hpp"
#include "engine/output/trajectory_csv.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "tests/support/maugis_units.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

struct Case {
  std::string name;
  std::string material_and_profile;  ///< [material] and [profile] text
  double glued;                      ///< preload contact radius [m]
  bool grips;
  std::string normal = {};  ///< the [loading] normal table's content, where not grips or load
};

/// Maugis' parabola (R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2) at lambda, glued at three of
/// Maugis' lengths (every fold lies below it).
Case parabola(double lambda, bool grips) {
  const test::MaugisUnits u;
  return {fmt::format("parabola lambda {} {}", lambda, grips ? "grips" : "load"),
          fmt::format("[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
                      "maugis_parameter = {}\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n",
                      lambda),
          3.0 * u.length(), grips};
}

/// A cone of 10 degrees, sigma_0 = ratio E* tan(theta), glued at 0.1 mm.
Case cone(double ratio, bool grips) {
  return {fmt::format("cone {} {}", ratio, grips ? "grips" : "load"),
          fmt::format("[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
                      "adhesive_stress = {}\n[profile]\ntype = \"cone\"\nslope_angle_deg = 10.0\n",
                      ratio * 1e6 * std::tan(10.0 * kPi / 180.0)),
          1e-4, grips};
}

Case sphere(bool grips) {
  return {fmt::format("sphere lambda 1 {}", grips ? "grips" : "load"),
          "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\nmaugis_parameter = 1.0\n"
          "[profile]\ntype = \"sphere\"\nradius = 0.01\n",
          3.0 * test::MaugisUnits{}.length(), grips};
}

Case power_law(bool grips) {
  return {
      fmt::format("power law 0.8 r^1.5 {}", grips ? "grips" : "load"),
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\nadhesive_stress = 2.0e4\n"
      "[profile]\ntype = \"power_law\"\ncoefficient = 0.8\nexponent = 1.5\n",
      5e-4, grips};
}

std::string scene_text(const Case& c, const std::string& tail) {
  return fmt::format("{}[loading]\npreload = {{ contact_radius = {} }}\nnormal = {{ {} }}\n{}",
                     c.material_and_profile, c.glued,
                     c.normal.empty()
                         ? fmt::format("control = \"{}\"", c.grips ? "fixed-grips" : "fixed-load")
                         : c.normal,
                     tail);
}

RunResult run(const Case& c, const std::string& tail, const ObserverList& observers = {}) {
  return run_scene(test::build_scene_text(scene_text(c, tail)), observers);
}

RunResult continuum(const Case& c) {
  return run(c, "[solver]\nmethod = \"continuum\"\n");  // rtol 1e-10
}

RunResult one_row(const Case& c, std::int64_t springs) {
  return run(
      c, fmt::format("[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n", springs));
}

/// Profiles with the opening's integral J in closed form (parabola, cone): every let-go costs
/// O(1) evaluations of it.
std::vector<Case> closed_form_cases() {
  std::vector<Case> out;
  for (const bool grips : {true, false}) {
    for (const double lambda : {0.3, 1.0, 3.0}) out.push_back(parabola(lambda, grips));
    out.push_back(cone(1.0, grips));
  }
  out.push_back(cone(0.7, true));   // no jump: below pi/4
  out.push_back(cone(0.85, true));  // a jump: above it
  // A compliant machine (about a fifth of the contact's stiffness 2 E* a at the pull-off): its
  // work holds the machine spring's energy.
  Case compliant = parabola(1.0, true);
  compliant.name = "parabola lambda 1 compliant";
  compliant.normal = "control = \"compliant\", stiffness = 100.0";
  out.push_back(compliant);
  return out;
}

/// Profiles whose J is a series (the sphere's in (x/R)^2, the power law's in the zone's angle)
/// rather than a few elementary terms.
std::vector<Case> quadrature_cases() {
  return {sphere(true), sphere(false), power_law(true), power_law(false)};
}

/// The force the rows refine: the critical point's, or the peak's where there is none.
double force_of(const RunResult& r) {
  return r.critical ? r.critical->normal_force : r.peak->normal_force;
}

// Rows of 500 to 8000 springs: each row's error against the continuum route within its
// estimate (RowSequence's plain rule over the rows up to it) and not 100 times below it; the
// error falls at first order where it is not rounding (the rows equal the continuum exactly
// where the path ends on the no-contact branch, which has no springs).
void check_convergence(const std::vector<Case>& cases) {
  std::printf("%-28s %6s %12s %12s %8s\n", "case", "N", "row error", "estimate", "order");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const RunResult exact = continuum(c);
    const Target target = exact.critical ? Target::critical : Target::peak;
    RowSequence seq(target);
    double last_error = 0.0;
    for (const std::int64_t n : {500, 1000, 2000, 4000, 8000}) {
      RunResult row = one_row(c, n);
      ASSERT_EQ(row.status, exact.status);
      const double error = std::abs(force_of(row) - force_of(exact));
      seq.add(std::move(row));
      const auto estimate = seq.estimate(Accuracy::Route::row);
      const double order = last_error > 0.0 && error > 0.0 ? std::log2(last_error / error) : 0.0;
      std::printf("%-28s %6lld %12.3e %12.3e %8.3f\n", c.name.c_str(), static_cast<long long>(n),
                  error / std::abs(force_of(exact)),
                  estimate ? *estimate / std::abs(force_of(exact)) : 0.0, order);
      // Below 1e-11 of F the row is the continuum's branch in closed form (no-contact jumps).
      const bool resolved = error > 1e-11 * std::abs(force_of(exact));
      if (estimate) {
        EXPECT_GE(*estimate, error);
        if (resolved) {
          EXPECT_LE(*estimate, 100.0 * error);
        }
      }
      last_error = error;
    }
  }
}

// Richardson over 500, 1000, 2000 springs and rtol 1e-6 meet the continuum's critical force,
// peak and work within their estimates; rtol's estimates meet rtol.
void check_richardson_and_rtol(const std::vector<Case>& cases) {
  std::printf("%-28s %12s %12s | %12s %12s %12s\n", "case", "richardson", "estimate", "rtol 1e-6",
              "estimate", "work error");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const RunResult exact = continuum(c);
    const RunResult rich = run(c,
                               "[discretization]\nsprings = 1000\nextrapolation = \"richardson\"\n"
                               "[solver]\nmethod = \"event\"\n");
    const RunResult tol = run(c, "[discretization]\nrtol = 1e-6\n[solver]\nmethod = \"event\"\n");
    ASSERT_EQ(rich.status, exact.status);
    ASSERT_EQ(tol.status, exact.status);
    const double scale = std::abs(force_of(exact));
    const double rich_error = std::abs(force_of(rich) - force_of(exact));
    const double tol_error = std::abs(force_of(tol) - force_of(exact));
    const double rich_estimate = exact.critical ? *rich.accuracy.critical_error_estimate
                                                : *rich.accuracy.peak_error_estimate;
    const double tol_estimate =
        exact.critical ? *tol.accuracy.critical_error_estimate : *tol.accuracy.peak_error_estimate;
    const double work_error = std::abs(tol.work->normal - exact.work->normal);
    std::printf("%-28s %12.3e %12.3e | %12.3e %12.3e %12.3e\n", c.name.c_str(), rich_error / scale,
                rich_estimate / scale, tol_error / scale, tol_estimate / scale,
                work_error / std::abs(exact.work->normal));
    EXPECT_GE(rich_estimate, rich_error);
    EXPECT_TRUE(tol.accuracy.rtol_met);
    EXPECT_LE(tol_error, 1e-6 * scale);
    EXPECT_GE(tol_estimate, tol_error);
    EXPECT_LE(std::abs(tol.peak->normal_force - exact.peak->normal_force),
              *tol.accuracy.peak_error_estimate);
    EXPECT_LE(work_error, tol.accuracy.work_error_estimate->normal);
    EXPECT_LE(work_error, 1e-6 * std::abs(exact.work->normal));
  }
}

TEST(DugdaleRows, RowsConvergeToTheContinuumAsTheirEstimatesSay) {
  check_convergence(closed_form_cases());
}
TEST(DugdaleRows, RowsConvergeOnQuadratureProfiles) { check_convergence(quadrature_cases()); }

TEST(DugdaleRows, RichardsonAndRtolMeetTheContinuum) {
  check_richardson_and_rtol(closed_form_cases());
}
TEST(DugdaleRows, RichardsonAndRtolMeetTheContinuumOnQuadratureProfiles) {
  check_richardson_and_rtol(quadrature_cases());
}

// The row's JSON-facing result is the continuum run's in shape: the preload state at a_p, the
// three stages, the jump, the route and the trajectory's cohesive_radius column.
TEST(DugdaleRows, ResultsHaveTheContinuumsShape) {
  const Case c = parabola(1.0, false);
  const RunResult exact = continuum(c);
  std::ostringstream csv;
  TrajectoryCsvWriter writer(csv, false, true);
  ObserverList observers;
  observers.add(writer);
  const RunResult row =
      run(c, "[discretization]\nsprings = 200\n[solver]\nmethod = \"event\"\n", observers);
  ASSERT_EQ(row.stages.size(), 3U);
  EXPECT_EQ(row.stages[0].name, "preload");
  // The preload state is the branch's at the preload depth: the continuum's a_p and d_p.
  EXPECT_NEAR(row.stages[0].end.contact_radius, exact.stages[0].end.contact_radius,
              1e-12 * exact.stages[0].end.contact_radius);
  EXPECT_NEAR(row.stages[0].end.indentation, exact.stages[0].end.indentation,
              1e-9 * std::abs(exact.stages[0].end.indentation));
  EXPECT_GT(row.stages[0].end.cohesive_radius, row.stages[0].end.contact_radius);
  ASSERT_EQ(row.jumps.size(), 1U);
  EXPECT_EQ(row.counts.events, 200 - row.critical->springs_in_contact + 1);
  EXPECT_EQ(row.springs, 200);
  const std::string text = csv.str();
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "stage,event,in_cascade,indentation,normal_force,contact_radius,"
            "tangential_displacement,tangential_force,springs_in_contact,cohesive_radius");
  EXPECT_NE(text.find("\npreload,preload,0,"), std::string::npos);
  EXPECT_NE(text.find("\npull-off,detached,0,"), std::string::npos);
}

// solver.max_events as on the JKR row: the run stops at that many let-gos with step-limit,
// the limit named, no critical point, and the pull-off stage ending at the last let-go, which
// is the unlimited row's own state there (the same let-go, to the bit); the rtol and
// Richardson drivers return that row as the JKR rows return their pilot.
TEST(DugdaleRows, MaxEventsStopsTheRowAsOnTheJkrRow) {
  const Case c = parabola(1.0, true);
  const std::string limit = "[solver]\nmethod = \"event\"\nmax_events = 10\n";
  EventRecorder recorder;
  ObserverList observers;
  observers.add(recorder);
  const RunResult free =
      run(c, "[discretization]\nsprings = 200\n[solver]\nmethod = \"event\"\n", observers);
  ASSERT_GT(free.counts.events, 10);
  const Event* tenth = nullptr;  // the unlimited row's tenth let-go
  for (const Event& e : recorder.events()) {
    if (e.kind == EventKind::spring_detached && e.state.springs_in_contact == 200 - 10 + 1) {
      tenth = &e;
    }
  }
  ASSERT_NE(tenth, nullptr);
  const RunResult stopped = run(c, "[discretization]\nsprings = 200\n" + limit);
  EXPECT_EQ(stopped.status, RunStatus::step_limit);
  ASSERT_TRUE(stopped.stop_reason.has_value());
  EXPECT_EQ(*stopped.stop_reason, StopReason::max_events);
  EXPECT_EQ(stopped.counts.events, 10);
  EXPECT_FALSE(stopped.critical.has_value());
  EXPECT_TRUE(stopped.jumps.empty());
  ASSERT_EQ(stopped.stages.size(), 3U);
  const ContactSnapshot& end = stopped.stages[2].end;
  EXPECT_EQ(end.springs_in_contact, 200 - 10 + 1);
  EXPECT_EQ(end.normal_force, tenth->state.normal_force);
  EXPECT_EQ(end.indentation, tenth->state.indentation);
  EXPECT_EQ(end.cohesive_radius, tenth->state.cohesive_radius);
  ASSERT_FALSE(stopped.warnings.empty());
  EXPECT_EQ(stopped.warnings.back(),
            "the row reached solver.max_events = 10 before the contact was lost: there is no "
            "critical point");
  for (const char* driver : {"rtol = 1e-6\n", "springs = 200\nextrapolation = \"richardson\"\n"}) {
    SCOPED_TRACE(driver);
    const RunResult r = run(c, std::string("[discretization]\n") + driver + limit);
    EXPECT_EQ(r.status, RunStatus::step_limit);
    EXPECT_EQ(r.counts.events, 10);
    EXPECT_FALSE(r.critical.has_value());
  }
}

}  // namespace
}  // namespace mdrsim
