// A held tangential force on a glued contact under friction (docs/friction.md "From adhesion to
// sliding friction"): the glue peels from its edge as the force rises past the adhesive peak,
// each pressed spring letting go where the stretch friction does not hold pays its surface
// energy, up to the peeling branch's largest force; there the rest of the glue breaks and the
// contact, whose friction holds less than that force, slides away. Closed forms derived here,
// apart from the engine.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

// R = 1 cm, E* = G* = 1 MPa, dgamma = 0.05 J/m^2, glued on touch at d = 12 d0 (a_g = 2 a0).
constexpr double kRadius = 0.01;
constexpr double kModulus = 1e6;
constexpr double kWork = 0.05;
constexpr double kDepth = 2.713781792333937e-5;

struct Transition {
  double mu;
  double a = std::sqrt(kRadius * kDepth);
  double normal_force = 4.0 * kModulus * a * a * a / (3.0 * kRadius);  // Hertz at d
  double u_c = std::sqrt(2.0 * std::numbers::pi * a * kWork / kModulus);
  double peak = 2.0 * std::sqrt(2.0 * std::numbers::pi * kWork * kModulus) * std::pow(a, 1.5);
  /// The peeling branch, glued inside c: the front's spring lets go where its stretch beyond
  /// what friction holds, u - mu (E*/G*) (d - g(c)), reaches the critical sqrt(2 pi c dgamma / G*).
  double u_at(double c) const {
    return mu * (a * a - c * c) / kRadius +
           std::sqrt(2.0 * std::numbers::pi * c * kWork / kModulus);
  }
  /// F_x there: the glued springs at G* u, the annulus sliding at mu E* (d - g).
  double force_at(double c) const {
    return 2.0 * (kModulus * c * u_at(c) +
                  mu * kModulus / kRadius * (a * a * (a - c) - (a * a * a - c * c * c) / 3.0));
  }
  /// The c at which force_at(c) = f on the branch's stable part (c above its largest force).
  double front_at(double f) const {
    double lo = largest_force_front();
    double hi = a;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (force_at(mid) > f ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  /// Where force_at is largest: golden-section search on (0, a) (one maximum there).
  double largest_force_front() const {
    double lo = 1e-3 * a;
    double hi = a;
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < 200; ++i) {
      const double c1 = hi - r * (hi - lo);
      const double c2 = lo + r * (hi - lo);
      (force_at(c1) > force_at(c2) ? hi : lo) = force_at(c1) > force_at(c2) ? c2 : c1;
    }
    return 0.5 * (lo + hi);
  }
  /// The machine's work along the branch from the edge (c = a) to c: the integral of F_x du,
  /// by Simpson's rule in c (smooth there) on 2000 intervals.
  double peeling_work(double c) const {
    constexpr int kIntervals = 2000;
    const double h = (c - a) / kIntervals;
    const auto slope = [&](double x) {  // du/dc
      return -2.0 * mu * x / kRadius +
             0.5 * std::sqrt(2.0 * std::numbers::pi * kWork / (kModulus * x));
    };
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double x = a + i * h;
      const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += weight * force_at(x) * slope(x);
    }
    return sum * h / 3.0;
  }
};

std::string scene(double mu, double force, int springs) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[[loading.stage]]\nname = \"glue\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\n[[loading.stage]]\nname = "
      "\"shear\"\ntangential = {{ control = \"fixed-load\", to = {:.17g} }}\n[friction]\n"
      "coefficient = {}\n[discretization]\nsprings = {}\n",
      kDepth, force, mu, springs);
}

RunResult run_text(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return run_scene(SceneDocument::from_text(text, "held.toml").build(registries), {});
}

// mu = 1: the held force 0.015 N lies between the adhesive peak (0.01333 N, where the edge lets
// go at u_c: to rounding, the row's N-th spring sits at a_g) and the peeling branch's largest
// force (0.0212 N): the ramp ends on the branch, glued inside c with F_x(c) = 0.015 N, no jump.
// The machine's work is the glue's G* a_g u_c^2 and the branch's integral of F_x du. Bounds: the
// row's sums over springs are off by O(1/N): u_x within 2/N, c within 2 spacings, the work within
// 4/N (observed below 1/N).
TEST(FrictionHeldForce, TheGluePeelsStablyPastTheAdhesivePeak) {
  const Transition t{.mu = 1.0};
  const double force = 0.015;
  ASSERT_LT(t.peak, force);
  ASSERT_LT(force, t.force_at(t.largest_force_front()));
  for (const int springs : {2000, 8000}) {
    SCOPED_TRACE(springs);
    const RunResult r = run_text(scene(t.mu, force, springs));
    EXPECT_EQ(r.status, RunStatus::completed);
    EXPECT_FALSE(r.sliding);
    EXPECT_TRUE(r.jumps.empty());
    ASSERT_EQ(r.stages.size(), 2u);
    const auto& end = r.stages[1].end;
    const double c = t.front_at(force);
    EXPECT_NEAR(end.tangential_force, force, 1e-12 * force);
    EXPECT_NEAR(end.tangential_displacement, t.u_at(c), 2.0 / springs * t.u_at(c));
    EXPECT_NEAR(end.glued_radius, c, 2.0 * t.a / springs);
    const double work = kModulus * t.a * t.u_c * t.u_c + t.peeling_work(c);
    EXPECT_NEAR(r.stages[1].work.tangential, work, 4.0 / springs * work);
    EXPECT_GT(r.stages[1].work.friction, 0.0);
  }
}

// mu = 0.5: the held force 0.015 N exceeds the branch's largest force (0.01414 N at c = 0.79 a_g):
// the rest of the glue breaks there, and friction, which holds mu F_z (0.00942 N) at most, cannot
// carry it: shear-off with "sliding", the critical point the branch's largest force, within 2/N.
TEST(FrictionHeldForce, FrictionBelowThePeelingPeakLetsTheContactSlideAway) {
  const Transition t{.mu = 0.5};
  const double c = t.largest_force_front();
  const double largest = t.force_at(c);
  ASSERT_LT(largest, 0.015);
  ASSERT_GT(largest, t.mu * t.normal_force);
  constexpr int kSprings = 2000;
  const RunResult r = run_text(scene(t.mu, 0.015, kSprings));
  EXPECT_EQ(r.status, RunStatus::shear_off);
  EXPECT_TRUE(r.sliding);
  ASSERT_TRUE(r.critical);
  EXPECT_NEAR(r.critical->tangential_force, largest, 2.0 / kSprings * largest);
  EXPECT_NEAR(r.critical->tangential_displacement, t.u_at(c), 2.0 / kSprings * t.u_at(c));
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("slides away"), std::string::npos) << r.warnings.front();
}

}  // namespace
}  // namespace mdrsim
