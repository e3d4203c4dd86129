// The preload's glued radius at absurd scales: a force preload on tip radii down to 1e-250 m.
#include "engine/model/preload.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "engine/reference/jkr_scenario.hpp"

using mdrsim::Scene;

// A force preload glues the non-adhesive (Hertz) radius of the parabola, F = 4 E* a^3/(3R): the
// glued radius must be a = (3 F R/(4 E*))^(1/3) to rounding (1e-12) at any scale where a^3 is a
// normal double, here R from 1 m to 1e-250 m, E* from 1e3 to 1e12 Pa, F from 1e-9 to 1e3 N.
TEST(EdgeCases, ForcePreloadAtAbsurdTipRadii) {
  for (const double radius : {1.0, 1e-3, 1e-9, 1e-20, 1e-50, 1e-100, 1e-150, 1e-200, 1e-250}) {
    for (const double modulus : {1e3, 1e12}) {
      for (const double force : {1e-9, 1e3}) {
        const Scene scene = mdrsim::test::build_scene_text(fmt::format(
            "[material]\neffective_modulus = {:.17g}\nwork_of_adhesion = 0.05\n"
            "[profile]\ntype = \"parabolic\"\nradius = {:.17g}\n"
            "[loading]\npreload = {{ force = {:.17g} }}\nnormal = {{ control = \"fixed-load\" }}\n",
            modulus, radius, force));
        const double want = std::cbrt(3.0 * force / (4.0 * modulus)) * std::cbrt(radius);
        EXPECT_NEAR(scene.glued_radius / want, 1.0, 1e-12)
            << "R = " << radius << " m, E* = " << modulus << " Pa, F = " << force << " N";
      }
    }
  }
}
