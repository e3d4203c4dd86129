// The MDR's Dugdale zone against Maugis' classical parabola (maugis_reference), its closed-form
// gap integrals against the quadrature, and its JKR limit for a shape Maugis did not solve.
#include "engine/model/dugdale_zone.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/reference/maugis_reference.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "tests/support/maugis_units.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
namespace maugis = maugis_reference;

using test::MaugisUnits;

// The MDR form of SPEC against Maugis' equations, written apart from it: lambda from the DMT
// side (0.3) to the JKR side (50), A from small to large. Tolerance 1e-11 of the scales: the
// two solve different equations for different unknowns (t here, Maugis' t from his own form),
// each to the last bits, and their sums round differently.
TEST(DugdaleZone, TheParabolaIsMaugis) {
  const MaugisUnits u;
  const ParabolicProfile parabola(u.radius);
  for (const double lambda : {0.3, 1.0, 50.0}) {
    for (const double a : {0.05, 0.5, 1.0, 2.0}) {
      SCOPED_TRACE(testing::Message() << "lambda " << lambda << " A " << a);
      const maugis::MaugisState m = maugis::contact_branch(lambda, a);
      const DugdaleState s = dugdale_contact_state(parabola, u.law(lambda), a * u.length());
      EXPECT_NEAR(s.cohesive_radius / u.length(), m.cohesive_radius, 1e-11 * m.cohesive_radius);
      EXPECT_NEAR(s.indentation / u.depth(), m.indentation, 1e-11);
      EXPECT_NEAR(s.normal_force / u.force(), m.force, 1e-11);
    }
    const double c0 = dugdale_closing_radius(parabola, u.law(lambda)) / u.length();
    EXPECT_NEAR(c0, maugis::closing_cohesive_radius(lambda), 1e-12 * c0);
    const DugdaleState free = dugdale_free_state(parabola, u.law(lambda), 0.7 * c0 * u.length());
    const maugis::MaugisState m = maugis::no_contact_branch(lambda, 0.7 * c0);
    EXPECT_NEAR(free.indentation / u.depth(), m.indentation, 1e-12);
    EXPECT_NEAR(free.normal_force / u.force(), m.force, 1e-12);
  }
}

// The closed forms against the base class's quadrature, at angles from the series' range
// (1e-3) to a zone many times the contact (1.5 rad). The quadrature sums g(c cos psi) - g(a),
// which cancels to about eps g(a) out of a difference of order g'(a) a t^2: 1e-12 relative, or
// 4 eps / t^2 where that is larger (9e-10 at t = 1e-3: the closed forms are the better numbers).
TEST(DugdaleZone, ClosedFormGapIntegralsMatchTheQuadrature) {
  const ParabolicProfile parabola(0.01);
  const ConeProfile cone(30.0);
  for (const double t : {1e-3, 0.05, 0.3, 1.0, 1.5}) {
    SCOPED_TRACE(t);
    const double a = 2e-4, c = a / std::cos(t);
    const double tolerance = std::max(1e-12, 4.0 * 2.220446049250313e-16 / (t * t));
    const double p = parabola.dugdale_gap_integral(a, c, t);
    EXPECT_NEAR(p, parabola.Profile::dugdale_gap_integral(a, c, t), tolerance * p);
    const double k = cone.dugdale_gap_integral(a, c, t);
    EXPECT_NEAR(k, cone.Profile::dugdale_gap_integral(a, c, t), tolerance * k);
  }
}

// sigma_0 -> infinity at fixed dgamma is JKR for any shape: the zone shrinks onto the edge
// and its stretch (2 sigma_0/E*) sqrt(c^2 - a^2) becomes Hess's sqrt(2 pi a dgamma/E*). A power
// law r^1.5 and the sphere (quadrature); the difference falls like 1/lambda^2 (checked: 1e-4 of
// Hess's stretch at sigma_0 = 1e8, 1e-6 at 1e9), so 1e-5 relative at 1e9 Pa.
TEST(DugdaleZone, LargeStressIsJkrForAnyShape) {
  const PowerLawProfile power(0.02, 1.5);
  const SphereProfile sphere(0.01);
  const DugdaleLaw law{.adhesive_stress = 1e9, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
  for (const Profile* profile :
       {static_cast<const Profile*>(&power), static_cast<const Profile*>(&sphere)}) {
    for (const double a : {1e-4, 5e-4}) {
      const double hess = std::sqrt(2.0 * kPi * a * 0.05 / 1e6);
      const DugdaleState s = dugdale_contact_state(*profile, law, a);
      EXPECT_NEAR(profile->mdr_image(a) - s.indentation, hess, 1e-5 * hess);
      const double jkr_force = 1e6 * (profile->nonadhesive_force_per_modulus(a) - 2.0 * a * hess);
      EXPECT_NEAR(s.normal_force, jkr_force, 1e-5 * std::abs(jkr_force));
    }
  }
}

// The cone's no-contact branch is straight: d(c) = c (tan(theta) - 4 sigma_0/(pi E*)) - h0, so
// under fixed grips it detaches smoothly below sigma_0/(E* tan(theta)) = pi/4 (SPEC).
TEST(DugdaleZone, TheConesFreeBranchIsStraight) {
  const ConeProfile cone(10.0);
  const double tan_theta = std::tan(10.0 * kPi / 180.0);
  const DugdaleLaw law{
      .adhesive_stress = 0.5 * 1e6 * tan_theta, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
  const double c0 = dugdale_closing_radius(cone, law);
  const DugdaleState one = dugdale_free_state(cone, law, 0.5 * c0);
  const DugdaleState two = dugdale_free_state(cone, law, c0);
  const double slope = (two.indentation - one.indentation) / (0.5 * c0);
  EXPECT_NEAR(slope, tan_theta - 4.0 * law.adhesive_stress / (kPi * 1e6), 1e-12);
  EXPECT_GT(slope, 0.0);  // sigma_0/(E* tan) = 1/2 < pi/4: d rises with c, no fold
}

}  // namespace
}  // namespace mdrsim
