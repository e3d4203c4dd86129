// Scene text in, outcome out: refused with SceneError, ran with finite numbers, or broken.
#include "tests/fuzz/scene_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <utility>

#include "engine/events/result_json.hpp"
#include "engine/model/snapshot_fields.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::test {
namespace {

// Caps that keep one input below a second or so under ASan. They bound the run's length only;
// every value is still parsed and checked by build(). A run is O(springs) (the event method)
// or O(steps * halvings) (stepping), so springs up to 10^9 and max_steps up to 10^15, both
// valid, would make single inputs take minutes: the fuzzer would time out on valid scenes and
// learn nothing new from them (10^7 springs is a test of its own: EdgeCasesLarge).
constexpr std::int64_t kMaxSprings = 100'000;
constexpr std::int64_t kMaxSteps = 100'000;
constexpr double kMinRtol = 1e-3;  // rtol picks the springs: 1e-3 keeps them near 10^4

/// The first value that is not finite, as "name = value", or empty.
std::string first_not_finite(std::initializer_list<std::pair<const char*, double>> values) {
  for (const auto& [name, value] : values) {
    if (!std::isfinite(value)) return fmt::format("{} = {}", name, value);
  }
  return {};
}

}  // namespace

SceneCheck check_scene_text(std::string_view text) {
  using Outcome = SceneCheck::Outcome;
  static const Registries registries = Registries::builtin();
  Scene scene;
  try {
    scene = SceneDocument::from_text(text, "fuzz.toml").build(registries);
  } catch (const SceneError&) {
    return {Outcome::refused, {}};
  } catch (const std::exception& e) {
    return {Outcome::broken, fmt::format("the reader threw a non-SceneError: {}", e.what())};
  }
  if (scene.springs > kMaxSprings) return {Outcome::ran, "skipped: springs above the cap"};
  scene.solver.max_steps = std::min(scene.solver.max_steps, kMaxSteps);
  if (scene.discretization.rtol) {
    scene.discretization.rtol = std::max(*scene.discretization.rtol, kMinRtol);
  }
  scene.discretization.max_row_springs = kMaxSprings;
  RunResult result;
  try {
    result = run_scene(scene, ObserverList{});
  } catch (const std::exception& e) {
    // A scene the reader accepted must run: anything else is an engine bug (mdrsim exits 1).
    return {Outcome::broken, fmt::format("the run of an accepted scene threw: {}", e.what())};
  }
  // SPEC: numbers are finite. The reader refuses values that overflow the run.
  const auto s = dimensionless_scales(scene);
  for (const auto& [what, snapshot] :
       {std::pair{"critical", &result.critical}, std::pair{"peak_adhesion", &result.peak}}) {
    if (!*snapshot) continue;
    // SI values, and the dimensionless ones of the JSON result, as apps/finite_result.cpp
    // checks them.
    for (const SnapshotField& f : kSnapshotFields) {
      const double value = (**snapshot).*f.member;
      if (!std::isfinite(value)) {
        return {Outcome::broken, fmt::format("{}.{} = {}", what, f.name, value)};
      }
      if (s && !std::isfinite(value / scale_of(*s, f.scale))) {
        return {Outcome::broken, fmt::format("{}.dimensionless.{} = {}", what, f.name,
                                             value / scale_of(*s, f.scale))};
      }
    }
  }
  if (const std::string bad = first_not_finite(
          {{"tangential_strength", result.tangential_strength.value_or(0.0)},
           {"critical_error_estimate", result.accuracy.critical_error_estimate.value_or(0.0)},
           {"peak_error_estimate", result.accuracy.peak_error_estimate.value_or(0.0)}});
      !bad.empty()) {
    return {Outcome::broken, bad};
  }
  // SPEC: an instability has its critical point; a status without one has none.
  if ((result.status == RunStatus::instability) != result.critical.has_value() &&
      result.status != RunStatus::shear_off) {
    return {Outcome::broken, fmt::format("status {} with{} a critical point",
                                         to_string(result.status), result.critical ? "" : "out")};
  }
  return {Outcome::ran, {}};
}

}  // namespace mdrsim::test
