// Google Benchmark: Hertz fitted to the real 2000-point JPK approach (nanite takes 3.2 ms for
// the fit alone on this machine), alone and with the file's reading and preprocessing; JKR and
// DMT fitted to a synthetic 2000-point retract and to the real JPK retract.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "engine/fit/adhesive_fit.hpp"
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

/// A JKR retract of a 5 um paraboloid (E* = 1.33 MPa, w = 0.02 J/m^2) from JKR's closed forms,
/// 2000 samples from six pull-off forces to half the depth above contact, the jump half way
/// between the fixed-load and fixed-grips pull-offs, 1 % noise; DMT's with Hertz less 2 pi w R.
mdrsim::fit::PreparedSegment synthetic_retract(mdrsim::fit::AdhesionModel model) {
  const double pi = std::numbers::pi, r = 5e-6, e = 1e6 / 0.75, w = 0.02;
  const bool jkr = model == mdrsim::fit::AdhesionModel::jkr;
  const auto depth_at = [&](double a) {
    return a * a / r - (jkr ? std::sqrt(2 * pi * a * w / e) : 0);
  };
  const auto force_at = [&](double a) {
    return 4 * e * a * a * a / (3 * r) -
           (jkr ? std::sqrt(8 * pi * w * e * a * a * a) : 2 * pi * w * r);
  };
  const double a_turn = std::cbrt(pi * w * r * r / (8 * e));
  const double a_load = std::cbrt(9 * pi * w * r * r / (8 * e));
  const double pull = jkr ? 1.5 * pi * w * r : 2 * pi * w * r;
  double a_deep = a_load;
  while (force_at(a_deep) < 6 * pull) a_deep *= 1.01;
  const double deepest = depth_at(a_deep);
  const double jump = jkr ? 0.5 * (depth_at(a_turn) + depth_at(a_load)) : 0.0;
  std::mt19937_64 random(1);
  std::normal_distribution<double> noise(0.0, 0.06 * pull);
  mdrsim::fit::PreparedSegment out;
  bool on = true;
  for (int i = 0; i < 2000; ++i) {
    const double depth = deepest * (1 - 1.5 * i / 1999.0);
    on = on && depth > jump;
    double f = 0.0;
    if (on) {
      double lo = jkr ? a_turn : 0.0, hi = a_deep * 2;
      for (int k = 0; k < 100; ++k) (depth_at(0.5 * (lo + hi)) < depth ? lo : hi) = 0.5 * (lo + hi);
      f = force_at(0.5 * (lo + hi));
    }
    out.tip_position.push_back(3e-6 - depth);
    out.force.push_back(f + noise(random));
  }
  return out;
}

void BM_AdhesiveFit(benchmark::State& state, mdrsim::fit::AdhesionModel model, bool real) {
  mdrsim::fit::PreparedSegment segment;
  if (real) {
    const auto file = mdrsim::measured::read_force_curves(kSpot3);
    segment = mdrsim::fit::prepare_segment(file.curves[0], mdrsim::measured::SegmentKind::retract);
  } else {
    segment = synthetic_retract(model);
  }
  mdrsim::fit::AdhesiveFitOptions fit_options;
  fit_options.model = model;
  fit_options.tip =
      mdrsim::fit::parse_tip(real ? "parabolic:radius=1e-5" : "parabolic:radius=5e-6");
  fit_options.retract = true;
  long evaluations = 0;
  for (auto _ : state) {
    const auto fit = mdrsim::fit::fit_adhesive(segment, fit_options);
    evaluations = fit.evaluations;
    benchmark::DoNotOptimize(fit.work_of_adhesion.value);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["points"] = static_cast<double>(segment.force.size());
}
BENCHMARK_CAPTURE(BM_AdhesiveFit, jkr_synthetic_retract, mdrsim::fit::AdhesionModel::jkr, false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AdhesiveFit, dmt_synthetic_retract, mdrsim::fit::AdhesionModel::dmt, false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AdhesiveFit, jkr_jpk_retract, mdrsim::fit::AdhesionModel::jkr, true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AdhesiveFit, dmt_jpk_retract, mdrsim::fit::AdhesionModel::dmt, true)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
