// mdrsim run: one pull-off, its JSON result, trajectory and a short summary.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "apps/commands.hpp"
#include "apps/interrupt_cleanup.hpp"
#include "apps/output_file.hpp"
#include "apps/scene_input.hpp"
#include "engine/events/log_observer.hpp"
#include "engine/output/finite_result.hpp"
#include "engine/output/result_json.hpp"
#include "engine/output/run_summary.hpp"
#include "engine/output/trajectory_csv.hpp"
#include "engine/output/trajectory_estimate.hpp"
#include "engine/output/trajectory_stride.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {

int run_command(const RunOptions& options) {
  if (options.trajectory.empty() && options.trajectory_stride != 1) {
    throw UsageError("--trajectory-stride: thins --trajectory, which is not given");
  }
  if (options.json == "-" && options.trajectory == "-") {
    throw UsageError("--trajectory: cannot share standard output with --json -");
  }
  require_distinct_outputs({{"--json", options.json}, {"--trajectory", options.trajectory}},
                           options.scene == "-" ? std::string() : options.scene);
  const SceneDocument document = load_scene_document(options.scene, options.sets);
  if (options.plan) {
    const Scene scene = document.build(Registries::builtin());
    std::fputs(fmt::format("route: {}\n", scene.plan.describe(scene)).c_str(), stdout);
    return 0;
  }
  // From here on a signal removes the outputs' temporaries (docs/cli.md "Exit codes").
  install_interrupt_cleanup();
  Scene scene = document.build(Registries::builtin());
  if (!options.trajectory.empty()) scene.solver.samples = options.samples;

  std::optional<OutputFile> json_file;
  if (!options.json.empty()) json_file.emplace("--json", options.json);
  std::optional<OutputFile> trajectory_file;
  std::unique_ptr<TrajectoryCsvWriter> trajectory;
  std::unique_ptr<TrajectoryStride> stride;
  ObserverList observers;
  LogObserver log;
  observers.add(log);
  if (!options.trajectory.empty()) {
    trajectory_file.emplace("--trajectory", options.trajectory);
    trajectory = std::make_unique<TrajectoryCsvWriter>(
        trajectory_file->stream(), scene.friction.has_value(), scene.material.finite_range(),
        scene.program && scene.program->timed());
    stride = std::make_unique<TrajectoryStride>(*trajectory, options.trajectory_stride);
    observers.add(*stride);
    if (const auto warning = large_trajectory_warning(scene, options.trajectory_stride)) {
      spdlog::warn("{}", *warning);
    }
  }

  spdlog::info("route: {}", scene.plan.describe(scene));
  const RunResult result = run_scene(scene, observers);
  require_finite(scene, result);
  if (stride) stride->finish();

  if (trajectory_file) trajectory_file->commit();
  if (json_file) {
    json_file->stream() << result_to_json(scene, result).dump(2) << '\n';
    json_file->commit();
  } else {
    print_summary(options.trajectory == "-" ? stderr : stdout, scene, result);
  }
  return 0;
}

}  // namespace mdrsim::cli
