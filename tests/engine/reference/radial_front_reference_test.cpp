// The radial front tracker against the JKR closed forms, the wavy w of the crack-front codes and
// a step of w where the front pins.
#include "engine/reference/radial_front_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace rf = mdrsim::radial_front_reference;
using std::numbers::pi;

rf::RadialWorkOfAdhesion uniform_work(double w, double scale) {
  return {[w](double) { return w; }, [](double) { return 0.0; }, scale};
}

/// w0 (1 + A sin(2 pi r / lambda)).
rf::RadialWorkOfAdhesion sinusoidal_work(double w0, double amplitude, double wavelength) {
  const double k = 2.0 * pi / wavelength;
  return {[=](double r) { return w0 * (1.0 + amplitude * std::sin(k * r)); },
          [=](double r) { return w0 * amplitude * k * std::cos(k * r); }, wavelength};
}

/// w_in for r < b, w_out for r >= b.
rf::RadialWorkOfAdhesion stepped_work(double w_in, double w_out, double b) {
  return {[=](double r) { return r < b ? w_in : w_out; }, [](double) { return 0.0; }, b, {b}};
}

/// Uniform w, c = 2 pi w/E*: d(a) = a^2/R - sqrt(c a), F(a) = E* (2 a d - 2 a^3/(3R)) =
/// E* (4 a^3/(3R) - 2 sqrt(c) a^(3/2)).
struct UniformClosedForms {
  double modulus, tip_radius, c;

  double depth(double a) const { return a * a / tip_radius - std::sqrt(c * a); }
  double force(double a, double d) const {
    return modulus * (2.0 * a * d - 2.0 * a * a * a / (3.0 * tip_radius));
  }
  /// d(a) = 0: the radius the touch jumps to.
  double touch_radius() const { return std::cbrt(c * tip_radius * tip_radius); }
  /// d'(a) = 2a/R - sqrt(c)/(2 sqrt(a)) = 0: the bottom of the branch, where it separates.
  double bottom_radius() const { return std::cbrt(c * tip_radius * tip_radius / 16.0); }
  /// d at the bottom: -(3/4) (c^2 R/4)^(1/3).
  double separation_depth() const { return -0.75 * std::cbrt(c * c * tip_radius / 4.0); }
  /// dF/da = E* (4a^2/R - 3 sqrt(c a)) = 0: a^3 = 9 c R^2/16, F = -(3/4) E* c R (-(3/2) pi w R,
  /// the JKR pull-off under fixed load, reached on the stable branch under fixed grips).
  double peak_tension_radius() const { return std::cbrt(9.0 * c * tip_radius * tip_radius / 16.0); }
  double peak_tension() const { return -0.75 * modulus * c * tip_radius; }
  /// F at the bottom: -(5/12) E* c R (-(5/6) pi w R, the fixed-grips pull-off).
  double separation_force() const { return -5.0 / 12.0 * modulus * c * tip_radius; }
  /// int F d'(a) da = P(a): F d' = E* (8a^4/(3R^2) - (14 sqrt(c)/(3R)) a^(5/2) + c a), so
  /// P(a) = E* (8a^5/(15R^2) - (4 sqrt(c)/(3R)) a^(7/2) + c a^2/2).
  double antiderivative(double a) const {
    const double r = tip_radius;
    return modulus * (8.0 * std::pow(a, 5) / (15.0 * r * r) -
                      4.0 * std::sqrt(c) / (3.0 * r) * std::pow(a, 3.5) + 0.5 * c * a * a);
  }
  /// The approach climbs from d = 0 (a_in) to d_max and the retract comes back down the same
  /// branch (those cancel), then goes on from d = 0 down to the bottom: W = int_{a_in}^{a_min}
  /// F d' da = P(a_min) - P(a_in), > 0 (F < 0 and dd < 0 there). With a = a_in s, a_in^3 = c R^2:
  /// P = E* a_in^5/R^2 (8 s^5/15 - 4 s^(7/2)/3 + s^2/2), -3/10 at s = 1 and 2^(-8/3)/5 at
  /// s^3 = 1/16, so W = E* a_in^5/R^2 (2^(-8/3)/5 + 3/10).
  double loop_energy() const {
    const double a = touch_radius();
    return modulus * std::pow(a, 5) / (tip_radius * tip_radius) *
           (std::pow(2.0, -8.0 / 3.0) / 5.0 + 0.3);
  }
};

UniformClosedForms closed_forms(double modulus, double tip_radius, double w) {
  return {modulus, tip_radius, 2.0 * pi * w / modulus};
}

double relative(double x, double y) { return std::abs(x - y) / std::abs(y); }

/// Checks a uniform w's loop against the closed forms: the jumps at 1e-12, the forces at 1e-12,
/// the peak tension's radius at 1e-7 (Brent: sqrt(eps)) and the loop energy at 1e-10.
void expect_uniform_loop(const rf::RadialLoopReference& loop, const UniformClosedForms& jkr) {
  ASSERT_EQ(loop.jumps.size(), 2u);
  EXPECT_EQ(loop.jumps_in(), 1u);
  EXPECT_EQ(loop.jumps_out(), 1u);
  const rf::RadialFrontJump& touch = loop.jumps[0];
  EXPECT_TRUE(touch.advancing);
  EXPECT_EQ(touch.indentation, 0.0);
  EXPECT_EQ(touch.from_radius, 0.0);
  EXPECT_LT(relative(touch.to_radius, jkr.touch_radius()), 1e-12) << touch.to_radius;
  const rf::RadialFrontJump& off = loop.jumps[1];
  EXPECT_FALSE(off.advancing);
  EXPECT_LT(relative(off.from_radius, jkr.bottom_radius()), 1e-12) << off.from_radius;
  EXPECT_EQ(off.to_radius, 0.0);
  EXPECT_LT(relative(off.indentation, jkr.separation_depth()), 1e-12) << off.indentation;
  EXPECT_EQ(loop.separation.indentation, off.indentation);
  EXPECT_EQ(loop.separation.contact_radius, off.from_radius);
  EXPECT_LT(relative(loop.separation.normal_force, jkr.separation_force()), 1e-12)
      << loop.separation.normal_force;
  EXPECT_LT(relative(loop.peak_tension.normal_force, jkr.peak_tension()), 1e-12)
      << loop.peak_tension.normal_force;
  EXPECT_LT(relative(loop.peak_tension.contact_radius, jkr.peak_tension_radius()), 1e-7)
      << loop.peak_tension.contact_radius;
  EXPECT_LT(relative(loop.loop_energy, jkr.loop_energy()), 1e-10) << loop.loop_energy;
  // The energy two ways: the closed form above and the antiderivative.
  EXPECT_LT(
      relative(jkr.antiderivative(jkr.bottom_radius()) - jkr.antiderivative(jkr.touch_radius()),
               jkr.loop_energy()),
      1e-13);
  // One stretch each way, meeting at d_max; the retract's states lie on d(a).
  ASSERT_EQ(loop.approach.size(), 1u);
  ASSERT_EQ(loop.retract.size(), 1u);
  EXPECT_EQ(loop.approach[0].to.indentation, loop.retract[0].from.indentation);
  EXPECT_EQ(loop.approach[0].to.contact_radius, loop.retract[0].from.contact_radius);
  const rf::RadialFrontState& turn = loop.retract[0].from;
  EXPECT_NEAR(jkr.depth(turn.contact_radius), turn.indentation,
              1e-13 * std::abs(jkr.separation_depth()));
  EXPECT_LT(relative(turn.normal_force, jkr.force(turn.contact_radius, turn.indentation)), 1e-15);
}

// 1. Uniform w in SI units: the touch at d = 0 jumps to a_in = (c R^2)^(1/3), the retract
// separates at the bottom of d(a), a_min = (c R^2/16)^(1/3), with -(5/6) pi w R; the most
// tensile state on the way is the JKR -(3/2) pi w R at a^3 = 9 c R^2/16.
TEST(RadialFrontReference, UniformWorkMatchesTheJkrClosedForms) {
  const double modulus = 1.0e6, tip_radius = 0.01, w = 0.05;
  const UniformClosedForms jkr = closed_forms(modulus, tip_radius, w);
  const double deepest = 1e-5;  // about a_in^2/R
  const rf::RadialLoopReference loop =
      rf::radial_fixed_grips_loop(modulus, tip_radius, uniform_work(w, tip_radius), deepest);
  expect_uniform_loop(loop, jkr);
  EXPECT_LT(relative(jkr.peak_tension(), -1.5 * pi * w * tip_radius), 1e-15);
  EXPECT_LT(relative(jkr.separation_force(), -5.0 / 6.0 * pi * w * tip_radius), 1e-15);
  EXPECT_EQ(loop.approach.back().to.indentation, deepest);
}

std::string twelve_digits(double x) {
  std::ostringstream out;
  out << std::setprecision(12) << x;
  return out.str();
}

// 2. The crack-front codes' axisymmetric case: E* = 3/4, w0 = 1/pi, R = 1 (F_JKR = -3/2),
// w = w0 (1 + A sin(2 pi r / 0.1)); this test's choice of the deepest indentation: d_max = 0.05.
TEST(RadialFrontReference, SinusoidalWorkOfTheCrackFrontCodes) {
  const double modulus = 0.75, w0 = 1.0 / pi, tip_radius = 1.0, wavelength = 0.1;
  const double deepest = 0.05;
  std::vector<rf::RadialLoopReference> loops;
  for (const double amplitude : {0.0, 0.1, 0.2}) {
    const rf::RadialWorkOfAdhesion w = sinusoidal_work(w0, amplitude, wavelength);
    const auto loop = rf::radial_fixed_grips_loop(modulus, tip_radius, w, deepest, 200);
    const auto finer = rf::radial_fixed_grips_loop(modulus, tip_radius, w, deepest, 400);
    std::ostringstream line;
    line << "A = " << amplitude << ": peak tension "
         << twelve_digits(loop.peak_tension.normal_force)
         << " (at a = " << twelve_digits(loop.peak_tension.contact_radius)
         << ", d = " << twelve_digits(loop.peak_tension.indentation) << "), loop energy "
         << twelve_digits(loop.loop_energy) << ", separation depth "
         << twelve_digits(loop.separation.indentation)
         << " (a = " << twelve_digits(loop.separation.contact_radius)
         << ", F = " << twelve_digits(loop.separation.normal_force) << "), jumps in "
         << loop.jumps_in() << ", out " << loop.jumps_out()
         << " (the touch and the separation included)";
    std::cout << line.str() << '\n';
    RecordProperty("A_" + std::to_string(static_cast<int>(std::lround(amplitude * 10))),
                   line.str());
    // Convergence: 200 and 400 samples of d'(a) per wavelength find the same extrema.
    EXPECT_EQ(finer.jumps.size(), loop.jumps.size()) << amplitude;
    EXPECT_LT(relative(finer.peak_tension.normal_force, loop.peak_tension.normal_force), 1e-10)
        << amplitude;
    EXPECT_LT(relative(finer.loop_energy, loop.loop_energy), 1e-10) << amplitude;
    loops.push_back(loop);
  }
  expect_uniform_loop(loops[0], closed_forms(modulus, tip_radius, w0));
  EXPECT_NEAR(loops[0].peak_tension.normal_force, -1.5, 1e-12);
  // The wavier w dissipates more and pulls harder...
  EXPECT_GT(loops[2].loop_energy, loops[1].loop_energy);
  EXPECT_GT(loops[1].loop_energy, loops[0].loop_energy);
  EXPECT_GT(loops[0].loop_energy, 0.0);
  EXPECT_LT(loops[2].peak_tension.normal_force, loops[1].peak_tension.normal_force);
  EXPECT_LT(loops[1].peak_tension.normal_force, loops[0].peak_tension.normal_force);
  // ... and jumps: with A = 0.1 or 0.2 d(a) has a bottom in every wavelength (d'(a) changes sign
  // once |sqrt(c a) (A/2) 2 pi/lambda| > 2a/R), so the retract jumps out once per wavelength
  // (d_max = 0.05 is too shallow for a jump-in beyond the touch). Yet A = 0.2 jumps one time
  // fewer than A = 0.1: its contact separates from a larger radius (0.62 against 0.53, the
  // deeper bottoms of d(a) leave no branch inside to land on one wavelength earlier), as the
  // brute-force grid loop below finds too.
  EXPECT_GT(loops[1].jumps.size(), loops[0].jumps.size());
  EXPECT_GT(loops[2].jumps.size(), loops[0].jumps.size());
  EXPECT_LT(loops[2].jumps.size(), loops[1].jumps.size());
  EXPECT_GT(loops[2].separation.contact_radius, loops[1].separation.contact_radius);
  for (const std::size_t i : {1u, 2u}) {
    EXPECT_EQ(loops[i].jumps_in(), 1u);
    for (std::size_t j = 2; j < loops[i].jumps.size(); ++j) {
      const double spacing = loops[i].jumps[j - 1].from_radius - loops[i].jumps[j].from_radius;
      EXPECT_NEAR(spacing, wavelength, 0.05 * wavelength) << i << ' ' << j;
    }
  }
  // Every jump-in goes out, every jump-out in, at constant d; the loop's ends are d = 0 and d_max.
  for (const auto& loop : loops) {
    for (const auto& jump : loop.jumps) {
      EXPECT_EQ(jump.advancing, jump.to_radius > jump.from_radius);
    }
    EXPECT_EQ(loop.approach.front().from.indentation, 0.0);
    EXPECT_EQ(loop.approach.back().to.indentation, deepest);
  }
}

/// The same loop by brute force, apart from the tracker: the front on a grid a_i = i h, d in
/// steps of dd. On the approach the front is the first passage of d(a) through d beyond it
/// (min{a_i >= a : d(a_i) >= d}), on the retract the nearest radius inward where d(a) is down to
/// d (max{a_i <= a : d(a_i) <= d}), none: separated. A move jumps when it passes over a point
/// beyond the level before; W = trapezoidal sum of F dd.
struct GridLoop {
  int jumps_in = 0;
  int jumps_out = 0;
  double peak_tension = 0.0;
  double separation_indentation = 0.0;
  double loop_energy = 0.0;
};

GridLoop grid_loop(double modulus, double tip_radius, const std::function<double(double)>& w,
                   double deepest, double h, double dd) {
  const auto depth = [&](long i) {
    const double a = static_cast<double>(i) * h;
    return a * a / tip_radius - std::sqrt(2.0 * pi * a * w(a) / modulus);
  };
  const auto force = [&](long i) {
    const double a = static_cast<double>(i) * h;
    return modulus * (2.0 * a * depth(i) - 2.0 * a * a * a / (3.0 * tip_radius));
  };
  GridLoop loop;
  long front = 1;
  while (depth(front) < 0.0) ++front;
  loop.jumps_in += front > 1 ? 1 : 0;
  double level = 0.0, f = force(front);
  const auto steps = static_cast<long>(std::ceil(deepest / dd));
  for (long k = 1; k <= steps; ++k) {
    const double next = k == steps ? deepest : static_cast<double>(k) * dd;
    double lowest = next;
    while (depth(front) < next) lowest = std::min(lowest, depth(front++));
    loop.jumps_in += lowest < level ? 1 : 0;
    const double f_next = force(front);
    loop.loop_energy += 0.5 * (f + f_next) * (next - level);
    level = next;
    f = f_next;
  }
  loop.peak_tension = f;
  for (;;) {
    const double next = level - dd;
    double highest = next;
    // The front's own point is left out: at the turn it may lie above d_max (the grid).
    for (long start = front; front > 0 && depth(front) > next; --front) {
      if (front != start) highest = std::max(highest, depth(front));
    }
    if (front == 0) {
      ++loop.jumps_out;
      loop.separation_indentation = level;
      return loop;
    }
    loop.jumps_out += highest > level ? 1 : 0;
    const double f_next = force(front);
    loop.loop_energy += 0.5 * (f + f_next) * (next - level);
    loop.peak_tension = std::min(loop.peak_tension, f_next);
    level = next;
    f = f_next;
  }
}

// 2b. The tracker against the brute-force grid loop (h = 1e-6, dd = 1e-5) on test 2's cases: the
// same jumps, the separation depth to 2 dd, the peak tension to 1e-7 and the loop energy to
// 2e-5 relative (the grid's errors: 4e-6, 1e-9 and 2.4e-6 at most).
TEST(RadialFrontReference, SinusoidalWorkAgreesWithABruteForceGridLoop) {
  const double modulus = 0.75, w0 = 1.0 / pi, tip_radius = 1.0, wavelength = 0.1;
  const double deepest = 0.05, dd = 1e-5;
  for (const double amplitude : {0.0, 0.1, 0.2}) {
    const rf::RadialWorkOfAdhesion w = sinusoidal_work(w0, amplitude, wavelength);
    const auto loop = rf::radial_fixed_grips_loop(modulus, tip_radius, w, deepest);
    const GridLoop grid = grid_loop(modulus, tip_radius, w.value, deepest, 1e-6, dd);
    EXPECT_EQ(grid.jumps_in, static_cast<int>(loop.jumps_in())) << amplitude;
    EXPECT_EQ(grid.jumps_out, static_cast<int>(loop.jumps_out())) << amplitude;
    EXPECT_NEAR(grid.separation_indentation, loop.separation.indentation, 2.0 * dd) << amplitude;
    EXPECT_LT(relative(grid.peak_tension, loop.peak_tension.normal_force), 1e-7) << amplitude;
    EXPECT_LT(relative(grid.loop_energy, loop.loop_energy), 2e-5) << amplitude;
  }
}

/// The pinned stretches of a path: the front at one radius while d changes.
std::vector<rf::RadialFrontSegment> pinned(const std::vector<rf::RadialFrontSegment>& path) {
  std::vector<rf::RadialFrontSegment> found;
  for (const auto& s : path) {
    if (s.from.contact_radius == s.to.contact_radius) found.push_back(s);
  }
  return found;
}

// 3. A tougher core, w_in > w_out for r < b: d(a) steps up at b (from g(b) - sqrt(2 pi b
// w_in/E*) inside to g(b) - sqrt(2 pi b w_out/E*) outside) and the front pins at b while d runs
// between them. With b = 0.9 the touch lands outside b (a_in = (8/3)^(1/3)), and the retract
// passes b: pinned, then down the inner branch (c_in = 2 pi w_in/E*) to its bottom, where the
// contact separates. Everything in closed form: the pinned interval at 1e-12, the peak tension
// (the inner end of the pinned stretch: F outside falls to -3/2 at a = 1.5^(1/3) > b, and inside
// rises from b in) at 1e-12, the loop energy (three stretches) at 1e-10.
TEST(RadialFrontReference, TougherCorePinsTheFrontAtTheStep) {
  const double modulus = 0.75, tip_radius = 1.0, w_out = 1.0 / pi, w_in = 2.0 / pi, b = 0.9;
  const double deepest = 0.05;
  const UniformClosedForms outer = closed_forms(modulus, tip_radius, w_out);
  const UniformClosedForms inner = closed_forms(modulus, tip_radius, w_in);
  const double d_outside = b * b / tip_radius - std::sqrt(2.0 * pi * b * w_out / modulus);
  const double d_inside = b * b / tip_radius - std::sqrt(2.0 * pi * b * w_in / modulus);
  ASSERT_LT(d_inside, d_outside);
  ASSERT_LT(inner.bottom_radius(), b);  // the inner branch rises into b
  ASSERT_GT(outer.touch_radius(), b);

  const auto loop =
      rf::radial_fixed_grips_loop(modulus, tip_radius, stepped_work(w_in, w_out, b), deepest);
  EXPECT_TRUE(pinned(loop.approach).empty());
  const auto stretches = pinned(loop.retract);
  ASSERT_EQ(stretches.size(), 1u);
  const rf::RadialFrontSegment& pin = stretches[0];
  EXPECT_EQ(pin.from.contact_radius, b);
  EXPECT_LT(relative(pin.from.indentation, d_outside), 1e-12) << pin.from.indentation;
  EXPECT_LT(relative(pin.to.indentation, d_inside), 1e-12) << pin.to.indentation;

  ASSERT_EQ(loop.jumps.size(), 2u);
  EXPECT_LT(relative(loop.jumps[0].to_radius, outer.touch_radius()), 1e-12);
  EXPECT_LT(relative(loop.separation.contact_radius, inner.bottom_radius()), 1e-12);
  EXPECT_LT(relative(loop.separation.indentation, inner.separation_depth()), 1e-12);
  const double pinned_force = inner.force(b, d_inside);
  EXPECT_LT(relative(loop.peak_tension.normal_force, pinned_force), 1e-12)
      << loop.peak_tension.normal_force;
  EXPECT_LT(pinned_force, outer.peak_tension());
  // W: outside from a_in down to b, pinned from d(b+) to d(b-) (F linear in d), inside from b
  // down to the bottom.
  const double pinned_work =
      modulus * (b * (d_inside * d_inside - d_outside * d_outside) -
                 2.0 * b * b * b / (3.0 * tip_radius) * (d_inside - d_outside));
  const double energy = outer.antiderivative(b) - outer.antiderivative(outer.touch_radius()) +
                        pinned_work + inner.antiderivative(inner.bottom_radius()) -
                        inner.antiderivative(b);
  EXPECT_LT(relative(loop.loop_energy, energy), 1e-10) << loop.loop_energy << " vs " << energy;
}

// 3b. The same core with b = 1.5, between a_in outside and a_in inside: d(b-) < 0 < d(b+), so
// the touch lands on the step itself and the approach is pinned at b from d = 0 to d(b+); the
// retract comes back through the whole gap, pinned from d(b+) to d(b-).
TEST(RadialFrontReference, TougherCorePinsTheApproachFromTheTouch) {
  const double modulus = 0.75, tip_radius = 1.0, w_out = 1.0 / pi, w_in = 2.0 / pi, b = 1.5;
  const double deepest = 0.5;
  const double d_outside = b * b / tip_radius - std::sqrt(2.0 * pi * b * w_out / modulus);
  const double d_inside = b * b / tip_radius - std::sqrt(2.0 * pi * b * w_in / modulus);
  ASSERT_LT(d_inside, 0.0);
  ASSERT_GT(d_outside, 0.0);
  ASSERT_LT(d_outside, deepest);
  const auto loop =
      rf::radial_fixed_grips_loop(modulus, tip_radius, stepped_work(w_in, w_out, b), deepest);
  ASSERT_FALSE(loop.jumps.empty());
  EXPECT_EQ(loop.jumps[0].to_radius, b);
  const auto on_approach = pinned(loop.approach);
  ASSERT_EQ(on_approach.size(), 1u);
  EXPECT_EQ(on_approach[0].from.indentation, 0.0);
  EXPECT_LT(relative(on_approach[0].to.indentation, d_outside), 1e-12);
  const auto on_retract = pinned(loop.retract);
  ASSERT_EQ(on_retract.size(), 1u);
  EXPECT_LT(relative(on_retract[0].from.indentation, d_outside), 1e-12);
  EXPECT_LT(relative(on_retract[0].to.indentation, d_inside), 1e-12);
  const UniformClosedForms inner = closed_forms(modulus, tip_radius, w_in);
  EXPECT_LT(relative(loop.separation.indentation, inner.separation_depth()), 1e-12);
}

// 3c. A weaker core, w_in < w_out: d(a) steps down at b, the front cannot pin there. With b =
// 0.9 the inner branch's bottom, -(3/4)(c_in^2 R/4)^(1/3), lies above d(b+): the retract leaves
// b+ at d(b+) with no rising branch inside to land on, so the contact separates from the step.
TEST(RadialFrontReference, WeakerCoreSeparatesAtTheStep) {
  const double modulus = 0.75, tip_radius = 1.0, w_out = 1.0 / pi, w_in = 0.5 / pi, b = 0.9;
  const double deepest = 0.05;
  const double d_outside = b * b / tip_radius - std::sqrt(2.0 * pi * b * w_out / modulus);
  const UniformClosedForms inner = closed_forms(modulus, tip_radius, w_in);
  ASSERT_GT(inner.separation_depth(), d_outside);
  const auto loop =
      rf::radial_fixed_grips_loop(modulus, tip_radius, stepped_work(w_in, w_out, b), deepest);
  EXPECT_TRUE(pinned(loop.approach).empty());
  EXPECT_TRUE(pinned(loop.retract).empty());
  ASSERT_EQ(loop.jumps.size(), 2u);
  EXPECT_EQ(loop.separation.contact_radius, b);
  EXPECT_LT(relative(loop.separation.indentation, d_outside), 1e-12);
  EXPECT_LT(relative(loop.separation.normal_force, inner.force(b, d_outside)), 1e-12);
}

TEST(RadialFrontReference, RefusesBadArguments) {
  const auto w = uniform_work(1.0, 1.0);
  EXPECT_THROW(rf::radial_fixed_grips_loop(0.0, 1.0, w, 0.1), std::invalid_argument);
  EXPECT_THROW(rf::radial_fixed_grips_loop(1.0, 1.0, w, -0.1), std::invalid_argument);
  auto no_slope = w;
  no_slope.slope = nullptr;
  EXPECT_THROW(rf::radial_fixed_grips_loop(1.0, 1.0, no_slope, 0.1), std::invalid_argument);
  auto unordered = w;
  unordered.steps = {0.5, 0.2};
  EXPECT_THROW(rf::radial_fixed_grips_loop(1.0, 1.0, unordered, 0.1), std::invalid_argument);
}

}  // namespace
