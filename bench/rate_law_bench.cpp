// Google Benchmark: a rate-law pull-off on the continuum route at rtol 1e-8 (the bench's target
// 1 ms per run): a parabola pressed reversibly to JKR's zero-force state, then retracted at
// beta = 0.01, 1 and 100 until the contact is lost, through run_scene; and the same pull-off
// on the row, on an elastic and on a relaxing bulk, per let-go.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace {

/// E* = 1 MPa, R = 1 cm, dgamma = 0.05 J/m^2, v* = 1 um/s, n = 1/2; the grips at
/// V = beta v* / (E* R / dgamma)^(1/3).
std::string rate_law_pull_off(double beta) {
  constexpr double kModulus = 1e6, kRadius = 0.01, kWork = 0.05, kFrontSpeed = 1e-6;
  const double a0 = std::cbrt(4.5 * std::numbers::pi * kWork * kRadius * kRadius / kModulus);
  const double d0 = a0 * a0 / kRadius - std::sqrt(2.0 * std::numbers::pi * a0 * kWork / kModulus);
  const double speed = beta * kFrontSpeed / std::cbrt(kModulus * kRadius / kWork);
  return fmt::format(
      "[material]\nyoungs_modulus = {}\npoisson_ratio = 0.0\nwork_of_adhesion = {}\n"
      "approach_work_of_adhesion = {}\n[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[detachment]\nfront_speed_law = {{ speed = {}, exponent = 0.5 }}\n"
      "[[loading.stage]]\nnormal = {{ control = \"fixed-grips\", to = {:.17g} }}\nduration = 1.0\n"
      "[[loading.stage]]\nnormal = {{ by = -1e-5 }}\nuntil = \"separation\"\nspeed = {:.17g}\n"
      "[solver]\nmethod = \"continuum\"\n[discretization]\nrtol = 1e-8\n",
      kModulus, kWork, kWork, kRadius, kFrontSpeed, d0, speed);
}

void BM_RateLawPullOff(benchmark::State& state) {
  const double beta = std::pow(10.0, static_cast<double>(state.range(0)));
  const mdrsim::Scene scene = mdrsim::test::build_scene_text(rate_law_pull_off(beta));
  mdrsim::RunResult r;
  for (auto _ : state) {
    r = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(r);
  }
  state.counters["ode_steps"] = static_cast<double>(r.counts.steps);
  state.counters["peak_N"] = r.peak ? r.peak->normal_force : 0.0;
  state.SetLabel(fmt::format("beta = {:g}", beta));
}
BENCHMARK(BM_RateLawPullOff)->Arg(-2)->Arg(0)->Arg(2)->Unit(benchmark::kMicrosecond);

/// The row's pull-off at beta = 1 on N springs: the scene above on the event method, its bulk
/// elastic (E* = 1 MPa) or relaxing (E_inf = 1 MPa, E_1 = 2 MPa, tau = 100 s, held 10^4 s after
/// the press: scenes/viscoelastic/rate_law_relaxing_row.toml).
std::string rate_law_row_pull_off(std::int64_t springs, bool relaxing) {
  const double speed = 1e-6 / std::cbrt(1e6 * 0.01 / 0.05);
  return fmt::format(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.05\n{}[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[detachment]\nfront_speed_law = {{ speed = 1e-6, exponent = 0.5 }}\n"
      "[[loading.stage]]\nnormal = {{ control = \"fixed-grips\", to = 5.7e-6 }}\nduration = 2.0\n"
      "[[loading.stage]]\nduration = 1e4\n"
      "[[loading.stage]]\nnormal = {{ by = -1e-4 }}\nuntil = \"separation\"\nspeed = {:.17g}\n"
      "[solver]\nmethod = \"event\"\n[discretization]\nsprings = {}\n",
      relaxing ? "relaxation = [ { modulus = 2e6, time = 100.0 } ]\n" : "", speed, springs);
}

void BM_RateLawRowPullOff(benchmark::State& state) {
  const std::int64_t springs = state.range(0);
  const bool relaxing = state.range(1) != 0;
  const mdrsim::Scene scene =
      mdrsim::test::build_scene_text(rate_law_row_pull_off(springs, relaxing));
  mdrsim::RunResult r;
  for (auto _ : state) {
    r = mdrsim::run_scene(scene, {});
    benchmark::DoNotOptimize(r);
  }
  state.counters["ode_steps"] = static_cast<double>(r.counts.steps);
  state.counters["ns_per_let_go"] = benchmark::Counter(
      static_cast<double>(r.counts.events) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(relaxing ? "relaxing" : "elastic");
}
BENCHMARK(BM_RateLawRowPullOff)
    ->Args({2000, 0})
    ->Args({2000, 1})
    ->Args({20000, 0})
    ->Args({20000, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
