// Google Benchmark: a rate-law pull-off on the continuum route at rtol 1e-8 (the bench's target
// 1 ms per run): a parabola pressed reversibly to JKR's zero-force state, then retracted at
// beta = 0.01, 1 and 100 until the contact is lost, through run_scene.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
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

}  // namespace

BENCHMARK_MAIN();
