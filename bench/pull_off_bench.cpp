// Google Benchmark: pull-off cost across springs, methods and stepping increments,
// registered at run time over the registered normal controllers.
#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench/bench_cases.hpp"
#include "engine/reference/part_examples.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"

namespace {

void pull_off(benchmark::State& state, std::string normal, std::string method, double increment) {
  const auto springs = static_cast<std::int64_t>(state.range(0));
  mdrsim::test::JkrScenario s;
  s.normal = normal;
  s.springs = springs;
  s.method = method;
  s.normal_extra = mdrsim::test::example_keys("controller", normal, ", ");
  mdrsim::Scene scene = mdrsim::test::build_scene_text(s.toml());
  if (method == "stepping") scene.solver.step = increment * scene.preload_depth;
  mdrsim::RunResult result;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(result.critical->normal_force);
  }
  const double exact =
      mdrsim::bench::paper_cases()[normal == "fixed-load" ? 0 : 2].exact_normal_force;
  state.counters["events"] = static_cast<double>(result.counts.events);
  state.counters["steps"] = static_cast<double>(result.counts.steps);
  state.counters["halvings"] = static_cast<double>(result.counts.halvings);
  state.counters["root_iterations"] = static_cast<double>(result.counts.root_iterations);
  if (normal != "compliant") {
    state.counters["relative_error"] =
        std::abs(result.critical->normal_force / s.scales().force - exact) / std::abs(exact);
  }
  state.SetItemsProcessed(state.iterations() * springs);
}

/// The work of adhesion of a program pull-off: "uniform" (0.05 J/m^2) or a table of `points`
/// equal values out to 1 mm (the same numbers to the bit, so only the table's cost differs).
std::string adhesion_of(int points) {
  if (points == 0) return "0.05";
  std::vector<double> r, value;
  for (int i = 0; i < points; ++i) {
    r.push_back(1e-3 * i / (points - 1));
    value.push_back(0.05);
  }
  return fmt::format("{{ r = [{:.17g}], value = [{:.17g}] }}", fmt::join(r, ", "),
                     fmt::join(value, ", "));
}

/// A program's pull-off (approach under fixed grips to 12 d0, retract until separation, 2000
/// springs) per event, with dgamma uniform or tabulated: what a table costs at each event.
void program_pull_off(benchmark::State& state, int points) {
  const mdrsim::Scene scene = mdrsim::test::build_scene_text(
      fmt::format("[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = {}\n"
                  "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
                  "[[loading.stage]]\nname = \"approach\"\n"
                  "normal = {{ control = \"fixed-grips\", to = 2.713781792333937e-05 }}\n"
                  "[[loading.stage]]\nname = \"retract\"\n"
                  "normal = {{ control = \"fixed-grips\", by = -2.713781792333937e-05 }}\n"
                  "until = \"separation\"\n[discretization]\nsprings = 2000\n",
                  adhesion_of(points)));
  mdrsim::RunResult result;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(result.work);
  }
  const auto events = static_cast<double>(result.counts.events);
  state.counters["events"] = events;
  state.counters["time_per_event"] =
      benchmark::Counter(events * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);
  for (const std::string& normal : mdrsim::Registries::builtin().controllers.names()) {
    benchmark::RegisterBenchmark(("event/" + normal).c_str(), pull_off, normal, "event", 0.0)
        ->RangeMultiplier(10)
        ->Range(100, 10'000'000)
        ->Unit(benchmark::kMillisecond);
    if (normal == "compliant") continue;  // stepping increments are in the control's units
    for (const double increment : {1e-2, 1e-3}) {
      benchmark::RegisterBenchmark(
          ("stepping/" + normal + "/increment:" + std::to_string(increment)).c_str(), pull_off,
          normal, "stepping", increment)
          ->RangeMultiplier(10)
          ->Range(100, 100'000)
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RegisterBenchmark("program_pull_off/dgamma:uniform", program_pull_off, 0)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("program_pull_off/dgamma:table_20001", program_pull_off, 20001)
      ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
