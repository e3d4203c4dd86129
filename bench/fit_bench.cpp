// Google Benchmark: Hertz fitted to the real 2000-point JPK approach (nanite takes 3.2 ms for
// the fit alone on this machine), alone and with the file's reading and preprocessing; JKR and
// DMT fitted to a synthetic 2000-point retract and to the real JPK retract; Maugis to a synthetic
// 2000-point retract (lambda = 1) and to the real JPK retract, and to a synthetic approach and
// retract together (lambda 0.12 and 1); whole maps through the map runner
// on 2 threads: a synthetic 64 x 64 JKR map, and the real force map with reading.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/fit_map.hpp"
#include "engine/fit/hertz_fit.hpp"
#include "engine/fit/maugis_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/measured/read_force_curves.hpp"
#include "engine/reference/maugis_lever.hpp"

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

/// A Maugis retract of a 5 um paraboloid (E = 1 MPa, nu = 0.5, w = 0.02 J/m^2, lambda = 1)
/// from the fit's own branch: 2000 samples from six pull-off forces to half the depth above
/// contact, the jump half way in depth from the fixed-load pull-off to the branch's end, 1 %
/// noise.
mdrsim::fit::PreparedSegment maugis_retract() {
  const double r = 5e-6, e = 1e6 / 0.75, w = 0.02, lambda = 1.0;
  const auto tip = mdrsim::fit::parse_tip("parabolic:radius=5e-6");
  const mdrsim::DugdaleLaw law{
      .adhesive_stress = mdrsim::fit::maugis_adhesive_stress(lambda, e, w, r),
      .work_of_adhesion = w,
      .effective_modulus = e};
  const mdrsim::fit::MaugisBranch probe(*tip.profile, law, 1e-9);
  const double pull = -probe.lowest_force();
  double deepest = 1e-9;
  while (mdrsim::fit::MaugisBranch(*tip.profile, law, deepest).at(deepest).force < 6 * pull) {
    deepest *= 1.05;
  }
  const mdrsim::fit::MaugisBranch branch(*tip.profile, law, deepest);
  double pull_depth = deepest;
  for (int i = 0; i <= 4000; ++i) {
    const double d = branch.shallowest_depth() + (deepest - branch.shallowest_depth()) * i / 4000;
    if (branch.at(d).force < branch.at(pull_depth).force) pull_depth = d;
  }
  const double jump = 0.5 * (pull_depth + branch.shallowest_depth());
  std::mt19937_64 random(1);
  std::normal_distribution<double> noise(0.0, 0.06 * pull);
  mdrsim::fit::PreparedSegment out;
  bool on = true;
  for (int i = 0; i < 2000; ++i) {
    const double depth = deepest * (1 - 1.5 * i / 1999.0);
    on = on && depth > jump;
    out.tip_position.push_back(3e-6 - depth);
    out.force.push_back((on ? branch.at(depth).force : 0.0) + noise(random));
  }
  return out;
}

void BM_MaugisFit(benchmark::State& state, bool real) {
  mdrsim::fit::PreparedSegment segment;
  if (real) {
    const auto file = mdrsim::measured::read_force_curves(kSpot3);
    segment = mdrsim::fit::prepare_segment(file.curves[0], mdrsim::measured::SegmentKind::retract);
  } else {
    segment = maugis_retract();
  }
  mdrsim::fit::MaugisFitOptions fit_options;
  fit_options.tip =
      mdrsim::fit::parse_tip(real ? "parabolic:radius=1e-5" : "parabolic:radius=5e-6");
  fit_options.retract = true;
  long evaluations = 0;
  double lambda = 0.0;
  for (auto _ : state) {
    const auto fit = mdrsim::fit::fit_maugis(segment, fit_options);
    evaluations = fit.evaluations;
    lambda = fit.maugis_parameter.value;
    benchmark::DoNotOptimize(fit.work_of_adhesion.value);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["points"] = static_cast<double>(segment.force.size());
  state.counters["lambda"] = lambda;
}

/// A lever's recorded segment with 1 % noise of its largest force, as the Maugis tests build
/// it (the noise seeded by `seed`).
mdrsim::fit::PreparedSegment with_lever_noise(const mdrsim::maugis_reference::LeverCurve& curve,
                                              unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, 0.01 * curve.peak);
  mdrsim::fit::PreparedSegment segment;
  segment.tip_position = curve.z;
  for (const double f : curve.force) segment.force.push_back(f + noise(random));
  segment.height_channel = "tip_position";
  segment.spring_constant = curve.kappa_si;
  return segment;
}

/// Approach and retract fitted together (fit_maugis_both, `--segment both`): Maugis' own path
/// through a lever of the contact's stiffness (kappa = 1, spring constant known), 2000 samples
/// each pressed to six pull-off forces, 1 % noise, the test's first seed (its sampling phases
/// and noise seeds). Target: <= 30 ms.
void BM_MaugisBothFit(benchmark::State& state, double lambda) {
  namespace ref = mdrsim::maugis_reference;
  const ref::MaugisScales scales{5e-6, 1e6 / 0.75, 0.02};
  const auto approach = with_lever_noise(ref::lever_curve(scales, lambda, true, 1.0, 6, 0.15), 1);
  const auto retract =
      with_lever_noise(ref::lever_curve(scales, lambda, false, 1.0, 6, 0.52), 1001);
  mdrsim::fit::MaugisFitOptions fit_options;
  fit_options.tip = mdrsim::fit::parse_tip("parabolic:radius=5e-6");
  long evaluations = 0;
  double fitted_lambda = 0.0;
  for (auto _ : state) {
    const auto fit = mdrsim::fit::fit_maugis_both(approach, retract, fit_options);
    evaluations = fit.evaluations;
    fitted_lambda = fit.maugis_parameter.value;
    benchmark::DoNotOptimize(fit.work_of_adhesion.value);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["lambda"] = fitted_lambda;
}

/// One evaluation of the Maugis model's parts at lambda = 1: the path sampled (the branch's
/// states), and 2000 depths placed on it.
void BM_MaugisBranch(benchmark::State& state, bool place) {
  const double e = 1e6 / 0.75, w = 0.02;
  const auto tip = mdrsim::fit::parse_tip("parabolic:radius=5e-6");
  const mdrsim::DugdaleLaw law{
      .adhesive_stress = mdrsim::fit::maugis_adhesive_stress(1.0, e, w, 5e-6),
      .work_of_adhesion = w,
      .effective_modulus = e};
  const double deepest = 1e-6;
  const mdrsim::fit::MaugisBranch branch(*tip.profile, law, deepest);
  for (auto _ : state) {
    if (place) {
      double sum = 0.0;
      for (int i = 0; i < 2000; ++i) sum += branch.at(deepest * (1 - 1.5 * i / 1999.0)).force;
      benchmark::DoNotOptimize(sum);
    } else {
      const mdrsim::fit::MaugisBranch built(*tip.profile, law, deepest);
      benchmark::DoNotOptimize(built.lowest_force());
    }
  }
}
BENCHMARK_CAPTURE(BM_MaugisBranch, build, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_MaugisBranch, place_2000, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_MaugisFit, synthetic_retract, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MaugisFit, jpk_retract, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MaugisBothFit, lambda_0_12, 0.12)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MaugisBothFit, lambda_1, 1.0)->Unit(benchmark::kMillisecond);

/// A 64 x 64 map of retracts (4096 curves of 2000 points, the synthetic retract `base` with each
/// curve's own extra noise), in memory as a reader would give it, fitted by `model` through the
/// map runner on 2 threads.
void fit_map64_on_2_threads(benchmark::State& state, const mdrsim::fit::PreparedSegment& base,
                            mdrsim::fit::FitModel model) {
  const double spread = 0.1 * (*std::max_element(base.force.begin(), base.force.end())) / 6;
  std::vector<mdrsim::measured::MeasuredFile> files(1);
  files[0].path = "synthetic-64x64";
  files[0].grid = mdrsim::measured::MapGrid{64, 64, 64e-6, 64e-6, 0.0, 0.0};
  for (long c = 0; c < 64 * 64; ++c) {
    std::mt19937_64 random(static_cast<std::uint64_t>(c) + 2);
    std::normal_distribution<double> noise(0.0, 0.01 * spread);
    mdrsim::measured::Segment retract;
    retract.name = "retract";
    retract.kind = mdrsim::measured::SegmentKind::retract;
    retract.tip_position = base.tip_position;
    for (const double f : base.force) retract.force.push_back(f + noise(random));
    mdrsim::measured::ForceCurve curve;
    curve.label = "index/" + std::to_string(c);
    curve.position =
        mdrsim::measured::MapPosition{(c % 64 - 31.5) * 1e-6, (c / 64 - 31.5) * 1e-6, c};
    curve.segments.push_back(std::move(retract));
    files[0].curves.push_back(std::move(curve));
  }
  mdrsim::fit::CurveFitOptions options;
  options.model = model;
  options.tip = mdrsim::fit::parse_tip("parabolic:radius=5e-6");
  mdrsim::fit::MapRun run;
  run.threads = 2;
  const auto curves = mdrsim::fit::every_curve(files);
  std::size_t fitted = 0;
  // The process's CPU time over every thread: on a shared machine the wall time says how busy
  // it is, this what the map costs.
  const std::clock_t cpu_start = std::clock();
  for (auto _ : state) {
    const auto fits = mdrsim::fit::fit_curves(files, curves, mdrsim::measured::SegmentKind::retract,
                                              options, run);
    fitted = static_cast<std::size_t>(std::count_if(fits.begin(), fits.end(), [](const auto& f) {
      return f.fit.status == mdrsim::fit::FitStatus::fitted;
    }));
  }
  state.counters["curves"] = static_cast<double>(curves.size());
  state.counters["fitted"] = static_cast<double>(fitted);
  state.counters["cpu_ms_per_curve"] =
      1e3 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC /
      static_cast<double>(curves.size() * static_cast<std::size_t>(state.iterations()));
  state.counters["per_curve_ms"] = benchmark::Counter(
      static_cast<double>(curves.size()) * 1e-3,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// JKR's map. Target: <= 30 s.
void BM_JkrMap64On2Threads(benchmark::State& state) {
  fit_map64_on_2_threads(state, synthetic_retract(mdrsim::fit::AdhesionModel::jkr),
                         mdrsim::fit::FitModel::jkr);
}
BENCHMARK(BM_JkrMap64On2Threads)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// Maugis' map (lambda fitted), of the Maugis retract above. Target: <= 3 min.
void BM_MaugisMap64On2Threads(benchmark::State& state) {
  fit_map64_on_2_threads(state, maugis_retract(), mdrsim::fit::FitModel::maugis);
}
BENCHMARK(BM_MaugisMap64On2Threads)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// The real force map (3 curves of 10000 + 4000 points): read, prepared and Hertz fitted to
/// the approaches on 2 threads, per curve. Target: <= 5 ms per curve, reading included.
void BM_ForceMapReadAndFitOn2Threads(benchmark::State& state) {
  const std::string map = std::string(MDRSIM_SOURCE_DIR) +
                          "/tests/data/afm/fmt-jpk-fd_map-data-reference-points.jpk-force-map";
  mdrsim::fit::CurveFitOptions options;
  options.tip = mdrsim::fit::parse_tip("parabolic:radius=1e-5");
  mdrsim::fit::MapRun run;
  run.threads = 2;
  std::size_t curves = 0;
  const std::clock_t cpu_start = std::clock();
  for (auto _ : state) {
    const std::vector<mdrsim::measured::MeasuredFile> files = {
        mdrsim::measured::read_force_curves(map)};
    const auto fits =
        mdrsim::fit::fit_curves(files, mdrsim::fit::every_curve(files),
                                mdrsim::measured::SegmentKind::approach, options, run);
    curves = fits.size();
    benchmark::DoNotOptimize(fits.front().fit.youngs_modulus.value);
  }
  state.counters["curves"] = static_cast<double>(curves);
  state.counters["cpu_ms_per_curve"] =
      1e3 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC /
      static_cast<double>(curves * static_cast<std::size_t>(state.iterations()));
  state.counters["per_curve_ms"] = benchmark::Counter(
      static_cast<double>(curves) * 1e-3,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ForceMapReadAndFitOn2Threads)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The force map's reading alone (unzip, parse, convert), and its reading and preparing with
/// the first guess: what a curve of the map costs before its fit.
void BM_ForceMapRead(benchmark::State& state) {
  const std::string map = std::string(MDRSIM_SOURCE_DIR) +
                          "/tests/data/afm/fmt-jpk-fd_map-data-reference-points.jpk-force-map";
  const mdrsim::fit::TipShape tip = mdrsim::fit::parse_tip("parabolic:radius=1e-5");
  const bool prepare = state.range(0) != 0;
  std::size_t curves = 0;
  for (auto _ : state) {
    const mdrsim::measured::MeasuredFile file = mdrsim::measured::read_force_curves(map);
    curves = file.curves.size();
    if (prepare) {
      for (const auto& curve : file.curves) {
        const auto segment =
            mdrsim::fit::prepare_segment(curve, mdrsim::measured::SegmentKind::approach);
        benchmark::DoNotOptimize(mdrsim::fit::first_guess(segment, tip, 0.5).contact_point);
      }
    }
  }
  state.counters["per_curve_us"] = benchmark::Counter(
      static_cast<double>(curves) * 1e-6,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ForceMapRead)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
