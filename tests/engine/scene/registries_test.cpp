// Every registered criterion, controller and friction law, and one of each kind from outside,
// through a short program, against a discrete row summed here and against each other.
#include "engine/scene/registries.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/reference/part_examples.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/scene_document.hpp"

namespace {

// The tests' JKR scene: R = 1 cm, E = 1 MPa, nu = 0.3, dgamma = 0.05 J/m^2, glue on touch.
constexpr double kTip = 0.01;
constexpr double kYoungs = 1e6;
constexpr double kPoisson = 0.3;
constexpr double kDgamma = 0.05;
constexpr int kSprings = 400;
const double kEStar = kYoungs / (1.0 - kPoisson * kPoisson);

/// Griffith's balance with the scene's dgamma, written outside the built-ins as a user would
/// (examples/custom_criterion): only the margin, so the engine root-finds every let-go.
class OutsideGriffith final : public mdrsim::DetachmentCriterion {
 public:
  explicit OutsideGriffith(const mdrsim::InterfaceProperties& p) : p_(p) {}
  double margin(const mdrsim::BoundarySpring& s) const override {
    return 2.0 * std::numbers::pi * s.contact_radius * p_.work_of_adhesion -
           p_.effective_modulus * s.elongation * s.elongation -
           p_.effective_shear_modulus * s.tangential_displacement * s.tangential_displacement;
  }

 private:
  mdrsim::InterfaceProperties p_;
};

constexpr const char* kOutside = "outside-griffith";

mdrsim::Registries registries_with_outside() {
  auto r = mdrsim::Registries::builtin();
  r.criteria.add({kOutside,
                  "Griffith's balance, from outside",
                  {},
                  [](const mdrsim::ParameterValues&, const mdrsim::InterfaceProperties& p) {
                    return std::make_unique<OutsideGriffith>(p);
                  }});
  return r;
}

std::string keys(std::string_view kind, const std::string& name, std::string_view separator) {
  if (name == kOutside) return "";
  const std::string k = mdrsim::test::example_keys(kind, name, separator);
  return k.empty() ? "" : std::string(separator) + k;
}

/// Approach to `to`, hold, retract by `by` per unit of the stage until separation, all under
/// `controller`.
std::string program(const std::string& controller, const std::string& criterion, double to,
                    double by) {
  const std::string axis =
      fmt::format("control = \"{}\"{}", controller, keys("controller", controller, ", "));
  return fmt::format(
      "[material]\nyoungs_modulus = {}\npoisson_ratio = {}\nwork_of_adhesion = {}\n"
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[detachment]\ncriterion = \"{}\"{}\n[discretization]\nsprings = {}\n"
      "[[loading.stage]]\nname = \"approach\"\nnormal = {{ {}, to = {} }}\n"
      "[[loading.stage]]\nname = \"hold\"\nnormal = {{ {} }}\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = {{ {}, by = {} }}\nuntil = "
      "\"separation\"\n",
      kYoungs, kPoisson, kDgamma, kTip, criterion, keys("criterion", criterion, "\n"), kSprings,
      axis, to, axis, axis, by);
}

struct RowState {
  double indentation;  ///< [m]
  double force;        ///< [N]
};

/// The discrete row's force at depth d, summed here: springs at x_i = i a_ref / N (spring N
/// at the run's frame radius a_ref), each pressed once touched (glue on touch: g_i = x_i^2 / R
/// <= d), F = 2 E* dx sum (d - g_i).
double row_force(double d, double a_ref, int n) {
  const double dx = a_ref / n;
  double sum = 0.0;
  for (int i = 1;; ++i) {
    const double x = i == n ? a_ref : dx * i;
    const double g = x * x / kTip;
    if (g > d) break;
    sum += d - g;
  }
  return 2.0 * kEStar * dx * sum;
}

/// Where the row meets the controller's constraint a_u d + a_F F(d) = held: bisection on d.
RowState discrete_approach_end(const mdrsim::AffineConstraint& c, double held, double a_ref,
                               int n) {
  const auto value = [&](double d) {
    return c.displacement_coefficient * d + c.force_coefficient * row_force(d, a_ref, n);
  };
  double lo = 0.0;
  double hi = 1e-9;
  while (value(hi) < held) hi *= 2.0;
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (value(mid) < held ? lo : hi) = mid;
  }
  return {hi, row_force(hi, a_ref, n)};
}

/// Coulomb's law written outside the built-ins as a user would (examples/custom_friction_law),
/// without saying it is uniform: the engine runs it spring by spring.
class OutsideCoulomb final : public mdrsim::FrictionLaw {
 public:
  explicit OutsideCoulomb(double mu) : mu_(mu) {}
  mdrsim::SlipLimit limit_at(double /*radius*/, double /*spacing*/) const override {
    return {mu_, 0.0};
  }

 private:
  double mu_;
};

}  // namespace

// Each controller approaches Hertz at 3 d0 (its held value through its own constraint), holds
// and retracts. The approach's end is the discrete row's, summed above: 1e-9 relative (the
// engine solves each equilibrium by one division, the sum is compensated; the bisection ends
// at adjacent doubles). The hold changes nothing. Without tangential load every criterion is
// the Hess rule (paper eq. 12), so each retract's critical force is the first criterion's to
// 1e-9 (closed forms against the outside criterion's root search, TOMS 748 to 2^-50).
TEST(Registries, EveryCriterionAndControllerRunsAProgram) {
  const mdrsim::Registries registries = registries_with_outside();
  std::vector<std::string> criteria = registries.criteria.names();
  ASSERT_GE(criteria.size(), 2U);
  const double d0 = std::cbrt(3.0 * std::numbers::pi * std::numbers::pi * kTip * kDgamma * kDgamma /
                              (64.0 * kEStar * kEStar));
  const double d_max = 3.0 * d0;
  const double f_max = 4.0 / 3.0 * kEStar * std::sqrt(kTip) * std::pow(d_max, 1.5);
  for (const std::string& controller : registries.controllers.names()) {
    std::optional<double> first_critical;
    for (const std::string& criterion : criteria) {
      const std::string where = controller + ", " + criterion;
      // The controller's held values: its constraint at Hertz's 3 d0, and twice that per unit
      // of the retract.
      const mdrsim::Scene probe =
          mdrsim::SceneDocument::from_text(program(controller, criterion, 1.0, -1.0), "test.toml")
              .build(registries);
      const mdrsim::AffineConstraint c =
          probe.program->stages.front().normal->controller->constraint();
      const double to = c.displacement_coefficient * d_max + c.force_coefficient * f_max;
      const mdrsim::Scene scene = mdrsim::SceneDocument::from_text(
                                      program(controller, criterion, to, -2.0 * to), "test.toml")
                                      .build(registries);
      const mdrsim::RunResult r = mdrsim::run_scene(scene, mdrsim::ObserverList{});
      ASSERT_EQ(r.stages.size(), 3U) << where;
      const RowState ref = discrete_approach_end(c, to, r.accuracy.outer_radius, kSprings);
      const mdrsim::ContactSnapshot& approach = r.stages[0].end;
      EXPECT_NEAR(approach.indentation, ref.indentation, 1e-9 * ref.indentation) << where;
      EXPECT_NEAR(approach.normal_force, ref.force, 1e-9 * ref.force) << where;
      EXPECT_NEAR(r.stages[1].end.normal_force, approach.normal_force, 1e-12 * ref.force) << where;
      ASSERT_TRUE(r.critical.has_value()) << where << ": " << mdrsim::to_string(r.status);
      EXPECT_LT(r.critical->normal_force, 0.0) << where;
      if (!first_critical) {
        first_critical = r.critical->normal_force;
      } else {
        EXPECT_NEAR(r.critical->normal_force, *first_critical, 1e-9 * std::abs(*first_critical))
            << where;
      }
    }
  }
}

// Every registered friction law, and one from outside, from its declared example values: pressed
// to 3 d0 at fixed grips without adhesion and sheared to twice Cattaneo-Mindlin's u* = mu E* d
// / G*, where every spring slides and F_x = 2 mu E* dx sum (d - g_i) of the row, summed here
// (1e-12: the same sums in another order). The laws' coefficients differ only through their
// example values; the outside law at the built-in's example gives the same F_x to 1e-12.
TEST(Registries, EveryFrictionLawRunsAProgram) {
  mdrsim::Registries registries = mdrsim::Registries::builtin();
  registries.friction_laws.add(
      {.name = "outside-coulomb",
       .summary = "mu max(f_z, 0), from outside",
       .parameters = {{.key = "mu", .help = "mu >= 0", .example = 0.5}},
       .create = [](const mdrsim::ParameterValues& v) -> std::unique_ptr<mdrsim::FrictionLaw> {
         return std::make_unique<OutsideCoulomb>(v.number("mu"));
       }});
  const double d0 = std::cbrt(3.0 * std::numbers::pi * std::numbers::pi * kTip * kDgamma * kDgamma /
                              (64.0 * kEStar * kEStar));
  const double d = 3.0 * d0;
  const double g_star = 4.0 * kYoungs / (2.0 * (1.0 + kPoisson)) / (2.0 - kPoisson);
  std::vector<double> forces;
  for (const std::string& name : registries.friction_laws.names()) {
    SCOPED_TRACE(name);
    std::string law_keys;
    double mu = 0.0;
    for (const mdrsim::ParameterSpec& spec : registries.friction_laws.find(name)->parameters) {
      ASSERT_TRUE(spec.example.has_value()) << spec.key;
      law_keys += fmt::format("{} = {}\n", spec.key, *spec.example);
      mu = *spec.example;  // each law here has its coefficient as its one key
    }
    const double u = 2.0 * mu * kEStar * d / g_star;
    const std::string text = fmt::format(
        "[material]\nyoungs_modulus = {}\npoisson_ratio = {}\nwork_of_adhesion = 0.0\n"
        "[profile]\ntype = \"parabolic\"\nradius = {}\n[discretization]\nsprings = {}\n"
        "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} "
        "}}\n[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to "
        "= {} }}\n[friction]\nlaw = \"{}\"\n{}",
        kYoungs, kPoisson, kTip, kSprings, d, u, name, law_keys);
    const mdrsim::Scene scene =
        mdrsim::SceneDocument::from_text(text, "test.toml").build(registries);
    const mdrsim::RunResult r = mdrsim::run_scene(scene, mdrsim::ObserverList{});
    ASSERT_EQ(r.stages.size(), 2U);
    const mdrsim::ContactSnapshot& end = r.stages[1].end;
    EXPECT_EQ(end.springs_sliding, end.springs_in_contact);
    const double expected = mu * row_force(d, r.accuracy.outer_radius, kSprings);
    EXPECT_NEAR(end.tangential_force, expected, 1e-12 * expected);
    forces.push_back(end.tangential_force);
  }
  ASSERT_EQ(forces.size(), 2U);
  EXPECT_NEAR(forces[0], forces[1], 1e-12 * forces[0]);
}
