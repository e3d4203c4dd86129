// Resolution choice and extrapolation on top of single pull-off runs.
#include "engine/run_scene.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mdrsim {
namespace {

constexpr std::int64_t kPilotSprings = 1024;
constexpr double kSafety = 1.15;
constexpr double kMaxSprings = 1e9;

void add_counts(RunCounts& total, const RunCounts& more) {
  total.events += more.events;
  total.steps += more.steps;
  total.halvings += more.halvings;
  total.root_iterations += more.root_iterations;
}

/// The row's estimate of the continuum critical point: its fold between springs where
/// there is one, else its last equilibrium.
const ContactSnapshot& best(const RunResult& r) { return r.fold ? *r.fold : r.critical; }

ContactSnapshot extrapolate(const ContactSnapshot& coarse, const ContactSnapshot& fine) {
  const auto twice_minus = [](double c, double f) { return 2.0 * f - c; };
  ContactSnapshot out = fine;
  out.normal_control = twice_minus(coarse.normal_control, fine.normal_control);
  out.indentation = twice_minus(coarse.indentation, fine.indentation);
  out.normal_force = twice_minus(coarse.normal_force, fine.normal_force);
  out.contact_radius = twice_minus(coarse.contact_radius, fine.contact_radius);
  out.tangential_displacement =
      twice_minus(coarse.tangential_displacement, fine.tangential_displacement);
  out.tangential_force = twice_minus(coarse.tangential_force, fine.tangential_force);
  return out;
}

/// Richardson over rows of n and 2n springs; the finer row's status and springs.
RunResult richardson(const Scene& scene, std::int64_t n, const ObserverList& observers) {
  const RunResult coarse = run_pull_off(scene, n, ObserverList{});
  RunResult fine = run_pull_off(scene, 2 * n, observers);
  add_counts(fine.counts, coarse.counts);
  fine.resolutions = {n, 2 * n};
  if (coarse.status == fine.status && coarse.status != RunStatus::step_limit) {
    fine.critical = extrapolate(best(coarse), best(fine));
  }
  fine.fold.reset();
  return fine;
}

std::int64_t clamp_springs(double n) {
  if (!(n < kMaxSprings)) return static_cast<std::int64_t>(kMaxSprings);
  return std::max<std::int64_t>(2, static_cast<std::int64_t>(std::ceil(n)));
}

}  // namespace

std::int64_t springs_for_rtol(const Scene& scene, double rtol, bool use_richardson,
                              RunCounts& counts) {
  const ObserverList quiet;
  const RunResult r1 = run_pull_off(scene, kPilotSprings, quiet);
  const RunResult r2 = run_pull_off(scene, 2 * kPilotSprings, quiet);
  add_counts(counts, r1.counts);
  add_counts(counts, r2.counts);
  const double q1 = best(r1).normal_force;
  const double q2 = best(r2).normal_force;
  const double limit = 2.0 * q2 - q1;
  const double scale = std::abs(limit);
  if (!(scale > 0.0)) return kPilotSprings;
  if (!use_richardson) {
    const double smooth = std::abs(q1 - limit) * static_cast<double>(kPilotSprings);
    const double quantization =
        r2.fold ? 0.5 * r2.fold_force_step * static_cast<double>(2 * kPilotSprings) : 0.0;
    return clamp_springs(kSafety * (smooth + quantization) / (rtol * scale));
  }
  const RunResult r4 = run_pull_off(scene, 4 * kPilotSprings, quiet);
  add_counts(counts, r4.counts);
  const double q4 = best(r4).normal_force;
  // Successive extrapolations differ by 3/4 of the coarser one's C2/N^2 error.
  const double c2 = std::abs((2.0 * q2 - q1) - (2.0 * q4 - q2)) * 4.0 / 3.0 *
                    static_cast<double>(kPilotSprings) * static_cast<double>(kPilotSprings);
  return clamp_springs(std::sqrt(kSafety * c2 / (rtol * scale)));
}

RunResult run_scene(const Scene& scene, const ObserverList& observers) {
  const auto started = std::chrono::steady_clock::now();
  RunCounts pilot;
  std::int64_t springs = scene.springs;
  if (scene.discretization.rtol) {
    springs =
        springs_for_rtol(scene, *scene.discretization.rtol, scene.discretization.richardson, pilot);
    spdlog::info("rtol {}: {} springs{}", *scene.discretization.rtol, springs,
                 scene.discretization.richardson ? " per row (richardson)" : "");
  }
  RunResult result = scene.discretization.richardson ? richardson(scene, springs, observers)
                                                     : run_pull_off(scene, springs, observers);
  add_counts(result.counts, pilot);
  result.springs = springs;
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace mdrsim
