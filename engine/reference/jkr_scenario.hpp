// Test scenes of a parabolic JKR contact, written as TOML so that tests go through the loader.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "engine/model/jkr_scales.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim::test {

/// R = 1 cm, E = 1 MPa, dgamma = 0.05 J/m^2 unless changed; lengths of the options are in
/// the JKR scales a0 and d0, forces in F0.
struct JkrScenario {
  std::string normal = "fixed-load";
  std::string normal_extra;  ///< more keys of the normal table, e.g. "stiffness = 2.0"
  std::int64_t springs = 10000;
  std::optional<double> rtol;  ///< written instead of springs when set
  bool richardson = false;     ///< discretization.extrapolation = "richardson"
  double glued_radius = 2.0;   ///< in a0
  double radius = 0.01;        ///< R [m]
  double youngs_modulus = 1e6;
  double poisson_ratio = 0.0;
  double work_of_adhesion = 0.05;
  std::optional<double> tangential_displacement;  ///< fixed-grips tangential, in d0
  std::optional<double> tangential_force;         ///< fixed-load tangential, in F0
  std::string criterion = "mode-mixed";
  std::string criterion_extra;  ///< e.g. "lambda = 0.5"
  std::string method = "event";
  std::string solver_extra;  ///< e.g. "step = 1e-9"

  /// Scales of the material; E* from E and nu.
  JkrScales scales() const;
  std::string toml() const;
  Scene build() const;
};

/// Builds a scene from TOML text named "test.toml" with the built-in parts.
Scene build_scene_text(std::string_view text);

/// Runs a scene with no observers.
RunResult run_quietly(const Scene& scene);

}  // namespace mdrsim::test
