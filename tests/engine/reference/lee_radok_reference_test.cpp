// The viscoelastic references themselves (tests/support/lee_radok): Dawson's function against
// known values, Lee-Radok's and Ting's closed forms against their elastic limits and against
// quadratures that take neither Dawson's function nor the integration by parts.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/lee_radok.hpp"

namespace mdrsim {
namespace {

using test::ParabolaRamp;
using test::StandardLinearSolid;

// Values of sqrt(pi)/2 exp(-x^2) erfi(x) at 30 digits (mpmath), to 1e-14 relative: each method
// (series, Rybicki's sum, asymptotic series) carries about 1e-16.
TEST(Dawson, KnownValues) {
  struct Known {
    double x, value;
  };
  for (const Known& known :
       {Known{0.001, 9.999993333336e-4}, Known{0.1, 0.0993359923978528611},
        Known{0.5, 0.424436383502022296}, Known{0.9241388730, 0.541044224635181698},
        Known{1.0, 0.538079506912768419}, Known{1.5, 0.428249071085398625},
        Known{2.0, 0.301340388923791966}, Known{3.0, 0.178271030610558287},
        Known{5.0, 0.102134074424276835}, Known{10.0, 0.050253847187598528},
        Known{30.0, 0.0166759414010591758}}) {
    EXPECT_NEAR(test::dawson(known.x), known.value, 1e-14 * known.value) << known.x;
    EXPECT_NEAR(test::dawson(-known.x), -known.value, 1e-14 * known.value) << known.x;
  }
  // Beyond |x| = 50 the asymptotic series.
  EXPECT_NEAR(test::dawson(60.0), 0.00833449122332905114, 1e-14 * 0.00833449122332905114);
  EXPECT_NEAR(test::dawson(1000.0), 0.00050000025000037500094, 1e-14 * 0.0005000002500003750);
  // The methods meet: either side of x = 1 and x = 50 (D is smooth: D' = 1 - 2 x D).
  for (const double edge : {1.0, 50.0}) {
    const double below = test::dawson(std::nextafter(edge, 0.0)), above = test::dawson(edge);
    EXPECT_NEAR(below, above, 1e-15 * above) << edge;
  }
}

// z - D(z) = 2 z^3 / 3 - 4 z^5 / 15 + ...: its series keeps the digits the difference loses.
// At z <= 1e-3 three terms leave 16 z^9 / 945 ~ 1e-14 of it; above, mpmath's values.
TEST(Dawson, ComplementAtSmallArguments) {
  for (const double z : {1e-6, 1e-3}) {
    const double z2 = z * z;
    const double series = z * z2 * (2.0 / 3.0 - 4.0 / 15.0 * z2 + 8.0 / 105.0 * z2 * z2);
    EXPECT_NEAR(test::dawson_complement(z), series, 1e-14 * series) << z;
  }
  EXPECT_NEAR(test::dawson_complement(0.1), 6.6400760214713885021e-4, 1e-14 * 6.64e-4);
  EXPECT_NEAR(test::dawson_complement(0.99), 0.45120545318550215287, 1e-14 * 0.4512);
  EXPECT_NEAR(test::dawson_complement(2.0), 2.0 - test::dawson(2.0), 1e-15);
}

// An SLS with E*_0 / E*_inf = 10, a parabola pressed for t_m = 2 tau.
constexpr StandardLinearSolid kSolid{1.0e6, 9.0e6, 0.1};
constexpr ParabolaRamp kRamp{0.01, 1.0e-4, 0.2};

// tau -> 0: Hertz with E*_inf, the arm adding (3/2) (E*_1 / E*_inf) (tau / t) relative (its
// complement ~ sqrt(x) - 1/(2 sqrt(x)), the next term a further tau / (2t) of it);
// tau -> infinity: Hertz with E*_0, less (2/5) (E*_1 / E*_0) (t / tau) relative.
TEST(LeeRadok, ElasticLimits) {
  const double t = 0.15;
  const double d = kRamp.indentation(t);
  {
    const StandardLinearSolid fast{kSolid.relaxed_modulus, kSolid.arm_modulus, 1e-9};
    const double hertz = test::hertz_force(fast.relaxed_modulus, kRamp.radius, d);
    const double correction = 1.5 * fast.arm_modulus / fast.relaxed_modulus * 1e-9 / t;
    EXPECT_NEAR(test::lee_radok_force(fast, kRamp, t) / hertz - 1.0, correction, 1e-6 * correction);
  }
  {
    const StandardLinearSolid slow{kSolid.relaxed_modulus, kSolid.arm_modulus, 1e9};
    const double hertz = test::hertz_force(slow.glassy_modulus(), kRamp.radius, d);
    const double correction = -0.4 * slow.arm_modulus / slow.glassy_modulus() * t / 1e9;
    EXPECT_NEAR(test::lee_radok_force(slow, kRamp, t) / hertz - 1.0, correction,
                1e-6 * std::abs(correction));
  }
}

// The closed form against a quadrature of the hereditary integral, to 1e-10 relative (the
// quadrature is asked for 1e-14; Dawson's function carries 1e-15).
TEST(LeeRadok, HereditaryIntegral) {
  for (const double t : {1e-4, 0.01, 0.05, 0.1, 0.2}) {
    const double force = test::lee_radok_force(kSolid, kRamp, t);
    EXPECT_NEAR(force, test::lee_radok_force_by_quadrature(kSolid, kRamp, t), 1e-10 * force) << t;
    EXPECT_NEAR(force, test::ting_force_by_springs(kSolid, kRamp, t), 1e-10 * force) << t;
  }
}

// Ting: the radius returns through the loading's radii, the force through the springs' sum (no
// integration by parts) to 1e-10, the contact lost between t_m and 2 t_m, where the force and
// the radius vanish, continuously from t_m on.
TEST(Ting, UnloadingAgainstTheSprings) {
  const double separation = test::ting_separation_time(kSolid, kRamp);
  EXPECT_GT(separation, kRamp.turn_time);
  EXPECT_LT(separation, 2.0 * kRamp.turn_time);
  EXPECT_NEAR(kSolid.relaxation_integral(separation),
              2.0 * kSolid.relaxation_integral(separation - kRamp.turn_time),
              1e-13 * kSolid.relaxation_integral(separation));
  double previous_radius = test::ting_contact_radius(kSolid, kRamp, kRamp.turn_time);
  for (const double fraction : {1e-6, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const double t = kRamp.turn_time + fraction * (separation - kRamp.turn_time);
    const double force = test::ting_force(kSolid, kRamp, t);
    EXPECT_GT(force, 0.0);
    EXPECT_NEAR(force, test::ting_force_by_springs(kSolid, kRamp, t), 1e-10 * force) << t;
    const double radius = test::ting_contact_radius(kSolid, kRamp, t);
    EXPECT_LT(radius, previous_radius);
    previous_radius = radius;
  }
  const double at_turn = test::lee_radok_force(kSolid, kRamp, kRamp.turn_time);
  const double just_after = test::ting_force(kSolid, kRamp, kRamp.turn_time * (1.0 + 1e-12));
  EXPECT_NEAR(just_after, at_turn, 1e-9 * at_turn);
  EXPECT_EQ(test::ting_force(kSolid, kRamp, separation * (1.0 + 1e-12)), 0.0);
  EXPECT_LT(test::ting_force(kSolid, kRamp, separation * (1.0 - 1e-9)), 1e-9 * at_turn);
}

// Both elastic limits unload along Hertz with d(t) = V (2 t_m - t) and separate at 2 t_m (psi is
// linear); E*_1 = 0 exactly, then tau -> 0 (the arm's integral a constant E*_1 tau, its
// matching time shifted by ~ tau) and tau -> infinity (psi = E*_0 t - E*_1 t^2 / (2 tau)).
TEST(Ting, ElasticLimits) {
  const double t = 1.5 * kRamp.turn_time;
  const double d = kRamp.indentation(t);
  {
    const StandardLinearSolid elastic{kSolid.relaxed_modulus, 0.0, 0.1};
    EXPECT_EQ(test::ting_separation_time(elastic, kRamp), 2.0 * kRamp.turn_time);
    const double hertz = test::hertz_force(elastic.relaxed_modulus, kRamp.radius, d);
    EXPECT_NEAR(test::ting_force(elastic, kRamp, t), hertz, 1e-13 * hertz);
  }
  {
    const StandardLinearSolid fast{kSolid.relaxed_modulus, kSolid.arm_modulus, 1e-9};
    const double hertz = test::hertz_force(fast.relaxed_modulus, kRamp.radius, d);
    EXPECT_NEAR(test::ting_force(fast, kRamp, t), hertz, 1e-6 * hertz);
    EXPECT_NEAR(test::ting_separation_time(fast, kRamp), 2.0 * kRamp.turn_time,
                1e-6 * kRamp.turn_time);
  }
  {
    const StandardLinearSolid slow{kSolid.relaxed_modulus, kSolid.arm_modulus, 1e9};
    const double hertz = test::hertz_force(slow.glassy_modulus(), kRamp.radius, d);
    EXPECT_NEAR(test::ting_force(slow, kRamp, t), hertz, 1e-6 * hertz);
    EXPECT_NEAR(test::ting_separation_time(slow, kRamp), 2.0 * kRamp.turn_time,
                1e-6 * kRamp.turn_time);
  }
}

}  // namespace
}  // namespace mdrsim
