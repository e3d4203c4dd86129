// Google Benchmark: the continuum route's critical point to 1e-10 per profile, its whole run,
// and the row route at rtol 1e-6 on the same scene, for the ratio (the bench's target 12).
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <string>
#include <vector>

#include "controllers/builtin_controllers.hpp"
#include "engine/continuum/continuum_pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace {

/// The [profile] table of a tabulated profile of the points (r_i, f_i).
std::string table_profile(const std::vector<double>& r, const std::vector<double>& f) {
  return fmt::format("type = \"tabulated\"\nr = [{:.17g}]\nf = [{:.17g}]\n", fmt::join(r, ", "),
                     fmt::join(f, ", "));
}

/// A 200-point table of a sphere of radius 1 cm, f = R - sqrt(R^2 - r^2), out to 0.6 R.
std::string tabulated_profile() {
  std::vector<double> r, f;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.006 * i / 199.0;
    r.push_back(x);
    f.push_back(0.01 - std::sqrt(0.01 * 0.01 - x * x));
  }
  return table_profile(r, f);
}

/// scenes/tabulated_power_law.csv: f = 0.8 r^1.5 at 201 points graded towards the tip, out to
/// 1 mm (its image grows like x^1.5 at the centre, where the disk check's quadrature in
/// engine/model/disk_validity.cpp needs its substitution).
std::string tabulated_power_law_profile() {
  std::vector<double> r, f;
  for (int k = 0; k <= 200; ++k) {
    const double x = 1e-3 * (k / 200.0) * (k / 200.0);
    r.push_back(x);
    f.push_back(0.8 * std::pow(x, 1.5));
  }
  return table_profile(r, f);
}

/// The scene of one profile: E = 1 MPa, dgamma = 0.05 J/m^2, glued at 0.5 mm, under the
/// normal control `normal` (fixed load unless named).
std::string scene(const std::string& profile, const std::string& discretization,
                  const std::string& normal = "fixed-load") {
  return fmt::format(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\n{}[loading]\npreload = {{ contact_radius = 5e-4 }}\n"
      "normal = {{ control = \"{}\" }}\n{}",
      profile, normal, discretization);
}

std::string profile_of(const std::string& name) {
  if (name == "sphere") return "type = \"sphere\"\nradius = 0.01\n";
  if (name == "parabolic") return "type = \"parabolic\"\nradius = 0.01\n";
  if (name == "cone") return "type = \"cone\"\nslope_angle_deg = 1.0\n";
  if (name == "power_law") return "type = \"power_law\"\ncoefficient = 3e3\nexponent = 2.5\n";
  if (name == "tabulated_power_law") return tabulated_power_law_profile();
  return tabulated_profile();
}

const std::string kContinuum = "[solver]\nmethod = \"continuum\"\n";
const std::string kRow = "[solver]\nmethod = \"event\"\n[discretization]\nrtol = 1e-6\n";

/// The critical point alone: the branch and the walk (what a sweep point needs).
void critical(benchmark::State& state, const std::string& name, const std::string& normal) {
  const mdrsim::Scene s =
      mdrsim::test::build_scene_text(scene(profile_of(name), kContinuum, normal));
  double force = 0.0;
  for (auto _ : state) {
    mdrsim::ContinuumBranch branch(*s.profile, *s.criterion, s.material,
                                   s.normal.controller->constraint(),
                                   mdrsim::FixedGripsController().constraint(), 0.0);
    const mdrsim::ContinuumPullOff p = mdrsim::continuum_pull_off(branch, s.glued_radius);
    force = p.critical.normal_force;
    state.counters["end"] = static_cast<double>(p.end);
    benchmark::DoNotOptimize(force);
  }
  state.counters["normal_force"] = force;
}

/// The whole run (run_scene): critical point, peak, stages, jumps and work by quadrature.
void run(benchmark::State& state, const std::string& name, const std::string& route) {
  const mdrsim::Scene s = mdrsim::test::build_scene_text(scene(profile_of(name), route));
  mdrsim::RunResult r;
  for (auto _ : state) {
    r = mdrsim::run_scene(s, {});
    benchmark::DoNotOptimize(r.critical);
  }
  state.counters["normal_force"] = r.critical ? r.critical->normal_force : 0.0;
}

/// The reversible JKR approach-retract cycle of scenes/programs/jkr_cycle_reversible.toml as a
/// 1000-point force curve (`sample` events into a vector); the target: <= 50 us.
void cycle_curve(benchmark::State& state) {
  const mdrsim::Scene s = mdrsim::test::build_scene_text(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.05\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"approach\"\n"
      "normal = { control = \"fixed-grips\", to = 6.7844544808348425e-6 }\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = { by = -1.0e-6 }\n"
      "until = \"separation\"\n" +
      kContinuum);
  struct Curve : mdrsim::Observer {
    std::vector<mdrsim::ContactSnapshot> points;
    void on_event(const mdrsim::Event& e) override {
      if (e.kind == mdrsim::EventKind::sample) points.push_back(e.state);
    }
  } curve;
  mdrsim::ObserverList observers;
  observers.add(curve);
  for (auto _ : state) {
    curve.points.clear();
    const mdrsim::RunResult r = mdrsim::run_scene(s, observers, 1000);
    benchmark::DoNotOptimize(r.work);
  }
  state.counters["points"] = static_cast<double>(curve.points.size());
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::err);
  for (const std::string name :
       {"sphere", "parabolic", "cone", "power_law", "tabulated", "tabulated_power_law"}) {
    for (const std::string normal : {"fixed-load", "fixed-grips"}) {
      benchmark::RegisterBenchmark(("continuum_critical/" + normal + "/" + name).c_str(), critical,
                                   name, normal)
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("continuum_run/" + name).c_str(), run, name, kContinuum)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("row_rtol_1e-6/" + name).c_str(), run, name, kRow)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("continuum_cycle_curve_1000/parabolic", cycle_curve)
      ->Unit(benchmark::kMicrosecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
