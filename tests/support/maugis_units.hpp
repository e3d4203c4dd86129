// Maugis' scales of one parabola in SI units, with its Dugdale law at a given lambda: the
// units both Dugdale tests compare the MDR route with Maugis' equations in.
#pragma once

#include "engine/model/dugdale_zone.hpp"
#include "engine/reference/maugis_reference.hpp"

namespace mdrsim::test {

/// A parabola R = 1 cm on E* = 1 MPa with dgamma = 0.05 J/m^2.
struct MaugisUnits : maugis_reference::MaugisScales {
  MaugisUnits() : maugis_reference::MaugisScales{.radius = 0.01, .modulus = 1e6, .work = 0.05} {}
  DugdaleLaw law(double lambda) const {
    return {.adhesive_stress = adhesive_stress(lambda),
            .work_of_adhesion = work,
            .effective_modulus = modulus};
  }
};

}  // namespace mdrsim::test
