// The friction references agree: closed forms, quadrature through g, the loop energy 3 ways.
#include "engine/reference/friction_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"

namespace {

namespace fr = mdrsim::friction_reference;

constexpr double kModulus = 1.0e6;       // E* [Pa]
constexpr double kShearModulus = 0.8e6;  // G* [Pa]
constexpr double kMu = 0.4;
// Quadrature (Gauss-Kronrod to 1e-14) against closed forms: 1e-10 relative leaves room for
// the profile's own root search of the contact radius.
constexpr double kQuadrature = 1e-10;

TEST(FrictionReference, ParabolaThroughGMatchesItsClosedForms) {
  const double radius = 0.01;
  const double a = 1e-4;
  const double d = a * a / radius;
  const mdrsim::ParabolicProfile profile(radius);
  const fr::CattaneoMindlin cm(profile, kModulus, kShearModulus, kMu, d);
  const double fz = 4.0 * kModulus * a * a * a / (3.0 * radius);
  EXPECT_NEAR(cm.contact_radius(), a, kQuadrature * a);
  EXPECT_NEAR(cm.normal_force(), fz, kQuadrature * fz);
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, d);
  EXPECT_NEAR(us, 3.0 * kMu * fz / (4.0 * a * kShearModulus), 1e-15 * us);  // u* two ways
  for (const double xi : {0.0, 0.1, 0.5, 0.9, 1.0, 1.3}) {
    const double u = xi * us;
    EXPECT_NEAR(cm.loading_force(u), fr::parabola_loading_force(kMu * fz, u, us),
                kQuadrature * kMu * fz)
        << xi;
    EXPECT_NEAR(cm.stick_radius(u), fr::parabola_stick_radius(a, u, us), kQuadrature * a) << xi;
  }
  // The inverse and the branches at their ends: unloading from u_m reaches -L(u_m) at -u_m.
  const double fx = fr::parabola_loading_force(kMu * fz, 0.6 * us, us);
  EXPECT_NEAR(fr::parabola_displacement_at_force(kMu * fz, fx, us), 0.6 * us, 1e-14 * us);
  EXPECT_NEAR(cm.unloading_force(0.6 * us, -0.6 * us), -fx, kQuadrature * fz);
  EXPECT_NEAR(cm.reloading_force(0.6 * us, 0.6 * us), fx, kQuadrature * fz);
}

TEST(FrictionReference, ConeThroughGMatchesItsClosedForms) {
  const mdrsim::ConeProfile profile(10.0);
  const double a = 1e-4;
  const double d = 0.5 * std::numbers::pi * std::tan(10.0 * std::numbers::pi / 180.0) * a;
  const fr::CattaneoMindlin cm(profile, kModulus, kShearModulus, kMu, d);
  const double fz =
      0.5 * std::numbers::pi * kModulus * std::tan(10.0 * std::numbers::pi / 180.0) * a * a;
  EXPECT_NEAR(cm.normal_force(), fz, kQuadrature * fz);
  const double us = cm.full_slip();
  for (const double xi : {0.05, 0.5, 0.95}) {
    EXPECT_NEAR(cm.loading_force(xi * us), fr::cone_loading_force(kMu * fz, xi * us, us),
                kQuadrature * kMu * fz);
    EXPECT_NEAR(cm.stick_radius(xi * us), fr::cone_stick_radius(a, xi * us, us), kQuadrature * a);
  }
}

TEST(FrictionReference, LoopEnergyAgreesSpringBySpringFromTheBranchesAndInTheLiterature) {
  const double radius = 0.01;
  const double a = 1e-4;
  const double d = a * a / radius;
  const mdrsim::ParabolicProfile profile(radius);
  const fr::CattaneoMindlin cm(profile, kModulus, kShearModulus, kMu, d);
  const double fz = cm.normal_force();
  const double us = cm.full_slip();
  for (const double xi : {0.05, 0.3, 0.7, 1.0, 1.5}) {
    const double um = xi * us;
    const double closed = fr::parabola_loop_energy(kMu * fz, us, um);
    // Below about xi = 0.05 W ~ mu F u* xi^3/2 is 6e-5 of mu F u*: the relative tolerance
    // of the nested quadrature (1e-10 of mu F u*) is still 1e-6 of it.
    const double tolerance = 1e-9 * kMu * fz * us;
    EXPECT_NEAR(cm.loop_energy(um), closed, tolerance) << xi;
    EXPECT_NEAR(cm.loop_energy_from_branches(um), closed, tolerance) << xi;
    if (xi <= 1.0) {
      const double amplitude = fr::parabola_loading_force(kMu * fz, um, us);
      EXPECT_NEAR(fr::parabola_loop_energy_at_force(kMu, fz, a, kShearModulus, amplitude), closed,
                  tolerance)
          << xi;
    }
  }
  // Small amplitudes: W -> mu F u* xi^3/2 (Mindlin's cubic law), to O(xi^4).
  const double xi = 1e-3;
  EXPECT_NEAR(fr::parabola_loop_energy(kMu * fz, us, xi * us) / (kMu * fz * us), 0.5 * xi * xi * xi,
              xi * xi * xi * xi + 1e-15);
  // Full slip: beyond u* the loop is 4 mu F (u_m - u*) wider than at u*, which is 4/5 mu F u*.
  EXPECT_NEAR(fr::parabola_loop_energy(kMu * fz, us, us), 0.8 * kMu * fz * us, 1e-14 * fz * us);
}

TEST(FrictionReference, BruteForceRowFollowsOneSpringByHand) {
  // One spring, kz = E* dx = 1, kx = G* dx = 0.8 (dx = 1e-6), g = 0, mu = 0.4: pressed to
  // d = 1e-6 its limit is 0.4 x 1 x 1e-6 = 4e-7 N. Sheared to u = 1e-6 it slips once
  // kx u = 4e-7, at u = 5e-7, and slides 5e-7: dissipated 4e-7 x 5e-7 per half, 4e-13 in all.
  fr::BruteForceRow row({0.0}, 1e-6, kModulus, kShearModulus, kMu);
  row.move_to(1e-6, 0.0, 10);
  row.move_to(1e-6, 1e-6, 1000);
  EXPECT_NEAR(row.tangential_force(), 2.0 * 4e-7, 1e-20);
  EXPECT_NEAR(row.dissipated(), 2.0 * 4e-7 * 5e-7, 1e-25);
  EXPECT_EQ(row.springs_sliding(), 1);
}

}  // namespace
