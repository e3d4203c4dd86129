// docs/programs.md "Discretization": spring N is in contact at the program's deepest state,
// also where a fixed load or a machine spring holds the normal axis there (a 256-spring pilot
// put it at N - 1 to N - 20 before, off by the pilot's O(1/256)).
//
// References, derived here from the MDR of the parabola g(x) = x^2 / R: a contact grown on an
// advancing front with the gluing limit l(a) = sqrt(2 pi a dgamma_a / E*) (0: glue on touch)
// has every spring at u_z = d - g(x) and its edge at d = g(a) - l(a), so
//   F(a) = 2 E* int_0^a (d - g) dx = 4 E* a^3 / (3 R) - 2 E* a l(a),
// and the deepest state of a stage holding F (or d + F / k through a machine spring of
// stiffness k) is the a where that control equals the held value. The row's own radius is
// within O(1/N) of it: held to 2/N relative (the rows here land at 0.2/N to 0.5/N).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "engine/program/held_front.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "profiles/parabolic_profile.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.01;      // R [m]
constexpr double kModulus = 1.0e6;    // E* = G* [Pa] (E = 1 MPa, nu = 0)
constexpr double kAdhesion = 0.05;    // dgamma [J/m^2]
constexpr double kStiffness = 200.0;  // the machine spring [N/m]

double limit(double a, double approach) { return std::sqrt(2.0 * kPi * a * approach / kModulus); }
double depth(double a, double approach) { return a * a / kRadius - limit(a, approach); }
double force(double a, double approach) {
  return 4.0 * kModulus * a * a * a / (3.0 * kRadius) - 2.0 * kModulus * a * limit(a, approach);
}

/// The continuum front where `control` (increasing in a on [lo, hi]) reaches `held`, by bisection.
template <class Control>
double front_at(Control control, double held) {
  double lo = 1e-6;
  double hi = 1e-2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (control(mid) < held ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::string scene_text(const std::string& press, double approach, std::int64_t springs) {
  return "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
         "approach_work_of_adhesion = " +
         std::to_string(approach) +
         "\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
         "[[loading.stage]]\nname = \"press\"\nnormal = " +
         press +
         "\n[[loading.stage]]\nname = \"pull\"\n"
         "normal = { control = \"fixed-grips\", by = -1e-5 }\nuntil = \"separation\"\n"
         "[discretization]\nsprings = " +
         std::to_string(springs) + "\n";
}

struct Case {
  const char* name;
  std::string press;
  double approach;
  double expected_radius;
};

TEST(HeldFront, DeepestHeldStateReachesSpringN) {
  const double held_force = 5e-3;
  const double held_end = 4e-5;
  const Case cases[] = {
      {"fixed load, glue on touch", "{ control = \"fixed-load\", to = 5e-3 }", 0.0,
       front_at([](double a) { return force(a, 0.0); }, held_force)},
      {"fixed load, reversible JKR", "{ control = \"fixed-load\", to = 5e-3 }", kAdhesion,
       front_at([](double a) { return force(a, kAdhesion); }, held_force)},
      {"compliant, glue on touch", "{ control = \"compliant\", stiffness = 200.0, to = 4e-5 }", 0.0,
       front_at([](double a) { return depth(a, 0.0) + force(a, 0.0) / kStiffness; }, held_end)},
  };
  for (const Case& c : cases) {
    for (const std::int64_t n : {1000, 4000, 20000}) {
      const Scene scene = test::build_scene_text(scene_text(c.press, c.approach, n));
      const RunResult r = run_scene(scene, {});
      ASSERT_GE(r.stages.size(), 1u) << c.name;
      const ContactSnapshot& end = r.stages[0].end;
      EXPECT_EQ(end.springs_in_contact, n) << c.name << " at " << n << " springs";
      EXPECT_NEAR(end.contact_radius / c.expected_radius, 1.0, 2.0 / static_cast<double>(n))
          << c.name << " at " << n << " springs";
    }
  }
}

TEST(HeldFront, RowRadiusPutsHeldBetweenSpringNAndTheNext) {
  const ParabolicProfile profile(kRadius);
  Material material = Material::from_youngs_modulus(kModulus, 0.0, kAdhesion);
  material.approach_work_of_adhesion = kAdhesion;  // the front glues at the Hess limit
  const HeldDeepest held{{0.0, 1.0}, 5e-3, true};
  for (const std::int64_t n : {3, 50, 1000}) {
    const double guess = front_at([](double a) { return force(a, kAdhesion); }, 5e-3);
    const auto a = row_radius_reaching_held(profile, material, held, n, guess);
    ASSERT_TRUE(a.has_value()) << n;
    // The row's force with N springs at the depth where spring N glues, and where N + 1 would.
    const double dx = *a / static_cast<double>(n);
    double images = 0.0;
    for (std::int64_t i = 1; i <= n; ++i) {
      const double x = dx * static_cast<double>(i);
      images += x * x / kRadius;
    }
    const auto row_force = [&](double d) {
      return 2.0 * kModulus * dx * (static_cast<double>(n) * d - images);
    };
    const double at_n = row_force(depth(*a, kAdhesion));
    const double at_next = row_force(depth(*a + dx, kAdhesion));
    EXPECT_LT(at_n, 5e-3) << n;
    EXPECT_GT(at_next, 5e-3) << n;
    // Half-way between them, to rounding of the sums.
    EXPECT_NEAR(0.5 * (at_n + at_next), 5e-3, 1e-12) << n;
  }
}

}  // namespace
}  // namespace mdrsim
