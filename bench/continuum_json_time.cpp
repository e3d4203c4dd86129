// CSV driver: the continuum route's own JSON time (wall_time_s) beside its bare root search.
//
// 130 seeded random shorthand scenes (engine/reference/random_scenes, seed 20240611) and the
// 200-point tabulated sphere, each read from its TOML text and run through run_scene at
// rtol 1e-10 with method = "continuum" (as `mdrsim run` does). Per scene, over 41 runs of each
// taken in turn: the median of the JSON's wall_time_s, of the bare critical point
// (ContinuumBranch and continuum_pull_off, what mdrsim_continuum_bench's continuum_critical
// times) and their ratio, and the scene's build from its text (not in wall_time_s);
// a last line sums up the medians. Usage: mdrsim_continuum_json_time [out.csv] (stdout if none).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "controllers/builtin_controllers.hpp"
#include "engine/continuum/continuum_pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/random_scenes.hpp"
#include "engine/run/run_scene.hpp"

namespace {

constexpr std::uint64_t kSeed = 20240611;
constexpr int kCount = 130;
constexpr int kRuns = 41;  ///< runs of each per scene, whose medians are reported
const std::string kRoute = "[solver]\nmethod = \"continuum\"\n[discretization]\nrtol = 1e-10\n";

struct NamedScene {
  std::string name;
  std::string toml;
};

/// The 200-point table of a sphere of radius 1 cm out to 0.6 R (continuum_bench's), glued at
/// 0.5 mm under `normal`.
NamedScene tabulated_sphere(const std::string& normal) {
  std::vector<double> r, f;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.006 * i / 199.0;
    r.push_back(x);
    f.push_back(0.01 - std::sqrt(0.01 * 0.01 - x * x));
  }
  return {"tabulated_sphere_200_" + normal,
          fmt::format("[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\n"
                      "work_of_adhesion = 0.05\n[profile]\ntype = \"tabulated\"\nr = [{:.17g}]\n"
                      "f = [{:.17g}]\n[loading]\npreload = {{ contact_radius = 5e-4 }}\n"
                      "normal = {{ control = \"{}\" }}\n",
                      fmt::join(r, ", "), fmt::join(f, ", "), normal)};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Seconds of one bare critical point, as run_continuum builds its branch.
double root_search_once(const mdrsim::Scene& s) {
  const mdrsim::AffineConstraint tangential = s.tangential
                                                  ? s.tangential->controller->constraint()
                                                  : mdrsim::FixedGripsController().constraint();
  const double held = s.tangential ? s.tangential->held_value : 0.0;
  const auto started = std::chrono::steady_clock::now();
  mdrsim::ContinuumBranch branch(*s.profile, *s.criterion, s.material,
                                 s.normal.controller->constraint(), tangential, held);
  const mdrsim::ContinuumPullOff p = mdrsim::continuum_pull_off(branch, s.glued_radius);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  volatile double force = p.critical.normal_force;
  (void)force;
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::err);
  std::FILE* out = argc > 1 ? std::fopen(argv[1], "w") : stdout;
  if (out == nullptr) {
    fmt::print(stderr, "cannot write {}\n", argv[1]);
    return 2;
  }
  std::vector<NamedScene> scenes;
  for (const mdrsim::test::RandomScene& r : mdrsim::test::random_scenes(kSeed, kCount))
    scenes.push_back({r.name, r.toml_without_discretization});
  scenes.push_back(tabulated_sphere("fixed-load"));
  scenes.push_back(tabulated_sphere("fixed-grips"));

  fmt::print(out, "scene,status,json_wall_time_s,root_search_s,ratio,build_s\n");
  std::vector<double> ratios, json_times, root_times;
  for (const NamedScene& n : scenes) {
    const std::string text = n.toml + kRoute;
    const auto built = std::chrono::steady_clock::now();
    const mdrsim::Scene s = mdrsim::test::build_scene_text(text);
    const double build_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - built).count();
    // Interleaved, so that the shared machine's load weighs on both alike.
    std::vector<double> times, roots;
    mdrsim::RunResult r;
    for (int k = 0; k < kRuns; ++k) {
      r = mdrsim::run_scene(s, {});
      times.push_back(r.wall_time_s);
      roots.push_back(root_search_once(s));
    }
    const double json = median(times);
    const double root = median(roots);
    fmt::print(out, "{},{},{:.4g},{:.4g},{:.3g},{:.4g}\n", n.name, mdrsim::to_string(r.status),
               json, root, json / root, build_s);
    std::fflush(out);
    if (n.name.rfind("tabulated", 0) != 0) {
      ratios.push_back(json / root);
      json_times.push_back(json);
      root_times.push_back(root);
    }
  }
  fmt::print(out,
             "# random set ({} scenes): median json {:.3g} s, median root search {:.3g} s, "
             "median ratio {:.3g}, max ratio {:.3g}, max json {:.3g} s\n",
             ratios.size(), median(json_times), median(root_times), median(ratios),
             *std::max_element(ratios.begin(), ratios.end()),
             *std::max_element(json_times.begin(), json_times.end()));
  if (out != stdout) std::fclose(out);
  return 0;
}
