// The shorthand's path as three stages: the work of the preload, of the tangential load and of
// the pull-off, and the pull-off's jumps, on rows of three and five springs computed by hand.
//
// The rows: a parabola g(x) = x^2/R, R = 1 cm, E* = 1 MPa, G* = 0.8 MPa, dgamma = 0.05 J/m^2.
// Each force is 2 E* dx sum (d - g_i) over the springs attached (both halves), linear in d,
// so the work between two let-gos is an integral of a line, written out below as
// K (d_b^2 - d_a^2)/2 - C (d_b - d_a) and not as the path's trapezoid. The sums are of a few
// terms of one size: 1e-12 relative holds their rounding, and misses no segment.
#include "engine/pull_off/shorthand_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "engine/model/contact.hpp"
#include "engine/model/spring_foundation.hpp"
#include "profiles/parabolic_profile.hpp"

namespace mdrsim {
namespace {

constexpr double kRadius = 0.01;  // R [m]
constexpr double kModulus = 1e6;  // E* [Pa]
constexpr double kShear = 0.8e6;  // G* [Pa]
const Material kMaterial{
    .effective_modulus = kModulus, .effective_shear_modulus = kShear, .work_of_adhesion = 0.05};
constexpr AffineConstraint kFixedGrips{1.0, 0.0};
constexpr AffineConstraint kFixedLoad{0.0, 1.0};

struct Records {
  std::vector<StageRecord> stages;
  std::vector<JumpRecord> jumps;
  std::optional<AxisWork> work;
  JumpEnd end;
};

Records finish(ShorthandPath& path, const Contact& contact) {
  Records r;
  r.end = path.finish(contact, r.stages, r.jumps, r.work);
  return r;
}

/// The work of a force K d - C [N] as d goes from a to b [J].
double line_work(double stiffness, double offset, double a, double b) {
  return 0.5 * stiffness * (b * b - a * a) - offset * (b - a);
}

// Five springs at x_i = i 0.1 mm (g_i = i^2 um) pressed to d_p = g_5: the work
// E* dx sum (d_p - g_i)^2 = 100 N/m (24^2 + 21^2 + 16^2 + 9^2 + 0) um^2 = 1.354e-7 J, the
// pressed-in springs' energy (each half stores E* dx (d - g_i)^2 / 2).
TEST(ShorthandPath, ThePreloadWorkIsTheSumOfTheSquaresOfThePressedDepths) {
  const ParabolicProfile profile(kRadius);
  const SpringFoundation row(profile, 5e-4, 5);
  Contact contact(row, kMaterial, kFixedGrips, kFixedGrips);
  contact.set_normal_control(contact.normal_control_at(25e-6));
  ShorthandPath path(kFixedGrips, kFixedGrips);
  path.preload(contact);
  path.tangential(contact, std::nullopt);
  const Records r = finish(path, contact);
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.stages[0].name, "preload");
  EXPECT_NEAR(r.stages[0].work.normal, 1.354e-7, 1e-12 * 1.354e-7);
  EXPECT_EQ(r.stages[0].work.tangential, 0.0);
  EXPECT_EQ(r.stages[0].end.springs_in_contact, 5);
  // Every spring in contact: the end is a right-endpoint sum, located as it is.
  ASSERT_TRUE(r.stages[0].refined_end.has_value());
  EXPECT_EQ(r.stages[0].refined_end->normal_force, r.stages[0].end.normal_force);
  EXPECT_EQ(r.stages[1].work.tangential, 0.0);
  EXPECT_EQ(r.stages[2].work.normal, 0.0);  // stopped where it started
  EXPECT_EQ(r.work->normal, r.stages[0].work.normal);
}

// u_x held at 0.1 um on the five springs: F_x = 2 G* dx 5 u_x = 80 uN and the work
// F_x u_x / 2 = 4e-12 J. Through a machine spring of k = 50 N/m (K = 800 N/m) with its end at
// w = 1.7 um: u_x = w k / (k + K) = 0.1 um again, and the work F_x u_x / 2 + F_x^2 / (2 k) =
// 6.8e-11 J, the machine's k K / (k + K) w^2 / 2.
TEST(ShorthandPath, TheTangentialWorkIsHalfTheForceTimesTheDisplacementPlusTheMachineSpring) {
  const ParabolicProfile profile(kRadius);
  const SpringFoundation row(profile, 5e-4, 5);
  for (const bool compliant : {false, true}) {
    const AffineConstraint tangential = compliant ? AffineConstraint{1.0, 1.0 / 50.0} : kFixedGrips;
    Contact contact(row, kMaterial, kFixedGrips, tangential);
    contact.set_normal_control(25e-6);
    ShorthandPath path(kFixedGrips, tangential);
    path.preload(contact);
    contact.set_tangential_held(compliant ? 1.7e-6 : 1e-7);
    path.tangential(contact, compliant ? std::optional<double>(50.0) : std::nullopt);
    const Records r = finish(path, contact);
    ASSERT_EQ(r.stages.size(), 3u);
    EXPECT_EQ(r.stages[1].name, "tangential");
    EXPECT_NEAR(r.stages[1].end.tangential_displacement, 1e-7, 1e-15 * 1e-7);
    EXPECT_NEAR(r.stages[1].end.tangential_force, 8e-5, 1e-14 * 8e-5);
    const double want = compliant ? 6.8e-11 : 4e-12;
    EXPECT_NEAR(r.stages[1].work.tangential, want, 1e-12 * want) << compliant;
    if (compliant) {
      const double stiffness = 50.0 * 800.0 / 850.0;
      EXPECT_NEAR(r.stages[1].work.tangential, 0.5 * stiffness * 1.7e-6 * 1.7e-6, 1e-12 * want);
    }
    EXPECT_EQ(r.stages[1].work.normal, 0.0);
  }
}

/// Three springs at x_i = i a_c / 2, a_c = (R sqrt(2 pi dgamma / E*) / 4)^(2/3) the fold of
/// the JKR indentation d(a) = a^2/R - sqrt(2 pi a dgamma / E*): spring i lets go at
/// d_i = d(x_i) (elongation g_i - d at the Hess limit), and d_1 > d_2 < d_3.
struct ThreeSprings {
  double spacing;
  double g[4];  ///< g_i [m]
  double d[4];  ///< d_i [m]
  double k;     ///< 2 E* dx [N/m]
  ThreeSprings() {
    const double c = 2.0 * std::numbers::pi * 0.05 / kModulus;
    spacing = std::pow(kRadius * std::sqrt(c) / 4.0, 2.0 / 3.0) / 2.0;
    for (int i = 1; i <= 3; ++i) {
      g[i] = (i * spacing) * (i * spacing) / kRadius;
      d[i] = g[i] - std::sqrt(c * i * spacing);
    }
    k = 2.0 * kModulus * spacing;
  }
  /// The force of springs 1..n at d [N].
  double force(int n, double at) const {
    double images = 0.0;
    for (int i = 1; i <= n; ++i) images += g[i];
    return k * (n * at - images);
  }
  double images(int n) const { return force(n, 0.0) / -k; }
};

/// One let-go of the boundary spring at the normal held value `held`: from an equilibrium
/// (the pull-off method lowered the held value to it) or, with no value, due at once.
AdvanceOutcome let_go(Contact& contact, std::optional<double> held) {
  AdvanceOutcome out;
  if (held) {
    contact.set_normal_control(*held);
    out.equilibrium_before = contact.save();
  }
  contact.detach_boundary_spring();
  out.detached = 1;
  return out;
}

// Fixed grips, pressed to d_p = g_3: spring 3 lets go alone at d_3, spring 2 at d_2, and
// spring 1, due at once (d_1 > d_2), with it: one jump of two springs from the equilibrium at
// d_2. The pull-off's work is that of three springs from d_p to d_3 and two from d_3 to d_2
// (a let-go moves no driving point under fixed grips), and the last spring leaves the
// indenter where it was: the stage ends there, with no spring.
TEST(ShorthandPath, APullOffUnderFixedGripsRecordsItsWorkAndItsJump) {
  const ThreeSprings h;
  ASSERT_GT(h.d[3], h.d[2]);
  ASSERT_GT(h.d[1], h.d[2]);
  const ParabolicProfile profile(kRadius);
  const SpringFoundation row(profile, 3 * h.spacing, 3);
  Contact contact(row, kMaterial, kFixedGrips, kFixedGrips);
  contact.set_normal_control(h.g[3]);
  ShorthandPath path(kFixedGrips, kFixedGrips);
  path.preload(contact);
  path.tangential(contact, std::nullopt);
  path.advanced(contact, let_go(contact, h.d[3]), true);
  path.advanced(contact, let_go(contact, h.d[2]), true);
  path.advanced(contact, let_go(contact, std::nullopt), false);
  const Records r = finish(path, contact);

  EXPECT_EQ(r.end, JumpEnd::state);
  const double want = line_work(3 * h.k, h.k * h.images(3), h.g[3], h.d[3]) +
                      line_work(2 * h.k, h.k * h.images(2), h.d[3], h.d[2]);
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.stages[2].name, "pull-off");
  EXPECT_NEAR(r.stages[2].work.normal, want, 1e-12 * std::abs(want));
  EXPECT_EQ(r.stages[2].end.springs_in_contact, 0);
  EXPECT_EQ(r.stages[2].end.indentation, h.d[2]);
  EXPECT_NEAR(r.work->normal, r.stages[0].work.normal + want, 1e-12 * r.stages[0].work.normal);

  ASSERT_EQ(r.jumps.size(), 1u);
  const JumpRecord& jump = r.jumps[0];
  EXPECT_EQ(jump.stage, "pull-off");
  EXPECT_FALSE(jump.inward);
  EXPECT_EQ(jump.springs, -2);
  EXPECT_EQ(jump.glued_springs, -2);
  EXPECT_FALSE(jump.by_shear);
  EXPECT_EQ(jump.end, JumpEnd::state);
  EXPECT_EQ(jump.critical.springs_in_contact, 2);
  EXPECT_EQ(jump.critical.indentation, h.d[2]);
  EXPECT_NEAR(jump.critical.normal_force, h.force(2, h.d[2]), 1e-12 * std::abs(h.force(2, h.d[2])));
  EXPECT_EQ(jump.after.springs_in_contact, 0);
  EXPECT_EQ(jump.after.indentation, h.d[2]);
}

// Fixed load, pressed to d_p = g_3 and held at its force: spring 3 lets go at the held force
// F_3(d_3); on two springs the same force needs d = (F + 2 E* dx (g_1 + g_2)) / (4 E* dx),
// where spring 2 is stretched beyond its Hess limit: springs 2 and 1 follow at once, the held
// tension loses the contact and the indenter separates. One jump of three springs from the
// equilibrium at d_3, to no state; the stage ends at that equilibrium, with the work up to it
// (the let-gos' moves at constant force after it are the flight's, not the path's).
TEST(ShorthandPath, APullOffUnderFixedLoadEndsAtTheEquilibriumBeforeItsFlight) {
  const ThreeSprings h;
  const ParabolicProfile profile(kRadius);
  const SpringFoundation row(profile, 3 * h.spacing, 3);
  Contact contact(row, kMaterial, kFixedLoad, kFixedGrips);
  contact.set_normal_control(contact.normal_control_at(h.g[3]));
  ShorthandPath path(kFixedLoad, kFixedGrips);
  path.preload(contact);
  path.tangential(contact, std::nullopt);
  const double held = h.force(3, h.d[3]);
  path.advanced(contact, let_go(contact, held), true);
  ASSERT_GT(h.g[2] - contact.indentation(), h.g[2] - h.d[2]);  // spring 2 is due
  path.advanced(contact, let_go(contact, std::nullopt), false);
  path.advanced(contact, let_go(contact, std::nullopt), false);
  const Records r = finish(path, contact);

  EXPECT_EQ(r.end, JumpEnd::separated);
  const double want = line_work(3 * h.k, h.k * h.images(3), h.g[3], h.d[3]);
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_NEAR(r.stages[2].work.normal, want, 1e-12 * std::abs(want));
  EXPECT_EQ(r.stages[2].end.springs_in_contact, 3);
  EXPECT_NEAR(r.stages[2].end.normal_force, held, 1e-12 * std::abs(held));
  ASSERT_EQ(r.jumps.size(), 1u);
  EXPECT_EQ(r.jumps[0].springs, -3);
  EXPECT_EQ(r.jumps[0].end, JumpEnd::separated);
  EXPECT_EQ(r.jumps[0].critical.springs_in_contact, 3);
  EXPECT_NEAR(r.jumps[0].critical.indentation, h.d[3], 1e-12 * std::abs(h.d[3]));
}

// Fixed load held at F_a = F_3(d_3): spring 3 lets go, and spring 2 with it at the same force
// (driven by hand: the path takes the let-gos as the row gives them), and the cascade stops on
// spring 1: a jump of two springs to a state. Each let-go moved the indenter at constant force,
// F_a (d' - d) with d = (F_a / k + sum g_i) / n on n springs, and that work is the stage's as
// the cascade ended in a state; then the held force goes to F_b = 1.1 F_a on the one spring,
// which lets go there and separates: the stage ends at F_b, with the work up to it.
TEST(ShorthandPath, AFixedLoadCascadeThatEndsInAStateCountsItsMovesAtConstantForce) {
  const ThreeSprings h;
  const ParabolicProfile profile(kRadius);
  const SpringFoundation row(profile, 3 * h.spacing, 3);
  Contact contact(row, kMaterial, kFixedLoad, kFixedGrips);
  contact.set_normal_control(contact.normal_control_at(h.g[3]));
  ShorthandPath path(kFixedLoad, kFixedGrips);
  path.preload(contact);
  path.tangential(contact, std::nullopt);
  const double held_a = h.force(3, h.d[3]);
  const double held_b = 1.1 * held_a;
  path.advanced(contact, let_go(contact, held_a), true);
  path.advanced(contact, let_go(contact, std::nullopt), false);
  path.advanced(contact, let_go(contact, held_b), true);
  const Records r = finish(path, contact);

  const auto depth = [&](int n, double held) { return (held / h.k + h.images(n)) / n; };
  const double want = line_work(3 * h.k, h.k * h.images(3), h.g[3], h.d[3]) +
                      held_a * (depth(2, held_a) - h.d[3]) +
                      held_a * (depth(1, held_a) - depth(2, held_a)) +
                      line_work(h.k, h.k * h.images(1), depth(1, held_a), depth(1, held_b));
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_NEAR(r.stages[2].work.normal, want, 1e-12 * std::abs(want));
  EXPECT_EQ(r.stages[2].end.springs_in_contact, 1);
  EXPECT_NEAR(r.stages[2].end.normal_force, held_b, 1e-12 * std::abs(held_b));
  ASSERT_EQ(r.jumps.size(), 1u);
  EXPECT_EQ(r.jumps[0].springs, -2);
  EXPECT_EQ(r.jumps[0].end, JumpEnd::state);
  EXPECT_EQ(r.jumps[0].after.springs_in_contact, 1);
  EXPECT_NEAR(r.jumps[0].after.indentation, depth(1, held_a), 1e-12 * std::abs(depth(1, held_a)));
}

}  // namespace
}  // namespace mdrsim
