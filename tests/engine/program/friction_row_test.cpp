// The friction row against Cattaneo-Mindlin, Mindlin-Deresiewicz, a brute-force row, its law.
#include "engine/program/friction_row.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "engine/reference/friction_reference.hpp"
#include "profiles/parabolic_profile.hpp"

namespace {

namespace fr = mdrsim::friction_reference;
using mdrsim::FrictionRow;
using mdrsim::LinearMotion;

constexpr double kModulus = 1.0e6;       // E* [Pa]
constexpr double kShearModulus = 0.8e6;  // G* [Pa]
constexpr double kMu = 0.4;
constexpr double kRadius = 0.01;  // R [m]
constexpr double kA = 1e-4;       // contact radius a [m]
constexpr double kD = kA * kA / kRadius;

const mdrsim::Material kMaterial{kModulus, kShearModulus, 0.0};

/// The parabola's row pressed to d = a^2/R with fixed grips: springs i = 1..N at i a/N, all in
/// contact (spring N at g = d carries nothing), none stretched.
FrictionRow pressed_row(std::int64_t springs, mdrsim::FrictionSettings settings = {kMu}) {
  const mdrsim::ParabolicProfile profile(kRadius);
  const double dx = kA / static_cast<double>(springs);
  FrictionRow row(kMaterial, settings, dx);
  for (std::int64_t i = 1; i <= springs; ++i) row.touch(profile.mdr_image(row.position(i)), 0.0);
  return row;
}

/// Drives the row along `motion` to `end`, event by event; returns the work dissipated and
/// adds the machine's work int F_x du (F_x is linear in u between events: the trapezoid is
/// exact) to `machine_work`.
double drive(FrictionRow& row, LinearMotion motion, double end, double& machine_work,
             std::int64_t* events = nullptr) {
  double dissipated = 0.0;
  // Each spring changes a few times per leg; a locator that keeps finding events at one t fails.
  for (std::int64_t guard = 0; guard < 100 * (row.in_contact() + 1); ++guard) {
    const auto event = row.next_event(motion, end);
    const double t = event ? event->event.at : end;
    const double f0 = row.tangential_force(motion.indentation, motion.tangential);
    dissipated += row.advance(motion, t);
    const double f1 = row.tangential_force(motion.indentation_at(t), motion.tangential_at(t));
    machine_work += 0.5 * (f0 + f1) * (motion.tangential_at(t) - motion.tangential);
    motion = motion.from(t);
    if (!event) return dissipated;
    row.apply(*event);
    if (events) ++*events;
  }
  ADD_FAILURE() << "drive: no end to the events at t = " << motion.start;
  return dissipated;
}

/// Fixed grips: d held, u from `from` to `to` as t runs over [0, 1].
LinearMotion shear(double from, double to) { return {0.0, kD, from, 0.0, to - from}; }

/// The right-endpoint sum of springs at x_i = i dx against the integral over [0, a] errs by at
/// most dx times the total variation of the integrand (cell by cell, the sum's value and the
/// cell's mean differ by at most the cell's oscillation). Both halves: twice that.
double row_sum_bound(double dx, double total_variation) { return 2.0 * dx * total_variation; }

TEST(FrictionRow, CattaneoMindlinLoadingAtTwoSpringCounts) {
  const double fz = 4.0 * kModulus * kA * kA * kA / (3.0 * kRadius);
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  const double um = 0.9 * us;
  std::vector<double> errors;
  for (const std::int64_t n : {400, 800}) {
    FrictionRow row = pressed_row(n);
    const double dx = kA / static_cast<double>(n);
    // The line load min(G* u, mu E* (d - g)) falls monotonically from at most mu E* d to 0.
    const double bound = row_sum_bound(dx, kMu * kModulus * kD);
    double work = 0.0;
    double worst = 0.0;
    double previous = 0.0;
    for (const double xi : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      const double u = xi * us;
      drive(row, shear(previous, u), 1.0, work);
      previous = u;
      const double exact = fr::parabola_loading_force(kMu * fz, u, us);
      const double fx = row.tangential_force(kD, u);
      EXPECT_NEAR(fx, exact, bound) << n << " springs, u/u* = " << xi;
      worst = std::max(worst, std::abs(fx - exact));
      // Spring i slides iff x_i >= c (its limit mu E* (d - g_i) dx is below G* u dx): the
      // stick radius x_{j-1} is within one spacing below c.
      const double c = fr::parabola_stick_radius(kA, u, us);
      EXPECT_LE(row.stick_radius(), c + 1e-12 * kA) << xi;
      EXPECT_GT(row.stick_radius(), c - dx) << xi;
      EXPECT_EQ(row.springs_sliding(), n - static_cast<std::int64_t>(row.stick_radius() / dx + 0.5))
          << xi;
    }
    errors.push_back(worst);
    (void)um;
  }
  // First order in dx (the right-endpoint sum's -dx h(0)/2 + O(dx^2)): doubling N halves it.
  const double order = std::log2(errors[0] / errors[1]);
  EXPECT_NEAR(order, 1.0, 0.1) << errors[0] << " " << errors[1];
}

// glued = "coulomb" with a shear strength tau_0 [Pa]: a contact glued across a, pressed to d =
// a^2/R and sheared at fixed grips. In 3D the traction slides at mu p + tau_0 in an annulus c < r
// < a and sticks inside; its MDR image slides at mu E* (d - g(x)) + 2 tau_0 sqrt(a^2 - x^2) per
// unit length for x > c, with G* u = that at c, so (both halves, g = x^2/R)
//   F_x = 2 [G* u c + mu E*/R (a^2 (a - c) - (a^3 - c^3)/3)
//            + tau_0 (pi a^2/2 - c sqrt(a^2 - c^2) - a^2 asin(c/a))],
// and at full slip mu F_z + tau_0 pi a^2: the shear strength times the contact's area (the
// local tau_0 dx per spring would give 2 tau_0 a, not even a force). First order in
// dx: doubling N halves the error (measured 1.5e-7 N at 400 springs, 7.6e-8 N at 800, order
// 1.005; 1.4e-3 of mu F_z).
TEST(FrictionRow, CattaneoMindlinWithAShearStrengthAtTwoSpringCounts) {
  const double tau0 = 0.25 * kMu * kModulus * kD / kA;
  const double stiff = kMu * kModulus / kRadius;  // mu E*/R [Pa/m]
  const double full_slip = (stiff * kA * kA + 2.0 * tau0 * kA) / kShearModulus;
  const auto exact = [&](double u) {
    // s = sqrt(a^2 - c^2) from G* u = mu E* s^2 / R + 2 tau_0 s.
    const double s =
        std::min((-2.0 * tau0 + std::sqrt(4.0 * tau0 * tau0 + 4.0 * stiff * kShearModulus * u)) /
                     (2.0 * stiff),
                 kA);
    const double c = std::sqrt(std::max(kA * kA - s * s, 0.0));
    return 2.0 * (kShearModulus * u * c +
                  stiff * (kA * kA * (kA - c) - (kA * kA * kA - c * c * c) / 3.0) +
                  tau0 * (std::numbers::pi * kA * kA / 2.0 - c * s - kA * kA * std::asin(c / kA)));
  };
  const double fz = 4.0 * kModulus * kA * kA * kA / (3.0 * kRadius);
  EXPECT_NEAR(exact(1.2 * full_slip), kMu * fz + tau0 * std::numbers::pi * kA * kA,
              1e-12 * kMu * fz);
  std::vector<double> errors;
  for (const std::int64_t n : {400, 800}) {
    FrictionRow row = pressed_row(n, {kMu, mdrsim::GluedShear::limited, tau0});
    for (std::int64_t i = 1; i <= n; ++i) row.glue_next(kD);
    const double dx = kA / static_cast<double>(n);
    // The line load min(G* u, mu E* (d - g) + 2 tau_0 sqrt(a^2 - x^2)) falls from at most its
    // centre's value to 0.
    const double bound = row_sum_bound(dx, kMu * kModulus * kD + 2.0 * tau0 * kA);
    double work = 0.0;
    double worst = 0.0;
    double previous = 0.0;
    for (const double xi : {0.1, 0.3, 0.5, 0.7, 0.9, 1.2}) {
      const double u = xi * full_slip;
      drive(row, shear(previous, u), 1.0, work);
      previous = u;
      const double fx = row.tangential_force(kD, u);
      EXPECT_NEAR(fx, exact(u), bound) << n << " springs, u/u* = " << xi;
      worst = std::max(worst, std::abs(fx - exact(u)));
    }
    EXPECT_EQ(row.springs_sliding(), n);  // past u*, every spring slides
    errors.push_back(worst);
  }
  const double order = std::log2(errors[0] / errors[1]);
  EXPECT_NEAR(order, 1.0, 0.15) << errors[0] << " " << errors[1];
}

// The boundary spring letting go shrinks a_g, and with it every glued spring's 2 tau_0
// sqrt(a_g^2 - x^2) dx: at full slip each glued spring slips down to its new limit at once and
// dissipates new limit x slip, (L_old - L_new) L_new / kx on each half; F_x falls to the sum of
// the new limits (the spring let go keeps mu f_z).
TEST(FrictionRow, ALetGoLowersEveryGluedSpringsShearStrength) {
  const std::int64_t n = 200;
  const double tau0 = 0.25 * kMu * kModulus * kD / kA;
  FrictionRow row = pressed_row(n, {kMu, mdrsim::GluedShear::limited, tau0});
  for (std::int64_t i = 1; i <= n; ++i) row.glue_next(kD);
  const double dx = kA / static_cast<double>(n);
  const double kz = kModulus * dx;
  const double kx = kShearModulus * dx;
  const double u = 2.0 * (kMu * kModulus * kD + 2.0 * tau0 * kA) / kShearModulus;  // past u*
  double work = 0.0;
  drive(row, shear(0.0, u), 1.0, work);
  ASSERT_EQ(row.springs_sliding(), n);
  const mdrsim::ParabolicProfile profile(kRadius);
  const auto strength = [&](std::int64_t i, std::int64_t glued) {
    const double a_g = dx * static_cast<double>(glued);
    const double x = dx * static_cast<double>(i);
    return 2.0 * tau0 * std::sqrt(std::max(a_g * a_g - x * x, 0.0)) * dx;
  };
  double expected_dissipation = 0.0;
  double expected_force = 0.0;
  const std::int64_t k = n - 1;
  for (std::int64_t i = 1; i <= n; ++i) {
    const double friction = kMu * kz * (kD - profile.mdr_image(dx * static_cast<double>(i)));
    const double old_limit = friction + strength(i, n);
    const double new_limit = friction + (i <= k ? strength(i, k) : 0.0);
    expected_dissipation += 2.0 * new_limit * (old_limit - new_limit) / kx;
    expected_force += 2.0 * new_limit;
  }
  const double dissipated = row.let_go_boundary(kD, u);
  EXPECT_EQ(row.glued(), k);
  EXPECT_NEAR(dissipated, expected_dissipation, 1e-12 * expected_dissipation);
  EXPECT_NEAR(row.tangential_force(kD, u), expected_force, 1e-12 * expected_force);
  EXPECT_EQ(row.springs_sliding(), n);
}

// Part of a glued `coulomb` contact sticks (partial slip); each let-go lowers every glued
// spring's strength, so sticking springs over their new limit slip at once. F_x from the row's
// sums must stay the sum of each spring's own force, let-go after let-go (the sticking offsets
// once lost the new offset of such a spring, not the one they held: 4e-5 of F_x after 3).
TEST(FrictionRow, StickingGluedSpringsThatSlipAtALetGoLeaveTheSumsRight) {
  const std::int64_t n = 200;
  const double tau0 = 0.25 * kMu * kModulus * kD / kA;
  FrictionRow row = pressed_row(n, {kMu, mdrsim::GluedShear::limited, tau0});
  for (std::int64_t i = 1; i <= n; ++i) row.glue_next(kD);
  const double u = 0.3 * (kMu * kModulus * kD + 2.0 * tau0 * kA) / kShearModulus;
  double work = 0.0;
  drive(row, shear(0.0, u), 1.0, work);
  const double kx = kShearModulus * kA / static_cast<double>(n);
  for (int go = 1; go <= 150; ++go) {
    row.let_go_boundary(kD, u);
    double each = 0.0;
    for (std::int64_t i = 1; i <= n; ++i) {
      if (i <= row.glued()) {
        each += 2.0 * kx * row.glued_stretch(i, kD, u);
        continue;
      }
      const mdrsim::StickSlipSpring s = row.spring(i);
      each +=
          2.0 * (s.sliding != 0 ? s.sliding * mdrsim::slip_limit(*row.law(i), row.geometry(i), kD)
                                : kx * (u - s.offset));
    }
    ASSERT_NEAR(row.tangential_force(kD, u), each, 1e-12 * std::abs(each)) << "let-go " << go;
  }
}

TEST(FrictionRow, MindlinDeresiewiczBranchesAndLoopEnergy) {
  const std::int64_t n = 1000;
  const double dx = kA / static_cast<double>(n);
  const mdrsim::ParabolicProfile profile(kRadius);
  const fr::CattaneoMindlin cm(profile, kModulus, kShearModulus, kMu, kD);
  const double fz = cm.normal_force();
  const double us = cm.full_slip();
  const double um = 0.8 * us;
  FrictionRow row = pressed_row(n);
  double work = 0.0;
  drive(row, shear(0.0, um), 1.0, work);
  // A spring's force on the branches rises as G* u, falls with the forward slip's l and comes
  // back up with the reverse slip's -l: its total variation over x is at most 3 mu E* d.
  const double bound = row_sum_bound(dx, 3.0 * kMu * kModulus * kD);
  double cycle_work = 0.0;
  double dissipated = 0.0;
  double previous = um;
  for (const double xi : {0.5, 0.0, -0.4, -0.8}) {  // unloading to -u_m
    dissipated += drive(row, shear(previous, xi * us), 1.0, cycle_work);
    previous = xi * us;
    EXPECT_NEAR(row.tangential_force(kD, previous),
                cm.loading_force(um) -
                    2.0 * fr::parabola_loading_force(kMu * fz, 0.5 * (um - previous), us),
                bound)
        << "unloading at u/u* = " << xi;
  }
  for (const double xi : {-0.3, 0.2, 0.8}) {  // reloading to u_m
    dissipated += drive(row, shear(previous, xi * us), 1.0, cycle_work);
    previous = xi * us;
    EXPECT_NEAR(row.tangential_force(kD, previous), cm.reloading_force(um, previous), bound)
        << "reloading at u/u* = " << xi;
  }
  // Over a closed cycle the machine's work is what the slips dissipated: both are sums of
  // exact pieces, so they agree to rounding, whatever the closed form.
  EXPECT_NEAR(cycle_work, dissipated, 1e-12 * kMu * fz * us);
  // Spring by spring the loop dissipates 4 l (u_m - l/G*)^+ per length, which rises from 0 to
  // at most G* u_m^2 and falls back: total variation 2 G* u_m^2.
  const double exact = fr::parabola_loop_energy(kMu * fz, us, um);
  EXPECT_NEAR(dissipated, exact, row_sum_bound(dx, 2.0 * kShearModulus * um * um)) << exact;
  EXPECT_GT(exact, 0.1 * kMu * fz * us);  // a loop wide enough for the check to mean something
}

TEST(FrictionRow, MatchesTheBruteForceRowUnderAChangingNormalLoad) {
  // Shear while the normal load falls by 30 %, reverse while it comes back, then shear again
  // pressed harder: springs slide while f_z changes, stick on reversal, slip again. Springs
  // with g_i < 0.7 d stay pressed throughout, so the contact set is fixed.
  const std::int64_t n = 60;
  const mdrsim::ParabolicProfile profile(kRadius);
  const double dx = kA / static_cast<double>(n);
  FrictionRow row(kMaterial, {kMu}, dx);
  std::vector<double> images;
  for (std::int64_t i = 1; i <= n && profile.mdr_image(i * dx) < 0.7 * kD; ++i) {
    images.push_back(profile.mdr_image(row.position(i)));
    row.touch(images.back(), 0.0);
  }
  const std::int64_t steps = 100000;
  fr::BruteForceRow brute(images, dx, kModulus, kShearModulus, kMu);
  brute.move_to(kD, 0.0, 100);  // press: every spring touches with u = 0
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  struct Leg {
    double d;
    double u;
  };
  const std::vector<Leg> legs{{0.7 * kD, 0.6 * us}, {kD, -0.2 * us}, {1.2 * kD, 0.9 * us}};
  double d = kD;
  double u = 0.0;
  double dissipated = 0.0;
  double work = 0.0;
  double limit_sum = 0.0;  // sum of the largest limits along the path, both halves [N]
  for (const double g : images) limit_sum += 2.0 * kMu * kModulus * dx * (1.2 * kD - g);
  double brute_bound = 0.0;
  std::int64_t events = 0;
  for (const Leg& leg : legs) {
    dissipated += drive(row, {0.0, d, u, leg.d - d, leg.u - u}, 1.0, work, &events);
    brute.move_to(leg.d, leg.u, steps);
    // The brute force's forces are exact at each step's end (a return map of a linear path);
    // its dissipation errs only in the step where a spring starts to slide, by at most the
    // limit times the slip of one step, |du| + mu E*/G* |dd|, for each spring and leg.
    brute_bound += limit_sum *
                   (std::abs(leg.u - u) + kMu * kModulus / kShearModulus * std::abs(leg.d - d)) /
                   static_cast<double>(steps);
    d = leg.d;
    u = leg.u;
    const double scale = 2.0 * kMu * kModulus * kD * kA;  // of F_x
    EXPECT_NEAR(row.tangential_force(d, u), brute.tangential_force(), 1e-12 * scale);
    EXPECT_NEAR(dissipated, brute.dissipated(), brute_bound);
  }
  EXPECT_GT(events, static_cast<std::int64_t>(images.size()));  // slips and sticks did happen
  EXPECT_GT(dissipated, 100.0 * brute_bound);
}

TEST(FrictionRow, LimitedGluedSpringsSlideInTensionLikeTheBruteForce) {
  // glued = "coulomb", tau_0 = mu E* d / (4 a) (its image at the centre, 2 tau_0 a, half the
  // centre's friction limit): springs 1..k glued at u = 0 carry tension near the edge (d below
  // their g) and slide at 2 tau_0 sqrt(a^2 - x^2) dx there, at mu f_z plus that inside; pulled out
  // (d falling to 0.6 d0) while sheared, the glued springs slide with kinks where f_z changes
  // sign. A glued spring under "unlimited" never slides.
  const std::int64_t n = 40;
  const mdrsim::ParabolicProfile profile(kRadius);
  const double dx = kA / static_cast<double>(n);
  const double tau0 = 0.25 * kMu * kModulus * kD / kA;
  FrictionRow row(kMaterial, {kMu, mdrsim::GluedShear::limited, tau0}, dx);
  std::vector<double> images;
  for (std::int64_t i = 1; i <= n; ++i) {
    images.push_back(profile.mdr_image(row.position(i)));
    row.touch(images.back(), 0.0);
    row.glue_next(kD);
  }
  fr::BruteForceRow brute(images, dx, kModulus, kShearModulus, kMu, n, tau0);
  brute.move_to(kD, 0.0, 10);
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  double work = 0.0;
  std::int64_t events = 0;
  const double dissipated = drive(row, {0.0, kD, 0.0, -0.4 * kD, 1.5 * us}, 1.0, work, &events);
  const std::int64_t steps = 200000;
  brute.move_to(0.6 * kD, 1.5 * us, steps);
  const double scale = 2.0 * (kMu * kModulus * kD + 2.0 * tau0 * kA) * kA;  // of F_x
  EXPECT_NEAR(row.tangential_force(0.6 * kD, 1.5 * us), brute.tangential_force(), 1e-12 * scale);
  // The brute force's dissipation errs by at most limit x one step's slip per spring (above).
  const double step_slip = (1.5 * us + kMu * kModulus / kShearModulus * 0.4 * kD) / steps;
  EXPECT_NEAR(dissipated, brute.dissipated(), scale * step_slip);
  EXPECT_EQ(row.springs_sliding(), n);  // everything slides at 1.5 u*
  EXPECT_GT(events, n);  // the slips, and the kinks of the springs that went into tension

  FrictionRow unlimited(kMaterial, {kMu}, dx);
  for (std::int64_t i = 1; i <= n; ++i) {
    unlimited.touch(images[static_cast<std::size_t>(i - 1)], 0.0);
    unlimited.glue_next(kD);
  }
  EXPECT_FALSE(unlimited.next_event({0.0, kD, 0.0, -0.4 * kD, 1.5 * us}, 1.0));
  const double stretched = 2.0 * n * kShearModulus * dx * 1.5 * us;  // 2 N kx u: all stuck
  EXPECT_NEAR(unlimited.tangential_force(0.6 * kD, 1.5 * us), stretched, 1e-14 * stretched);
}

/// A law of its own: mu (1 + x / a) max(f_z, 0) + c0 (x / a) dx, rising with the radius; or,
/// with `like_coulomb`, Coulomb's mu max(f_z, 0) without saying so (spring by spring).
class GradedLaw final : public mdrsim::FrictionLaw {
 public:
  GradedLaw(double cohesion, bool like_coulomb) : cohesion_(cohesion), like_(like_coulomb) {}
  mdrsim::SlipLimit limit_at(double radius, double spacing) const override {
    if (like_) return {kMu, 0.0};
    return {kMu * (1.0 + radius / kA), cohesion_ * radius / kA * spacing};
  }

 private:
  double cohesion_;  ///< [N/m]
  bool like_;
};

// A law of its own runs spring by spring with each spring's limit from the law. Against the
// brute-force row with the same per-spring limits, along the path of the test above (the normal
// load falling, coming back, rising): its F_x to rounding, its dissipation within the brute
// force's own error. Coulomb's law given as a law of its own equals the keyed row exactly.
TEST(FrictionRow, ALawOfItsOwnMatchesTheBruteForceRow) {
  const std::int64_t n = 60;
  const mdrsim::ParabolicProfile profile(kRadius);
  const double dx = kA / static_cast<double>(n);
  const double cohesion = 0.1 * kMu * kModulus * kD;  // [N/m]
  const auto law = std::make_shared<GradedLaw>(cohesion, false);
  FrictionRow row(kMaterial, {kMu, mdrsim::GluedShear::unlimited, 0.0, law}, dx);
  FrictionRow keyed(kMaterial, {kMu}, dx);
  FrictionRow coulomb_own(
      kMaterial, {kMu, mdrsim::GluedShear::unlimited, 0.0, std::make_shared<GradedLaw>(0.0, true)},
      dx);
  std::vector<double> images, coefficients, constants;
  for (std::int64_t i = 1; i <= n && profile.mdr_image(i * dx) < 0.7 * kD; ++i) {
    images.push_back(profile.mdr_image(row.position(i)));
    const mdrsim::SlipLimit l = law->limit_at(row.position(i), dx);
    coefficients.push_back(l.coefficient);
    constants.push_back(l.constant);
    row.touch(images.back(), 0.0);
    keyed.touch(images.back(), 0.0);
    coulomb_own.touch(images.back(), 0.0);
  }
  const std::int64_t steps = 100000;
  fr::BruteForceRow brute(images, dx, kModulus, kShearModulus, kMu);
  brute.set_limits(coefficients, constants);
  brute.move_to(kD, 0.0, 100);
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  const std::vector<std::pair<double, double>> legs{
      {0.7 * kD, 0.6 * us}, {kD, -0.2 * us}, {1.2 * kD, 0.9 * us}};
  double d = kD, u = 0.0, dissipated = 0.0, keyed_dissipated = 0.0, own_dissipated = 0.0;
  double work = 0.0, brute_bound = 0.0;
  double limit_sum = 0.0;  // the largest limits along the path, both halves [N]
  for (std::size_t i = 0; i < images.size(); ++i)
    limit_sum += 2.0 * (coefficients[i] * kModulus * dx * (1.2 * kD - images[i]) + constants[i]);
  std::int64_t events = 0, keyed_events = 0, own_events = 0;
  for (const auto& [leg_d, leg_u] : legs) {
    const LinearMotion motion{0.0, d, u, leg_d - d, leg_u - u};
    dissipated += drive(row, motion, 1.0, work, &events);
    keyed_dissipated += drive(keyed, motion, 1.0, work, &keyed_events);
    own_dissipated += drive(coulomb_own, motion, 1.0, work, &own_events);
    brute.move_to(leg_d, leg_u, steps);
    brute_bound +=
        limit_sum *
        (std::abs(leg_u - u) + 2.0 * kMu * kModulus / kShearModulus * std::abs(leg_d - d)) /
        static_cast<double>(steps);
    d = leg_d;
    u = leg_u;
    const double scale = 2.0 * (2.0 * kMu * kModulus * kD + cohesion) * kA;  // of F_x
    EXPECT_NEAR(row.tangential_force(d, u), brute.tangential_force(), 1e-12 * scale);
    EXPECT_NEAR(dissipated, brute.dissipated(), brute_bound);
    EXPECT_NEAR(coulomb_own.tangential_force(d, u), keyed.tangential_force(d, u), 1e-12 * scale);
    EXPECT_NEAR(own_dissipated, keyed_dissipated, 1e-12 * scale * us);
    EXPECT_EQ(coulomb_own.springs_sliding(), keyed.springs_sliding());
    EXPECT_EQ(coulomb_own.stick_radius(), keyed.stick_radius());
  }
  EXPECT_EQ(own_events, keyed_events);
  EXPECT_GT(events, 20);  // slips and sticks did happen (30 of them; the graded law holds more)
  EXPECT_GT(dissipated, 100.0 * brute_bound);
}

TEST(FrictionRow, ASpringWhoseGlueLetsGoSlipsToItsLimit) {
  // Glued "unlimited" at u = 0, sheared to u = 2 mu E* (d - g)/G* of spring 1 with d held: once
  // its glue lets go it keeps its stretch, twice its limit, and slips half of it at once,
  // dissipating limit x slip on both halves.
  const double dx = 1e-6;
  FrictionRow row(kMaterial, {kMu}, dx);
  row.touch(0.0, 0.0);
  row.glue_next(kD);
  const double limit = kMu * kModulus * dx * kD;
  const double u = 2.0 * limit / (kShearModulus * dx);
  EXPECT_DOUBLE_EQ(row.let_go_boundary(kD, u), 2.0 * limit * (u / 2.0));
  EXPECT_EQ(row.glued(), 0);
  EXPECT_EQ(row.springs_sliding(), 1);
  EXPECT_EQ(row.stick_radius(), 0.0);
  EXPECT_DOUBLE_EQ(row.tangential_force(kD, u), 2.0 * limit);
}

TEST(FrictionRow, ACopyGoesOnLikeTheOriginal) {
  // A copy keeps its own keys and sliders (the row once kept iterators into its ordered keys, a
  // copy's pointing into the original's). Both go on along the same path and must agree exactly.
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  FrictionRow original = pressed_row(100);
  double work = 0.0;
  drive(original, shear(0.0, 0.5 * us), 1.0, work);
  FrictionRow copy = original;
  for (FrictionRow* row : {&original, &copy}) {
    drive(*row, shear(0.5 * us, -0.3 * us), 1.0, work);
    row->touch(kD, -0.3 * us);
    drive(*row, shear(-0.3 * us, 0.2 * us), 1.0, work);
  }
  EXPECT_EQ(copy.tangential_force(kD, 0.2 * us), original.tangential_force(kD, 0.2 * us));
  EXPECT_EQ(copy.springs_sliding(), original.springs_sliding());
  EXPECT_GT(original.springs_sliding(), 0);
}

TEST(FrictionRow, ItsSlopesAreThoseOfItsForce) {
  // Halfway up the Cattaneo-Mindlin curve: F_x is affine in u and d while no spring changes, so
  // a difference quotient over a step too small for any event equals the slopes to rounding.
  // The springs sliding along +x carry mu E* dx (d - g_i) each: 2 mu E* dx per spring per d.
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  FrictionRow row = pressed_row(200);
  double work = 0.0;
  drive(row, shear(0.0, 0.5 * us), 1.0, work);
  const double dx = kA / 200.0;
  const double sliding = static_cast<double>(row.springs_sliding());
  const double sticking = 200.0 - sliding;
  EXPECT_DOUBLE_EQ(row.tangential_stiffness(), 2.0 * sticking * kShearModulus * dx);
  EXPECT_DOUBLE_EQ(row.tangential_force_per_indentation(kD), 2.0 * sliding * kMu * kModulus * dx);
  const double h = 1e-6 * us;
  const double du =
      (row.tangential_force(kD, 0.5 * us + h) - row.tangential_force(kD, 0.5 * us)) / h;
  const double dd =
      (row.tangential_force(kD + h, 0.5 * us) - row.tangential_force(kD, 0.5 * us)) / h;
  // Rounding of F_x ~ 1e-16 F_x over h: 1e-16 x 2 mu E* d a / (1e-6 u*), some 1e-8 relative.
  EXPECT_NEAR(du, row.tangential_stiffness(), 1e-6 * row.tangential_stiffness());
  EXPECT_NEAR(dd, row.tangential_force_per_indentation(kD),
              1e-6 * row.tangential_force_per_indentation(kD));
}

/// The row spring by spring: every query a pass over the springs with the one-spring law, the
/// events the earliest of each spring's own (the law's tests fix those by hand).
struct SpringBySpringRow {
  mdrsim::FrictionSettings settings;
  double dx;
  std::vector<mdrsim::StickSlipSpring> states;
  std::vector<double> images;
  std::int64_t glued = 0;

  mdrsim::SpringGeometry geometry(std::size_t i) const {
    return {kModulus * dx, kShearModulus * dx, images[i]};
  }
  std::optional<mdrsim::SlipLimit> law(std::size_t i) const {
    if (static_cast<std::int64_t>(i) >= glued) return mdrsim::SlipLimit{settings.coefficient};
    if (settings.glued == mdrsim::GluedShear::unlimited) return std::nullopt;
    // tau_0 over the glued disk r < a_g = x_glued, seen by the spring at x: 2 tau_0 sqrt(a_g^2 -
    // x^2) per unit length.
    const double a_g = dx * static_cast<double>(glued);
    const double x = dx * static_cast<double>(i + 1);
    return mdrsim::SlipLimit{
        settings.coefficient,
        2.0 * settings.shear_strength * std::sqrt(std::max(a_g * a_g - x * x, 0.0)) * dx};
  }
  /// A new glued radius moves every glued spring's limit: within it a spring sticks, over it
  /// it slips to it at once. Returns the dissipated work, both halves [J].
  double relimit(double d, double u) {
    double dissipated = 0.0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(glued); ++i) {
      states[i].sliding = 0;
      dissipated += 2.0 * mdrsim::slip_to_limit(states[i], *law(i), geometry(i), d, u);
    }
    return dissipated;
  }
  double tangential_force(double d, double u) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < states.size(); ++i) {
      const auto l = law(i);
      sum += l ? mdrsim::spring_tangential_force(states[i], *l, geometry(i), d, u)
               : kShearModulus * dx * (u - states[i].offset);
    }
    return 2.0 * sum;
  }
  double drive(LinearMotion motion, double end, std::int64_t& events) {
    double dissipated = 0.0;
    while (true) {
      std::optional<mdrsim::FrictionEvent> first;
      std::size_t which = 0;
      for (std::size_t i = 0; i < states.size(); ++i) {
        const auto l = law(i);
        if (!l) continue;
        const auto e = mdrsim::next_friction_event(states[i], *l, geometry(i), motion, end);
        if (e && (!first || e->at < first->at)) {
          first = e;
          which = i;
        }
      }
      const double t = first ? first->at : end;
      for (std::size_t i = 0; i < states.size(); ++i)
        if (const auto l = law(i))
          dissipated += 2.0 * mdrsim::advance_spring(states[i], *l, geometry(i), motion, t);
      motion = motion.from(t);
      if (!first) return dissipated;
      mdrsim::apply_friction_event(states[which], *first);
      ++events;
    }
  }
};

TEST(FrictionRow, IndexedEventsEqualTheSpringBySpringLaw) {
  // One path through every change of the row: springs touch, glue, let go (slipping to their
  // limit), lift; the indenter shears back and forth while it presses and unloads. The row's
  // keys and sums must give what each spring's own law gives, event for event, to rounding.
  // Also with Coulomb's law given as a law of its own: every spring spring by spring.
  for (const bool own_law : {false, true})
    for (const auto glued_law : {mdrsim::GluedShear::unlimited, mdrsim::GluedShear::limited}) {
      SCOPED_TRACE(own_law ? "a law of its own" : "the keys");
      mdrsim::FrictionSettings settings{kMu, glued_law, 0.1 * kMu * kModulus * kD / kA};
      if (own_law) settings.law = std::make_shared<GradedLaw>(0.0, true);
      const std::int64_t n = 50;
      const double dx = kA / static_cast<double>(n);
      const mdrsim::ParabolicProfile profile(kRadius);
      FrictionRow row(kMaterial, settings, dx);
      SpringBySpringRow oracle{settings, dx, {}, {}, 0};
      const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
      double d = 0.8 * kD;
      double u = 0.0;
      const auto touch_pressed = [&] {
        while (row.in_contact() < n && profile.mdr_image(row.position(row.in_contact() + 1)) < d) {
          const double g = profile.mdr_image(row.position(row.in_contact() + 1));
          row.touch(g, u);
          oracle.states.push_back({u, 0});
          oracle.images.push_back(g);
        }
      };
      const auto lift_unpressed = [&](double d_next) {
        while (row.in_contact() > row.glued() && oracle.images.back() >= d_next) {
          row.lift_outer();
          oracle.states.pop_back();
          oracle.images.pop_back();
        }
      };
      touch_pressed();
      for (int k = 0; k < 12; ++k) {
        row.glue_next(d);
        ++oracle.glued;
      }
      struct Leg {
        double d;
        double u;
        int let_go;  ///< boundary springs that let go before the leg
      };
      const std::vector<Leg> legs{{0.8 * kD, 0.6 * us, 0},   {0.9 * kD, -0.4 * us, 3},
                                  {0.7 * kD, 0.3 * us, 2},   {1.0 * kD, 0.9 * us, 0},
                                  {0.75 * kD, -0.8 * us, 4}, {0.75 * kD, 0.1 * us, 0}};
      double dissipated_row = 0.0;
      double dissipated_oracle = 0.0;
      std::int64_t events_row = 0;
      std::int64_t events_oracle = 0;
      double work = 0.0;
      for (const Leg& leg : legs) {
        for (int k = 0; k < leg.let_go; ++k) {
          const std::size_t b = static_cast<std::size_t>(oracle.glued - 1);
          --oracle.glued;
          // The spring slides at its glued limit or sticks: as an unglued spring it starts stuck.
          oracle.states[b].sliding = 0;
          dissipated_oracle += 2.0 * mdrsim::slip_to_limit(oracle.states[b], *oracle.law(b),
                                                           oracle.geometry(b), d, u);
          if (glued_law == mdrsim::GluedShear::limited) dissipated_oracle += oracle.relimit(d, u);
          dissipated_row += row.let_go_boundary(d, u);
        }
        lift_unpressed(leg.d);
        const LinearMotion motion{0.0, d, u, leg.d - d, leg.u - u};
        dissipated_row += drive(row, motion, 1.0, work, &events_row);
        dissipated_oracle += oracle.drive(motion, 1.0, events_oracle);
        d = leg.d;
        u = leg.u;
        touch_pressed();
        const double scale = 2.0 * kMu * kModulus * kD * kA;  // of F_x
        EXPECT_NEAR(row.tangential_force(d, u), oracle.tangential_force(d, u), 1e-12 * scale);
        EXPECT_NEAR(dissipated_row, dissipated_oracle, 1e-12 * scale * us);
        std::int64_t sliding = 0;
        std::int64_t first_sliding = 0;
        for (std::int64_t i = 1; i <= row.in_contact(); ++i) {
          const auto& expected = oracle.states[static_cast<std::size_t>(i - 1)];
          EXPECT_EQ(row.spring(i).sliding, expected.sliding) << i;
          EXPECT_NEAR(row.spring(i).offset, expected.offset, 1e-12 * us) << i;
          if (expected.sliding != 0) {
            ++sliding;
            if (first_sliding == 0) first_sliding = i;
          }
        }
        EXPECT_EQ(row.springs_sliding(), sliding);
        EXPECT_EQ(row.stick_radius(),
                  row.position(first_sliding == 0 ? row.in_contact() : first_sliding - 1));
      }
      EXPECT_EQ(events_row, events_oracle);
      EXPECT_GT(events_row, 2 * n);
    }
}

TEST(FrictionRow, KeyedGluedSpringsMatchTheSpringBySpringRowOnRandomFretting) {
  // glued = "coulomb" on the keys against the row spring by spring (every query a pass over
  // every spring with the one-spring law: O(N) per event, O(N^2) per path). Random images,
  // not monotone in i: the glued springs' images straddle the range of d, so that they cross
  // between pressed and tension; the unglued ones lie below it (the row's lift events keep
  // them pressed). Random legs of d and u_x, let-gos between them, tau_0 = 0 and > 0. After
  // each leg: F_x (also at a d away from the present one), the dissipated work and every
  // spring's state, to rounding.
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  for (const double tau0 : {0.0, 0.1 * kMu * kModulus * kD / kA}) {
    for (std::uint32_t seed = 1; seed <= 6; ++seed) {
      SCOPED_TRACE(testing::Message() << "tau0 " << tau0 << " seed " << seed);
      std::mt19937_64 random(seed);
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      const mdrsim::FrictionSettings settings{kMu, mdrsim::GluedShear::limited, tau0};
      const std::int64_t n = 60;
      const std::int64_t glued = 40;
      const double dx = kA / static_cast<double>(n);
      FrictionRow row(kMaterial, settings, dx);
      SpringBySpringRow oracle{settings, dx, {}, {}, 0};
      double d = kD;
      double u = 0.0;
      for (std::int64_t i = 1; i <= n; ++i) {
        // Glued: 0.4 .. 1.6 d0 against d in 0.6 .. 1.4 d0; unglued, and the four glued ones
        // that let go: below 0.5 d0.
        const bool crosses = i <= glued - 4;
        const double g = crosses ? kD * (0.4 + 1.2 * unit(random)) : 0.5 * kD * unit(random);
        row.touch(g, u);
        oracle.states.push_back({u, 0});
        oracle.images.push_back(g);
      }
      for (std::int64_t i = 1; i <= glued; ++i) {
        row.glue_next(d);
        ++oracle.glued;
      }
      double dissipated_row = 0.0;
      double dissipated_oracle = 0.0;
      std::int64_t events_row = 0;
      std::int64_t events_oracle = 0;
      const double scale = 2.0 * (kMu * kModulus * 1.6 * kD + 2.0 * tau0 * kA) * kA;  // of F_x
      for (int leg = 0; leg < 16; ++leg) {
        if (leg % 4 == 3 && row.glued() > 1) {
          // The boundary spring lets go, as in IndexedEventsEqualTheSpringBySpringLaw, pressed
          // (an unglued spring in contact stays pressed).
          const std::size_t b = static_cast<std::size_t>(oracle.glued - 1);
          --oracle.glued;
          oracle.states[b].sliding = 0;
          dissipated_oracle += 2.0 * mdrsim::slip_to_limit(oracle.states[b], *oracle.law(b),
                                                           oracle.geometry(b), d, u);
          dissipated_oracle += oracle.relimit(d, u);
          dissipated_row += row.let_go_boundary(d, u);
        }
        const double d1 = kD * (0.6 + 0.8 * unit(random));
        const double u1 = us * (2.0 * unit(random) - 1.0);
        LinearMotion motion{0.0, d, u, d1 - d, u1 - u};
        // The keyed row, counting its slips and sticks.
        for (int guard = 0;; ++guard) {
          ASSERT_LT(guard, 100 * n);
          const auto event = row.next_event(motion, 1.0);
          const double t = event ? event->event.at : 1.0;
          dissipated_row += row.advance(motion, t);
          motion = motion.from(t);
          if (!event) break;
          row.apply(*event);
          if (event->event.kind != mdrsim::FrictionEventKind::limit_kink) ++events_row;
        }
        // The oracle, the same.
        motion = {0.0, d, u, d1 - d, u1 - u};
        while (true) {
          std::optional<mdrsim::FrictionEvent> first;
          std::size_t which = 0;
          for (std::size_t i = 0; i < oracle.states.size(); ++i) {
            const auto e = mdrsim::next_friction_event(oracle.states[i], *oracle.law(i),
                                                       oracle.geometry(i), motion, 1.0);
            if (e && (!first || e->at < first->at)) {
              first = e;
              which = i;
            }
          }
          const double t = first ? first->at : 1.0;
          for (std::size_t i = 0; i < oracle.states.size(); ++i)
            dissipated_oracle += 2.0 * mdrsim::advance_spring(oracle.states[i], *oracle.law(i),
                                                              oracle.geometry(i), motion, t);
          motion = motion.from(t);
          if (!first) break;
          mdrsim::apply_friction_event(oracle.states[which], *first);
          if (first->kind != mdrsim::FrictionEventKind::limit_kink) ++events_oracle;
        }
        d = d1;
        u = u1;
        // F_x sums some 100 terms of size up to mu E* dx 1.6 d0: rounding of 1e-12 of the
        // scale; the work the same relative to scale x us.
        EXPECT_NEAR(row.tangential_force(d, u), oracle.tangential_force(d, u), 1e-12 * scale);
        EXPECT_NEAR(dissipated_row, dissipated_oracle, 1e-12 * scale * us);
        ASSERT_EQ(row.in_contact(), static_cast<std::int64_t>(oracle.states.size()));
        std::int64_t sliding = 0;
        for (std::int64_t i = 1; i <= row.in_contact(); ++i) {
          const auto& expected = oracle.states[static_cast<std::size_t>(i - 1)];
          EXPECT_EQ(row.spring(i).sliding, expected.sliding) << i;
          // An offset is u_x less a stretch of at most the limit over kx: rounding of 1e-12 us.
          EXPECT_NEAR(row.spring(i).offset, expected.offset, 1e-12 * 2.0 * us) << i;
          sliding += expected.sliding != 0 ? 1 : 0;
        }
        EXPECT_EQ(row.springs_sliding(), sliding);
        // At a d away from the present one (an equilibrium's search), classes that no longer
        // hold are corrected spring by spring.
        for (const double elsewhere : {0.5 * kD, 1.5 * kD})
          EXPECT_NEAR(row.tangential_force(elsewhere, u), oracle.tangential_force(elsewhere, u),
                      1e-12 * scale);
      }
      // Events at one t come in another order where keys tie (the keys give the larger i
      // backward, the oracle the smaller), and a spring at a zero limit in tension may stick
      // and slip again in between: the counts need not agree, the states after them do.
      EXPECT_GT(events_row, 4 * n);
      EXPECT_GT(events_oracle, 4 * n);
    }
  }
}

TEST(FrictionRow, RandomNonMonotoneMotionsMatchTheBruteForceRow) {
  // Springs with images in random order along the row (keys not monotone in i, unlike a
  // parabola's) sheared and pressed along random legs, each reversing its slips anywhere in the
  // row: the indexed keys must find the events each spring's own law finds, one for one, and
  // the forces of the brute-force return map. All images lie below the smallest d, so the
  // contact set stays whole. At 80 springs the keys make fewer runs of neighbours than SlipKeys
  // keeps as runs; at 600 they make some 200 and the keys become a tree.
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  struct Case {
    std::int64_t n;
    unsigned seed;
  };
  for (const auto [n, seed] : {Case{80, 1}, Case{80, 2}, Case{80, 3}, Case{80, 4}, Case{600, 5}}) {
    const double dx = kA / static_cast<double>(n);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    FrictionRow row(kMaterial, {kMu}, dx);
    SpringBySpringRow oracle{{kMu}, dx, {}, {}, 0};
    std::vector<double> images;
    for (std::int64_t i = 1; i <= n; ++i) {
      images.push_back(0.5 * kD * unit(random));
      row.touch(images.back(), 0.0);
      oracle.states.push_back({0.0, 0});
      oracle.images.push_back(images.back());
    }
    fr::BruteForceRow brute(images, dx, kModulus, kShearModulus, kMu);
    brute.move_to(kD, 0.0, 1);  // every spring touches unstretched at u = 0
    double limit_sum = 0.0;     // the largest limits along the path, both halves [N]
    for (const double g : images) limit_sum += 2.0 * kMu * kModulus * dx * (1.3 * kD - g);
    const std::int64_t steps = 20000;
    double d = kD;
    double u = 0.0;
    double dissipated = 0.0;
    double dissipated_oracle = 0.0;
    double brute_bound = 0.0;
    double work = 0.0;
    std::int64_t events = 0;
    std::int64_t events_oracle = 0;
    for (int leg = 0; leg < 12; ++leg) {
      const double d1 = (0.6 + 0.7 * unit(random)) * kD;
      const double u1 = (2.0 * unit(random) - 1.0) * 1.5 * us;
      const LinearMotion motion{0.0, d, u, d1 - d, u1 - u};
      dissipated += drive(row, motion, 1.0, work, &events);
      dissipated_oracle += oracle.drive(motion, 1.0, events_oracle);
      brute.move_to(d1, u1, steps);
      // As in MatchesTheBruteForceRowUnderAChangingNormalLoad: one step's slip per spring and leg.
      brute_bound += limit_sum *
                     (std::abs(u1 - u) + kMu * kModulus / kShearModulus * std::abs(d1 - d)) /
                     static_cast<double>(steps);
      d = d1;
      u = u1;
      const double scale = 2.0 * kMu * kModulus * kD * kA;  // of F_x
      EXPECT_NEAR(row.tangential_force(d, u), brute.tangential_force(), 1e-12 * scale) << seed;
      EXPECT_NEAR(dissipated, brute.dissipated(), brute_bound) << seed;
      EXPECT_NEAR(row.tangential_force(d, u), oracle.tangential_force(d, u), 1e-12 * scale);
      EXPECT_NEAR(dissipated, dissipated_oracle, 1e-12 * scale * us);
      std::int64_t sliding = 0;
      std::int64_t first_sliding = 0;
      for (std::int64_t i = 1; i <= n; ++i) {
        const auto& expected = oracle.states[static_cast<std::size_t>(i - 1)];
        EXPECT_EQ(row.spring(i).sliding, expected.sliding) << seed << " " << i;
        EXPECT_NEAR(row.spring(i).offset, expected.offset, 1e-12 * us) << seed << " " << i;
        if (expected.sliding != 0) {
          ++sliding;
          if (first_sliding == 0) first_sliding = i;
        }
      }
      EXPECT_EQ(row.springs_sliding(), sliding);
      EXPECT_EQ(row.stick_radius(), row.position(first_sliding == 0 ? n : first_sliding - 1));
      if (HasFailure()) return;
    }
    EXPECT_EQ(events, events_oracle) << seed;
    EXPECT_GT(events, 2 * n) << seed;  // slips and sticks all over the row did happen
    EXPECT_GT(dissipated, 100.0 * brute_bound) << seed;
  }
}

TEST(FrictionRow, WhereNothingCanSlipItSaysSo) {
  // What the program loop skips on, to keep a friction event cheap: with nothing sliding, F_x at a
  // fixed u_x is the same number for every d (only a slider's mu f_z depends on d), and along a
  // press at still u_x no spring can slip (every limit grows, no stretch moves), so next_event need
  // not be asked. Each "nothing" is checked against the force and the event search themselves.
  const double us = fr::full_slip_displacement(kMu, kModulus, kShearModulus, kD);
  FrictionRow row = pressed_row(50);
  const LinearMotion press{0.0, kD, 0.0, 0.5 * kD, 0.0};
  const LinearMotion still{0.0, kD, 0.0, 0.0, 0.0};
  const LinearMotion unload{0.0, kD, 0.0, -0.5 * kD, 0.0};
  const LinearMotion shear{0.0, kD, 0.0, 0.0, 0.3 * us};
  EXPECT_FALSE(row.force_follows_indentation());
  EXPECT_FALSE(row.may_change(press));
  EXPECT_FALSE(row.may_change(still));
  EXPECT_FALSE(row.next_event(press, 1e9));
  // Unloading, spring N (g = d, no limit left) slips at once; shearing, the outer springs slip.
  EXPECT_TRUE(row.may_change(unload));
  EXPECT_TRUE(row.next_event(unload, 1.0));
  EXPECT_TRUE(row.may_change(shear));
  EXPECT_TRUE(row.next_event(shear, 1.0));
  // Sheared: the outer springs slide at their limits, which grow with d by 2 mu E* dx each.
  double work = 0.0;
  drive(row, shear, 1.0, work);
  const double u = 0.3 * us;
  const auto sliding = static_cast<double>(row.springs_sliding());
  ASSERT_GT(sliding, 0.0);
  EXPECT_TRUE(row.force_follows_indentation());
  EXPECT_TRUE(row.may_change(press.from(0.0)));
  const double dx = kA / 50.0;
  const double slope = 2.0 * kMu * kModulus * dx * sliding;  // dF_x/dd [N/m]
  // Rounding of a few terms of size mu F_z: 1e-12 of it.
  EXPECT_NEAR(row.tangential_force(1.1 * kD, u) - row.tangential_force(kD, u), slope * 0.1 * kD,
              1e-12 * kMu * kModulus * kD * kA);
  // A small step back pressing on (spring N at g = d has no limit at d but gains one): every
  // slider sticks, each keeping its own offset, and F_x leaves d alone, to the bit.
  drive(row, {0.0, kD, u, 0.05 * kD, -0.01 * us}, 1.0, work);
  EXPECT_EQ(row.springs_sliding(), 0);
  EXPECT_FALSE(row.force_follows_indentation());
  const double back = 0.99 * u;
  const double deeper = 1.05 * kD;
  for (const double d : {0.9 * kD, 1.1 * kD, 2.0 * kD})
    EXPECT_EQ(row.tangential_force(d, back), row.tangential_force(deeper, back)) << d;
  const LinearMotion press_back{0.0, deeper, back, 0.5 * kD, 0.0};
  EXPECT_FALSE(row.may_change(press_back));
  EXPECT_FALSE(row.next_event(press_back, 1e9));
  EXPECT_TRUE(row.may_change({0.0, deeper, back, -0.5 * kD, 0.0}));
}

}  // namespace
