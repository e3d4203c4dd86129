// The two engines against each other: each shorthand scene and its equal program.
//
//   build/bench/mdrsim_engines [--out PATH.csv] [--repeats N] [--part springs|rtol|all]
//                              [--case fig2|tangential-u|tangential-F|cone|cone-u]
//
// Every shorthand scene (preload to the glued radius, tangential load, pull-off) is also run as
// its three-stage program (tests/engine/run/shorthand_program_grid_test.cpp builds the same).
// Part `springs`: one row of 1e4, 1e5 and 1e6 springs, events and wall time of each engine,
// ns per event and their ratio. Part `rtol`: discretization.rtol 1e-4, 1e-6 and 1e-8, wall
// time, the finest row's springs and whether rtol was met. Each measurement is the best of
// `repeats` runs (default 3), the engines interleaved (shorthand, program, shorthand, ...) so
// that the load of a shared machine hits both alike. CSV rows to --out (default standard
// output; with --out, one line per row on standard output); progress to standard error. Exit
// code 1 where the engines disagree (status, or critical force beyond 1e-9 on one row and 2 rtol
// with rtol), 2 for bad arguments.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace {

using mdrsim::RunResult;
using mdrsim::Scene;

constexpr const char* kMaterial =
    "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n";
constexpr const char* kParabola = "[profile]\ntype = \"parabolic\"\nradius = 0.01\n";
constexpr double kTwoA0 = 5.209397078678047e-4;  ///< 2 a0 of the Fig. 2 scenes [m]
constexpr double kD0 = 2.2614848269449475e-6;    ///< d0 of the Fig. 2 scenes [m]
constexpr double kF0 = 2.35619449019234e-3;      ///< F0 of the Fig. 2 scenes [N]

/// A shorthand scene by its parts; the program of the same path is derived from them.
struct Case {
  std::string name;
  std::string profile;             ///< the [profile] table
  std::string criterion;           ///< detachment.criterion
  std::string normal;              ///< "fixed-grips" or "fixed-load"
  double glued_radius;             ///< [m]
  std::string tangential_control;  ///< empty: no tangential load
  double tangential = 0.0;         ///< the held displacement [m] or force [N]
};

std::vector<Case> cases() {
  const std::string cone = "[profile]\ntype = \"cone\"\nslope_angle_deg = 10.0\n";
  return {
      // scenes/fig2_*.toml
      {"fig2", kParabola, "mode-mixed", "fixed-grips", kTwoA0, "", 0.0},
      {"fig2", kParabola, "mode-mixed", "fixed-load", kTwoA0, "", 0.0},
      // scenes/fig3a_fixed_grips.toml (u = d0) under the three criteria
      {"tangential-u", kParabola, "mode-mixed", "fixed-grips", kTwoA0, "fixed-grips", kD0},
      {"tangential-u", kParabola, "deformation", "fixed-grips", kTwoA0, "fixed-grips", kD0},
      {"tangential-u", kParabola, "stress", "fixed-grips", kTwoA0, "fixed-grips", kD0},
      // scenes/tangential_force_fixed_load.toml (1 F0)
      {"tangential-F", kParabola, "mode-mixed", "fixed-load", kTwoA0, "fixed-load", kF0},
      // scenes/cone_fixed_*.toml
      {"cone", cone, "mode-mixed", "fixed-grips", 2.0e-5, "", 0.0},
      {"cone", cone, "mode-mixed", "fixed-load", 2.0e-5, "", 0.0},
      // sheared by 1 um: under fixed grips the glue shears off at a compression, and the
      // shorthand runs as its program, which follows the springs it leaves pressed
      // (engine/run/shorthand_as_program.hpp): the same numbers, the same engine
      {"cone-u", cone, "mode-mixed", "fixed-grips", 2.0e-5, "fixed-grips", 1.0e-6},
      {"cone-u", cone, "mode-mixed", "fixed-load", 2.0e-5, "fixed-grips", 1.0e-6},
  };
}

Scene build(const std::string& text) {
  return mdrsim::SceneDocument::from_text(text, "engines_bench.toml")
      .build(mdrsim::Registries::builtin());
}

std::string head(const Case& c, const std::string& discretization) {
  // method = "event": the row at rtol too (rtol alone takes the continuum route).
  return fmt::format(
      "{}{}[detachment]\ncriterion = \"{}\"\n[solver]\nmethod = \"event\"\n[discretization]\n{}\n",
      kMaterial, c.profile, c.criterion, discretization);
}

std::string shorthand_text(const Case& c, const std::string& discretization) {
  const std::string tangential =
      c.tangential_control.empty()
          ? std::string()
          : fmt::format("tangential = {{ control = \"{}\", {} = {:.17g} }}\n", c.tangential_control,
                        c.tangential_control == "fixed-load" ? "force" : "displacement",
                        c.tangential);
  return head(c, discretization) +
         fmt::format(
             "[loading]\npreload = {{ contact_radius = {:.17g} }}\n{}normal = {{ control "
             "= \"{}\" }}\n",
             c.glued_radius, tangential, c.normal);
}

/// The same path as a program: a fixed-grips preload to the shorthand's preload depth (the
/// glued radius), the tangential load at the held normal control, and the pull-off until
/// separation at one preload value (depth or force) per unit of the stage parameter.
std::string program_text(const Case& c, const Scene& shorthand, const std::string& discretization) {
  const std::string tangential =
      c.tangential_control.empty()
          ? std::string()
          : fmt::format("tangential = {{ control = \"{}\", to = {:.17g} }}\n", c.tangential_control,
                        c.tangential);
  const double rate =
      c.normal == "fixed-load" ? std::abs(shorthand.preload_force) : shorthand.preload_depth;
  return head(c, discretization) +
         fmt::format(
             "[loading]\n[[loading.stage]]\nname = \"preload\"\nnormal = {{ control = "
             "\"fixed-grips\", to = {:.17g} }}\n[[loading.stage]]\nname = \"tangential\"\n"
             "normal = {{ control = \"{}\" }}\n{}[[loading.stage]]\nname = \"pull-off\"\n"
             "normal = {{ by = {:.17g} }}\nuntil = \"separation\"\n",
             shorthand.preload_depth, c.normal, tangential, -rate);
}

struct Best {
  double seconds = INFINITY;
  RunResult result;
};

double seconds_of(const Scene& scene, RunResult& result) {
  const auto start = std::chrono::steady_clock::now();
  result = mdrsim::run_scene(scene, {});
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The program's first stage alone: what its preload costs (the shorthand sets it in closed
/// form; the program presses the springs one event each).
std::string preload_text(const std::string& program) {
  return program.substr(0, program.find("[[loading.stage]]\nname = \"tangential\""));
}

/// Best of `repeats` runs of each scene, interleaved; fewer repeats once a round takes > 20 s.
std::vector<Best> measure(const std::vector<const Scene*>& scenes, int repeats) {
  std::vector<Best> best(scenes.size());
  for (int i = 0; i < repeats; ++i) {
    double round = 0.0;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      RunResult r;
      const double t = seconds_of(*scenes[k], r);
      if (t < best[k].seconds) best[k] = {t, std::move(r)};
      round += t;
    }
    if (round > 20.0) break;
  }
  return best;
}

std::optional<double> critical_force(const RunResult& r) {
  if (!r.critical) return std::nullopt;
  return r.critical->normal_force;
}

/// |F_program - F_shorthand| / |F_shorthand|, or "none" where one has no critical point.
std::string relative_difference(const RunResult& s, const RunResult& p) {
  const auto fs = critical_force(s), fp = critical_force(p);
  if (!fs || !fp) return fs || fp ? "one-sided" : "none";
  return fmt::format("{:.2e}", std::abs(*fp - *fs) / std::abs(*fs));
}

/// The engines agree: the same status and, with a critical point, the same force -- to 1e-9
/// on one row (the same sums in another order, as ShorthandProgramGrid checks) and to 2 rtol
/// where both met rtol (each within rtol of the continuum by its estimate).
bool agree(double rtol, const RunResult& s, const RunResult& p) {
  const auto fs = critical_force(s), fp = critical_force(p);
  if (s.status != p.status || fs.has_value() != fp.has_value()) return false;
  if (!fs) return true;
  if (rtol > 0.0 && !(s.accuracy.rtol_met && p.accuracy.rtol_met)) return true;
  return std::abs(*fp - *fs) <= (rtol > 0.0 ? 2.0 * rtol : 1e-9) * std::abs(*fs);
}

std::string force(const RunResult& r) {
  const auto f = critical_force(r);
  return f ? fmt::format("{:.10g}", *f) : std::string();
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path;
  std::string part = "all";
  std::string only;  // one case name alone, e.g. fig2
  int repeats = 3;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out_path = argv[++i];
    } else if (std::strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--part") == 0 && i + 1 < argc) {
      part = argv[++i];
    } else if (std::strcmp(argv[i], "--case") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else {
      fmt::print(stderr,
                 "usage: mdrsim_engines [--out PATH.csv] [--repeats N] [--part springs|rtol|all] "
                 "[--case NAME]\n");
      return 2;
    }
  }
  // Under-resolved rows and capped rtol runs warn; the CSV carries what matters.
  spdlog::set_level(spdlog::level::err);
  std::FILE* out = out_path.empty() ? stdout : std::fopen(out_path.c_str(), "w");
  if (out == nullptr) {
    fmt::print(stderr, "mdrsim_engines: cannot write {}\n", out_path);
    return 2;
  }
  fmt::print(out,
             "part,case,criterion,normal,springs,rtol,shorthand_status,program_status,"
             "shorthand_F_N,program_F_N,F_rel_diff,shorthand_events,program_events,"
             "shorthand_s,program_s,time_ratio,shorthand_ns_per_event,program_ns_per_event,"
             "ns_per_event_ratio,shorthand_finest_springs,program_finest_springs,"
             "shorthand_rtol_met,program_rtol_met,program_preload_s,program_pull_ns_per_event,"
             "pull_ratio\n");
  int disagree = 0;
  const auto row = [&](const char* kind, const Case& c, const std::string& springs, double tol,
                       const Best& s, const Best& p, std::optional<double> preload_s) {
    const std::string rtol = tol > 0.0 ? fmt::format("{}", tol) : std::string();
    const auto ns = [](const Best& b) {
      return b.result.counts.events > 0
                 ? 1e9 * b.seconds / static_cast<double>(b.result.counts.events)
                 : NAN;
    };
    // The program's time past its preload per shorthand event (the same detachments).
    const auto pull_ns = [&](double preload) {
      return 1e9 * (p.seconds - preload) / static_cast<double>(s.result.counts.events);
    };
    fmt::print(out,
               "{},{},{},{},{},{},{},{},{},{},{},{},{},{:.4e},{:.4e},{:.3f},{:.1f},{:.1f},"
               "{:.3f},{},{},{},{},{},{},{}\n",
               kind, c.name, c.criterion, c.normal, springs, rtol, to_string(s.result.status),
               to_string(p.result.status), force(s.result), force(p.result),
               relative_difference(s.result, p.result), s.result.counts.events,
               p.result.counts.events, s.seconds, p.seconds, p.seconds / s.seconds, ns(s), ns(p),
               ns(p) / ns(s), s.result.springs, p.result.springs, s.result.accuracy.rtol_met,
               p.result.accuracy.rtol_met, preload_s ? fmt::format("{:.4e}", *preload_s) : "",
               preload_s ? fmt::format("{:.1f}", pull_ns(*preload_s)) : "",
               preload_s ? fmt::format("{:.3f}", pull_ns(*preload_s) / ns(s)) : "");
    std::fflush(out);
    const bool same = agree(tol, s.result, p.result);
    if (!same) ++disagree;
    if (out == stdout) return;
    // With --out, one line per row on standard output.
    const std::string what = tol > 0.0 ? "rtol " + rtol : springs + " springs";
    // The target: a program equal to a shorthand scene costs at most 2x the shorthand.
    const double ratio = p.seconds / s.seconds;
    fmt::print("{:4} {} {} {} {}: program/shorthand {:.2f}x in time ({} <= 2x)",
               same ? "SAME" : "DIFF", c.name, c.criterion, c.normal, what, ratio,
               ratio <= 2.0 ? "MET" : "OPEN");
    if (preload_s) {
      fmt::print(", {:.2f}x per event, {:.2f}x per detachment past the preload", ns(p) / ns(s),
                 pull_ns(*preload_s) / ns(s));
    } else {
      fmt::print(", finest rows {} and {} springs, rtol met {}/{}", s.result.springs,
                 p.result.springs, s.result.accuracy.rtol_met ? "yes" : "no",
                 p.result.accuracy.rtol_met ? "yes" : "no");
    }
    fmt::print("; critical force differs by {}\n", relative_difference(s.result, p.result));
    std::fflush(stdout);
  };
  for (const Case& c : cases()) {
    if (!only.empty() && c.name != only) continue;
    if (part == "all" || part == "springs") {
      for (const std::int64_t n : {10'000, 100'000, 1'000'000}) {
        const std::string d = fmt::format("springs = {}", n);
        const Scene shorthand = build(shorthand_text(c, d));
        const std::string text = program_text(c, shorthand, d);
        const Scene program = build(text);
        const Scene preload = build(preload_text(text));
        const auto b = measure({&shorthand, &program, &preload}, repeats);
        row("springs", c, std::to_string(n), 0.0, b[0], b[1], b[2].seconds);
      }
    }
    if (part == "all" || part == "rtol") {
      for (const double rtol : {1e-4, 1e-6, 1e-8}) {
        const std::string d = fmt::format("rtol = {}", rtol);
        const Scene shorthand = build(shorthand_text(c, d));
        const Scene program = build(program_text(c, shorthand, d));
        const auto b = measure({&shorthand, &program}, repeats);
        row("rtol", c, "", rtol, b[0], b[1], std::nullopt);
      }
    }
    fmt::print(stderr, "engines: {} {} {} done\n", c.name, c.criterion, c.normal);
  }
  if (out != stdout) std::fclose(out);
  if (disagree > 0) {
    fmt::print(stderr, "mdrsim_engines: the engines disagree on {} row(s)\n", disagree);
    return 1;
  }
  return 0;
}
