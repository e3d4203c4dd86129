// Google Benchmark: a Maugis-Dugdale let-go of the spring row beside a JKR let-go, per event at
// 1e5 springs (the target: at most 3x), whole pull-offs divided by their events: the
// row alone, and a scene with solver.method = "event" through run_scene as the JKR one.
#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include <fmt/format.h>

#include <cstdint>
#include <string>

#include "engine/pull_off/dugdale_row.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/maugis_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "profiles/parabolic_profile.hpp"

namespace {

constexpr std::int64_t kSprings = 100'000;

void per_event(benchmark::State& state, double events) {
  state.counters["events"] = events;
  state.counters["time_per_event"] =
      benchmark::Counter(events * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/// Maugis' parabola (R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2) at lambda, glued at 3 a_M.
void dugdale_event(benchmark::State& state, bool grips, double lambda) {
  const mdrsim::maugis_reference::MaugisScales scales{.radius = 0.01, .modulus = 1e6, .work = 0.05};
  const mdrsim::ParabolicProfile parabola(scales.radius);
  const mdrsim::DugdaleLaw law{.adhesive_stress = scales.adhesive_stress(lambda),
                               .work_of_adhesion = scales.work,
                               .effective_modulus = scales.modulus};
  const mdrsim::DugdaleRowSpec spec{
      .springs = kSprings,
      .glued_radius = 3.0 * scales.length(),
      .normal = grips ? mdrsim::AffineConstraint{1.0, 0.0} : mdrsim::AffineConstraint{0.0, 1.0}};
  mdrsim::DugdaleRowResult result;
  for (auto _ : state) {
    result = mdrsim::run_dugdale_row(parabola, law, spec);
    benchmark::DoNotOptimize(result.critical.normal_force);
  }
  const auto events = static_cast<double>(result.counts.events);
  per_event(state, events);
  state.counters["openings_per_event"] =
      static_cast<double>(result.counts.opening_evaluations) / events;
}

/// The same parabola as a scene on the spring row (method = "event", one row), through run_scene.
void dugdale_scene_event(benchmark::State& state, const std::string& normal, double lambda) {
  const mdrsim::maugis_reference::MaugisScales scales{.radius = 0.01, .modulus = 1e6, .work = 0.05};
  const mdrsim::Scene scene = mdrsim::test::build_scene_text(fmt::format(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\nmaugis_parameter = {}\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\npreload = {{ contact_radius = {} }}\nnormal = {{ control = \"{}\" }}\n"
      "[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n",
      lambda, 3.0 * scales.length(), normal, kSprings));
  mdrsim::RunResult result;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(result.peak->normal_force);
  }
  per_event(state, static_cast<double>(result.counts.events));
}

/// The JKR shorthand's event method on the same parabola, glued at 2 a0.
void jkr_event(benchmark::State& state, const std::string& normal) {
  mdrsim::test::JkrScenario s;
  s.normal = normal;
  s.springs = kSprings;
  s.method = "event";
  const mdrsim::Scene scene = mdrsim::test::build_scene_text(s.toml());
  mdrsim::RunResult result;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(result.critical->normal_force);
  }
  per_event(state, static_cast<double>(result.counts.events));
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);
  for (const std::string normal : {"fixed-grips", "fixed-load"}) {
    benchmark::RegisterBenchmark(("jkr_let_go/" + normal + "/springs:100000").c_str(), jkr_event,
                                 normal)
        ->Unit(benchmark::kMillisecond);
    for (const double lambda : {0.3, 1.0, 3.0}) {
      benchmark::RegisterBenchmark(("dugdale_let_go/" + normal + "/lambda:" +
                                    std::to_string(lambda).substr(0, 3) + "/springs:100000")
                                       .c_str(),
                                   dugdale_event, normal == "fixed-grips", lambda)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("dugdale_scene_let_go/" + normal + "/lambda:" +
                                    std::to_string(lambda).substr(0, 3) + "/springs:100000")
                                       .c_str(),
                                   dugdale_scene_event, normal, lambda)
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
