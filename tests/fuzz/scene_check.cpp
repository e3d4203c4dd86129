// Scene text in, outcome out: refused with SceneError, ran with finite numbers, or broken.
#include "tests/fuzz/scene_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <string_view>
#include <utility>

#include "engine/output/finite_check.hpp"
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

}  // namespace

SceneCheck check_scene_text(std::string_view text) {
  using Outcome = SceneCheck::Outcome;
  static const Registries registries = Registries::builtin();
  Scene scene;
  try {
    // TOML, or JSON when the text opens an object (mdrsim run reads both).
    scene = SceneDocument::from_scene_text(text, "fuzz.toml").build(registries);
  } catch (const SceneError&) {
    return {Outcome::refused, {}};
  } catch (const std::exception& e) {
    return {Outcome::broken, fmt::format("the reader threw a non-SceneError: {}", e.what())};
  }
  if (scene.springs > kMaxSprings) return {Outcome::ran, "skipped: springs above the cap"};
  // A program's cost grows with its stages times its springs (each stage may sweep the row).
  if (scene.program &&
      static_cast<double>(scene.program->stages.size()) * static_cast<double>(scene.springs) >
          static_cast<double>(kMaxSprings)) {
    return {Outcome::ran, "skipped: stages x springs above the cap"};
  }
  scene.solver.max_steps = std::min(scene.solver.max_steps, kMaxSteps);
  if (scene.discretization.rtol) {
    scene.discretization.rtol = std::max(*scene.discretization.rtol, kMinRtol);
  }
  scene.discretization.max_row_springs = kMaxSprings;
  RunResult result;
  try {
    result = run_scene(scene, ObserverList{});
  } catch (const SceneError& e) {
    // docs/continuum.md: a program the continuum route cannot follow to its end is refused by
    // its run (decided by the disk's state at a stage), with one line naming the key that
    // chose the route: exit 2, as the reader's refusals.
    const std::string_view why = e.what();
    if (why.rfind("fuzz.toml:", 0) == 0 && why.find('\n') == std::string_view::npos) {
      return {Outcome::refused, {}};
    }
    return {Outcome::broken,
            fmt::format("the run refused without one line naming the file: {}", why)};
  } catch (const std::exception& e) {
    // A scene the reader accepted must run: anything else is an engine bug (mdrsim exits 1).
    return {Outcome::broken, fmt::format("the run of an accepted scene threw: {}", e.what())};
  }
  // docs: numbers are finite. The reader refuses values that overflow the run.
  if (const auto bad = first_not_finite(scene, result)) return {Outcome::broken, *bad};
  // docs: an instability has its critical point; a status without one has none.
  // (A completed program reports the last loss of contact, if there was one.)
  if ((result.status == RunStatus::instability) != result.critical.has_value() &&
      result.status != RunStatus::shear_off && result.status != RunStatus::completed) {
    return {Outcome::broken, fmt::format("status {} with{} a critical point",
                                         to_string(result.status), result.critical ? "" : "out")};
  }
  return {Outcome::ran, {}};
}

}  // namespace mdrsim::test
