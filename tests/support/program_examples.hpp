// The example scenes of scenes/programs/ for tests: their text with another discretization, and
// the critical points the continuum gives for the shear ramps and the inclined pull.
#pragma once

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/reference/program_reference.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim::test {

// The example scenes: R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2.
inline const double kExampleForce = 1.5 * std::numbers::pi * 0.01 * 0.05;  ///< F0 [N]
inline const double kExampleDepth = std::cbrt(3.0 * std::numbers::pi * std::numbers::pi * 0.01 *
                                              0.05 * 0.05 / (64.0 * 1e6 * 1e6));  ///< d0 [m]

/// scenes/programs/NAME.toml with its `springs = ...` line replaced by `discretization`
/// (lines of the [discretization] table).
inline Scene program_example(const std::string& name, const std::string& discretization) {
  const std::string path = std::string(MDRSIM_SOURCE_DIR) + "/scenes/programs/" + name;
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::size_t at = s.find("springs = ");
  s.replace(at, s.find('\n', at) - at, discretization);
  return SceneDocument::from_text(s, name).build(Registries::builtin());
}

/// An example whose critical point the continuum gives in closed form or by quadrature.
struct ExampleCriticalPoint {
  const char* scene;
  double normal_force;  ///< F/F0 at the critical point
};

/// The shear ramps and the inclined pull (scenes/programs/ comments: preload radius 2 a0, held
/// F = -0.5 F0 or d = -1 d0; the pull from d_p = 2 d0 at 45 degrees).
inline std::vector<ExampleCriticalPoint> shear_and_inclined_examples() {
  namespace pr = program_reference;
  return {
      {"shear_ramp_fixed_load.toml", pr::shear_ramp_at_held_force(2.0, -0.5).critical.normal_force},
      {"shear_ramp_fixed_grips.toml",
       pr::shear_ramp_at_held_indentation(2.0, -1.0).critical.normal_force},
      {"inclined_pull_45.toml", pr::inclined_pull(2.0).critical.normal_force},
  };
}

}  // namespace mdrsim::test
