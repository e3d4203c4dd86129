// Google Benchmark: per-event cost of an event-method pull-off, mode-dependent vs mode-mixed.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <ctime>
#include <map>
#include <string>
#include <utility>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace {

// ns per event of mode-mixed by springs, so that a later mode-dependent case can show its ratio.
std::map<std::int64_t, double>& closed_form_cost() {
  static std::map<std::int64_t, double> cost;
  return cost;
}

// The Fig. 3a scene (fixed-grips normal and tangential, nu = 0) at u = d0: springs let go
// under mode mixity, so the let-go depends on ux. The clock runs around the runs alone (the
// scene is parsed once, outside) and counts CPU time, not wall time: the machine is shared.
void pull_off_per_event(benchmark::State& state, std::string criterion, std::string extra) {
  mdrsim::test::JkrScenario s;
  s.normal = "fixed-grips";
  s.tangential_displacement = 1.0;
  s.criterion = criterion;
  s.criterion_extra = extra;
  s.springs = state.range(0);
  s.method = "event";
  const mdrsim::Scene scene = mdrsim::test::build_scene_text(s.toml());
  std::int64_t events = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    const std::clock_t start = std::clock();
    const mdrsim::RunResult result = mdrsim::run_scene(scene, {});
    seconds += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    events += result.counts.events;
    benchmark::DoNotOptimize(result.counts.events);
  }
  const double ns_per_event = 1e9 * seconds / static_cast<double>(events);
  state.counters["events"] = static_cast<double>(events / state.iterations());
  state.counters["ns_per_event"] = ns_per_event;
  if (criterion == "mode-mixed") {
    closed_form_cost()[state.range(0)] = ns_per_event;
  } else if (const auto mixed = closed_form_cost().find(state.range(0));
             mixed != closed_form_cost().end()) {
    state.counters["ratio_to_mode_mixed"] = ns_per_event / mixed->second;
  }
}

// The executable's main() is pull_off_bench.cpp's; an object file linked straight into the
// executable keeps its static initializers (unlike the registries' static libraries). Mode-mixed
// is registered first so that the mode-dependent case after it can report the ratio.
const bool kRegistered = [] {
  for (const auto& [criterion, extra] : {std::pair<std::string, std::string>{"mode-mixed", ""},
                                         {"mode-dependent", "lambda = 0.5"}}) {
    benchmark::RegisterBenchmark(("criterion_cost/" + criterion).c_str(), pull_off_per_event,
                                 criterion, extra)
        ->Arg(1'000'000)
        ->Arg(10'000'000)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
