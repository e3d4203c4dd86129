// libFuzzer target over scene text: bad input must fail as SceneError, good input must run to a
// status with finite numbers. Any other exception (from the reader or from a run of a scene it
// accepted), a non-finite result, a signal, a leak or a sanitizer report is a crash.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "engine/registries.hpp"
#include "engine/result_json.hpp"
#include "engine/run_scene.hpp"
#include "engine/scene_document.hpp"
#include "engine/scene_error.hpp"

namespace {

// Caps that keep one input below a second or so under ASan. They bound the run's length only;
// every value is still parsed and checked by build(). A run is O(springs) (the event method)
// or O(steps * halvings) (stepping), so springs up to 10^9 and max_steps up to 10^15, both
// valid, would make single inputs take minutes: the fuzzer would time out on valid scenes and
// learn nothing new from them (10^7 springs is a test of its own: EdgeCasesLarge).
constexpr std::int64_t kMaxSprings = 100'000;
constexpr std::int64_t kMaxSteps = 100'000;
constexpr double kMinRtol = 1e-3;  // rtol picks the springs: 1e-3 keeps them near 10^4

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

// The engine's progress and rtol logs would only slow the fuzzer down.
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  spdlog::set_level(spdlog::level::off);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const mdrsim::Registries registries = mdrsim::Registries::builtin();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  mdrsim::Scene scene;
  try {
    scene = mdrsim::SceneDocument::from_text(text, "fuzz.toml").build(registries);
  } catch (const mdrsim::SceneError&) {
    return 0;  // bad input, reported with its one line: what must happen
  }
  if (scene.springs > kMaxSprings) return 0;
  scene.solver.max_steps = std::min(scene.solver.max_steps, kMaxSteps);
  if (scene.discretization.rtol) {
    scene.discretization.rtol = std::max(*scene.discretization.rtol, kMinRtol);
  }
  const mdrsim::RunResult result = mdrsim::run_scene(scene, mdrsim::ObserverList{});
  // SPEC: numbers are finite. The scene reader refuses values that overflow the run.
  const mdrsim::ContactSnapshot& c = result.critical;
  if (!all_finite({c.normal_force, c.tangential_force, c.contact_radius, c.indentation,
                   c.tangential_displacement, c.normal_control})) {
    __builtin_trap();
  }
  // The dimensionless values of the JSON result, as apps/finite_result.cpp checks them.
  const auto s = mdrsim::dimensionless_scales(scene);
  if (s && !all_finite({c.normal_force / s->force, c.tangential_force / s->force,
                        c.contact_radius / s->radius, c.indentation / s->depth,
                        c.tangential_displacement / s->depth})) {
    __builtin_trap();
  }
  return 0;
}
