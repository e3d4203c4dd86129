// The MDR's Maugis-Dugdale states (dugdale_contact_state) against a ring boundary-element
// solution of the half-space that uses no Abel transform (tests/support/axisymmetric_half_space),
// after that solver's own checks on closed forms: the uniform disk, Hertz and the flat punch.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "engine/model/dugdale_zone.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "tests/support/axisymmetric_half_space.hpp"
#include "tests/support/maugis_units.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

using test::DugdaleHalfSpace;
using test::DugdaleHalfSpaceProblem;

// The arithmetic-geometric mean against libstdc++'s K(k) away from k = 1, where both are good to
// a few ulps (1e-14), and its log form ln(4/k') + (k'^2/4)(ln(4/k') - 1) at k' = 1e-6, whose
// next term is O(k'^4 ln k') ~ 1e-23.
TEST(AxisymmetricHalfSpace, EllipticKFromTheComplement) {
  for (const double k : {0.0, 0.3, 0.9, 0.999}) {
    const double expected = std::comp_ellint_1(k);
    EXPECT_NEAR(test::elliptic_k_of_complement(std::sqrt((1.0 - k) * (1.0 + k))), expected,
                1e-14 * expected);
  }
  const double kp = 1e-6, log_term = std::log(4.0 / kp);
  const double expected = log_term + 0.25 * kp * kp * (log_term - 1.0);
  EXPECT_NEAR(test::elliptic_k_of_complement(kp), expected, 1e-14 * expected);
}

// A uniform pressure p0 on r < c: u = (4 p0 c / (pi E*)) E(r/c) inside and
// (4 p0 r / (pi E*)) (E(c/r) - (1 - c^2/r^2) K(c/r)) outside (Johnson, Contact Mechanics, 3.29).
// The quadrature, log-singular at s = r, against libstdc++'s E and K: 1e-12 relative (the rules
// err by < 1e-16; the closed forms near k = 1 lose a few digits, 3e-14 at r/c = 0.999).
TEST(AxisymmetricHalfSpace, UniformDiskIsTheClosedForm) {
  const double modulus = 1e6, p0 = 1e3, c = 2e-4;
  for (const double ratio : {0.0, 0.3, 0.999, 1.0, 1.001, 1.5, 4.0}) {
    SCOPED_TRACE(ratio);
    const double r = ratio * c;
    const double expected =
        ratio <= 1.0 ? 4.0 * p0 * c / (kPi * modulus) * std::comp_ellint_2(ratio)
                     : 4.0 * p0 * r / (kPi * modulus) *
                           (std::comp_ellint_2(1.0 / ratio) -
                            (1.0 - 1.0 / (ratio * ratio)) * std::comp_ellint_1(1.0 / ratio));
    EXPECT_NEAR(test::annulus_displacement(modulus, p0, 0.0, c, r), expected, 1e-12 * expected);
  }
}

DugdaleHalfSpaceProblem hertz_problem(double modulus, double radius, double a) {
  return {.shape = [radius](double r) { return r * r / (2.0 * radius); },
          .effective_modulus = modulus,
          .contact_radius = a,
          .cohesive_radius = a,
          .indentation = a * a / radius};
}

// Hertz, no adhesion: p = (2 E*/(pi R)) sqrt(a^2 - r^2), F = 4 E* a^3/(3R), no singularity at a,
// and the gap outside (a^2/(pi R)) ((2 - r^2/a^2) asin(a/r) + sqrt(r^2/a^2 - 1)) + r^2/(2R) - d
// (Johnson 3.42 for u). Elements of 5 points; the errors fall like h^6 or faster: the order from
// 4, 8 and 16 elements, log2 of the ratio of successive errors, asserted above 5. At 16 elements
// F is good to 1e-13 relative, p, the gap and K_I to 1e-9 of their scales (E* a / R, a^2 / R,
// E* (a/R) sqrt(a)); the tolerances are 10 times those.
TEST(AxisymmetricHalfSpace, HertzConvergesToItsClosedForm) {
  const double modulus = 1e6, radius = 0.01, a = 1e-4;
  const double force = 4.0 * modulus * a * a * a / (3.0 * radius);
  const double p_scale = modulus * a / radius, depth = a * a / radius;
  std::vector<double> force_error;
  for (const int n : {4, 8, 16}) {
    SCOPED_TRACE(n);
    const DugdaleHalfSpace h(hertz_problem(modulus, radius, a), {.elements = n, .points = 5});
    force_error.push_back(std::abs(h.normal_force() - force));
    if (n != 16) continue;
    EXPECT_NEAR(h.normal_force(), force, 1e-12 * force);
    EXPECT_NEAR(h.stress_intensity() / (p_scale * std::sqrt(a)), 0.0, 1e-8);
    for (const double ratio : {0.001, 0.5, 0.999}) {
      const double expected = 2.0 / kPi * p_scale * std::sqrt(1.0 - ratio * ratio);
      EXPECT_NEAR(h.pressure(ratio * a), expected, 1e-8 * p_scale);
    }
    for (const double ratio : {1.001, 1.5, 3.0}) {
      const double u =
          depth / kPi *
          ((2.0 - ratio * ratio) * std::asin(1.0 / ratio) + std::sqrt(ratio * ratio - 1.0));
      EXPECT_NEAR(h.gap(ratio * a), (0.5 * ratio * ratio - 1.0) * depth + u, 1e-8 * depth);
    }
  }
  std::printf("Hertz: F's relative error at 4, 8, 16 elements %.2e %.2e %.2e\n",
              force_error[0] / force, force_error[1] / force, force_error[2] / force);
  EXPECT_GT(std::log2(force_error[0] / force_error[1]), 5.0);
  EXPECT_GT(std::log2(force_error[1] / force_error[2]), 5.0);
}

// A flat punch pressed by delta: p = E* delta / (pi sqrt(a^2 - r^2)), the pure singularity the
// extraction must see: K_I = -E* delta / sqrt(pi a), F = 2 a E* delta, and outside
// u = (2 delta / pi) asin(a/r). w is constant, which the elements hold exactly: 1e-12.
TEST(AxisymmetricHalfSpace, FlatPunchHasItsStressIntensity) {
  const double modulus = 1e6, a = 1e-4, delta = 1e-6;
  const DugdaleHalfSpace h({.shape = [](double) { return 0.0; },
                            .effective_modulus = modulus,
                            .contact_radius = a,
                            .cohesive_radius = a,
                            .indentation = delta},
                           {.elements = 4, .points = 5});
  const double k = -modulus * delta / std::sqrt(kPi * a);
  EXPECT_NEAR(h.stress_intensity(), k, 1e-12 * std::abs(k));
  EXPECT_NEAR(h.normal_force(), 2.0 * a * modulus * delta, 1e-12 * 2.0 * a * modulus * delta);
  EXPECT_NEAR(h.gap(2.0 * a), 2.0 * delta / kPi * std::asin(0.5) - delta, 1e-12 * delta);
}

/// One quantity at meshes of elements of 5 points, its engine value and scale.
struct Sequence {
  const char* name;
  std::vector<double> values;
  double engine, scale;
};

/// The half-space loaded by the engine's d, a, c (and sigma_0): F, h(c) and K_I at each mesh.
std::vector<Sequence> solve_at_meshes(const Profile& profile, const DugdaleLaw& law,
                                      const DugdaleState& s, int grading,
                                      const std::vector<int>& meshes) {
  std::vector<Sequence> out{
      {"F", {}, s.normal_force, std::abs(s.normal_force)},
      {"h(c)", {}, law.range(), law.range()},
      {"K_I", {}, 0.0, std::sqrt(2.0 * law.effective_modulus * law.work_of_adhesion)}};
  for (const int n : meshes) {
    const DugdaleHalfSpace h({.shape = [&profile](double r) { return profile.shape(r); },
                              .effective_modulus = law.effective_modulus,
                              .adhesive_stress = law.adhesive_stress,
                              .contact_radius = s.contact_radius,
                              .cohesive_radius = s.cohesive_radius,
                              .indentation = s.indentation},
                             {.elements = n, .points = 5, .grading = grading});
    out[0].values.push_back(h.normal_force());
    out[1].values.push_back(h.gap(s.cohesive_radius));
    out[2].values.push_back(h.stress_intensity());
  }
  return out;
}

// One state's check: the half-space loaded by the engine's d, a, c has the engine's F, the gap h0
// at c and no stress singularity at a (Maugis' condition), each to 1e-6 (the issue's): F and h0
// relative to themselves, K_I relative to sqrt(2 E* dgamma), the JKR limit's K_I. Asserted with
// it: the half-space's own error, the change from 32 to 64 elements, below 1e-7 (so that the
// 1e-6 measures the engine), Richardson's limit from 16, 32, 64 within the same 1e-6, and the
// order from 4, 8, 16 above 4.5 (the parabola shows 6 to 7, the cone 5.3 to 7). And the check
// has teeth: the same state with c moved by 1e-5 misses each of the three by more than 1e-6
// (they move by 1.6 to 4.8 times the change of c).
void check_state(const char* name, const Profile& profile, const DugdaleLaw& law, double a,
                 int grading) {
  const DugdaleState s = dugdale_contact_state(profile, law, a);
  std::printf("%s: a = %.6g m, c/a = %.9f, d = %.9g m, F = %.9g N, h0 = %.6g m\n", name, a,
              s.cohesive_radius / a, s.indentation, s.normal_force, law.range());
  std::printf("  (half-space - engine) / scale at 4, 8, 16, 32, 64 elements, Richardson; order\n");
  for (const Sequence& q : solve_at_meshes(profile, law, s, grading, {4, 8, 16, 32, 64})) {
    SCOPED_TRACE(q.name);
    const std::vector<double>& v = q.values;
    const test::Richardson limit = test::richardson(v);
    const test::Richardson early = test::richardson({v[0], v[1], v[2]});
    std::printf("  %-5s", q.name);
    for (const double x : v) std::printf(" %10.2e", (x - q.engine) / q.scale);
    std::printf(" %10.2e %5.2f\n", (limit.value - q.engine) / q.scale, early.order);
    EXPECT_NEAR(v.back(), q.engine, 1e-6 * q.scale);
    EXPECT_NEAR(limit.value, q.engine, 1e-6 * q.scale);
    EXPECT_LT(std::abs(v[4] - v[3]), 1e-7 * q.scale);
    EXPECT_GT(early.order, 4.5);
  }
  DugdaleState moved = s;
  moved.cohesive_radius *= 1.0 + 1e-5;
  for (const Sequence& q : solve_at_meshes(profile, law, moved, grading, {16})) {
    SCOPED_TRACE(q.name);
    EXPECT_GT(std::abs(q.values[0] - q.engine), 1e-6 * q.scale);
  }
}

// The parabola R = 1 cm in the transition, lambda = 1, at Maugis' A = 1 (c/a = 1.416): its
// pressure is smooth in phi, the elements are not graded.
TEST(DugdaleHalfSpace, TheParabolaAtLambdaOne) {
  const test::MaugisUnits u;
  const ParabolicProfile parabola(u.radius);
  check_state("parabola, lambda 1, A 1", parabola, u.law(1.0), u.length(), 1);
}

// The cone of 10 degrees with sigma_0 / (E* tan(theta)) = 1, beyond the fixed-grips threshold
// pi/4, at the JKR scale a0 = 18 dgamma / (pi E* tan^2(theta)) (c/a = 1.114): its pressure has
// a log singularity on the axis, the elements are graded there (q = 2).
TEST(DugdaleHalfSpace, TheConeAtUnitStressRatio) {
  const ConeProfile cone(10.0);
  const double tan_theta = std::tan(10.0 * kPi / 180.0), modulus = 1e6, work = 0.05;
  const DugdaleLaw law{.adhesive_stress = modulus * tan_theta,
                       .work_of_adhesion = work,
                       .effective_modulus = modulus};
  const double a0 = 18.0 * work / (kPi * modulus * tan_theta * tan_theta);
  check_state("cone 10 deg, sigma_0 = E* tan(theta), a = a0", cone, law, a0, 2);
}

}  // namespace
}  // namespace mdrsim
