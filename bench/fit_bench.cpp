// Google Benchmark: Hertz fitted to the real 2000-point JPK approach (nanite takes 3.2 ms for
// the fit alone on this machine), alone and with the file's reading and preprocessing.
#include <benchmark/benchmark.h>

#include <string>

#include "engine/fit/hertz_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/measured/read_force_curves.hpp"

namespace {

const std::string kSpot3 =
    std::string(MDRSIM_SOURCE_DIR) + "/tests/data/afm/fmt-jpk-fd_spot3-0192.jpk-force";

mdrsim::fit::HertzFitOptions options() {
  mdrsim::fit::HertzFitOptions out;
  out.tip = mdrsim::fit::parse_tip("parabolic:radius=1e-5");
  out.poisson_ratio = 0.5;
  out.fixed.baseline_slope = 0.0;
  return out;
}

void BM_HertzFitAlone(benchmark::State& state) {
  const auto file = mdrsim::measured::read_force_curves(kSpot3);
  const auto segment =
      mdrsim::fit::prepare_segment(file.curves[0], mdrsim::measured::SegmentKind::approach);
  const auto fit_options = options();
  long evaluations = 0;
  for (auto _ : state) {
    const auto fit = mdrsim::fit::fit_hertz(segment, fit_options);
    evaluations = fit.evaluations;
    benchmark::DoNotOptimize(fit.youngs_modulus.value);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["points"] = static_cast<double>(segment.force.size());
}
BENCHMARK(BM_HertzFitAlone)->Unit(benchmark::kMicrosecond);

void BM_HertzReadPreprocessFit(benchmark::State& state) {
  const auto fit_options = options();
  for (auto _ : state) {
    const auto file = mdrsim::measured::read_force_curves(kSpot3);
    const auto segment =
        mdrsim::fit::prepare_segment(file.curves[0], mdrsim::measured::SegmentKind::approach);
    const auto fit = mdrsim::fit::fit_hertz(segment, fit_options);
    benchmark::DoNotOptimize(fit.youngs_modulus.value);
  }
}
BENCHMARK(BM_HertzReadPreprocessFit)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
