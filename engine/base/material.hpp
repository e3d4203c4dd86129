// The elastic half-space and the interface: effective moduli (paper eqs. 8-9) and adhesion,
// shared by the engine and the parts (a criterion sees it as InterfaceProperties).
#pragma once

namespace mdrsim {

struct Material {
  double effective_modulus;        ///< E* = E/(1 - nu^2) [Pa]
  double effective_shear_modulus;  ///< G* = 4G/(2 - nu) [Pa]
  double work_of_adhesion;         ///< dgamma [J/m^2]
  /// dgamma_a [J/m^2], 0 <= dgamma_a <= dgamma: the advancing front of a loading program glues
  /// the spring just outside the contact at the gap sqrt(2 pi x dgamma_a / E*) (0: on touch).
  double approach_work_of_adhesion = 0.0;

  /// From Young's modulus E [Pa] and Poisson's ratio nu (paper eq. 8).
  static Material from_youngs_modulus(double youngs_modulus, double poisson_ratio,
                                      double work_of_adhesion);

  /// What a detachment criterion sees: the material itself (kept as a name for the parts).
  const Material& interface_properties() const { return *this; }
};

/// The interface's elastic and adhesive properties that every criterion sees.
using InterfaceProperties = Material;

}  // namespace mdrsim
