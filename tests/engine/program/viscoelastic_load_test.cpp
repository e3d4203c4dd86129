// Viscoelastic stages under a fixed load and a machine spring, run by `mdrsim run`'s path, against
// Lee-Radok's hereditary integral for a growing contact derived here (no engine code): creep of a
// parabola under a load stepped on and held and under a ramp, the relaxation of a fixed-grips
// hold after the creep, and a machine spring's Volterra equation solved on a fine grid; the
// energy balance of every stage.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

// ---- The references -------------------------------------------------------------------------
//
// A standard linear solid in plane strain, E*(t) = E_inf + E_1 exp(-t / tau). Its creep
// compliance J (the strain under a unit stress step, int_0^t E(t - u) dJ(u) = 1): with Laplace
// transforms s J^(s) = 1 / (s E^(s)) = (s tau + 1) / (E_0 s tau + E_inf), E_0 = E_inf + E_1, so
//   J(t) = 1 / E_inf - (1 / E_inf - 1 / E_0) exp(-t / tau_c),  tau_c = tau E_0 / E_inf,
// 1 / E_0 at once (glassy) and 1 / E_inf at long times (relaxed).
//
// A parabola f = r^2 / (2R) whose contact radius a(t) only grows (Lee and Radok 1960): the
// elastic solution holds with the elastic modulus replaced by the hereditary operator, so with
// Hertz's F = 4 E a^3 / (3 R), d = a^2 / R,
//   a(t)^3 = (3 R / 4) Phi(t),  Phi(t) = int_0^t J(t - u) dF(u),
// and conversely F(t) = int_0^t E(t - u) dP(u) with P = 4 a^3 / (3 R) = Phi.
// Limits: tau -> 0 gives Hertz with E_inf, tau -> infinity Hertz with E_0 (checked below).
struct Solid {
  double relaxed;  // E_inf [Pa]
  double arm;      // E_1 [Pa]
  double time;     // tau [s]
  double glassy() const { return relaxed + arm; }
  double retardation_time() const { return time * glassy() / relaxed; }
  double compliance(double t) const {
    return 1.0 / relaxed - (1.0 / relaxed - 1.0 / glassy()) * std::exp(-t / retardation_time());
  }
  double modulus(double t) const { return relaxed + arm * std::exp(-t / time); }
  /// int_0^m J(t - u) du; the difference of exponentials by expm1 (a slow arm's m / tau_c is
  /// tiny).
  double compliance_integral(double t, double m) const {
    const double tc = retardation_time();
    return m / relaxed -
           (1.0 / relaxed - 1.0 / glassy()) * tc * std::exp(-(t - m) / tc) * -std::expm1(-m / tc);
  }
};

/// F(u) = F0 min(u / t_r, 1): Phi(t) = (F0 / t_r) int_0^min(t, t_r) J(t - u) du.
double ramp_hold_phi(const Solid& solid, double f0, double ramp, double t) {
  return f0 / ramp * solid.compliance_integral(t, std::min(t, ramp));
}

double depth_of_phi(double radius, double phi) {
  return std::pow(0.75 * radius * phi, 2.0 / 3.0) / radius;
}

/// The force after a ramp-and-hold of F0 until t_h, the depth then held (fixed grips): the contact
/// no longer grows (each spring's stretch stays and its load stays positive), so F(t) = int_0^t_h
/// E(t - s) P'(s) ds with P' = (F0 / t_r) J(s) while s < t_r and (F0 / t_r) (J(s) - J(s - t_r))
/// after (d/ds int_0^min(s,t_r) J(s - u) du). Simpson's rule on each smooth piece, 4000 panels:
/// error near 1e-13. At t = t_h it is F0 (int E dJ = 1): checked below.
double relaxing_force(const Solid& solid, double f0, double ramp, double hold_end, double t) {
  const auto simpson = [&](double lo, double hi, auto fn) {
    const int panels = 4000;
    const double h = (hi - lo) / panels;
    double sum = 0.0;
    for (int i = 0; i <= panels; ++i) {
      sum += fn(lo + h * i) * (i == 0 || i == panels ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    return sum * h / 3.0;
  };
  const double rate = f0 / ramp;
  return simpson(0.0, ramp,
                 [&](double s) { return solid.modulus(t - s) * rate * solid.compliance(s); }) +
         simpson(ramp, hold_end, [&](double s) {
           return solid.modulus(t - s) * rate * (solid.compliance(s) - solid.compliance(s - ramp));
         });
}

/// A machine spring of stiffness k whose end moves at V from the apex's touch: F = k (V t - d),
/// d = (3 R Phi / 4)^(2/3) / R, Phi = int J(t - u) dF(u) (F grows, and so does the contact).
/// On a grid of `steps` steps, Phi(t_n) = sum_m J(t_n - t_(m - 1/2)) (F_m - F_(m-1)) (the
/// midpoint rule, second order) and F_n solves F_n = k (V t_n - d(Phi_n)) by bisection (the
/// right side falls as F_n grows). Returns F at every grid time.
std::vector<double> machine_spring_forces(const Solid& solid, double radius, double stiffness,
                                          double speed, double span, int steps) {
  const double h = span / steps;
  std::vector<double> f(steps + 1, 0.0);
  for (int n = 1; n <= steps; ++n) {
    double known = 0.0;
    for (int m = 1; m < n; ++m) known += solid.compliance(h * (n - m + 0.5)) * (f[m] - f[m - 1]);
    const double newest = solid.compliance(0.5 * h);
    const auto excess = [&](double force) {
      const double phi = known + newest * (force - f[n - 1]);
      return force - stiffness * (speed * h * n - depth_of_phi(radius, std::max(phi, 0.0)));
    };
    double lo = f[n - 1], hi = std::max(2.0 * f[n - 1], 1e-12);
    while (excess(hi) < 0.0) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (excess(mid) < 0.0 ? lo : hi) = mid;
    }
    f[n] = 0.5 * (lo + hi);
  }
  return f;
}

// ---- The runs -------------------------------------------------------------------------------

const Solid kSolid{1.0e6, 9.0e6, 0.1};  // the scene's, plane strain
constexpr double kRadius = 0.01;
constexpr double kLoad = 0.05;
constexpr double kStepTime = 0.001;
constexpr double kCreepEnd = 2.001;
constexpr double kRelaxEnd = 2.501;

std::string creep_scene_text() {
  std::ifstream in(std::string(MDRSIM_SOURCE_DIR) + "/scenes/viscoelastic/creep_parabola.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced_text(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

class TouchRecorder : public Observer {
 public:
  void on_event(const Event& e) override {
    if (e.kind == EventKind::spring_touched || e.kind == EventKind::spring_lifted) {
      states.push_back(e.state);
      stages.emplace_back(e.stage);
    }
  }
  std::vector<ContactSnapshot> states;
  std::vector<std::string> stages;
};

struct LoadRun {
  RunResult result;
  TouchRecorder events;
};

LoadRun run_load_text(const std::string& text) {
  LoadRun run;
  const Scene scene = SceneDocument::from_text(text, "load.toml").build(Registries::builtin());
  ObserverList observers;
  observers.add(run.events);
  run.result = run_scene(scene, observers);
  return run;
}

void expect_balanced_stages(const RunResult& r) {
  // Rounding of sums over the springs of terms of the size of the energy they hold: 1e-12 of the
  // largest stage's work or stored change.
  double scale = 0.0;
  for (const StageRecord& stage : r.stages) {
    scale = std::max({scale, std::abs(stage.energy->machine_work),
                      std::abs(stage.energy->stored_change), stage.energy->dissipated_by_bulk});
  }
  for (const StageRecord& stage : r.stages) {
    ASSERT_TRUE(stage.energy.has_value());
    const EnergyBalance& e = *stage.energy;
    EXPECT_EQ(e.machine_work, stage.work.normal) << stage.name;
    EXPECT_NEAR(e.machine_work, e.stored_change + e.dissipated_by_bulk, 1e-12 * scale)
        << stage.name;
  }
}

// The references at their limits: a very fast arm is Hertz with E_inf, a very slow one Hertz
// with E_0 (to 1e-6: the arms' exp(-t / tau) left over), and the relaxing force starts at F0.
TEST(ViscoelasticLoad, ReferencesMeetTheirElasticLimits) {
  const auto hertz_depth = [](double modulus, double force) {
    return std::pow(3.0 * kRadius * force / (4.0 * modulus), 2.0 / 3.0) / kRadius;
  };
  const Solid fast{1.0e6, 9.0e6, 1e-9};
  const Solid slow{1.0e6, 9.0e6, 1e9};
  EXPECT_NEAR(depth_of_phi(kRadius, ramp_hold_phi(fast, kLoad, kStepTime, 0.5)),
              hertz_depth(1.0e6, kLoad), 1e-6 * hertz_depth(1.0e6, kLoad));
  EXPECT_NEAR(depth_of_phi(kRadius, ramp_hold_phi(slow, kLoad, kStepTime, 0.5)),
              hertz_depth(1.0e7, kLoad), 1e-6 * hertz_depth(1.0e7, kLoad));
  EXPECT_NEAR(relaxing_force(kSolid, kLoad, kStepTime, kCreepEnd, kCreepEnd), kLoad, 1e-9 * kLoad);
}

struct CreepErrors {
  double depth;  // largest |d - d_ref| at a touch, over d_ref at the creep's end
  double force;  // |F - F_ref| at the relaxation's end, over F0
};

CreepErrors creep_errors(std::int64_t n) {
  const LoadRun run = run_load_text(
      replaced_text(creep_scene_text(), "springs = 400", fmt::format("springs = {}", n)));
  const RunResult& r = run.result;
  EXPECT_EQ(r.status, RunStatus::completed);
  EXPECT_TRUE(r.warnings.empty());
  const double scale = depth_of_phi(kRadius, ramp_hold_phi(kSolid, kLoad, kStepTime, kCreepEnd));
  CreepErrors errors{0.0, 0.0};
  int touches = 0;
  for (std::size_t i = 0; i < run.events.states.size(); ++i) {
    const ContactSnapshot& s = run.events.states[i];
    if (run.events.stages[i] == "relax") continue;
    ++touches;
    // Under the held load the force is the held value at its time.
    const double held = kLoad * std::min(s.time / kStepTime, 1.0);
    EXPECT_NEAR(s.normal_force, held, 1e-9 * kLoad) << i;
    const double ref = depth_of_phi(kRadius, ramp_hold_phi(kSolid, kLoad, kStepTime, s.time));
    errors.depth = std::max(errors.depth, std::abs(s.indentation - ref) / scale);
  }
  EXPECT_GT(touches, n / 2);
  EXPECT_EQ(r.stages.size(), 3u);
  if (r.stages.size() != 3) return errors;
  EXPECT_EQ(r.stages[2].end.time, kRelaxEnd);
  EXPECT_EQ(r.stages[2].end.indentation, r.stages[1].end.indentation);  // fixed grips hold it
  errors.force = std::abs(r.stages[2].end.normal_force -
                          relaxing_force(kSolid, kLoad, kStepTime, kCreepEnd, kRelaxEnd)) /
                 kLoad;
  expect_balanced_stages(r);
  std::printf(
      "N = %lld: creep depth error %.3e of d(%.3f s), relaxed force error %.3e of F0, %d "
      "touches\n",
      static_cast<long long>(n), errors.depth, kCreepEnd, errors.force, touches);
  return errors;
}

// The scene's creep (a load stepped on in 1 ms, held 2 s) and the fixed-grips hold after it. The
// row's error is its sampling of the contact edge, order 1 in 1/N: the depth within 2 / N of the
// creep's end depth and falling at least 3x from 100 to 400 springs (4x at order 1). The held
// force after the relaxation has no such error: the row's force is the hereditary operator E
// applied to its own P(d) (its elastic force per unit modulus), and under the held load that P
// is J applied to F exactly, whatever the springs, so the force is F0's history relaxed: to
// 1e-10 of F0 (the quadrature's error is near 1e-13).
TEST(ViscoelasticLoad, CreepThenRelaxationFollowLeeRadokAtTwoSpringCounts) {
  const CreepErrors coarse = creep_errors(100);
  const CreepErrors fine = creep_errors(400);
  EXPECT_LT(coarse.depth, 2.0 / 100);
  EXPECT_LT(fine.depth, 2.0 / 400);
  EXPECT_LT(fine.depth, coarse.depth / 3.0);
  EXPECT_LT(coarse.force, 1e-10);
  EXPECT_LT(fine.force, 1e-10);
}

// A load ramped over 0.3 s (three relaxation times) to F0, from the first touch: the depth at
// every touch against Lee-Radok, within 2 / N of the end depth at two spring counts.
TEST(ViscoelasticLoad, RampedLoadFollowsLeeRadok) {
  constexpr double kRamp = 0.3;
  std::vector<double> errors;
  for (const std::int64_t n : {100, 400}) {
    std::string text = replaced_text(creep_scene_text(), "duration = 0.001", "duration = 0.3");
    text = replaced_text(text, "springs = 400", fmt::format("springs = {}", n));
    const LoadRun run = run_load_text(text);
    const double scale = depth_of_phi(kRadius, ramp_hold_phi(kSolid, kLoad, kRamp, kRamp));
    double error = 0.0;
    for (std::size_t i = 0; i < run.events.states.size(); ++i) {
      if (run.events.stages[i] != "step") continue;
      const ContactSnapshot& s = run.events.states[i];
      const double ref = depth_of_phi(kRadius, ramp_hold_phi(kSolid, kLoad, kRamp, s.time));
      error = std::max(error, std::abs(s.indentation - ref) / scale);
    }
    std::printf("N = %lld: ramp depth error %.3e of d(t_r)\n", static_cast<long long>(n), error);
    EXPECT_LT(error, 2.0 / static_cast<double>(n));
    expect_balanced_stages(run.result);
    errors.push_back(error);
  }
  EXPECT_LT(errors[1], errors[0] / 3.0);
}

// A machine spring (k = 2000 N/m) whose end advances at 1e-4 m/s for 0.3 s, then is held 0.5 s:
// the force at every touch of the advance against the Volterra equation's solution (2000 steps:
// error near 1e-7 of F), within 2 / N of the largest force; and the balance of both stages, with
// the machine spring's energy F^2 / (2k) in what is stored.
TEST(ViscoelasticLoad, MachineSpringFollowsItsVolterraEquation) {
  constexpr double kStiffness = 2000.0, kSpeed = 1.0e-4, kSpan = 0.3;
  constexpr int kSteps = 2000;
  const std::vector<double> ref =
      machine_spring_forces(kSolid, kRadius, kStiffness, kSpeed, kSpan, kSteps);
  const double peak = ref.back();
  std::vector<double> errors;
  for (const std::int64_t n : {100, 400}) {
    std::string text = creep_scene_text();
    text = replaced_text(text, "normal = { control = \"fixed-load\", to = 0.05 }\nduration = 0.001",
                         fmt::format("normal = {{ control = \"compliant\", stiffness = {}, by = {} "
                                     "}}\nduration = {}",
                                     kStiffness, kSpeed * kSpan, kSpan));
    text = replaced_text(text, "springs = 400", fmt::format("springs = {}", n));
    const LoadRun run = run_load_text(text);
    double error = 0.0;
    int touches = 0;
    for (std::size_t i = 0; i < run.events.states.size(); ++i) {
      if (run.events.stages[i] != "step") continue;
      const ContactSnapshot& s = run.events.states[i];
      ++touches;
      // The machine end is held: h = d + F / k = V t.
      EXPECT_NEAR(s.normal_control, kSpeed * s.time, 1e-12) << i;
      EXPECT_NEAR(s.indentation + s.normal_force / kStiffness, kSpeed * s.time, 1e-12) << i;
      const double at = s.time / kSpan * kSteps;
      const auto lo = static_cast<std::size_t>(std::min(std::floor(at), kSteps - 1.0));
      const double f_ref = ref[lo] + (ref[lo + 1] - ref[lo]) * (at - static_cast<double>(lo));
      error = std::max(error, std::abs(s.normal_force - f_ref) / peak);
    }
    std::printf("N = %lld: machine spring force error %.3e of F(end), %d touches\n",
                static_cast<long long>(n), error, touches);
    EXPECT_GT(touches, n / 4);
    EXPECT_LT(error, 2.0 / static_cast<double>(n));
    expect_balanced_stages(run.result);
    errors.push_back(error);
  }
  EXPECT_LT(errors[1], errors[0] / 3.0);
}

}  // namespace
}  // namespace mdrsim

namespace mdrsim {
namespace {

// Pressed under a fixed load, unloaded under it to a quarter (springs let go under the held
// force), then retracted through a machine spring until separation.
const std::string kHeldCycle =
    "[material]\n"
    "effective_modulus = 1.0e6\n"
    "work_of_adhesion = 0.0\n"
    "relaxation = [ { modulus = 9.0e6, time = 0.1 } ]\n"
    "[profile]\n"
    "type = \"parabolic\"\n"
    "radius = 0.01\n"
    "[[loading.stage]]\n"
    "name = \"press\"\n"
    "normal = { control = \"fixed-load\", to = 0.05 }\n"
    "duration = 0.2\n"
    "[[loading.stage]]\n"
    "name = \"unload\"\n"
    "normal = { control = \"fixed-load\", to = 0.0125 }\n"
    "duration = 0.2\n"
    "[[loading.stage]]\n"
    "name = \"retract\"\n"
    "normal = { control = \"compliant\", stiffness = 2000.0, by = -1.0e-4 }\n"
    "until = \"separation\"\n"
    "duration = 1.0\n"
    "[discretization]\n"
    "springs = 200\n";

// An arm of tau = 1e-9 s relaxes at once: the held cycle is the elastic program of E*_inf (the
// scene without `relaxation`, run by the elastic program's own row), every touch and let-go in
// order with its force and time within 1e-6 of F0 and of the stage's second (the arm adds E_1 d'
// tau to a load), each stage's end and work the same. With tau = 0.1 s the cycle creeps on while
// it is unloaded and still separates, every stage balanced.
TEST(ViscoelasticLoad, HeldCycleOfAFastArmIsTheElasticProgram) {
  const LoadRun fast = run_load_text(replaced_text(kHeldCycle, "time = 0.1 }", "time = 1.0e-9 }"));
  const LoadRun elastic = run_load_text(
      replaced_text(kHeldCycle, "relaxation = [ { modulus = 9.0e6, time = 0.1 } ]\n", ""));
  ASSERT_EQ(fast.events.states.size(), elastic.events.states.size());
  EXPECT_EQ(fast.events.stages, elastic.events.stages);
  for (std::size_t i = 0; i < fast.events.states.size(); ++i) {
    const ContactSnapshot& f = fast.events.states[i];
    const ContactSnapshot& e = elastic.events.states[i];
    EXPECT_EQ(f.springs_in_contact, e.springs_in_contact) << i;
    EXPECT_NEAR(f.normal_force, e.normal_force, 1e-6 * kLoad) << i;
    EXPECT_NEAR(f.time, e.time, 1e-6) << i;
  }
  EXPECT_EQ(fast.result.status, RunStatus::no_instability);
  EXPECT_EQ(fast.result.status, elastic.result.status);
  ASSERT_EQ(fast.result.stages.size(), 3u);
  ASSERT_EQ(elastic.result.stages.size(), 3u);
  const double work_scale = std::abs(elastic.result.stages[0].work.normal);
  for (std::size_t i = 0; i < 3; ++i) {
    const StageRecord& f = fast.result.stages[i];
    const StageRecord& e = elastic.result.stages[i];
    EXPECT_NEAR(f.end.normal_force, e.end.normal_force, 1e-6 * kLoad) << f.name;
    EXPECT_NEAR(f.end.indentation, e.end.indentation,
                1e-6 * elastic.result.stages[0].end.indentation)
        << f.name;
    EXPECT_NEAR(f.end.time, e.end.time, 1e-6) << f.name;
    EXPECT_NEAR(f.work.normal, e.work.normal, 1e-6 * work_scale) << f.name;
  }
  expect_balanced_stages(fast.result);

  const LoadRun slow = run_load_text(kHeldCycle);
  EXPECT_EQ(slow.result.status, RunStatus::no_instability);
  ASSERT_EQ(slow.result.stages.size(), 3u);
  EXPECT_EQ(slow.result.stages[2].end.springs_in_contact, 0);
  EXPECT_GT(slow.result.stages[1].end.indentation, slow.result.stages[0].end.indentation);
  for (std::size_t i = 0; i < slow.events.states.size(); ++i) {
    // Under the held load every touch and let-go sits at the held force of its time.
    if (slow.events.stages[i] == "retract") continue;
    const double t = slow.events.states[i].time;
    const double held = t <= 0.2 ? kLoad * t / 0.2 : kLoad - 0.75 * kLoad * (t - 0.2) / 0.2;
    EXPECT_NEAR(slow.events.states[i].normal_force, held, 1e-9 * kLoad) << i;
  }
  expect_balanced_stages(slow.result);
}

}  // namespace
}  // namespace mdrsim
