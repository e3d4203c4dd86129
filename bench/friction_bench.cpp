// Google Benchmark: a fretting cycle of the example sphere under friction at 1e6 springs, and the
// cost of a friction event against a detachment event.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

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

/// The same fretting cycle, adhesive (w = 0.05 J/m^2 on approach and on let-go) with its glued
/// springs under Coulomb's law (glued = "coulomb"), its glued springs on the slip keys.
std::string glued_fretting(std::int64_t springs) {
  const std::string text = fretting(springs, 0.5);
  const std::string dry = "work_of_adhesion = 0\n";
  const std::string friction = "[friction]\n";
  std::string wet = text;
  wet.replace(wet.find(dry), dry.size(),
              "work_of_adhesion = 0.05\napproach_work_of_adhesion = 0.05\n");
  wet.replace(wet.find(friction), friction.size(), friction + "glued = \"coulomb\"\n");
  return wet;
}

/// A JKR cycle of the same sphere, glued on touch and retracted until separation: one
/// detachment event per spring; with `approach_only`, its approach alone (the touches).
std::string jkr_cycle(std::int64_t springs, bool approach_only = false) {
  const std::string retract = approach_only ? "" : R"(
[[loading.stage]]
name = "retract"
normal = { by = -1.0e-4 }
until = "separation"
)";
  return fmt::format(kMaterial, 0.05) + R"(
[[loading.stage]]
name = "approach"
normal = { control = "fixed-grips", to = 2.0e-5 }
)" + retract +
         fmt::format("[discretization]\nsprings = {}\n", springs);
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

/// The console's lines, then the friction event's costs, derived from them (CPU time; with
/// --benchmark_repetitions, of the medians).
class EventCostReporter : public benchmark::ConsoleReporter {
 public:
  EventCostReporter()
      : ConsoleReporter(isatty(fileno(stdout)) != 0 ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      const auto events = r.counters.find("events");
      if (events == r.counters.end()) continue;
      runs_[r.run_name.function_name] = {r.GetAdjustedCPUTime(), events->second.value};
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto have = [&](const char* name) { return runs_.count(name) > 0; };
    if (!have("fretting_cycle/mu:0.5") || !have("fretting_cycle/mu:0") ||
        !have("fretting_press/mu:0.5") || !have("jkr_cycle") || !have("jkr_approach")) {
      return;  // a filter left some out: nothing to derive
    }
    const Measured& cycle = runs_["fretting_cycle/mu:0.5"];
    const Measured& twin = runs_["fretting_cycle/mu:0"];
    const Measured& press = runs_["fretting_press/mu:0.5"];
    const Measured& jkr = runs_["jkr_cycle"];
    const Measured& approach = runs_["jkr_approach"];
    // ms per run -> ns per event.
    const double detachment = 1e6 * (jkr.ms - approach.ms) / (jkr.events - approach.events);
    const double friction_events = cycle.events - twin.events;
    const double alone = 1e6 * (cycle.ms - press.ms) / friction_events;
    const double with_touches = 1e6 * (cycle.ms - twin.ms) / friction_events;
    const auto verdict = [](double ratio) { return ratio <= 1.5 ? "MET" : "MISSED"; };
    std::printf(
        "\nA detachment event (the JKR cycle's let-gos: cycle - approach): %.1f ns\n"
        "A friction event alone (fretting cycle - its press, over %.0f slips and sticks): %.1f "
        "ns = %.2fx a detachment event (target <= 1.5x: %s)\n"
        "A friction event with the touches' friction bookkeeping (cycle - frictionless twin): "
        "%.1f ns = %.2fx (%s)\n"
        "The fretting cycle at 1e6 springs: %.0f ms (target < 500 ms: %s)\n",
        detachment, friction_events, alone, alone / detachment, verdict(alone / detachment),
        with_touches, with_touches / detachment, verdict(with_touches / detachment), cycle.ms,
        cycle.ms < 500.0 ? "MET" : "MISSED");
  }

 private:
  struct Measured {
    double ms = 0.0;  ///< CPU time per run [ms]
    double events = 0.0;
  };
  std::map<std::string, Measured> runs_;
};

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);
  constexpr std::int64_t kSprings = 1'000'000;
  // The fretting cycle: 1e6 touches, then a slip per sliding spring on loading, a stick and a
  // slip each on unloading and reloading. Its press alone runs the touches with the friction
  // row's bookkeeping (a spring's keys, its pages): the cycle's difference from it over the
  // friction events is the cost of a friction event alone. Its frictionless twin runs the same
  // touches without that bookkeeping: the difference from it charges the friction events with
  // the touches' bookkeeping too.
  benchmark::RegisterBenchmark("fretting_cycle/mu:0.5", run, fretting(kSprings, 0.5))
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("fretting_cycle/mu:0", run, fretting(kSprings, 0.0))
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("fretting_press/mu:0.5", run, fretting(kSprings, 0.5, true))
      ->Unit(benchmark::kMillisecond);
  // Detachment events: the JKR cycle glues each spring as it touches (the approach, taken in
  // one pass: press_in_bulk, a few ns per spring) and lets each go (a
  // spring-detachment event of the loop); the cycle's difference from its approach over the
  // let-gos is the cost of a detachment event.
  benchmark::RegisterBenchmark("jkr_cycle", run, jkr_cycle(kSprings))
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("jkr_approach", run, jkr_cycle(kSprings, true))
      ->Unit(benchmark::kMillisecond);
  // The adhesive fretting cycle with glued = "coulomb": its glued springs on the slip keys, the
  // cost per event against N (O(log N)).
  for (const std::int64_t springs : {4000, 16000, 64000})
    benchmark::RegisterBenchmark(fmt::format("glued_fretting/springs:{}", springs).c_str(), run,
                                 glued_fretting(springs))
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  EventCostReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
