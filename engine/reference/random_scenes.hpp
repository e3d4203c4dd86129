// A fixed-seed set of random pull-off scenes (TOML) with their continuum references.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/reference/continuum_reference.hpp"

namespace mdrsim::test {

struct RandomScene {
  /// "NNN_profile_criterion_normal_tangential", letters, digits and '_' only (a valid
  /// GoogleTest parameter name), e.g. "017_cone_mode_dependent_compliant_held_force".
  std::string name;
  /// A complete scene file without [discretization] and [solver]: append e.g.
  /// "[discretization]\nrtol = 1e-4\n". Numbers are written with 17 digits.
  std::string toml_without_discretization;
  /// The continuum pull-off of exactly the numbers in the text; kind fold or shear_off, at
  /// a radius below a_g / 1.05.
  ContinuumCritical reference;
  double glued_radius = 0.0;         ///< a_g [m]
  double tangential_fraction = 0.0;  ///< held value over its shear-off limit at a_g [1]
};

/// Draws thrown away, by reason.
struct RandomSceneDiscards {
  int none = 0;                      ///< the reference peels off smoothly
  int shear_off_at_application = 0;  ///< the tangential load alone breaks the glue at a_g
  int first_detachment = 0;          ///< the first let-go at a_g empties the contact
  int near_glued_radius = 0;         ///< the critical radius within 5 % of a_g (nearly the above)
  int near_zero_force = 0;           ///< |critical force| < 1e-3 |peak adhesive force|
  int setup = 0;  ///< the scene's normal problem had no fold to scale a_g on, or a sphere's
                  ///< glued radius came out beyond 0.3 R

  int total() const {
    return none + shear_off_at_application + first_detachment + near_glued_radius +
           near_zero_force + setup;
  }
};

struct RandomSceneSet {
  std::vector<RandomScene> scenes;
  RandomSceneDiscards discarded;
  int draws = 0;  ///< scenes kept plus discarded
};

/// `count` scenes from std::mt19937_64(seed) with uniform numbers mapped here (not by the
/// standard library's distributions), so the set is the same on every platform. Drawn:
/// profile (parabolic, sphere, cone, power_law with n in [1.2, 4]), criterion (mode-mixed,
/// deformation, stress, normal-only, mode-dependent with lambda in [0, 1]), E, nu in
/// [0, 0.5], dgamma, normal control (fixed-grips, fixed-load, compliant with k from 1e-2 to
/// 1e2 times 2 E* a_c), tangential (none, fixed-grips u, fixed-load F_x, at 0-80 % of the
/// shear-off limit at a_g) and a_g = f a_c with f log-uniform in [1.2, 20], a_c being the
/// critical radius of the scene without its tangential load.
RandomSceneSet random_scene_set(std::uint64_t seed, int count);

/// The scenes of random_scene_set.
std::vector<RandomScene> random_scenes(std::uint64_t seed, int count);

}  // namespace mdrsim::test
