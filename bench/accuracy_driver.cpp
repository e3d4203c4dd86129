// Speed against accuracy: one CSV row per (case, method, springs, increment), and the targets.
#include <fmt/format.h>
#include <fmt/os.h>
#include <spdlog/spdlog.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "apps/commands.hpp"
#include "bench/bench_cases.hpp"
#include "bench/timing.hpp"
#include "engine/reference/program_reference.hpp"
#include "engine/reference/random_scenes.hpp"
#include "engine/run/run_scene.hpp"

namespace {

using mdrsim::bench::BenchCase;
using mdrsim::bench::seconds_per_run;

/// The continuum route's rtol values on the chart, coarsest first.
const std::vector<double> kContinuumRtols{1e-4, 1e-6, 1e-8, 1e-10};

struct Row {
  std::string case_name, control, method;
  std::int64_t springs;
  double increment;  ///< stepping: base increment as a fraction of the preload's control value
  double error;      ///< relative error of the critical normal force
  double seconds;
  mdrsim::RunCounts counts;
  double rtol = 0.0;  ///< the continuum route's discretization.rtol; 0 on the row
};

std::string scene_text(const BenchCase& c, const std::string& method, std::int64_t springs,
                       bool richardson) {
  mdrsim::test::JkrScenario s = c.scenario;
  s.method = method;
  s.springs = springs;
  s.richardson = richardson;
  if (method == "stepping") s.solver_extra = "max_halvings = 30";
  return s.toml();
}

double relative_error(const BenchCase& c, const mdrsim::RunResult& r) {
  if (!r.critical) return INFINITY;
  const double force = r.critical->normal_force / c.scenario.scales().force;
  return std::abs(force - c.exact_normal_force) / std::abs(c.exact_normal_force);
}

Row measure(const BenchCase& c, const std::string& method, std::int64_t springs, double increment,
            bool richardson) {
  mdrsim::Scene scene = mdrsim::test::build_scene_text(scene_text(c, method, springs, richardson));
  if (method == "stepping") {
    // Relative to the control value at the preload, as the default increment is.
    const double preload_control =
        c.scenario.normal == "fixed-load"
            ? scene.material.effective_modulus *
                  scene.profile->nonadhesive_force_per_modulus(scene.glued_radius)
            : scene.preload_depth;
    scene.solver.step = increment * std::abs(preload_control);
  }
  mdrsim::RunResult result;
  const double seconds = seconds_per_run([&] { result = mdrsim::run_scene(scene, {}); });
  return {c.name,  c.scenario.normal, richardson ? "event+richardson" : method,
          springs, increment,         relative_error(c, result),
          seconds, result.counts};
}

/// The continuum route (no springs) at `rtol`: a point of the chart and target 12.
Row measure_continuum(const BenchCase& c, double rtol) {
  mdrsim::test::JkrScenario s = c.scenario;
  s.method = "continuum";
  s.rtol = rtol;
  const mdrsim::Scene scene = s.build();
  mdrsim::RunResult result;
  const double seconds = seconds_per_run([&] { result = mdrsim::run_scene(scene, {}); });
  Row row{c.name, c.scenario.normal,         "continuum", 0,
          0.0,    relative_error(c, result), seconds,     result.counts};
  row.rtol = rtol;
  return row;
}

/// Target 5: rtol lands within the accuracy, and its own estimate bounds the error.
struct RtolCheck {
  std::int64_t springs, events;
  double error, estimate, seconds;
};

RtolCheck check_rtol(const BenchCase& c, double rtol) {
  mdrsim::test::JkrScenario s = c.scenario;
  s.rtol = rtol;
  const mdrsim::Scene scene = s.build();
  mdrsim::RunResult r;
  const double seconds = seconds_per_run([&] { r = mdrsim::run_scene(scene, {}); });
  const double force = r.critical ? std::abs(r.critical->normal_force) : INFINITY;
  return {r.springs, r.counts.events, relative_error(c, r),
          r.accuracy.critical_error_estimate.value_or(INFINITY) / force, seconds};
}

/// A scene text's run: its result and its own engine time (wall_time_s, best of three).
mdrsim::RunResult timed_run(const std::string& text, double& seconds) {
  const mdrsim::Scene scene = mdrsim::test::build_scene_text(text);
  mdrsim::RunResult r = mdrsim::run_scene(scene, {});
  seconds = r.wall_time_s;
  for (int i = 0; i < 2 && r.wall_time_s < 1.0; ++i) {
    r = mdrsim::run_scene(scene, {});
    seconds = std::min(seconds, r.wall_time_s);
  }
  return r;
}

std::string cone_text(double theta, const char* normal) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"cone\"\nslope_angle_deg = {}\n[loading]\npreload = {{ "
      "contact_radius = 1e-4 }}\nnormal = {{ control = \"{}\" }}\n[solver]\nmethod = \"event\"\n"
      "[discretization]\nrtol = 1e-4\n",
      theta, normal);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}

/// ns per event of an event-method pull-off at 1e6 springs (Fig. 3a scene, u = d0).
double ns_per_event(const std::string& criterion, const std::string& extra) {
  mdrsim::test::JkrScenario s;
  s.normal = "fixed-grips";
  s.tangential_displacement = 1.0;
  s.criterion = criterion;
  s.criterion_extra = extra;
  s.springs = 1'000'000;
  const mdrsim::Scene scene = s.build();
  mdrsim::RunResult r;
  const double seconds = seconds_per_run([&] { r = mdrsim::run_scene(scene, {}); });
  return 1e9 * seconds / static_cast<double>(r.counts.events);
}

struct CycleRun {
  std::int64_t springs;
  double seconds;
  std::int64_t events;
  std::size_t jumps;
};

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// The fastest row of a method that reaches `accuracy` reliably: the row and every row of
/// the same line (method and increment) with more springs are within it. Under fixed grips
/// the plain rows' error is a sawtooth, and a lucky row does not count.
const Row* fastest(const std::vector<Row>& rows, const std::string& case_name,
                   const std::string& control, const std::string& method, double accuracy) {
  const auto same_line = [&](const Row& a, const Row& b) {
    return a.case_name == b.case_name && a.control == b.control && a.method == b.method &&
           a.increment == b.increment;
  };
  const Row* best = nullptr;
  for (const Row& r : rows) {
    if (r.case_name != case_name || r.control != control || r.method != method) continue;
    const bool reliable = std::all_of(rows.begin(), rows.end(), [&](const Row& other) {
      return !same_line(r, other) || other.springs < r.springs || other.error <= accuracy;
    });
    if (!reliable) continue;
    if (!best || r.seconds < best->seconds) best = &r;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path = "speed_accuracy.csv";
  bool full = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--full") == 0) {
      full = true;
    } else if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out_path = argv[++i];
    } else {
      fmt::print(stderr, "usage: mdrsim_accuracy [--out PATH.csv] [--full]\n");
      return 2;
    }
  }
  // The program cycles run before anything else, so that the growth of the peak RSS between
  // 1e6 and 1e7 springs is theirs.
  std::vector<CycleRun> cycles;
  double cycles_rss_growth = 0.0;
  for (const std::int64_t springs : {std::int64_t{1'000'000}, std::int64_t{10'000'000}}) {
    const double rss_before = peak_rss_mb();
    double seconds = 0.0;
    const mdrsim::RunResult r = timed_run(mdrsim::bench::cycle_text(springs), seconds);
    if (springs == 10'000'000) cycles_rss_growth = peak_rss_mb() - rss_before;
    cycles.push_back({springs, seconds, r.counts.events, r.jumps.size()});
  }
  spdlog::set_level(
      spdlog::level::err);  // under-resolved rows on purpose: their warnings are noise here
  std::vector<Row> rows;
  const std::vector<std::int64_t> event_springs{100,   300,    1000,   3000,    10000,
                                                30000, 100000, 300000, 1000000, 10000000};
  const std::vector<std::int64_t> richardson_springs{64, 100, 250, 500, 1000, 2500, 5000};
  const std::vector<std::int64_t> stepping_springs{1000, 3000, 10000, 30000, 100000};
  const std::vector<double> increments{1e-2, 1e-3, 1e-4};
  for (const BenchCase& c : mdrsim::bench::paper_cases()) {
    for (const std::int64_t n : event_springs) {
      if (n > 1000000 && (!full && c.name != "jkr")) continue;
      rows.push_back(measure(c, "event", n, 0.0, false));
    }
    for (const std::int64_t n : richardson_springs)
      rows.push_back(measure(c, "event", n, 0.0, true));
    for (const std::int64_t n : stepping_springs) {
      for (const double h : increments) {
        if (n == 100000 && h < 1e-3 && !full) continue;
        rows.push_back(measure(c, "stepping", n, h, false));
      }
    }
    for (const double rtol : kContinuumRtols) rows.push_back(measure_continuum(c, rtol));
    fmt::print(stderr, "bench: {} {} done\n", c.name, c.scenario.normal);
  }

  auto csv = fmt::output_file(out_path);
  csv.print(
      "case,control,method,springs,increment,relative_error,time_s,events,steps,halvings,rtol\n");
  for (const Row& r : rows) {
    csv.print("{},{},{},{},{},{},{},{},{},{},{}\n", r.case_name, r.control, r.method, r.springs,
              r.method == "stepping" ? fmt::format("{}", r.increment) : std::string(), r.error,
              r.seconds, r.counts.events, r.counts.steps, r.counts.halvings,
              r.rtol > 0.0 ? fmt::format("{}", r.rtol) : std::string());
  }
  csv.close();

  // The targets. An accuracy target (a wrong number) fails the run. A speed target is
  // measured again, up to twice, before a MISS is declared (a busy machine slows a run, it
  // never speeds one up, so the fastest measurement counts), and never fails the run: the
  // main job fails on a wrong number only.
  bool accurate = true;
  int speed_missed = 0;
  const auto accuracy = [&](bool met, const std::string& text) {
    accurate = accurate && met;
    fmt::print("{} {}\n", met ? "MET " : "MISS", text);
  };
  // `check(again)` returns whether the target is met and its line; with again = true it
  // measures anew first.
  const auto speed = [&](const std::function<std::pair<bool, std::string>(bool)>& check) {
    auto [met, text] = check(false);
    for (int again = 0; !met && again < 2; ++again) std::tie(met, text) = check(true);
    if (!met) ++speed_missed;
    fmt::print("{} {}\n", met ? "MET " : "MISS", text);
  };
  // A row of the table measured again; the faster time is kept.
  const auto remeasure = [&](Row& r) {
    for (const BenchCase& c : mdrsim::bench::paper_cases()) {
      if (c.name != r.case_name || c.scenario.normal != r.control) continue;
      const bool richardson = r.method == "event+richardson";
      const Row again =
          measure(c, richardson ? "event" : r.method, r.springs, r.increment, richardson);
      r.seconds = std::min(r.seconds, again.seconds);
    }
  };
  const auto rows_of = [&](const std::string& control, const std::string& method) {
    std::vector<Row*> out;
    for (Row& r : rows) {
      if (r.case_name == "jkr" && r.control == control && r.method == method) out.push_back(&r);
    }
    return out;
  };
  for (const char* control : {"fixed-load", "fixed-grips"}) {
    for (Row* r : rows_of(control, "event")) {
      if (r->springs != 1000000 && r->springs != 10000000) continue;
      const double limit = r->springs == 1000000 ? 0.1 : 1.0;
      speed([&, r, limit](bool again) {
        if (again) remeasure(*r);
        return std::pair{r->seconds < limit,
                         fmt::format("1. {} {:.0e} springs: {:.4f} s (< {} s)", control,
                                     static_cast<double>(r->springs), r->seconds, limit)};
      });
    }
    // Linear cost: time per spring from 1e4 to 1e7 springs varies by less than a factor 2.
    speed([&](bool again) {
      std::vector<double> per_spring;
      for (Row* r : rows_of(control, "event")) {
        if (r->springs < 10000) continue;
        if (again) remeasure(*r);
        per_spring.push_back(r->seconds / static_cast<double>(r->springs));
      }
      const auto [lo, hi] = std::minmax_element(per_spring.begin(), per_spring.end());
      return std::pair{*hi < 2.0 * *lo,
                       fmt::format("1. {} cost per spring 1e4..1e7: {:.1f} to {:.1f} ns", control,
                                   *lo * 1e9, *hi * 1e9)};
    });
  }
  accuracy(peak_rss_mb() < 200.0,
           fmt::format("1. peak memory of the whole bench (1e7-spring runs included): {:.1f} MB "
                       "(< 200 MB)",
                       peak_rss_mb()));
  for (const char* control : {"fixed-load", "fixed-grips"}) {
    const Row* event = fastest(rows, "jkr", control, "event+richardson", 1e-4);
    const Row* plain = fastest(rows, "jkr", control, "event", 1e-4);
    const Row* stepping = fastest(rows, "jkr", control, "stepping", 1e-4);
    accuracy(event && stepping,
             fmt::format("2. {}: event+richardson and stepping reach 1e-4", control));
    if (event && stepping) {
      Row* fast = const_cast<Row*>(event);
      speed([&, fast](bool again) {
        if (again) remeasure(*fast);
        return std::pair{
            stepping->seconds >= 100.0 * fast->seconds,
            fmt::format("2. {} at 1e-4: event+richardson {:.2e} s ({} springs), plain event "
                        "{:.2e} s, stepping {:.2e} s ({} springs, increment {}): {:.0f}x",
                        control, fast->seconds, fast->springs, plain ? plain->seconds : NAN,
                        stepping->seconds, stepping->springs, stepping->increment,
                        stepping->seconds / fast->seconds)};
      });
    }
    const Row* precise = fastest(rows, "jkr", control, "event+richardson", 1e-6);
    accuracy(precise != nullptr, precise
                                     ? fmt::format("3. {} within 1e-6: {} springs, error {:.1e}",
                                                   control, precise->springs, precise->error)
                                     : fmt::format("3. {}: 1e-6 never reached", control));
    if (precise) {
      Row* row = const_cast<Row*>(precise);
      speed([&, row](bool again) {
        if (again) remeasure(*row);
        return std::pair{row->seconds < 1e-3, fmt::format("3. {} within 1e-6: {:.2e} s (< 1 ms)",
                                                          control, row->seconds)};
      });
    }
  }
  // 4. The Fig. 3a sweep through the command's own code, both controls, two threads.
  speed([&](bool) {
    const double sweep_seconds = seconds_per_run([&] {
      for (const char* scene : {"fig3a_fixed_grips.toml", "fig3a_fixed_load.toml"}) {
        mdrsim::cli::SweepOptions options;
        options.scene = std::string(MDRSIM_SOURCE_DIR) + "/scenes/" + scene;
        options.vary = {"loading.tangential.displacement=0:9.04593930777979e-06:41"};
        options.csv = "/dev/null";
        options.threads = 2;
        mdrsim::cli::sweep_command(options);
      }
    });
    return std::pair{sweep_seconds < 1.0,
                     fmt::format("4. Fig. 3a sweep, 41 points x 2 controls, 2 threads: {:.3f} s",
                                 sweep_seconds)};
  });
  // Target 11: a sweep scales with its threads (scenes built in the workers, rows streamed).
  // Open: a target not met prints OPEN (a shared machine may not give two whole cores).
  {
    mdrsim::cli::SweepOptions options;
    options.scene = std::string(MDRSIM_SOURCE_DIR) + "/scenes/fig3a_fixed_grips.toml";
    options.vary = {"loading.tangential.displacement=0:9.04593930777979e-06:2000"};
    options.sets = {"discretization.springs=1000", "discretization.extrapolation=richardson"};
    options.csv = "/dev/null";
    // The process's CPU time over the wall time says how many cores the run was given.
    const auto cpu_seconds = [] {
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
             1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    };
    double best[3] = {1e300, 1e300, 1e300};
    double cores = 0.0;  // of the fastest two-thread run
    for (int repeat = 0; repeat < 5; ++repeat) {
      for (const int threads : {1, 2}) {
        options.threads = threads;
        const double cpu = cpu_seconds();
        const auto start = std::chrono::steady_clock::now();
        mdrsim::cli::sweep_command(options);
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (wall < best[threads]) {
          best[threads] = wall;
          if (threads == 2) cores = (cpu_seconds() - cpu) / wall;
        }
      }
    }
    const double speedup = best[1] / best[2];
    fmt::print("{} {}\n", speedup >= 1.8 ? "MET " : "OPEN",
               fmt::format("11. sweep of 2000 scenes of 1000 springs (Richardson): 1 thread "
                           "{:.3f} s, 2 threads {:.3f} s: {:.2f}x (>= 1.8x on 2 cores; the two "
                           "threads were given {:.2f} cores)",
                           best[1], best[2], speedup, cores));
  }
  for (const BenchCase& c : mdrsim::bench::paper_cases()) {
    if (c.name != "jkr") continue;
    for (const double rtol : {1e-3, 1e-4, 1e-5, 1e-6}) {
      const RtolCheck check = check_rtol(c, rtol);
      accuracy(check.error <= rtol && check.error <= check.estimate && check.estimate <= rtol,
               fmt::format("5. {} rtol {}: error {:.2e} <= estimate {:.2e} <= rtol; finest row "
                           "{} springs, {} events in all, {:.2e} s",
                           c.scenario.normal, rtol, check.error, check.estimate, check.springs,
                           check.events, check.seconds));
    }
  }
  // Target 6: folds far below the glued radius in seconds, not with 1e9 uniform springs.
  const double e_star = 1e6, dgamma = 0.05;
  for (const double theta : {45.0, 55.0, 65.0, 75.0, 85.0}) {
    const double t3 = std::pow(std::tan(theta * std::numbers::pi / 180.0), 3);
    for (const char* normal : {"fixed-load", "fixed-grips"}) {
      const double exact = (std::strcmp(normal, "fixed-load") == 0 ? -54.0 : -6.0) * dgamma *
                           dgamma / (std::numbers::pi * e_star * t3);
      double seconds = 0.0;
      const mdrsim::RunResult r = timed_run(cone_text(theta, normal), seconds);
      const double error = r.critical ? std::abs(r.critical->normal_force / exact - 1.0) : 1.0;
      accuracy(
          error <= 1e-4,
          fmt::format("6. cone {} deg glued at 0.1 mm, {}, rtol 1e-4: error {:.1e}, fold at "
                      "{:.1e} of the glued radius",
                      theta, normal, error, r.critical ? r.critical->contact_radius / 1e-4 : NAN));
      speed([&, seconds](bool again) mutable {
        if (again) timed_run(cone_text(theta, normal), seconds);
        return std::pair{seconds < 10.0, fmt::format("6. cone {} deg glued at 0.1 mm, {}, rtol "
                                                     "1e-4: {:.2e} s (< 10 s)",
                                                     theta, normal, seconds)};
      });
    }
  }
  for (const BenchCase& c : mdrsim::bench::paper_cases()) {
    if (c.name != "jkr") continue;
    mdrsim::test::JkrScenario far = c.scenario;
    far.glued_radius = 1000.0;
    far.rtol = 1e-4;
    double seconds = 0.0;
    const mdrsim::RunResult r = timed_run(far.toml(), seconds);
    const double error = relative_error(c, r);
    accuracy(error <= 1e-4, fmt::format("6. parabola glued at 1000 a0, {}, rtol 1e-4: error {:.1e}",
                                        c.scenario.normal, error));
    speed([&, seconds](bool again) mutable {
      if (again) timed_run(far.toml(), seconds);
      return std::pair{seconds < 10.0,
                       fmt::format("6. parabola glued at 1000 a0, {}, rtol 1e-4: {:.2e} s (< 10 s)",
                                   c.scenario.normal, seconds)};
    });
    mdrsim::test::JkrScenario fig2 = c.scenario;
    fig2.rtol = 1e-6;
    const mdrsim::RunResult precise = timed_run(fig2.toml(), seconds);
    accuracy(
        relative_error(c, precise) <= 1e-6,
        fmt::format(
            "6. Fig. 2 {} with rtol = 1e-6 alone: error {:.1e} by {}", c.scenario.normal,
            relative_error(c, precise),
            precise.accuracy.route == mdrsim::Accuracy::Route::richardson ? "richardson" : "row"));
    speed([&, seconds](bool again) mutable {
      if (again) timed_run(fig2.toml(), seconds);
      return std::pair{seconds < 1e-3,
                       fmt::format("6. Fig. 2 {} with rtol = 1e-6 alone: engine time {:.2e} s "
                                   "(< 1 ms)",
                                   c.scenario.normal, seconds)};
    });
  }
  // The cost of rtol over the random set of the guarantee test.
  const auto set = mdrsim::test::random_scenes(20240611, 120);
  for (const double rtol : {1e-4, 1e-6}) {
    std::vector<double> times, events;
    int misses = 0;
    for (const auto& scene : set) {
      double seconds = 0.0;
      const mdrsim::RunResult r = timed_run(
          scene.toml_without_discretization +
              fmt::format("[solver]\nmethod = \"event\"\n[discretization]\nrtol = {}\n", rtol),
          seconds);
      times.push_back(seconds);
      events.push_back(static_cast<double>(r.counts.events));
      const double exact = scene.reference.point.normal_force;
      if (!r.critical || std::abs(r.critical->normal_force / exact - 1.0) > rtol) ++misses;
    }
    accuracy(misses == 0,
             fmt::format("7. random set, {} scenes, rtol {}: {} misses; engine time median {:.2e} "
                         "s, worst {:.2e} s; events median {:.0f}, worst {:.0f}",
                         set.size(), rtol, misses, median(times),
                         *std::max_element(times.begin(), times.end()), median(events),
                         *std::max_element(events.begin(), events.end())));
  }
  // mode-dependent against the closed-form criteria, per event: a ratio within one run.
  double mixed = 0.0;
  speed([&](bool) {
    mixed = ns_per_event("mode-mixed", "");
    const double dependent = ns_per_event("mode-dependent", "lambda = 0.5");
    return std::pair{dependent <= 2.0 * mixed,
                     fmt::format("8. per event at 1e6 springs: mode-dependent (lambda 0.5) {:.1f} "
                                 "ns, mode-mixed {:.1f} ns: {:.2f}x (<= 2x)",
                                 dependent, mixed, dependent / mixed)};
  });
  // Target 9: loading programs (run first, above), against the shorthand's pull-off. Its speed
  // lines print OPEN when missed and do not fail the run (a busy machine can miss them).
  const auto report_open = [&](bool met, const std::string& text) {
    fmt::print("{} {}\n", met ? "MET " : "OPEN", text);
  };
  for (const CycleRun& c : cycles) {
    const double limit = c.springs == 1'000'000 ? 0.1 : 1.0;
    accuracy(c.jumps == 2, fmt::format("9. the cycle of {:.0e} springs jumps in and out: {} jumps",
                                       static_cast<double>(c.springs), c.jumps));
    report_open(
        c.seconds < limit,
        fmt::format("9. approach-retract cycle (reversible JKR, fixed grips), {:.0e} springs: "
                    "{:.3f} s (< {} s), {} events, {} jumps",
                    static_cast<double>(c.springs), c.seconds, limit, c.events, c.jumps));
  }
  accuracy(cycles_rss_growth < 1.0,
           fmt::format("9. memory of the cycles, run first: peak RSS grew {:.2f} MB from 1e6 to "
                       "1e7 springs (< 1 MB: nothing is stored per spring)",
                       cycles_rss_growth));
  const double cycle_ns_per_event =
      1e9 * cycles.front().seconds / static_cast<double>(cycles.front().events);
  report_open(
      cycle_ns_per_event <= 1.5 * mixed,
      fmt::format("9. per event at 1e6 springs: program cycle {:.1f} ns, shorthand pull-off "
                  "{:.1f} ns: {:.2f}x (<= 1.5x)",
                  cycle_ns_per_event, mixed, cycle_ns_per_event / mixed));
  // One approach-retract curve to 1e-4 in F/F0, by Richardson over rows of 64, 128 and 256
  // springs: the jump in, the end of the approach and the fold against eqs. 18-19.
  {
    const mdrsim::Scene scene = mdrsim::test::build_scene_text(mdrsim::bench::cycle_text(128) +
                                                               "extrapolation = \"richardson\"\n");
    mdrsim::RunResult r;
    const double seconds = seconds_per_run([&] { r = mdrsim::run_scene(scene, {}); });
    const double force = 1.5 * std::numbers::pi * 0.01 * 0.05;  // F0 [N]
    const double depth = std::cbrt(3.0 * std::numbers::pi * std::numbers::pi * 0.01 * 0.05 * 0.05 /
                                   (64.0 * 1e6 * 1e6));  // d0 [m]
    const auto expected = mdrsim::program_reference::reversible_jkr_cycle(2e-5 / depth);
    double error = 1.0;
    if (r.jumps.size() == 2 && r.stages.size() == 2) {
      error = std::max(
          {std::abs(r.jumps[0].after.normal_force / force - expected.jump_in_after.normal_force),
           std::abs(r.stages[0].end.normal_force / force - expected.approach_end.normal_force),
           std::abs(r.jumps[1].critical.normal_force / force -
                    expected.retract_critical.normal_force)});
    }
    report_open(error <= 1e-4 && seconds < 150e-6,
                fmt::format("9. one approach-retract curve to 1e-4 in F/F0 (richardson, rows of "
                            "64/128/256 springs): largest error {:.1e} F0, {:.0f} us (< 150 us)",
                            error, 1e6 * seconds));
  }
  // Target 12: the continuum route within rtol of the closed form on every paper case, and
  // the whole run at 1e-10 against the row route at rtol 1e-6 (the same scene with method =
  // "event"), each by its engine time (wall_time_s, best of three), as target 6 times it.
  for (const Row& r : rows) {
    if (r.method != "continuum") continue;
    accuracy(r.error <= r.rtol,
             fmt::format("12. continuum {} {} rtol {:.0e}: error {:.1e} (<= rtol), {:.1f} us",
                         r.case_name, r.control, r.rtol, r.error, 1e6 * r.seconds));
  }
  for (const BenchCase& c : mdrsim::bench::paper_cases()) {
    if (c.name != "jkr") continue;
    mdrsim::test::JkrScenario row = c.scenario, continuum = c.scenario;
    row.rtol = 1e-6;
    continuum.method = "continuum";
    continuum.rtol = 1e-10;
    double row_seconds = 0.0, continuum_seconds = 0.0;
    timed_run(row.toml(), row_seconds);
    timed_run(continuum.toml(), continuum_seconds);
    fmt::print(
        "{} 12. jkr {}: continuum at rtol 1e-10 {:.1f} us, the row at rtol 1e-6 {:.1f} us: "
        "{:.0f}x (>= 50x; engine time)\n",
        row_seconds >= 50.0 * continuum_seconds ? "MET " : "OPEN", c.scenario.normal,
        1e6 * continuum_seconds, 1e6 * row_seconds, row_seconds / continuum_seconds);
  }
  if (speed_missed > 0) {
    fmt::print(
        "speed: {} target(s) missed after measuring each three times: the machine may be busy; "
        "speed targets do not fail the run\n",
        speed_missed);
  }
  fmt::print("rows written to {}\n", out_path);
  return accurate ? 0 : 1;
}
