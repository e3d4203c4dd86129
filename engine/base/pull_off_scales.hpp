// The scales of a profile's dimensionless output: its fixed-load pull-off in closed form.
#pragma once

#include <string>

namespace mdrsim {

/// F0, a0 and d0 divide forces, radii and displacements in the dimensionless output (paper
/// eq. 16); for a parabolic tip they are eq. 17.
struct PullOffScales {
  double force;       ///< F0: |F| at the fixed-load pull-off [N]
  double radius;      ///< a0: the contact radius there [m]
  double depth;       ///< d0: the indentation scale [m]
  std::string basis;  ///< the profile and the closed forms, one line for the JSON result
};

}  // namespace mdrsim
