// Google Benchmark: whole runs as a user meets them, through run_scene: the Fig. 2 and sphere
// pull-offs at rtol 1e-6 and the reversible JKR approach-retract cycle at 1e6 and 1e7 springs.
// bench/compare_binaries.py compares two builds' binaries side by side.
#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include <fmt/format.h>

#include <cstdint>
#include <string>

#include "bench/bench_cases.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace {

mdrsim::Scene scene_of(const std::string& text) {
  return mdrsim::SceneDocument::from_text(text, "bench.toml").build(mdrsim::Registries::builtin());
}

/// scenes/fig2_fixed_*.toml and scenes/sphere_fixed_*.toml with `discretization = { rtol }`.
std::string pull_off_text(const char* profile, const char* normal) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"{}\"\nradius = 0.01\n"
      "[loading]\npreload = {{ contact_radius = 5.209397078678047e-4 }}\n"
      "normal = {{ control = \"{}\" }}\n[detachment]\ncriterion = \"mode-mixed\"\n"
      "[discretization]\nrtol = 1e-6\n[solver]\nmethod = \"event\"\n",
      profile, normal);
}

/// The benchmark's time is the run's; `wall_time_s` is the time the JSON reports.
void run(benchmark::State& state, const std::string& text) {
  const mdrsim::Scene scene = scene_of(text);
  mdrsim::RunResult result;
  double wall = 0.0;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    wall += result.wall_time_s;
    benchmark::DoNotOptimize(result.work);
  }
  state.counters["events"] = static_cast<double>(result.counts.events);
  state.counters["wall_time_s"] = wall / static_cast<double>(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::err);
  for (const char* profile : {"parabolic", "sphere"}) {
    for (const char* normal : {"fixed-load", "fixed-grips"}) {
      benchmark::RegisterBenchmark(fmt::format("rtol_1e-6/{}/{}", profile, normal).c_str(), run,
                                   pull_off_text(profile, normal))
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime();
    }
  }
  for (const std::int64_t springs : {std::int64_t{1'000'000}, std::int64_t{10'000'000}}) {
    benchmark::RegisterBenchmark(fmt::format("jkr_cycle/springs:{}", springs).c_str(), run,
                                 mdrsim::bench::cycle_text(springs))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
