// Google Benchmark: a fretting cycle of the example sphere under friction at 1e6 springs, and the
// cost of a friction event against a detachment event (issue 21's speed targets).
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace {

constexpr const char* kMaterial = R"(
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = {}
[profile]
type = "parabolic"
radius = 0.01
)";

/// scenes/programs/fretting_parabola.toml at `springs` (mu = 0: the same path, frictionless);
/// with `press_only`, its first stage alone (the touches, no friction event).
std::string fretting(std::int64_t springs, double mu, bool press_only = false) {
  const std::string press = R"(
[[loading.stage]]
name = "press"
normal = { control = "fixed-load", to = 1.0e-3 }
)";
  if (press_only)
    return fmt::format(kMaterial, 0.0) + press +
           fmt::format("[friction]\ncoefficient = {}\n[discretization]\nsprings = {}\n", mu,
                       springs);
  return fmt::format(kMaterial, 0.0) + press +
         fmt::format(R"(
[[loading.stage]]
name = "load"
tangential = {{ control = "fixed-grips", by = 1.0e-6 }}
[[loading.stage]]
name = "unload"
tangential = {{ by = -2.0e-6 }}
[[loading.stage]]
name = "reload"
tangential = {{ by = 2.0e-6 }}
[friction]
coefficient = {}
[discretization]
springs = {}
)",
                     mu, springs);
}

/// A JKR cycle of the same sphere, glued on touch and retracted until separation: one
/// detachment event per spring.
std::string jkr_cycle(std::int64_t springs) {
  return fmt::format(kMaterial, 0.05) + fmt::format(R"(
[[loading.stage]]
name = "approach"
normal = {{ control = "fixed-grips", to = 2.0e-5 }}
[[loading.stage]]
name = "retract"
normal = {{ by = -1.0e-4 }}
until = "separation"
[discretization]
springs = {}
)",
                                                    springs);
}

void run(benchmark::State& state, std::string text) {
  const mdrsim::Scene scene =
      mdrsim::SceneDocument::from_text(text, "bench.toml").build(mdrsim::Registries::builtin());
  mdrsim::RunResult result;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(result.work);
  }
  state.counters["events"] = static_cast<double>(result.counts.events);
  // Events per second of CPU time, inverted: seconds per event.
  state.counters["s_per_event"] = benchmark::Counter(
      static_cast<double>(result.counts.events) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);
  constexpr std::int64_t kSprings = 1'000'000;
  // The fretting cycle: 1e6 touches, then a slip per sliding spring on loading, a stick and a
  // slip each on unloading and reloading. Its frictionless twin runs the same touches only, so
  // the difference over the friction events is one friction event's cost, the touches' own
  // friction bookkeeping (a spring's keys, its pages) included. Its press alone runs the
  // touches with that bookkeeping: the cycle's difference from it over the friction events is
  // the cost of the friction events alone.
  benchmark::RegisterBenchmark("fretting_cycle/mu:0.5", run, fretting(kSprings, 0.5))
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("fretting_cycle/mu:0", run, fretting(kSprings, 0.0))
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("fretting_press/mu:0.5", run, fretting(kSprings, 0.5, true))
      ->Unit(benchmark::kMillisecond);
  // Detachment events: a touch (glue) and a let-go per spring.
  benchmark::RegisterBenchmark("jkr_cycle", run, jkr_cycle(kSprings))
      ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
