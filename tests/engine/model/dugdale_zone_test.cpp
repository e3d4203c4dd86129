// The MDR's Dugdale zone against Maugis' classical parabola (maugis_reference), its closed-form
// gap integrals against the quadrature, its solved states against their opening condition in
// 50 digits, and its JKR limit for a shape Maugis did not solve.
#include "engine/model/dugdale_zone.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/reference/maugis_reference.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"
#include "profiles/wavy_profile.hpp"
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

// The closed forms against the quadrature every other profile takes (dugdale_gap_quadrature),
// at angles from a thin zone (1e-6) to a zone many times the contact (1.5 rad). Neither
// cancels (the quadrature integrates g' by parts): 2e-14, some tens of ulps of the rule's error
// and rounding (tests/profiles/dugdale_gap_test.cpp holds both to 50 digits).
TEST(DugdaleZone, ClosedFormGapIntegralsMatchTheQuadrature) {
  const ParabolicProfile parabola(0.01);
  const ConeProfile cone(30.0);
  for (const double t : {1e-6, 1e-3, 0.05, 0.3, 1.0, 1.5}) {
    SCOPED_TRACE(t);
    const double a = 2e-4, c = a / std::cos(t);
    for (const Profile* profile :
         {static_cast<const Profile*>(&parabola), static_cast<const Profile*>(&cone)}) {
      const DugdaleGap closed = profile->dugdale_gap(a, c, t);
      const DugdaleGap quadrature = dugdale_gap_quadrature(*profile, a, c, t);
      EXPECT_NEAR(closed.integral, quadrature.integral, 2e-14 * closed.integral);
      EXPECT_NEAR(closed.angle_slope, quadrature.angle_slope, 2e-14 * closed.angle_slope);
    }
  }
}

// The solved state satisfies the opening condition: the zone's opening at c, evaluated apart
// from the solver in 50 digits from the definition (J = int_0^t (g(c cos psi) - g(a)) dpsi,
// s t - (c - a) without its rewriting), equals h0 within 1e-12 of it, for the sphere (the
// quadrature) and the parabola, power law and cone (closed forms), from the JKR side (sigma_0
// = 1e9 Pa, t ~ 1e-3) to the DMT side (1e4 Pa, the zone far beyond the contact). t is the
// unknown and the opening rises like t^2 at small t: a relative error e in t is 2e in O.
TEST(DugdaleZone, TheSolvedStateOpensTheZoneByItsRange) {
  using Wide = boost::multiprecision::cpp_bin_float_50;
  const double radius = 0.01;
  const SphereProfile sphere(radius);
  const ParabolicProfile parabola(radius);
  const PowerLawProfile power(3e3, 2.5);
  const ConeProfile cone(10.0);
  const Wide power_k = power.mdr_image(1.0), cone_k = cone.mdr_image(1.0);
  struct Case {
    const Profile* profile;
    std::function<Wide(const Wide&)> image;
  };
  const Case cases[] = {
      {&sphere, [&](const Wide& x) { return Wide(x * atanh(x / radius)); }},
      {&parabola, [&](const Wide& x) { return Wide(x * x / radius); }},
      {&power, [&](const Wide& x) { return Wide(power_k * pow(x, Wide(2.5))); }},
      {&cone, [&](const Wide& x) { return Wide(cone_k * x); }},
  };
  for (const Case& k : cases) {
    for (const double stress : {1e9, 1e7, 1e5, 1e4}) {
      const DugdaleLaw law{
          .adhesive_stress = stress, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
      for (const double a : {1e-5, 2e-4, 1e-3}) {
        SCOPED_TRACE(testing::Message() << "sigma_0 " << stress << " a " << a);
        DugdaleState s;
        try {
          s = dugdale_contact_state(*k.profile, law, a);
        } catch (const std::domain_error&) {
          continue;  // the sphere's zone would pass its edge
        }
        const Wide t = s.angle, wa = a;
        const Wide c = wa / cos(t);
        const Wide ga = k.image(wa);
        // Over psi = t u, u in [0, 1] (Boost's error estimate is not scaled by the width).
        const Wide gap = boost::math::quadrature::gauss_kronrod<Wide, 61>::integrate(
            [&](const Wide& u) { return Wide(t * (k.image(c * cos(t * u)) - ga)); }, Wide(0),
            Wide(1), 12, Wide(1e-30));
        const Wide stretch = sqrt(c * c - wa * wa) * t - (c - wa);
        const Wide open =
            2 / boost::math::constants::pi<Wide>() * (gap + Wide(law.zone_strain()) * stretch);
        EXPECT_NEAR(static_cast<double>(open / law.range()), 1.0, 1e-12);
        // c = a / cos t to the rounding of t, which a wide zone magnifies by t tan t.
        const double c_rounding = 4e-16 * (1.0 + s.angle * std::tan(s.angle));
        EXPECT_NEAR(s.cohesive_radius, static_cast<double>(c), c_rounding * s.cohesive_radius);
      }
    }
  }
}

// A state solved from a guess of its half-chord is the state from the small-t cubic: near
// guesses (1e-6 off, a root search's neighbour) and far ones (half, twice) alike, to the same
// 1e-13 of the force's terms as a curve from neighbours, for the same reason.
TEST(DugdaleZone, AStateFromAGuessIsTheIndependentState) {
  const SphereProfile sphere(0.01);
  const PowerLawProfile power(3e3, 2.5);
  const DugdaleLaw law{
      .adhesive_stress = 1.5e4, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
  for (const Profile* profile :
       {static_cast<const Profile*>(&sphere), static_cast<const Profile*>(&power)}) {
    for (const double a : {1e-5, 1e-4, 5e-4}) {
      const DugdaleState alone = dugdale_contact_state(*profile, law, a);
      const double half_chord = alone.cohesive_radius * std::sin(alone.angle);
      const double terms =
          1e6 * profile->nonadhesive_force_per_modulus(a) +
          2.0 * law.adhesive_stress * alone.cohesive_radius * alone.cohesive_radius * alone.angle;
      for (const double factor : {1.0 - 1e-6, 1.0 + 1e-6, 0.5, 2.0}) {
        SCOPED_TRACE(testing::Message() << "a " << a << " guess " << factor);
        const DugdaleState guessed = dugdale_contact_state(*profile, law, a, factor * half_chord);
        EXPECT_NEAR(guessed.cohesive_radius, alone.cohesive_radius, 1e-13 * alone.cohesive_radius);
        EXPECT_NEAR(guessed.normal_force, alone.normal_force, 1e-13 * terms);
      }
    }
  }
}

// The branch's slopes dd/da and dF/da by implicit differentiation against a fourth-order central
// difference of the states, step 1e-3 a: its truncation (1e-3)^4 of the scale, its rounding
// about 1e-16/1e-3 of the force's terms over a. Tolerance 1e-9 of the terms over a (dF/da, dd/da
// themselves cross zero at the folds), from a thin zone (sigma_0 = 1e8 Pa) to a wide one (1e3).
TEST(DugdaleZone, BranchSlopesMatchTheStatesDifferences) {
  const ParabolicProfile parabola(0.01);
  const SphereProfile sphere(0.01);
  const PowerLawProfile power(3e3, 2.5);
  const ConeProfile cone(5.0);
  for (const Profile* profile :
       {static_cast<const Profile*>(&parabola), static_cast<const Profile*>(&sphere),
        static_cast<const Profile*>(&power), static_cast<const Profile*>(&cone)}) {
    for (const double stress : {1e8, 1.5e4, 1e3}) {
      const DugdaleLaw law{
          .adhesive_stress = stress, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
      for (const double a : {2e-5, 1e-4, 2.5e-4, 5e-4}) {
        SCOPED_TRACE(testing::Message() << "sigma_0 " << stress << " a " << a);
        const DugdaleState state = dugdale_contact_state(*profile, law, a);
        const DugdaleSlopes slopes = dugdale_contact_slopes(*profile, law, state);
        const double h = 1e-3 * a;
        const auto at = [&](double x) { return dugdale_contact_state(*profile, law, x); };
        const auto difference = [&](auto value) {
          return (8.0 * (value(at(a + h)) - value(at(a - h))) -
                  (value(at(a + 2 * h)) - value(at(a - 2 * h)))) /
                 (12.0 * h);
        };
        const double force_terms =
            1e6 * profile->nonadhesive_force_per_modulus(a) +
            2.0 * stress * state.cohesive_radius * state.cohesive_radius * state.angle;
        EXPECT_NEAR(slopes.normal_force,
                    difference([](const DugdaleState& x) { return x.normal_force; }),
                    1e-9 * force_terms / a);
        const double depth_terms =
            profile->mdr_image(a) + law.zone_strain() * state.cohesive_radius;
        EXPECT_NEAR(slopes.indentation,
                    difference([](const DugdaleState& x) { return x.indentation; }),
                    1e-9 * depth_terms / a);
        // ds/da of the half-chord s = c sin t, whose scale is c.
        EXPECT_NEAR(slopes.half_chord, difference([](const DugdaleState& x) {
                      return x.cohesive_radius * std::sin(x.angle);
                    }),
                    1e-9 * state.cohesive_radius / a);
      }
    }
  }
}

/// A profile that counts its gap integrals (what a solve costs).
class CountingProfile final : public Profile {
 public:
  explicit CountingProfile(const Profile& p) : p_(p) {}
  double shape(double r) const override { return p_.shape(r); }
  double mdr_image(double x) const override { return p_.mdr_image(x); }
  double mdr_image_slope(double x) const override { return p_.mdr_image_slope(x); }
  double nonadhesive_force_per_modulus(double a) const override {
    return p_.nonadhesive_force_per_modulus(a);
  }
  DugdaleGap dugdale_gap(double a, double c, double t) const override {
    ++gaps;
    return p_.dugdale_gap(a, c, t);
  }
  double outer_radius() const override { return p_.outer_radius(); }
  mutable int gaps = 0;

 private:
  const Profile& p_;
};

// A curve solved from each point's neighbour is the curve of independent solves: both stop
// once Newton's step is below 1e-9 of the half-chord, when the root is at its rounding, so the
// two agree to a few ulps of the force's terms (1e-13 allows the opening's rounding over its
// slope near the closing point, where the zone is 300 times the contact). The sphere, a power
// law and the bench's table of the sphere (200 points to 0.6 R, its gap on the image's Hermite
// pieces). Each point's guess, the Hermite cubic through the last two zones with their slopes,
// lies inside Newton's 1e-9 on these close radii (1000, the bench's curve): one gap integral a
// point (the worst seen: 1.015, the power law; 1.05 allowed).
TEST(DugdaleZone, ACurveFromNeighboursIsTheCurveOfIndependentStates) {
  const SphereProfile sphere(0.01);
  const PowerLawProfile power(3e3, 2.5);
  ProfileTable table;
  for (int i = 0; i < 200; ++i) {
    const double r = 0.6 * 0.01 * i / 199.0;
    table.radii.push_back(r);
    table.gaps.push_back(0.01 - std::sqrt(0.01 * 0.01 - r * r));
  }
  const TabulatedProfile tabulated(table);
  const DugdaleLaw law{
      .adhesive_stress = 1.5e4, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
  std::vector<double> radii;
  for (int k = 1000; k >= 1; --k) radii.push_back(5e-4 * k / 1000.0);
  for (const Profile* inner :
       {static_cast<const Profile*>(&sphere), static_cast<const Profile*>(&power),
        static_cast<const Profile*>(&tabulated)}) {
    const CountingProfile profile(*inner);
    const std::vector<DugdaleState> curve = dugdale_contact_states(profile, law, radii);
    ASSERT_EQ(curve.size(), radii.size());
    EXPECT_LE(profile.gaps, 1.05 * static_cast<double>(radii.size()));
    for (std::size_t k = 0; k < radii.size(); ++k) {
      const DugdaleState alone = dugdale_contact_state(*inner, law, radii[k]);
      EXPECT_NEAR(curve[k].cohesive_radius, alone.cohesive_radius, 1e-13 * alone.cohesive_radius);
      // F = E* nf(a) - 2 sigma_0 (a s + c^2 t) crosses zero: relative to its terms.
      const double terms =
          1e6 * inner->nonadhesive_force_per_modulus(radii[k]) +
          2.0 * law.adhesive_stress * alone.cohesive_radius * alone.cohesive_radius * alone.angle;
      EXPECT_NEAR(curve[k].normal_force, alone.normal_force, 1e-13 * terms);
    }
  }
}

// A solve started at its own root (a walk that stands still, as the path's phase [0, 1] does
// where the preload is the glued radius's own depth) takes one gap integral and ends there: a
// step onto its bracket's end, where the excess rounds to zero, is converged, not bisected.
TEST(DugdaleZone, AStateFromItsOwnRootTakesOneGapIntegral) {
  const SphereProfile sphere(0.01);
  const PowerLawProfile power(3e3, 2.5);
  const DugdaleLaw law{
      .adhesive_stress = 1.5e4, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
  for (const Profile* inner :
       {static_cast<const Profile*>(&sphere), static_cast<const Profile*>(&power)}) {
    const CountingProfile profile(*inner);
    for (const double a : {1e-5, 1e-4, 5e-4}) {
      const DugdaleState alone = dugdale_contact_state(profile, law, a);
      const double half_chord = alone.cohesive_radius * std::sin(alone.angle);
      const DugdaleState again = dugdale_contact_state(profile, law, a, half_chord);
      profile.gaps = 0;
      const DugdaleState third =
          dugdale_contact_state(profile, law, a, again.cohesive_radius * std::sin(again.angle));
      EXPECT_EQ(profile.gaps, 1) << a;
      EXPECT_NEAR(third.cohesive_radius, alone.cohesive_radius, 1e-15 * alone.cohesive_radius);
    }
  }
}

// The slopes a solve reads at its last iterate (dugdale_sloped_contact_state) are the state's
// own slopes where that iterate is the root (a solve from its own half-chord: one gap integral,
// offset within 32 eps of the half-chord, slopes equal to dugdale_contact_slopes to 1e-12 of their
// terms times the cancellation's gain 1 + g'/((2 sigma_0/E*) t)). Where the premise fails, an
// iterate 1e-3 of the half-chord from the root (a guess that far off, taken as it stands), the
// offset says so: it is 1e-3 of the half-chord, the slopes differ from the state's by more than
// 1e-9 of their terms (not the state's to the route's 1e-10: a root search refuses them) and by
// less than 64 times the offset's share of them times the gain (the margin a scan reading their
// sign keeps; the worst seen is 1.4).
TEST(DugdaleZone, SlopesAtTheLastIterateAreTheStatesToItsOffset) {
  const ParabolicProfile parabola(0.01);
  const SphereProfile sphere(0.01);
  const PowerLawProfile power(3e3, 2.5);
  const ConeProfile cone(5.0);
  double worst = 0.0;
  for (const Profile* inner :
       {static_cast<const Profile*>(&parabola), static_cast<const Profile*>(&sphere),
        static_cast<const Profile*>(&power), static_cast<const Profile*>(&cone)}) {
    const CountingProfile profile(*inner);
    for (const double stress : {1e8, 1.5e4, 1e3}) {
      const DugdaleLaw law{
          .adhesive_stress = stress, .work_of_adhesion = 0.05, .effective_modulus = 1e6};
      const double z = law.zone_strain();
      for (const double a : {2e-5, 1e-4, 5e-4}) {
        SCOPED_TRACE(testing::Message() << "sigma_0 " << stress << " a " << a);
        const DugdaleState state = dugdale_contact_state(profile, law, a);
        const DugdaleSlopes exact = dugdale_contact_slopes(profile, law, state);
        const double chord = state.cohesive_radius * std::sin(state.angle);
        const double image_slope = profile.mdr_image_slope(a);
        const double terms = (1.0 + image_slope / (z * state.angle)) *
                             (image_slope + z * std::abs(exact.half_chord));
        profile.gaps = 0;
        const DugdaleSlopedState at_root = dugdale_sloped_contact_state(profile, law, a, chord);
        EXPECT_EQ(profile.gaps, 1);
        EXPECT_LE(at_root.offset, 32.0 * std::numeric_limits<double>::epsilon() * chord);
        EXPECT_NEAR(at_root.slopes.indentation, exact.indentation, 1e-12 * terms);
        EXPECT_NEAR(at_root.state.cohesive_radius, state.cohesive_radius,
                    1e-14 * state.cohesive_radius);  // a step of the excess's rounding

        const auto first_iterate = [](const DugdaleSlopedState&) { return true; };
        const DugdaleSlopedState off =
            dugdale_sloped_contact_state(profile, law, a, (1.0 + 1e-3) * chord, first_iterate);
        EXPECT_GT(off.offset, 0.5e-3 * chord);
        EXPECT_LT(off.offset, 2e-3 * chord);
        const double miss = std::abs(off.slopes.indentation - exact.indentation);
        EXPECT_GT(miss, 1e-9 * terms);
        EXPECT_LT(miss, 8.0 * (off.offset / chord) * terms);
        worst = std::max(worst, miss / ((off.offset / chord) * terms));
      }
    }
  }
  RecordProperty("worst_miss_over_offset", std::to_string(worst));
  std::printf("worst slope miss over the offset's share: %.3g\n", worst);
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

/// The wavy profile with the generic quadrature's non-adhesive force (Gauss-Kronrod, the slow
/// path its states took before the closed form); its zone's gap integral is the profile's own.
class WavyByQuadrature final : public Profile {
 public:
  explicit WavyByQuadrature(const WavyProfile& wavy) : wavy_(wavy) {}
  double shape(double r) const override { return wavy_.shape(r); }
  double mdr_image(double x) const override { return wavy_.mdr_image(x); }
  double mdr_image_slope(double x) const override { return wavy_.mdr_image_slope(x); }
  DugdaleGap dugdale_gap(double a, double c, double t) const override {
    return wavy_.dugdale_gap(a, c, t);
  }

 private:
  const WavyProfile& wavy_;
};

// Wavy states with the closed-form non-adhesive force against the same states by the quadrature
// it replaces, in the transition (lambda = 1) on the bench's ripple (10 nm at 100 um, R = 1 cm)
// and one ten times as strong: the zone is the same solve (a, c, d bit for bit), and F within
// 1e-12 of its terms E* nf(a) + 2 sigma_0 c^2 t (each nf is good to about 1e-13 of 2 a g(a):
// WavyProfile.NonadhesiveForceIsItsDefinition, the quadrature to its 1e-14 request).
TEST(DugdaleZone, WavyStatesKeepTheirForceWithTheClosedFormContactForce) {
  const double radius = 0.01, modulus = 1e6, work = 0.05;
  const double stress =
      1.0 / std::cbrt(9.0 * radius / (2.0 * kPi * work * modulus * modulus));  // lambda = 1
  const DugdaleLaw law{
      .adhesive_stress = stress, .work_of_adhesion = work, .effective_modulus = modulus};
  for (const double amplitude : {1e-8, 1e-7}) {
    const WavyProfile wavy(radius, amplitude, 1e-4);
    const WavyByQuadrature slow(wavy);
    for (const double a : {3e-5, 2.05e-4, 5e-4}) {
      SCOPED_TRACE(testing::Message() << amplitude << " " << a);
      const DugdaleState fast = dugdale_contact_state(wavy, law, a);
      const DugdaleState before = dugdale_contact_state(slow, law, a);
      EXPECT_EQ(fast.cohesive_radius, before.cohesive_radius);
      EXPECT_EQ(fast.indentation, before.indentation);
      const double terms = modulus * wavy.nonadhesive_force_per_modulus(a) +
                           2.0 * stress * fast.cohesive_radius * fast.cohesive_radius * fast.angle;
      EXPECT_NEAR(fast.normal_force, before.normal_force, 1e-12 * terms);
    }
  }
}

}  // namespace
}  // namespace mdrsim
