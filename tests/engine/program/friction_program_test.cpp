// Programs with Coulomb friction: Cattaneo-Mindlin loading, Mindlin-Deresiewicz unloading and
// reloading and the loop energy against the closed forms, the slip events, the glue that lets
// go into sliding, and mu = 0 as the frictionless run.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/output/trajectory_csv.hpp"
#include "engine/reference/friction_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "profiles/parabolic_profile.hpp"

namespace mdrsim {
namespace {

using friction_reference::CattaneoMindlin;

// E* = G* = 1 MPa (nu = 0), R = 1 cm, mu = 0.5, pressed to d = 4 um: a = 2e-4 m.
constexpr double kModulus = 1e6;
constexpr double kRadius = 0.01;
constexpr double kMu = 0.5;
constexpr double kDepth = 4e-6;
constexpr int kPoints = 4;  // stage ends per branch

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "scene.toml").build(registries);
}

std::string header(double work_of_adhesion) {
  return fmt::format(R"(
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = {}
[profile]
type = "parabolic"
radius = 0.01
)",
                     work_of_adhesion);
}

std::string stage(const std::string& name, const std::string& axes) {
  return fmt::format("[[loading.stage]]\nname = \"{}\"\n{}\n", name, axes);
}

/// Pressed to kDepth (fixed grips), then u_x to u_m in kPoints stages, down to -u_m and back up
/// to u_m in 2 kPoints stages each: a fretting cycle with its branches sampled at stage ends.
std::string fretting(double amplitude, std::int64_t springs, double mu) {
  std::string text = header(0.0);
  text += stage("press", fmt::format("normal = {{ control = \"fixed-grips\", to = {} }}", kDepth));
  for (int i = 1; i <= kPoints; ++i) {
    text += stage(fmt::format("load-{}", i),
                  fmt::format("tangential = {{ by = {} }}", amplitude / kPoints));
  }
  for (const char* branch : {"unload", "reload"}) {
    const double sign = std::string(branch) == "unload" ? -1.0 : 1.0;
    for (int i = 1; i <= 2 * kPoints; ++i) {
      text += stage(fmt::format("{}-{}", branch, i),
                    fmt::format("tangential = {{ by = {} }}", sign * amplitude / kPoints));
    }
  }
  text +=
      fmt::format("[friction]\ncoefficient = {}\n[discretization]\nsprings = {}\n", mu, springs);
  return text;
}

/// An event kept past its run: Event::stage views the scene's stage name, which goes with the
/// scene, so the name is copied.
struct KeptEvent {
  Event event;
  std::string stage;
};

struct Counter final : Observer {
  std::vector<KeptEvent> events;
  void on_event(const Event& e) override {
    if (e.kind == EventKind::spring_slipped || e.kind == EventKind::spring_stuck) {
      events.push_back({e, std::string(e.stage)});
    }
  }
};

struct Fretting {
  RunResult result;
  Counter slips;
};

Fretting run_fretting(double amplitude, std::int64_t springs) {
  Fretting f;
  ObserverList observers;
  observers.add(f.slips);
  f.result = run_scene(build(fretting(amplitude, springs, kMu)), observers);
  return f;
}

const CattaneoMindlin& closed_form() {
  static const ParabolicProfile profile(kRadius);
  static const CattaneoMindlin cm(profile, kModulus, kModulus, kMu, kDepth);
  return cm;
}

/// The largest error of the stage ends against the branches, over mu E* d dx: a sum over springs
/// at x_i = i dx of a monotone line load differs from its integral by at most dx times the
/// load's variation, mu E* d per half (friction_row_test.cpp), and the row's outermost spring
/// sits within dx of a: 2 dx mu E* d for the two halves, 4 for both causes together.
double branch_error(const RunResult& r, double amplitude, std::int64_t springs) {
  const CattaneoMindlin& cm = closed_form();
  const double dx = cm.contact_radius() / static_cast<double>(springs);
  double worst = 0.0;
  for (const StageRecord& s : r.stages) {
    const double u = s.end.tangential_displacement;
    double expected = 0.0;
    if (s.name.starts_with("load")) expected = cm.loading_force(u);
    if (s.name.starts_with("unload")) expected = cm.unloading_force(amplitude, u);
    if (s.name.starts_with("reload")) expected = cm.reloading_force(amplitude, u);
    worst = std::max(worst,
                     std::abs(s.end.tangential_force - expected) / (kMu * kModulus * kDepth * dx));
  }
  return worst;
}

TEST(FrictionProgram, FrettingCycleFollowsCattaneoMindlinAndMindlinDeresiewicz) {
  const double amplitude = 0.6 * closed_form().full_slip();
  const Fretting f = run_fretting(amplitude, 400);
  ASSERT_EQ(f.result.status, RunStatus::completed);
  ASSERT_EQ(f.result.stages.size(), 1u + 5u * kPoints);
  EXPECT_LT(branch_error(f.result, amplitude, 400), 4.0);
  EXPECT_LT(branch_error(run_fretting(amplitude, 800).result, amplitude, 800), 4.0);

  // The stick radius at the end of loading: within one spacing of c = a sqrt(1 - u/u*) (the
  // innermost sliding spring's inner neighbour; plus dx for the row's own a).
  const CattaneoMindlin& cm = closed_form();
  const double dx = cm.contact_radius() / 400.0;
  const StageRecord& loaded = f.result.stages[kPoints];
  EXPECT_NEAR(loaded.end.stick_radius, cm.stick_radius(amplitude), 2.0 * dx);
  EXPECT_GT(loaded.end.springs_sliding, 0);
  EXPECT_LT(loaded.end.springs_sliding, loaded.end.springs_in_contact);
}

TEST(FrictionProgram, SlipEventsOncePerSlidingSpringOnLoading) {
  const double amplitude = 0.6 * closed_form().full_slip();
  const Fretting f = run_fretting(amplitude, 400);
  std::int64_t loading_slips = 0;
  std::int64_t unloading_sticks = 0;
  for (const auto& [e, stage] : f.slips.events) {
    if (stage.starts_with("load") && e.kind == EventKind::spring_slipped) ++loading_slips;
    if (stage == "unload-1" && e.kind == EventKind::spring_stuck) ++unloading_sticks;
  }
  // On loading each spring outside c slips once and slides on; on reversal they all stick.
  const std::int64_t sliding = f.result.stages[kPoints].end.springs_sliding;
  EXPECT_EQ(loading_slips, sliding);
  EXPECT_EQ(unloading_sticks, sliding);
}

TEST(FrictionProgram, LoopEnergyIsTheClosedFormAndTheMachineWork) {
  const double amplitude = 0.6 * closed_form().full_slip();
  const double closed = closed_form().loop_energy(amplitude);
  double previous_error = 0.0;
  for (const std::int64_t springs : {400, 800}) {
    const RunResult r = run_fretting(amplitude, springs).result;
    double work = 0.0;
    double dissipated = 0.0;
    for (const StageRecord& s : r.stages) {
      if (s.name.starts_with("load") || s.name == "press") continue;
      work += s.work.tangential;
      dissipated += s.work.friction;
    }
    // Over the closed cycle every spring returns to its state: the machine's work is what
    // friction dissipated, to rounding (some 10^3 trapezoids of 1e-16 each).
    EXPECT_NEAR(work, dissipated, 1e-12 * closed);
    // Against W within 4 dx G* u_m^2 (friction_row_test.cpp: each spring's 4 l (u_m - l/G*) is a
    // line load of variation G* u_m^2, summed at x_i = i dx on both halves over two branches).
    const double dx = closed_form().contact_radius() / static_cast<double>(springs);
    const double error = std::abs(dissipated - closed);
    EXPECT_LT(error, 4.0 * dx * kModulus * amplitude * amplitude) << springs;
    // It falls with dx (here faster than first order: the row's end and the sums' errors
    // partly cancel).
    if (previous_error > 0.0) {
      EXPECT_LT(error, 0.6 * previous_error) << springs;
    }
    std::printf("loop energy, %lld springs: relative error %.3g, bound %.3g\n",
                static_cast<long long>(springs), error / closed,
                4.0 * dx * kModulus * amplitude * amplitude / closed);
    previous_error = error;
    EXPECT_NEAR(r.work->friction,
                dissipated + r.stages[1].work.friction + r.stages[2].work.friction +
                    r.stages[3].work.friction + r.stages[4].work.friction,
                1e-12 * closed);
  }
}

TEST(FrictionProgram, ZeroCoefficientIsTheFrictionlessRunBitForBit) {
  const double amplitude = 0.6 * closed_form().full_slip();
  const RunResult with = run_scene(build(fretting(amplitude, 200, 0.0)), {});
  std::string text = fretting(amplitude, 200, 0.0);
  text.replace(text.find("[friction]\ncoefficient = 0\n"),
               std::string("[friction]\ncoefficient = 0\n").size(), "");
  const RunResult without = run_scene(build(text), {});
  ASSERT_EQ(with.stages.size(), without.stages.size());
  for (std::size_t i = 0; i < with.stages.size(); ++i) {
    EXPECT_EQ(with.stages[i].end.tangential_force, without.stages[i].end.tangential_force);
    EXPECT_EQ(with.stages[i].end.normal_force, without.stages[i].end.normal_force);
    EXPECT_EQ(with.stages[i].work.tangential, without.stages[i].work.tangential);
    EXPECT_EQ(with.stages[i].work.friction, 0.0);
  }
}

TEST(FrictionProgram, GlueThatLetsGoUnderShearSlidesAtMuFz) {
  // An adhesive contact glued on touch to 3 um, pressed, then sheared far beyond the glue's
  // strength under fixed grips: the boundary lets go spring by spring, each keeping its
  // stretch and slipping to its limit; at the end every spring in contact slides and
  // F_x = mu F_z, a sum of mu k_z (d - g_i) over the same springs as F_z: to rounding.
  std::string text = header(0.05);
  text += stage("press", "normal = { control = \"fixed-grips\", to = 3.0e-6 }");
  text += stage("shear", "tangential = { control = \"fixed-grips\", by = 2.0e-4 }");
  text += "[friction]\ncoefficient = 0.3\n[discretization]\nsprings = 500\n";
  const RunResult r = run_scene(build(text), {});
  ASSERT_EQ(r.stages.size(), 2u);
  const ContactSnapshot& end = r.stages[1].end;
  ASSERT_GT(end.springs_in_contact, 0);
  EXPECT_EQ(end.springs_sliding, end.springs_in_contact);
  EXPECT_NEAR(end.tangential_force, 0.3 * end.normal_force, 1e-12 * end.normal_force);
  EXPECT_EQ(end.stick_radius, 0.0);
  // Friction dissipated energy, and no more than the machine put in.
  EXPECT_GT(r.stages[1].work.friction, 0.0);
  EXPECT_LE(r.stages[1].work.friction, r.stages[1].work.tangential);
}

TEST(FrictionProgram, TrajectoryHasTheSlidingColumnAndTheSlipAndStickRows) {
  const double amplitude = 0.6 * closed_form().full_slip();
  std::ostringstream csv;
  TrajectoryCsvWriter writer(csv, true);
  ObserverList observers;
  observers.add(writer);
  const RunResult r = run_scene(build(fretting(amplitude, 100, kMu)), observers);
  std::istringstream in(csv.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "stage,event,in_cascade,indentation,normal_force,contact_radius,"
            "tangential_displacement,tangential_force,springs_in_contact,sliding");
  std::int64_t slips = 0;
  std::int64_t sticks = 0;
  std::string loaded_end;
  while (std::getline(in, line)) {
    if (line.find(",slip,") != std::string::npos) ++slips;
    if (line.find(",stick,") != std::string::npos) ++sticks;
    if (line.starts_with(fmt::format("load-{},stage-end,", kPoints))) loaded_end = line;
  }
  EXPECT_GT(slips, 0);
  EXPECT_GT(sticks, 0);
  // The last column of the loaded stage's end is its springs_sliding.
  const std::int64_t sliding = r.stages[kPoints].end.springs_sliding;
  EXPECT_TRUE(loaded_end.ends_with(fmt::format(",{}", sliding))) << loaded_end;
}

TEST(FrictionProgram, HeldTangentialForceFollowsCattaneoMindlinThenSlidesAway) {
  // Pressed to kDepth, then F_x ramped under a fixed tangential load in kPoints stages to 0.9 of
  // mu F_z and on past mu F_z: u_x at each stage end on the loading curve (its F_x(u) within
  // branch_error's 4 dx mu E* d of the held force), then gross sliding where every spring slides:
  // shear-off with "sliding", at F_x = mu F_z of the row (a sum over the same springs as F_z).
  const CattaneoMindlin& cm = closed_form();
  const double limit = kMu * cm.normal_force();
  std::string text = header(0.0);
  text += stage("press", fmt::format("normal = {{ control = \"fixed-grips\", to = {} }}", kDepth));
  for (int i = 1; i <= kPoints; ++i) {
    text += stage(
        fmt::format("load-{}", i),
        fmt::format("tangential = {{ control = \"fixed-load\", by = {} }}", 0.9 * limit / kPoints));
  }
  // Unpressed a little at the held F_x: the sliding springs' mu f_z falls, so u_x moves on.
  text += stage("unpress", fmt::format("normal = {{ by = {} }}", -0.05 * kDepth));
  text += stage("slide", fmt::format("tangential = {{ by = {} }}", 0.5 * limit));
  text += fmt::format("[friction]\ncoefficient = {}\n[discretization]\nsprings = 400\n", kMu);
  const RunResult r = run_scene(build(text), {});
  const double dx = cm.contact_radius() / 400.0;
  for (int i = 1; i <= kPoints; ++i) {
    const ContactSnapshot& end = r.stages[static_cast<std::size_t>(i)].end;
    EXPECT_NEAR(end.tangential_force, 0.9 * limit * i / kPoints, 1e-12 * limit);
    EXPECT_NEAR(cm.loading_force(end.tangential_displacement), end.tangential_force,
                4.0 * kMu * kModulus * kDepth * dx)
        << i;
  }
  // At a constant F_x the machine's tangential work is F_x times the way u_x went.
  const StageRecord& loaded = r.stages[kPoints];
  const StageRecord& unpressed = r.stages[kPoints + 1];
  const double moved = unpressed.end.tangential_displacement - loaded.end.tangential_displacement;
  EXPECT_GT(moved, 0.0);
  EXPECT_NEAR(unpressed.work.tangential, loaded.end.tangential_force * moved,
              1e-12 * std::abs(loaded.end.tangential_force * moved));
  EXPECT_EQ(r.status, RunStatus::shear_off);
  EXPECT_TRUE(r.sliding);
  ASSERT_TRUE(r.critical);
  EXPECT_EQ(r.critical->springs_sliding, r.critical->springs_in_contact);
  EXPECT_NEAR(r.critical->tangential_force, kMu * r.critical->normal_force,
              1e-12 * r.critical->normal_force);
}

TEST(FrictionProgram, NoEnergyAppearsOrVanishesUncountedWhenTheGlueLetsGo) {
  // An adhesive contact glued on touch to d = 5 um (a = sqrt(R d), spring N at a), sheared
  // until the whole glued contact lets go in one jump at u_c, moved back, then pulled off. Each
  // spring keeps its stretch as its glue lets go and slips to its limit: the glue releases
  // (k_x u_c - mu k_z (d - g_i))^2 / (2 k_x) of each spring above its limit, friction
  // dissipates the rest, and nothing is stored at the end. So the machine's work is the
  // glue's release (summed here by hand over the springs) plus dissipated_by_friction, to
  // rounding (some thousand trapezoids and sums: 1e-12 of the total).
  constexpr double mu = 0.4;
  constexpr double depth = 5e-6;
  constexpr std::int64_t springs = 500;
  std::string text = header(0.05);
  text += stage("press", fmt::format("normal = {{ control = \"fixed-grips\", to = {} }}", depth));
  text += stage("shear", "tangential = { control = \"fixed-grips\", by = 1.0e-5 }");
  text += stage("back", "tangential = { by = -0.5e-5 }");
  text +=
      stage("pull", "normal = { control = \"fixed-load\", by = -1.0e-2 }\nuntil = \"separation\"");
  text +=
      fmt::format("[friction]\ncoefficient = {}\n[discretization]\nsprings = {}\n", mu, springs);
  const RunResult r = run_scene(build(text), {});
  ASSERT_EQ(r.jumps.size(), 1u);  // the shear's let-go of the whole glued contact
  EXPECT_EQ(r.jumps.front().stage, "shear");
  EXPECT_EQ(r.stages.back().end.normal_force, 0.0);
  const double u = r.jumps.front().critical.tangential_displacement;
  const double a = std::sqrt(kRadius * depth);
  const double dx = a / static_cast<double>(springs);
  double released = 0.0;
  for (std::int64_t i = 1; i <= springs; ++i) {
    const double x = i == springs ? a : dx * static_cast<double>(i);
    const double excess = kModulus * dx * u - mu * kModulus * dx * (depth - x * x / kRadius);
    if (excess > 0.0) released += 2.0 * excess * excess / (2.0 * kModulus * dx);
  }
  ASSERT_TRUE(r.work);
  EXPECT_GT(r.work->friction, 0.0);
  EXPECT_NEAR(r.work->normal + r.work->tangential, released + r.work->friction,
              1e-12 * (released + r.work->friction));
}

struct SpringEvents final : Observer {
  std::vector<KeptEvent> events;
  void on_event(const Event& e) override {
    if (e.kind == EventKind::spring_slipped || e.kind == EventKind::spring_stuck ||
        e.kind == EventKind::spring_glued || e.kind == EventKind::spring_detached) {
      events.push_back({e, std::string(e.stage)});
    }
  }
};

TEST(FrictionProgram, WithRebindingASlidingSpringGluesOnceItSticksKeepingItsStretch) {
  // Glued on touch, sheared until the whole glued contact lets go (every spring then slides
  // under friction), then moved back: each slide reverses, each spring sticks and, with
  // rebinding, glues again at once keeping its stretch. So at the reversal no spring glues
  // before its stick, and F_x does not change as they glue (to rounding: a sum over 300
  // springs); the stretches then carry the glued contact back with 2 G* a of stiffness. Pulled
  // off under fixed grips, the boundary spring k lets go where its elongation and its kept
  // stretch s_k = mu (E*/G*) (d0 - g_k) - 5 um (its limit's stretch at the reversal, moved back)
  // meet the criterion, E* (g_k - d)^2 + G* s_k^2 = 2 pi x_k dgamma (paper eq. 20): to rounding,
  // where a glue at zero stretch would miss by up to 1e-2 d0.
  std::string text = header(0.05);
  text += "[loading]\nrebinding = true\n";
  text += stage("press", "normal = { control = \"fixed-grips\", to = 5.0e-6 }");
  text += stage("shear", "tangential = { control = \"fixed-grips\", by = 1.0e-5 }");
  text += stage("back", "tangential = { by = -0.5e-5 }");
  text += stage("pull", "normal = { by = -1.0e-5 }\nuntil = \"separation\"");
  text += "[friction]\ncoefficient = 0.4\n[discretization]\nsprings = 300\n";
  SpringEvents seen;
  ObserverList observers;
  observers.add(seen);
  const RunResult r = run_scene(build(text), observers);
  ASSERT_EQ(r.stages.size(), 4u);
  const ContactSnapshot& sheared = r.stages[1].end;
  ASSERT_EQ(sheared.springs_sliding, 300);
  std::vector<bool> stuck(301, false);
  int glued = 0;
  for (const auto& [e, stage] : seen.events) {
    if (stage != "back") continue;
    if (e.kind == EventKind::spring_stuck) stuck[static_cast<std::size_t>(e.spring)] = true;
    if (e.kind != EventKind::spring_glued) continue;
    ++glued;
    EXPECT_TRUE(stuck[static_cast<std::size_t>(e.spring)]) << "spring " << e.spring;
    EXPECT_NEAR(e.state.tangential_force, sheared.tangential_force,
                1e-12 * std::abs(sheared.tangential_force));
  }
  EXPECT_EQ(glued, 300);
  const double a = std::sqrt(kRadius * 5e-6);
  int checked = 0;
  for (const auto& [e, stage] : seen.events) {
    if (stage != "pull" || e.kind != EventKind::spring_detached || e.in_cascade) continue;
    const double x = e.spring == 300 ? a : a * static_cast<double>(e.spring) / 300.0;
    const double g = x * x / kRadius;
    const double stretch = 0.4 * (5e-6 - g) - 0.5e-5;
    const double expected =
        g -
        std::sqrt((2.0 * std::numbers::pi * x * 0.05 - kModulus * stretch * stretch) / kModulus);
    EXPECT_NEAR(e.state.indentation, expected, 1e-9 * 5e-6) << "spring " << e.spring;
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_NEAR(r.stages[2].end.tangential_force,
              sheared.tangential_force - 2.0 * kModulus * a * 0.5e-5,
              1e-9 * std::abs(sheared.tangential_force));
}

TEST(FrictionProgram, RtolSaysWhichStatesAreTheFinestRows) {
  const double amplitude = 0.6 * closed_form().full_slip();
  std::string text = fretting(amplitude, 200, kMu);
  text.replace(text.find("springs = 200"), std::string("springs = 200").size(), "rtol = 1e-3");
  const RunResult r = run_scene(build(text), {});
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.back(),
            fmt::format("friction: springs_sliding, stick_radius and dissipated_by_friction are "
                        "the finest row's ({} springs), not covered by rtol's estimates",
                        r.springs));
  // rtol's estimate covers F_x at the stage ends: the loaded end is on Cattaneo-Mindlin within it
  // (and the row's O(dx) bound of branch_error).
  const StageRecord& loaded = r.stages[kPoints];
  ASSERT_TRUE(loaded.tangential_force_error_estimate);
  const double dx = closed_form().contact_radius() / static_cast<double>(r.springs);
  EXPECT_NEAR(loaded.end.tangential_force, closed_form().loading_force(amplitude),
              *loaded.tangential_force_error_estimate + 4.0 * kMu * kModulus * kDepth * dx);
}

}  // namespace
}  // namespace mdrsim
