// Without adhesion: every spring leaves at zero stretch and the run ends smoothly at zero force,
// and any tangential displacement shears the glue off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/events/event_recorder.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/part_examples.hpp"
#include "engine/scene/registries.hpp"

using mdrsim::Event;
using mdrsim::EventKind;
using mdrsim::RunResult;
using mdrsim::RunStatus;
using mdrsim::Scene;
using mdrsim::test::run_quietly;

/// ", keys" for an inline table, or nothing.
std::string with_separator(const std::string& keys) { return keys.empty() ? "" : ", " + keys; }

std::string no_adhesion_scene(const std::string& normal, const std::string& tangential,
                              const std::string& criterion, const std::string& method) {
  return "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.0\n"
         "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
         "[loading]\npreload = { depth = 1e-5 }\nnormal = { control = \"" +
         normal + "\"" + with_separator(mdrsim::test::example_keys("controller", normal, ", ")) +
         " }\n" + tangential + "[detachment]\ncriterion = \"" + criterion + "\"\n" +
         mdrsim::test::example_keys("criterion", criterion, "\n") + "\n" +
         "[discretization]\nsprings = 500\n[solver]\nmethod = \"" + method + "\"\n";
}

// Without adhesion (dgamma = 0) nothing holds a spring in tension: each leaves as its stretch
// reaches zero, no detachment happens inside a cascade and the last spring leaves carrying no
// force: no-instability, at zero force. Under every controller, criterion and method.
// Tolerances: the event method detaches each spring exactly at zero stretch, so forces are
// >= 0 and the last one is 0 up to rounding (1e-9 of the preload force); stepping detaches a
// spring after the step that stretched it and stops one step before the last spring leaves,
// so its forces are off by at most one base step (1e-3 of the preload control), i.e. 1e-3 of
// the preload force under fixed load and 1.5e-3 under fixed grips (2 E* a d = 1.5 F for Hertz),
// less with a compliant machine: 2e-3 covers all.
// The event method flags the first detachment in_cascade: glued at the non-adhesive radius, the
// boundary spring is at zero stretch at the preload and lets go at the preload's own control
// value. That row is the preload equilibrium, not a jump, so only the later ones are checked.
TEST(NoAdhesion, EndsSmoothlyAtZeroForceUnderEveryPart) {
  const auto registries = mdrsim::Registries::builtin();
  for (const auto& normal : registries.controllers.names()) {
    for (const auto& criterion : registries.criteria.names()) {
      for (const std::string method : {"event", "stepping"}) {
        const Scene scene =
            mdrsim::test::build_scene_text(no_adhesion_scene(normal, "", criterion, method));
        mdrsim::EventRecorder recorder;
        mdrsim::ObserverList observers;
        observers.add(recorder);
        const RunResult r = mdrsim::run_pull_off(scene, observers);
        const std::string where = normal + " " + criterion + " " + method;
        EXPECT_EQ(r.status, RunStatus::no_instability) << where;
        EXPECT_EQ(r.critical->springs_in_contact, 1) << where;
        const double preload_force = recorder.events().front().state.normal_force;
        ASSERT_GT(preload_force, 0.0);
        const double tolerance = (method == "event" ? 1e-9 : 2e-3) * preload_force;
        EXPECT_LE(std::abs(r.critical->normal_force), tolerance) << where;
        bool first = true;
        for (const Event& e : recorder.events()) {
          if (e.kind != EventKind::spring_detached) continue;
          EXPECT_TRUE(first || !e.in_cascade) << where << " spring " << e.spring;
          EXPECT_GE(e.state.normal_force, -tolerance) << where << " spring " << e.spring;
          first = false;
        }
      }
    }
  }
}

// Without adhesion the glued contact has no tangential strength either (eq. 20 with dgamma = 0:
// any u_x != 0 breaks the boundary spring): a tangential displacement shears it off at once,
// for every criterion that sees u_x. normal-only ignores u_x and peels off smoothly.
TEST(NoAdhesion, AnyTangentialDisplacementShearsOff) {
  const auto registries = mdrsim::Registries::builtin();
  const std::string tangential =
      "tangential = { control = \"fixed-grips\", displacement = 1e-9 }\n";
  for (const auto& criterion : registries.criteria.names()) {
    const RunResult r = run_quietly(mdrsim::test::build_scene_text(
        no_adhesion_scene("fixed-load", tangential, criterion, "event")));
    EXPECT_EQ(r.status,
              criterion == "normal-only" ? RunStatus::no_instability : RunStatus::shear_off)
        << criterion;
  }
}
