// Google Benchmark: a viscoelastic event of the program row against an elastic let-go, per event at
// 1e5 springs (the target: at most 2x with one Prony term, at most +50 % per term), whole
// programs through run_scene divided by their events.
#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace {

constexpr std::int64_t kSprings = 100'000;

/// A parabola (R = 1 cm, E*_inf = 1 MPa) pressed to 20 um at 0.1 mm/s and withdrawn at that
/// speed until separation (scenes/viscoelastic/lee_radok_parabola.toml), or the press alone.
std::string lee_radok_program(const std::string& material, bool withdraw) {
  std::string text = fmt::format(
      "[material]\neffective_modulus = 1.0e6\n{}"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = 2.0e-5 }}\n"
      "speed = 1.0e-4\n",
      material);
  if (withdraw) {
    text +=
        "[[loading.stage]]\nname = \"withdraw\"\nnormal = { control = \"fixed-grips\", by = "
        "-2.0e-5 "
        "}\nuntil = \"separation\"\nspeed = 1.0e-4\n";
  }
  return text +
         fmt::format("[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n", kSprings);
}

/// `terms` Prony terms sharing E*_1 = 9 MPa, their relaxation times spread about 0.1 s.
std::string relaxation(int terms) {
  const std::vector<double> times{0.1, 0.03, 0.3, 0.01};
  std::string text = "work_of_adhesion = 0.0\nrelaxation = [";
  for (int j = 0; j < terms; ++j) {
    text += fmt::format("{}{{ modulus = {}, time = {} }}", j == 0 ? " " : ", ", 9.0e6 / terms,
                        times[static_cast<std::size_t>(j)]);
  }
  return text + " ]\n";
}

void run_program(benchmark::State& state, const mdrsim::Scene& scene) {
  mdrsim::RunResult result;
  for (auto _ : state) {
    result = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(result.status);
  }
  const auto events = static_cast<double>(result.counts.events);
  state.counters["events"] = events;
  state.counters["time_per_event"] =
      benchmark::Counter(events * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(mdrsim::to_string(result.status));
}

void run_program(benchmark::State& state, const std::string& text) {
  run_program(state, mdrsim::test::build_scene_text(text));
}

/// The elastic program's row: glued as it presses (dgamma_a = dgamma = 0.05 J/m^2), every spring
/// let go as it withdraws (an event per spring each way).
void elastic_let_go(benchmark::State& state) {
  run_program(state, lee_radok_program(
                         "work_of_adhesion = 0.05\napproach_work_of_adhesion = 0.05\n", true));
}

/// The elastic program without adhesion: a touch and a lift per spring, as the viscoelastic one.
void elastic_touch_lift(benchmark::State& state) {
  run_program(state, lee_radok_program("work_of_adhesion = 0.0\n", true));
}

/// The elastic program's press alone: a glue per spring.
void elastic_glue(benchmark::State& state) {
  run_program(state, lee_radok_program(
                         "work_of_adhesion = 0.05\napproach_work_of_adhesion = 0.05\n", false));
}

/// The viscoelastic row: a touch per spring pressing, a release per spring withdrawing (Ting).
void viscoelastic_event(benchmark::State& state, int terms) {
  run_program(state, lee_radok_program(relaxation(terms), true));
}

/// The press alone: a touch per spring.
void viscoelastic_touch(benchmark::State& state, int terms) {
  run_program(state, lee_radok_program(relaxation(terms), false));
}

/// scenes/viscoelastic/pull_off_after_shear_relaxing.toml at 1e4 springs: friction under a
/// relaxing bulk with rebinding (glued, relaxed, sheared past the glue's strength, held, pulled
/// off): slips, sticks, a cascade of glues from the front, let-gos.
void shear_then_pull_off_relaxing(benchmark::State& state) {
  mdrsim::SceneDocument doc = mdrsim::SceneDocument::from_file(
      std::string(MDRSIM_SOURCE_DIR) + "/scenes/viscoelastic/pull_off_after_shear_relaxing.toml");
  doc.set_value("discretization.springs", "10000");
  run_program(state, doc.build(mdrsim::Registries::builtin()));
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);
  const std::string springs = "/springs:" + std::to_string(kSprings);
  benchmark::RegisterBenchmark(("elastic_let_go" + springs).c_str(), elastic_let_go)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("elastic_touch_lift" + springs).c_str(), elastic_touch_lift)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("elastic_press" + springs).c_str(), elastic_glue)
      ->Unit(benchmark::kMillisecond);
  for (const int terms : {1, 2, 4}) {
    benchmark::RegisterBenchmark(
        ("viscoelastic_press_withdraw/terms:" + std::to_string(terms) + springs).c_str(),
        viscoelastic_event, terms)
        ->Unit(benchmark::kMillisecond);
  }
  for (const int terms : {1, 2, 4}) {
    benchmark::RegisterBenchmark(
        ("viscoelastic_press/terms:" + std::to_string(terms) + springs).c_str(), viscoelastic_touch,
        terms)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("viscoelastic_friction_shear_pull_off/springs:10000",
                               shear_then_pull_off_relaxing)
      ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
