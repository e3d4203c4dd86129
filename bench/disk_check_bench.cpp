// Google Benchmark: the disk check of a run's reported states (engine/run/disk_states), as
// run_scene pays it, on the wavy sphere and on the 201-point tabulated power law.
#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include <string>
#include <utility>
#include <vector>

#include "engine/run/disk_states.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace {

/// A scene of scenes/, with `--set` overrides.
mdrsim::Scene scene_file(const std::string& name,
                         const std::vector<std::pair<std::string, std::string>>& set) {
  mdrsim::SceneDocument doc =
      mdrsim::SceneDocument::from_file(std::string(MDRSIM_SOURCE_DIR) + "/scenes/" + name);
  for (const auto& [key, value] : set) doc.set_value(key, value);
  return doc.build(mdrsim::Registries::builtin());
}

/// The states the check visits: the critical point, the peak, stage ends and jump states.
int checked_states(const mdrsim::RunResult& r) {
  int n = (r.critical ? 1 : 0) + (r.peak ? 1 : 0) + static_cast<int>(r.stages.size());
  for (const mdrsim::JumpRecord& jump : r.jumps) n += jump.end == mdrsim::JumpEnd::state ? 2 : 1;
  return n;
}

void disk_check(benchmark::State& state, const std::string& name,
                const std::vector<std::pair<std::string, std::string>>& set) {
  const mdrsim::Scene scene = scene_file(name, set);
  mdrsim::RunResult result = mdrsim::run_scene(scene, {});
  const bool valid = result.disk_valid;
  for (auto _ : state) {
    result.warnings.clear();
    mdrsim::check_disk_states(scene, result);
    benchmark::DoNotOptimize(result.disk_valid);
  }
  state.counters["states"] = checked_states(result);
  state.counters["disk_valid"] = valid ? 1.0 : 0.0;
  state.counters["time_per_state"] =
      benchmark::Counter(checked_states(result) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::err);
  benchmark::RegisterBenchmark("disk_check/wavy_sphere", disk_check, "wavy_sphere.toml",
                               std::vector<std::pair<std::string, std::string>>{})
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(
      "disk_check/wavy_sphere/amplitude:9.06e-7", disk_check, "wavy_sphere.toml",
      std::vector<std::pair<std::string, std::string>>{{"profile.amplitude", "9.06e-7"}})
      ->Unit(benchmark::kMillisecond);
  for (const std::string normal : {"fixed_load", "fixed_grips"}) {
    benchmark::RegisterBenchmark(("disk_check/tabulated_power_law_" + normal).c_str(), disk_check,
                                 "tabulated_power_law_" + normal + ".toml",
                                 std::vector<std::pair<std::string, std::string>>{})
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
