// The general branch against the paper's closed forms (parabola), the derived cone and held-force
// folds, Kendall's punch, and finite differences of itself.
#include "engine/reference/branch_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/model/jkr_scales.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/flat_punch_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"

namespace br = mdrsim::branch_reference;
namespace ref = mdrsim::parabolic_reference;
using br::TangentialHold;
using mdrsim::AffineConstraint;
using mdrsim::Material;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr AffineConstraint kFixedGrips{1.0, 0.0};
constexpr AffineConstraint kFixedLoad{0.0, 1.0};
const double kRadius = 0.01;  // R [m]

/// The paper's material (E* = G*) and one with nu = 0.3 (G*/E* = 0.8235).
Material material(double nu) { return Material::from_youngs_modulus(1e6, nu, 0.05); }
double gamma_of(const Material& m) { return m.effective_shear_modulus / m.effective_modulus; }
mdrsim::JkrScales scales(const Material& m) {
  return *mdrsim::JkrScales::of(kRadius, m.effective_modulus, m.work_of_adhesion);
}

TangentialHold held_displacement(double u) { return {TangentialHold::Kind::displacement, u}; }
TangentialHold held_force(double f) { return {TangentialHold::Kind::force, f}; }

}  // namespace

// With g = x^2/R the branch is eqs. 25-27: every quantity and both slopes, in the paper's
// units, to 1e-12 (rounding of the unit conversions).
TEST(BranchReference, ParabolaIsThePapersBranch) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  for (const double nu : {0.0, 0.3}) {
    const Material m = material(nu);
    const auto s = scales(m);
    const double gamma = gamma_of(m);
    for (const double u : {0.0, 1.5, 3.0}) {
      const br::EquilibriumBranch branch(parabola, m, held_displacement(u * s.depth));
      for (const double a : {0.7, 1.0, 2.0}) {
        const br::BranchPoint p = branch.at(a * s.radius);
        EXPECT_NEAR(p.indentation / s.depth, ref::indentation(a, u, gamma), 1e-12);
        EXPECT_NEAR(p.normal_force / s.force, ref::normal_force(a, u, gamma), 1e-12);
        EXPECT_NEAR(p.tangential_force / s.force, ref::tangential_force(a, u, gamma), 1e-12);
        EXPECT_NEAR(branch.indentation_slope(a * s.radius) * s.radius / s.depth,
                    ref::indentation_slope(a, u, gamma), 1e-11);
        EXPECT_NEAR(branch.normal_force_slope(a * s.radius) * s.radius / s.force,
                    ref::normal_force_slope(a, u, gamma), 1e-11);
      }
    }
  }
}

// The numerically located folds are the paper's: eq. 31 (fixed grips), eq. 29 (fixed load)
// and the compliant fold dF/da + k dd/da = 0, each solved by TOMS 748 in both codes: 1e-10.
TEST(BranchReference, ParabolaFoldsAreEquationsTwentyNineAndThirtyOne) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  for (const double nu : {0.0, 0.3}) {
    const Material m = material(nu);
    const auto s = scales(m);
    const double gamma = gamma_of(m);
    for (const double u : {0.0, 1.0, 2.5, 4.0}) {
      const br::EquilibriumBranch branch(parabola, m, held_displacement(u * s.depth));
      const double glued = 3.0 * s.radius;
      const br::Critical fg = branch.critical(kFixedGrips, glued);
      const br::Critical fl = branch.critical(kFixedLoad, glued);
      ASSERT_EQ(fg.kind, br::Critical::Kind::fold);
      ASSERT_EQ(fl.kind, br::Critical::Kind::fold);
      EXPECT_NEAR(fg.point.normal_force / s.force, ref::fixed_grips_critical(u, gamma).normal_force,
                  1e-10);
      EXPECT_NEAR(fg.point.contact_radius / s.radius,
                  ref::fixed_grips_critical(u, gamma).contact_radius, 1e-10);
      EXPECT_NEAR(fl.point.normal_force / s.force, ref::fixed_load_critical(u, gamma).normal_force,
                  1e-10);
      EXPECT_NEAR(fl.point.contact_radius / s.radius,
                  ref::fixed_load_critical(u, gamma).contact_radius, 1e-10);
      for (const double k : {0.3, 3.0}) {
        const AffineConstraint compliant{1.0, s.depth / (k * s.force)};
        EXPECT_NEAR(branch.critical(compliant, glued).point.normal_force / s.force,
                    ref::compliant_critical(k, u, gamma).normal_force, 1e-10);
      }
    }
  }
}

// With F_x held the same search finds the folds derived in parabolic_reference.cpp
// (a^3 = 1 + q/4 under fixed load, the cubic under fixed grips): two independent routes.
TEST(BranchReference, HeldTangentialForceFoldsAreTheDerivedOnes) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  for (const double nu : {0.0, 0.3}) {
    const Material m = material(nu);
    const auto s = scales(m);
    const double gamma = gamma_of(m);
    for (const double fx : {0.0, 0.5, 2.0, 4.0}) {
      const br::EquilibriumBranch branch(parabola, m, held_force(fx * s.force));
      const double glued = 3.0 * s.radius;
      const auto fl = branch.critical(kFixedLoad, glued);
      const auto fg = branch.critical(kFixedGrips, glued);
      const auto want_fl = ref::fixed_load_critical_at_tangential_force(fx, gamma);
      const auto want_fg = ref::fixed_grips_critical_at_tangential_force(fx, gamma);
      EXPECT_NEAR(fl.point.normal_force / s.force, want_fl.normal_force, 1e-10) << fx;
      EXPECT_NEAR(fl.point.contact_radius / s.radius, want_fl.contact_radius, 1e-10) << fx;
      EXPECT_NEAR(fl.point.indentation / s.depth, want_fl.indentation, 1e-10) << fx;
      EXPECT_NEAR(fl.point.tangential_displacement / s.depth, want_fl.tangential_displacement,
                  1e-10)
          << fx;
      EXPECT_NEAR(fg.point.normal_force / s.force, want_fg.normal_force, 1e-10) << fx;
      EXPECT_NEAR(fg.point.contact_radius / s.radius, want_fg.contact_radius, 1e-10) << fx;
      EXPECT_NEAR(fg.point.indentation / s.depth, want_fg.indentation, 1e-10) << fx;
      EXPECT_NEAR(fl.point.tangential_force / s.force, fx, 1e-12);
    }
  }
}

// The cone, g = k x with k = (pi/2) tan(theta) and w = 2 pi dgamma/E*: d = k a - sqrt(w a),
// F = E* k a^2 - 2 E* sqrt(w) a^(3/2).
//   fixed load,  F' = 0: sqrt(a) = 3 sqrt(w)/(2k), a = 9w/(4k^2), F = -E* sqrt(w) a^(3/2)/2
//                        = -27 E* w^2/(16 k^3) = -54 dgamma^2/(pi E* tan^3 theta);
//   fixed grips, d' = 0: sqrt(a) = sqrt(w)/(2k),  a = w/(4k^2),  F = -(3/2) E* sqrt(w) a^(3/2)
//                        = -3 E* w^2/(16 k^3) = -6 dgamma^2/(pi E* tan^3 theta), d = -w/(4k).
TEST(BranchReference, ConeFoldsHaveClosedForms) {
  const Material m = material(0.0);
  for (const double angle : {5.0, 10.0, 30.0}) {
    const mdrsim::ConeProfile cone(angle);
    const double t = std::tan(angle * kPi / 180.0);
    const double k = 0.5 * kPi * t;
    const double w = 2.0 * kPi * m.work_of_adhesion / m.effective_modulus;
    const double dg2 = m.work_of_adhesion * m.work_of_adhesion;
    const br::EquilibriumBranch branch(cone, m);
    const double glued = 10.0 * w / (k * k);
    const auto fl = branch.critical(kFixedLoad, glued);
    const auto fg = branch.critical(kFixedGrips, glued);
    const double f_fl = -54.0 * dg2 / (kPi * m.effective_modulus * t * t * t);
    const double f_fg = -6.0 * dg2 / (kPi * m.effective_modulus * t * t * t);
    EXPECT_NEAR(fl.point.contact_radius, 9.0 * w / (4.0 * k * k), 1e-10 * w / (k * k));
    EXPECT_NEAR(fl.point.normal_force, f_fl, 1e-10 * std::abs(f_fl));
    EXPECT_NEAR(fg.point.contact_radius, w / (4.0 * k * k), 1e-10 * w / (k * k));
    EXPECT_NEAR(fg.point.normal_force, f_fg, 1e-10 * std::abs(f_fg));
    EXPECT_NEAR(fg.point.indentation, -w / (4.0 * k), 1e-10 * w / k);
  }
}

// Kendall's flat punch: d = -e(a), dd/da < 0 at the edge already, so the first let-go is the
// jump, at F = -2 E* A dl(A) = -sqrt(8 pi A^3 E* dgamma) under either control.
TEST(BranchReference, FlatPunchLetsGoAtOnceWithKendallsForce) {
  const Material m = material(0.0);
  const double a = 1e-4;
  const mdrsim::FlatPunchProfile punch(a);
  const double kendall = -std::sqrt(8.0 * kPi * a * a * a * m.effective_modulus * 0.05);
  for (const AffineConstraint c : {kFixedGrips, kFixedLoad}) {
    const auto critical = br::EquilibriumBranch(punch, m).critical(c, a);
    EXPECT_EQ(critical.kind, br::Critical::Kind::first_detachment);
    EXPECT_NEAR(critical.point.normal_force, kendall, 1e-14 * std::abs(kendall));
  }
}

// The slopes are the a-derivatives of the branch: fourth-order differences (step 1e-4 a,
// error ~1e-13) of at(), for profiles without a closed-form fold, with either tangential hold.
TEST(BranchReference, SlopesAreDerivativesOfTheBranch) {
  const Material m = material(0.3);
  const mdrsim::SphereProfile sphere(2e-3);
  const mdrsim::PowerLawProfile power(0.8, 1.5);
  mdrsim::ProfileTable t;
  for (int i = 0; i <= 20; ++i) {
    t.radii.push_back(1e-4 * i);
    t.gaps.push_back(power.shape(1e-4 * i));
  }
  const mdrsim::TabulatedProfile table(t);
  for (const mdrsim::Profile* p :
       {static_cast<const mdrsim::Profile*>(&sphere), static_cast<const mdrsim::Profile*>(&power),
        static_cast<const mdrsim::Profile*>(&table)}) {
    for (const TangentialHold hold : {held_displacement(1e-6), held_force(1e-3)}) {
      const br::EquilibriumBranch branch(*p, m, hold);
      for (const double a : {3e-4, 7e-4, 1.3e-3}) {
        const double h = 1e-4 * a;
        const auto diff = [&](auto get) {
          return (8.0 * (get(branch.at(a + h)) - get(branch.at(a - h))) -
                  (get(branch.at(a + 2 * h)) - get(branch.at(a - 2 * h)))) /
                 (12.0 * h);
        };
        const double dd = diff([](const br::BranchPoint& q) { return q.indentation; });
        const double df = diff([](const br::BranchPoint& q) { return q.normal_force; });
        EXPECT_NEAR(branch.indentation_slope(a), dd, 1e-7 * std::abs(dd) + 1e-12);
        EXPECT_NEAR(branch.normal_force_slope(a), df, 1e-7 * std::abs(df) + 1e-9);
      }
    }
  }
}

// The branch ends where eq. 21 has no real stretch: with u held at a = (G*/E*) u^2 E*/(2 pi
// dgamma), with F_x held where F_x^2 = 8 pi G* a^3 dgamma. Glued below it, the contact
// shears off at once; without adhesion nothing jumps.
TEST(BranchReference, EndsWhereTheTangentialLoadShearsTheGlueOff) {
  const Material m = material(0.3);
  const mdrsim::ParabolicProfile parabola(kRadius);
  const double fx = 2e-3;
  const br::EquilibriumBranch by_force(parabola, m, held_force(fx));
  const double a_force = by_force.shear_off_radius();
  EXPECT_NEAR(fx * fx, 8.0 * kPi * m.effective_shear_modulus * std::pow(a_force, 3) * 0.05,
              1e-12 * fx * fx);
  EXPECT_EQ(by_force.stretch(a_force * (1 - 1e-9)), 0.0);
  EXPECT_GT(by_force.stretch(a_force * (1 + 1e-6)), 0.0);
  EXPECT_EQ(by_force.critical(kFixedLoad, 0.99 * a_force).kind, br::Critical::Kind::shear_off);
  EXPECT_EQ(by_force.critical(kFixedLoad, 5.0 * a_force).kind, br::Critical::Kind::fold);

  const double u = 1e-6;
  const br::EquilibriumBranch by_displacement(parabola, m, held_displacement(u));
  EXPECT_NEAR(by_displacement.shear_off_radius(),
              m.effective_shear_modulus * u * u / (2.0 * kPi * 0.05), 1e-15);

  const Material sticky_free = Material::from_youngs_modulus(1e6, 0.0, 0.0);
  EXPECT_EQ(br::EquilibriumBranch(parabola, sticky_free).critical(kFixedLoad, 1e-4).kind,
            br::Critical::Kind::none);
}
