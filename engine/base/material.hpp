// The elastic half-space and the interface: effective moduli (paper eqs. 8-9) and adhesion,
// shared by the engine and the parts (a criterion sees it as InterfaceProperties).
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "engine/base/hess_scale.hpp"
#include "engine/base/radial_adhesion.hpp"

namespace mdrsim {

/// A modulus that grows with depth, E(z) = E0 (z / z0)^k, nu constant (docs/graded.md); its
/// constants are engine/model/graded_constants'.
struct Grading {
  double exponent = 0.0;        ///< k [1], 0 <= k < 1; 0: the homogeneous half-space
  double depth = 1.0;           ///< z0 [m] > 0: E(z0) = E0
  double punch_constant = 0.0;  ///< C_k [Pa / m^k]: a flat punch carries C_k d a^(1+k)

  /// Whether the modulus varies with depth (k > 0); k = 0 takes the homogeneous path.
  bool graded() const { return exponent > 0.0; }
};

/// One Prony term of a viscoelastic bulk: a Maxwell arm (spring E_i, dashpot E_i tau_i) in
/// parallel with the relaxed spring (docs/viscoelastic.md).
struct PronyTerm {
  double modulus;  ///< E_i* = E_i / (1 - nu^2) [Pa] > 0, plane strain as E* is
  double time;     ///< tau_i [s] > 0
};

struct Material {
  double effective_modulus;        ///< E* = E/(1 - nu^2) [Pa]
  double effective_shear_modulus;  ///< G* = 4G/(2 - nu) [Pa]
  double work_of_adhesion;         ///< dgamma [J/m^2]
  /// dgamma_a [J/m^2], 0 <= dgamma_a <= dgamma: the advancing front of a loading program glues
  /// the spring just outside the contact at the gap advancing_glue_gap(x) below.
  double approach_work_of_adhesion = 0.0;
  /// dgamma(r) and dgamma_a(r) where the scene gives a table or a sinusoid (null: the numbers
  /// above hold at every radius). The numbers above are then the scale values (the mean, or
  /// the value at r = 0): F0, a0 and d0 use them; a spring at radius x uses the value at x.
  std::shared_ptr<const RadialAdhesion> work_of_adhesion_by_radius;
  std::shared_ptr<const RadialAdhesion> approach_work_of_adhesion_by_radius;
  /// sigma_0 [Pa] of the Dugdale law (docs/maugis.md): the adhesion acts at this stress over the
  /// gap dgamma / sigma_0; 0: no range (JKR, Hess's rule lets each spring go).
  double adhesive_stress = 0.0;
  /// material.grading; E* and G* above are then E0's (the springs' stiffness is
  /// grading.punch_constant's, docs/graded.md).
  Grading grading;
  /// material.relaxation: E*(t) = E* + sum_i E_i* exp(-t / tau_i), E* above then the relaxed
  /// (long-time) modulus. Empty: an elastic bulk.
  std::vector<PronyTerm> relaxation;

  /// dgamma at the radius r [m] of a spring [J/m^2]: every criterion lets go with this.
  double work_of_adhesion_at(double r) const {
    return work_of_adhesion_by_radius ? work_of_adhesion_by_radius->at(r) : work_of_adhesion;
  }
  /// dgamma_a at the radius r [m]: the advancing front glues with this.
  double approach_work_of_adhesion_at(double r) const {
    return approach_work_of_adhesion_by_radius ? approach_work_of_adhesion_by_radius->at(r)
                                               : approach_work_of_adhesion;
  }
  /// The gap g(x) - d [m] at which the advancing front glues the spring at radius x [m]:
  /// sqrt(2 pi x dgamma_a(x) / E*) (0: on touch). The depth it gives is gluing_depth()
  /// (engine/model/gluing_depth.hpp).
  double advancing_glue_gap(double x) const {
    return std::sqrt(hess_scale(approach_work_of_adhesion_at(x), effective_modulus) * x);
  }
  /// Whether the advancing front glues (or presses) each spring as it touches it: dgamma_a = 0
  /// at every radius (its Hess scale 2 pi dgamma_a / E* is 0).
  bool glues_on_touch() const {
    const auto& by_radius = approach_work_of_adhesion_by_radius;
    return hess_scale(by_radius ? by_radius->largest() : approach_work_of_adhesion,
                      effective_modulus) == 0.0;
  }
  /// Whether either work of adhesion varies with the radius.
  bool adhesion_varies() const {
    return work_of_adhesion_by_radius != nullptr || approach_work_of_adhesion_by_radius != nullptr;
  }
  /// The largest dgamma at any radius [J/m^2] (the scales of what is zero use it).
  double largest_work_of_adhesion() const {
    return work_of_adhesion_by_radius ? work_of_adhesion_by_radius->largest() : work_of_adhesion;
  }
  /// Whether the adhesion has a finite range (Maugis-Dugdale): sigma_0 > 0.
  bool finite_range() const { return adhesive_stress > 0.0; }
  /// Whether the bulk relaxes (material.relaxation has terms).
  bool relaxes() const { return !relaxation.empty(); }
  /// E_0* = E* + sum_i E_i* [Pa]: the glassy (instantaneous) modulus.
  double glassy_modulus() const {
    double sum = effective_modulus;
    for (const PronyTerm& term : relaxation) {
      sum += term.modulus;
    }
    return sum;
  }
  /// Whether any spring has glue to lose: dgamma > 0 somewhere.
  bool adhesive() const { return largest_work_of_adhesion() > 0.0; }

  /// From Young's modulus E [Pa] and Poisson's ratio nu (paper eq. 8).
  static Material from_youngs_modulus(double youngs_modulus, double poisson_ratio,
                                      double work_of_adhesion);

  /// What a detachment criterion sees: the material itself (kept as a name for the parts).
  const Material& interface_properties() const { return *this; }
};

/// The interface's elastic and adhesive properties that every criterion sees.
using InterfaceProperties = Material;

}  // namespace mdrsim
