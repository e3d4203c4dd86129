// The contact's running sums against brute force, and the material's effective moduli.
#include "engine/model/contact.hpp"

#include <gtest/gtest.h>

#include "controllers/builtin_controllers.hpp"
#include "engine/base/material.hpp"
#include "profiles/parabolic_profile.hpp"

// Paper eqs. 8-9 at nu = 0.3.
TEST(Material, EffectiveModuliOfEquation8) {
  const auto m = mdrsim::Material::from_youngs_modulus(1e6, 0.3, 0.05);
  const double shear = 1e6 / 2.6;
  EXPECT_DOUBLE_EQ(m.effective_modulus, 1e6 / 0.91);
  EXPECT_DOUBLE_EQ(m.effective_shear_modulus, 4 * shear / 1.7);
  EXPECT_NEAR(m.effective_shear_modulus / m.effective_modulus, (2 - 0.6) / 1.7, 1e-15);  // eq. 9
}

// After removing most of a million springs one by one, the force from the running sum
// equals a fresh sum over the remaining springs.
TEST(Contact, RunningSumsStayExactOverManyRemovals) {
  const mdrsim::ParabolicProfile profile(0.01);
  const mdrsim::SpringFoundation foundation(profile, 5e-4, 1'000'000);
  const auto material = mdrsim::Material::from_youngs_modulus(1e6, 0.0, 0.05);
  mdrsim::Contact contact(foundation, material, mdrsim::FixedGripsController().constraint(),
                          mdrsim::FixedLoadController().constraint());
  contact.set_normal_control(1e-6);
  contact.set_tangential_held(1e-3);
  while (contact.springs_in_contact() > 1000) contact.detach_boundary_spring();
  double fresh = 0.0;
  for (std::int64_t i = 1; i <= 1000; ++i) fresh += 1e-6 - foundation.image(i);
  const double dx = foundation.spacing();
  const auto s = contact.snapshot();
  EXPECT_NEAR(s.normal_force, 2 * material.effective_modulus * dx * fresh,
              1e-12 * std::abs(s.normal_force));
  EXPECT_DOUBLE_EQ(s.contact_radius, 5e-4 * 1000 / 1'000'000);
  // Fixed tangential load: u = F / (2 G* dx n) over the remaining springs.
  EXPECT_NEAR(s.tangential_displacement, 1e-3 / (2 * material.effective_shear_modulus * dx * 1000),
              1e-18);
  EXPECT_NEAR(s.tangential_force, 1e-3, 1e-15);
}

// The boundary spring of the full row sits exactly at the glued radius.
TEST(Contact, BoundarySpringOfTheFullRowIsAtTheGluedRadius) {
  const mdrsim::ParabolicProfile profile(0.01);
  const mdrsim::SpringFoundation foundation(profile, 3e-4, 7);
  EXPECT_EQ(foundation.position(7), 3e-4);
  EXPECT_THROW(mdrsim::SpringFoundation(profile, 3e-4, 0), std::invalid_argument);
}
