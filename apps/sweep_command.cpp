// mdrsim sweep: one run per value of a key, in parallel, one CSV row each in input order.
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "apps/commands.hpp"
#include "apps/finite_result.hpp"
#include "apps/output_file.hpp"
#include "apps/scene_input.hpp"
#include "apps/vary_spec.hpp"
#include "engine/events/result_json.hpp"
#include "engine/model/snapshot_fields.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim::cli {
namespace {

/// A number, or an empty field where the run has none.
std::string field(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : std::string();
}

/// The status leads each row, and a run without a critical point leaves the critical columns
/// empty, so that no plot mistakes it for one.
void write_csv(std::ostream& out, const VarySpec& vary, const std::vector<Scene>& scenes,
               const std::vector<RunResult>& results) {
  const bool dimensionless = std::any_of(scenes.begin(), scenes.end(), [](const Scene& s) {
    return dimensionless_scales(s).has_value();
  });
  out << "status," << vary.key;
  for (const SnapshotField& f : kSnapshotFields) out << ',' << f.name;
  out << ",springs_in_contact";
  if (dimensionless) {
    for (const SnapshotField& f : kSnapshotFields) out << ",dimensionless_" << f.name;
  }
  out << ",peak_normal_force";
  if (dimensionless) out << ",dimensionless_peak_normal_force";
  out << ",tangential_strength,critical_error_estimate\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const RunResult& r = results[i];
    const auto s = dimensionless_scales(scenes[i]);
    fmt::print(out, "{},{}", to_string(r.status), vary.values[i]);
    // One field per column, empty where the run has no critical point.
    for (const SnapshotField& f : kSnapshotFields) {
      out << ',' << (r.critical ? fmt::format("{}", *r.critical.*f.member) : std::string());
    }
    out << ',' << (r.critical ? fmt::format("{}", r.critical->springs_in_contact) : std::string());
    if (dimensionless) {
      for (const SnapshotField& f : kSnapshotFields) {
        out << ','
            << (s && r.critical ? fmt::format("{}", *r.critical.*f.member / scale_of(*s, f.scale))
                                : std::string());
      }
    }
    out << ',' << (r.peak ? fmt::format("{}", r.peak->normal_force) : std::string());
    if (dimensionless) {
      out << ','
          << (s && r.peak ? fmt::format("{}", r.peak->normal_force / s->force) : std::string());
    }
    out << ',' << field(r.tangential_strength) << ',' << field(r.accuracy.critical_error_estimate)
        << '\n';
  }
}

}  // namespace

int sweep_command(const SweepOptions& options) {
  const VarySpec vary = parse_vary(options.vary);
  require_distinct_outputs({{"--csv", options.csv}}, options.scene);
  const SceneDocument base = load_scene_document(options.scene, options.sets);
  const Registries registries = Registries::builtin();

  // Every scene is built (and so checked) before any run: bad values fail with no output.
  std::vector<Scene> scenes;
  scenes.reserve(vary.values.size());
  for (const double value : vary.values) {
    SceneDocument document = base;
    document.set_number(vary.key, value, "--vary");
    scenes.push_back(document.build(registries));
  }
  OutputFile csv("--csv", options.csv);

  const auto started = std::chrono::steady_clock::now();
  std::vector<RunResult> results(scenes.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const ObserverList no_observers;
  const auto worker = [&] {
    for (std::size_t i = next++; i < scenes.size(); i = next++) {
      try {
        results[i] = run_scene(scenes[i], no_observers);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  const int threads = std::max(1, std::min<int>(options.threads, static_cast<int>(scenes.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  for (std::size_t i = 0; i < scenes.size(); ++i) require_finite(scenes[i], results[i]);

  write_csv(csv.stream(), vary, scenes, results);
  csv.commit();
  spdlog::info("sweep: {} runs of {} on {} threads in {:.3g} s", scenes.size(), vary.key, threads,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  return 0;
}

}  // namespace mdrsim::cli
