// Friction on pressed springs under a relaxing bulk, against derivations written here (no engine
// code) and against the elastic friction program where the two must agree.
//
// The derivations. (1) A spring of relaxed modulus G with one Maxwell arm (G_1, tau) under a
// prescribed line load F(s) = c + b s (a sliding spring held at its limit mu f_z with f_z
// linear): G w + sigma = F and sigma' = G_1 w' - sigma / tau give G_0 w' = F' + (F - G w) / tau,
// G_0 = G + G_1, so w relaxes at the retardation rate mu_r = G / (tau G_0) towards the line
// A + B s, B = b / G, A = (c - b tau G_1 / G) / G, from w(0) = (c - sigma_0) / G:
//   w(s) = A + B s + (w(0) - A) exp(-mu_r s).
// (2) Cattaneo-Mindlin in the MDR (parabola of radius R pressed to d, contact radius a =
// sqrt(R d), sheared by u under fixed grips, nothing glued): a spring sticks while G* u <= mu E*
// (d - x^2 / R), so the stick radius is c = sqrt(a^2 - G* u R / (mu E*)) and
//   F_x = 2 [G* u c + (mu E* / R)(a^2 (a - c) - (a^3 - c^3) / 3)].
// A bulk that relaxes slowly against the program (every stage far slower than tau) is the
// elastic material of (E_inf, G_inf); far faster, the glassy one (E_0, G_0). With G_j = E_j G* /
// E* the ratio G / E is the same in both, so c is too and F_x scales by E_0 / E_inf.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_slide.hpp"
#include "engine/program/viscoelastic_slide.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kFrictionRadius = 0.01;  // R [m]
constexpr double kFrictionTau = 0.1;      // [s]

RunResult run_friction_text(const std::string& text) {
  return run_scene(SceneDocument::from_text(text, "friction.toml").build(Registries::builtin()),
                   {});
}

/// An adhesive parabola pressed to a = 1.5 mm, sheared to `ux`, held 0.5 s, pulled off until
/// separation, under mu = 1; `arm` > 0: a standard linear solid (E*_1 = arm, tau).
std::string shear_pull_friction_text(double ux, double arm, std::int64_t springs) {
  std::string text = "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n";
  if (arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", arm, kFrictionTau);
  }
  text += fmt::format(
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = 2.25e-4 "
      "}}\nspeed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to = {} }}\n"
      "speed = 1.0e-4\n[[loading.stage]]\nname = \"hold\"\nduration = 0.5\n"
      "[[loading.stage]]\nname = \"pull\"\nnormal = {{ by = -1.0 }}\nuntil = \"separation\"\n"
      "speed = 1.0e-3\n[friction]\ncoefficient = 1.0\n[discretization]\nsprings = {}\n"
      "[solver]\nmethod = \"event\"\n",
      kFrictionRadius, ux, springs);
  return text;
}

/// A non-adhesive parabola pressed to `depth` over `press_time`, held `hold` [s], sheared to `ux`
/// over `shear_time` (then back to -ux and to ux again with `cycle`), under mu = 0.5, G* = E* =
/// 1 MPa; `arm` > 0: a standard linear solid.
struct MindlinRun {
  double depth = 1.0e-5;
  double press_time = 0.01;
  double hold = 0.0;
  double ux = 2.0e-6;
  double shear_time = 0.02;
  bool cycle = false;
  double arm = 0.0;
  std::int64_t springs = 200;
};

std::string mindlin_text(const MindlinRun& m) {
  std::string text =
      "[material]\neffective_modulus = 1.0e6\neffective_shear_modulus = 1.0e6\n"
      "work_of_adhesion = 0.0\n";
  if (m.arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", m.arm, kFrictionTau);
  }
  text += fmt::format(
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
      "duration = {}\n",
      kFrictionRadius, m.depth, m.press_time);
  if (m.hold > 0.0)
    text += fmt::format("[[loading.stage]]\nname = \"hold\"\nduration = {}\n", m.hold);
  const auto shear = [&](const char* name, double to, double time) {
    text += fmt::format(
        "[[loading.stage]]\nname = \"{}\"\ntangential = {{ control = \"fixed-grips\", to = {} "
        "}}\nduration = {}\n",
        name, to, time);
  };
  shear("shear", m.ux, m.shear_time);
  if (m.cycle) {
    shear("back", -m.ux, 2.0 * m.shear_time);
    shear("again", m.ux, 2.0 * m.shear_time);
  }
  text += fmt::format(
      "[friction]\ncoefficient = 0.5\n[discretization]\nsprings = {}\n[solver]\nmethod = "
      "\"event\"\n",
      m.springs);
  return text;
}

/// Every stage's balance closes to rounding of the run's energies: `tolerance` of them.
void expect_balances_close(const RunResult& r, const std::string& what, double tolerance = 1e-12) {
  double scale = 0.0;
  for (const StageRecord& stage : r.stages) {
    ASSERT_TRUE(stage.energy) << what;
    scale = std::max(
        {scale, std::abs(stage.energy->machine_work), std::abs(stage.energy->stored_change)});
  }
  for (const StageRecord& stage : r.stages) {
    const EnergyBalance& e = *stage.energy;
    // Each term is a compensated sum of closed forms, and what the springs store a sum of
    // energies as large as the run's work: a few ulps of it, 1e-12.
    EXPECT_LE(std::abs(e.residual), tolerance * scale) << what << " " << stage.name;
    EXPECT_GE(e.dissipated_by_friction, -1e-15 * scale) << what << " " << stage.name;
    EXPECT_GE(e.jump_losses, -tolerance * scale) << what << " " << stage.name;
  }
}

TEST(ViscoelasticFriction, ASlidingSpringUnderALinearLoadCreepsAsItsClosedForm) {
  // Derivation (1): G = 1 MPa, G_1 = 4 MPa, tau = 0.1 s, sigma_0 = 3 N/m, F = 5 + 40 s N/m.
  const double g = 1.0e6, g1 = 4.0e6, tau = 0.1, sigma0 = 3.0, c = 5.0, b = 40.0;
  const std::vector<PronyTerm> terms{{g1, tau}};
  const RetardationModes modes(g, terms);
  const PrescribedLoadResponse r =
      response_to_load(modes, std::vector<double>{sigma0}, ExponentialSum{c, b, {}});
  const double rate = g / (tau * (g + g1));
  const double a = (c - b * tau * g1 / g) / g;
  const double w0 = (c - sigma0) / g;
  double worst = 0.0;
  for (const double s : {0.0, 0.01, 0.05, 0.1, 0.3, 1.0, 3.0}) {
    const double w = a + b / g * s + (w0 - a) * std::exp(-rate * s);
    const double sigma = c + b * s - g * w;
    worst = std::max(worst, std::abs(r.stretch.at(s) - w) / std::abs(w));
    worst = std::max(worst, std::abs(r.stresses[0].at(s) - sigma) / (std::abs(sigma) + 1e-300));
  }
  std::printf("one sliding spring, linear load: worst relative error %.3e\n", worst);
  // Closed form against closed form: rounding of a few terms.
  EXPECT_LT(worst, 1e-12);
}

/// RK4 of G w + sum_j s_j = F(s), s_j' = G_j w' - s_j / tau_j: w' from the constraint, (G +
/// sum G_j) w' = F' + sum_j s_j / tau_j.
std::vector<double> integrate_slide(double g, const std::vector<PronyTerm>& terms,
                                    std::vector<double> s, const ExponentialSum& f, double span,
                                    int steps) {
  double g0 = g;
  for (const PronyTerm& t : terms) g0 += t.modulus;
  const auto rhs = [&](double at, const std::vector<double>& y) {
    double sum = 0.0;
    for (std::size_t j = 0; j < y.size(); ++j) sum += y[j] / terms[j].time;
    const double wdot = (f.slope_at(at) + sum) / g0;
    std::vector<double> dy(y.size());
    for (std::size_t j = 0; j < y.size(); ++j) {
      dy[j] = terms[j].modulus * wdot - y[j] / terms[j].time;
    }
    return dy;
  };
  const double h = span / steps;
  for (int i = 0; i < steps; ++i) {
    const double t = i * h;
    const auto k1 = rhs(t, s);
    std::vector<double> y(s.size());
    for (std::size_t j = 0; j < s.size(); ++j) y[j] = s[j] + 0.5 * h * k1[j];
    const auto k2 = rhs(t + 0.5 * h, y);
    for (std::size_t j = 0; j < s.size(); ++j) y[j] = s[j] + 0.5 * h * k2[j];
    const auto k3 = rhs(t + 0.5 * h, y);
    for (std::size_t j = 0; j < s.size(); ++j) y[j] = s[j] + h * k3[j];
    const auto k4 = rhs(t + h, y);
    for (std::size_t j = 0; j < s.size(); ++j) {
      s[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
  }
  return s;
}

TEST(ViscoelasticFriction, ASlidingSpringUnderARelaxingLimitMatchesItsOdeIntegrated) {
  // Two arms, a load with decays at both relaxation times (a limit mu f_z whose normal arms
  // relax) and at a third time: the arms' stresses after 0.4 s against RK4 at 20000 steps
  // (error ~ (h / tau)^4 ~ 1e-14 of the stresses).
  const double g = 1.0e6;
  const std::vector<PronyTerm> terms{{3.0e6, 0.05}, {2.0e6, 0.4}};
  const RetardationModes modes(g, terms);
  const ExponentialSum f{2.0, -3.0, {{1.5, 0.05}, {-0.7, 0.4}, {0.9, 0.17}}};
  const std::vector<double> start{0.8, -0.3};
  const PrescribedLoadResponse r = response_to_load(modes, start, f);
  const std::vector<double> ode = integrate_slide(g, terms, start, f, 0.4, 20000);
  double worst = 0.0;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    worst = std::max(worst, std::abs(r.stresses[j].at(0.4) - ode[j]));
  }
  const double w = (f.at(0.4) - ode[0] - ode[1]) / g;
  std::printf("sliding spring, relaxing limit: stresses %.3e (ODE), stretch %.12e (%.12e)\n", worst,
              r.stretch.at(0.4), w);
  EXPECT_LT(worst, 1e-10);  // of stresses ~1 N/m: RK4's error
  EXPECT_NEAR(r.stretch.at(0.4), w, 1e-10 * std::abs(w));
}

TEST(ViscoelasticFriction, ASlideCountsItsWorkAsItsLimitAndStretch) {
  // A slide's work, friction and dashpot loss against a midpoint quadrature of its own closed
  // form (w, sigma from derivation (1)): work = u' int F, friction = int F (u' - w'), bulk =
  // int sigma^2 / (G_1 tau); the three balance with the stored energy.
  const double g = 1.0e6, g1 = 4.0e6, tau = 0.1, sigma0 = 3.0, c = 5.0, b = 40.0, u = 2.0e-5;
  const std::vector<PronyTerm> terms{{g1, tau}};
  const RetardationModes modes(g, terms);
  const ViscoelasticSlide slide(modes, std::vector<double>{sigma0}, ExponentialSum{c, b, {}}, 1.0,
                                1, u, 0.0);
  const SlideCount count = slide.count(terms, 0.05, 0.35);
  const double rate = g / (tau * (g + g1));
  const double a = (c - b * tau * g1 / g) / g;
  const double w0 = (c - sigma0) / g;
  const auto w = [&](double s) { return a + b / g * s + (w0 - a) * std::exp(-rate * s); };
  const auto wdot = [&](double s) { return b / g - rate * (w0 - a) * std::exp(-rate * s); };
  double work = 0.0, friction = 0.0, bulk = 0.0;
  const int n = 200000;
  const double h = 0.3 / n;
  for (int i = 0; i < n; ++i) {
    const double s = 0.05 + (i + 0.5) * h;
    const double f = c + b * s;
    const double sigma = f - g * w(s);
    work += u * f * h;
    friction += f * (u - wdot(s)) * h;
    bulk += sigma * sigma / (g1 * tau) * h;
  }
  std::printf("slide count: work %.12e (%.12e) friction %.12e (%.12e) bulk %.12e (%.12e)\n",
              count.work, work, count.friction, friction, count.bulk, bulk);
  // The midpoint rule's error ~ h^2 / 24 of the curvature: 1e-10.
  EXPECT_NEAR(count.work, work, 1e-10 * std::abs(work));
  EXPECT_NEAR(count.friction, friction, 1e-9 * std::abs(friction));
  EXPECT_NEAR(count.bulk, bulk, 1e-9 * bulk);
}

TEST(ViscoelasticFriction, AVanishingArmIsTheElasticFrictionProgram) {
  // E_1 = 1e-9 E_inf: the elastic friction program must give the same critical point, status,
  // stage ends and dissipated_by_friction; the arm shifts every spring's load by ~1e-9 of
  // itself, so forces agree to 1e-8 of the press's force and the friction to 1e-8 of the
  // tangential work (a difference of loads). The shears span a let-go in tension (3e-6), a
  // glue let go pressed into friction (8e-6) and one broken by the shear (1.5e-5, 2e-5).
  for (const double ux : {3.0e-6, 8.0e-6, 1.5e-5, 2.0e-5}) {
    const RunResult v = run_friction_text(shear_pull_friction_text(ux, 1.0e-3, 200));
    const RunResult e = run_friction_text(shear_pull_friction_text(ux, 0.0, 200));
    ASSERT_TRUE(v.critical && e.critical && v.work && e.work) << ux;
    std::printf(
        "vanishing arm, u_x = %g: critical F %.12e (elastic %.12e), F_x %.12e (%.12e), sliding "
        "%lld (%lld), friction %.12e (%.12e), status %d (%d)\n",
        ux, v.critical->normal_force, e.critical->normal_force, v.critical->tangential_force,
        e.critical->tangential_force, static_cast<long long>(v.critical->springs_sliding),
        static_cast<long long>(e.critical->springs_sliding), v.work->friction, e.work->friction,
        static_cast<int>(v.status), static_cast<int>(e.status));
    if (v.peak && e.peak) {
      std::printf("  peak F %.12e (elastic %.12e)\n", v.peak->normal_force, e.peak->normal_force);
    }
    const double press_force = e.stages.front().end.normal_force;
    const double shear_work = e.work->tangential;
    EXPECT_NEAR(v.critical->normal_force, e.critical->normal_force, 1e-8 * press_force);
    EXPECT_NEAR(v.critical->tangential_force, e.critical->tangential_force, 1e-8 * press_force);
    EXPECT_EQ(v.critical->springs_in_contact, e.critical->springs_in_contact);
    EXPECT_EQ(v.critical->springs_sliding, e.critical->springs_sliding);
    EXPECT_EQ(v.status, e.status);
    EXPECT_NEAR(v.work->friction, e.work->friction, 1e-8 * shear_work);
    ASSERT_EQ(v.peak.has_value(), e.peak.has_value()) << ux;
    if (v.peak) {
      EXPECT_NEAR(v.peak->normal_force, e.peak->normal_force, 1e-8 * press_force);
    }
    ASSERT_EQ(v.stages.size(), e.stages.size());
    for (std::size_t i = 1; i < v.stages.size(); ++i) {
      EXPECT_NEAR(v.stages[i].end.normal_force, e.stages[i].end.normal_force, 1e-8 * press_force);
      EXPECT_NEAR(v.stages[i].end.tangential_force, e.stages[i].end.tangential_force,
                  1e-8 * press_force);
      EXPECT_EQ(v.stages[i].end.springs_sliding, e.stages[i].end.springs_sliding);
      EXPECT_NEAR(v.stages[i].work.friction, e.stages[i].work.friction, 1e-8 * shear_work);
    }
    expect_balances_close(v, fmt::format("u_x = {}", ux));
  }
}

/// An adhesive parabola pressed to 2.3e-4 m and eased back to 2.25e-4 m (the row's last spring
/// then glued or apart alike on both rows), sheared to 3e-5 m (past the glue's strength at its
/// edge), back to 0, held 0.5 s and pulled off, under mu = 1 with rebinding.
std::string rebinding_text(double arm) {
  std::string text = "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n";
  if (arm > 0.0) {
    text += fmt::format("relaxation = [ {{ modulus = {}, time = {} }} ]\n", arm, kFrictionTau);
  }
  text += fmt::format(
      "[loading]\nrebinding = true\n[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = 2.3e-4 }}\n"
      "speed = 1.0e-3\n[[loading.stage]]\nname = \"ease\"\nnormal = {{ control = "
      "\"fixed-grips\", to = 2.25e-4 }}\nspeed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = {{ control = \"fixed-grips\", to = 3.0e-5 "
      "}}\nspeed = 1.0e-4\n[[loading.stage]]\nname = \"back\"\ntangential = {{ control = "
      "\"fixed-grips\", to = 0.0 }}\nspeed = 1.0e-4\n[[loading.stage]]\nname = \"hold\"\n"
      "duration = 0.5\n[[loading.stage]]\nname = \"pull\"\nnormal = {{ by = -1.0 }}\n"
      "until = \"separation\"\nspeed = 1.0e-3\n[friction]\ncoefficient = 1.0\n"
      "[discretization]\nsprings = 200\n[solver]\nmethod = \"event\"\n",
      kFrictionRadius);
  return text;
}

TEST(ViscoelasticFriction, AVanishingArmRebindsAsTheElasticFrictionProgram) {
  // The shear lets the glue's outer springs go pressed (they slide); shearing back, they stick
  // and glue again keeping their stretch where the run holds (docs/friction.md "Rebinding"):
  // every stage up to the pull as the elastic program's (glue, stick and let-go counts, F_x,
  // sliding springs, friction to 1e-8), and the pull-off's critical point. In the pull the
  // elastic row glues the edge spring again at the instant it lifts (its gap 0 within the glue
  // gap), the viscoelastic edge takes no spring back at the time it lifted: that stage's
  // friction differs and is not compared.
  const RunResult v = run_friction_text(rebinding_text(1.0e-3));
  const RunResult e = run_friction_text(rebinding_text(0.0));
  ASSERT_TRUE(v.critical && e.critical);
  ASSERT_EQ(v.stages.size(), e.stages.size());
  const double press_force = e.stages.front().end.normal_force;
  const double shear_work = std::abs(e.stages[2].work.tangential);
  for (std::size_t i = 0; i + 1 < v.stages.size(); ++i) {
    std::printf(
        "rebinding, stage %s: F_x %.12e (elastic %.12e), in contact %lld (%lld), "
        "sliding %lld (%lld), friction %.12e (%.12e)\n",
        v.stages[i].name.c_str(), v.stages[i].end.tangential_force,
        e.stages[i].end.tangential_force,
        static_cast<long long>(v.stages[i].end.springs_in_contact),
        static_cast<long long>(e.stages[i].end.springs_in_contact),
        static_cast<long long>(v.stages[i].end.springs_sliding),
        static_cast<long long>(e.stages[i].end.springs_sliding), v.stages[i].work.friction,
        e.stages[i].work.friction);
    EXPECT_NEAR(v.stages[i].end.tangential_force, e.stages[i].end.tangential_force,
                1e-8 * press_force);
    EXPECT_EQ(v.stages[i].end.glued_radius, e.stages[i].end.glued_radius) << i;
    EXPECT_EQ(v.stages[i].end.springs_sliding, e.stages[i].end.springs_sliding) << i;
    EXPECT_NEAR(v.stages[i].work.friction, e.stages[i].work.friction, 1e-8 * shear_work);
  }
  // Shearing back glues springs again: the glued radius at the end of "back" exceeds the
  // shear's.
  EXPECT_GT(v.stages[3].end.glued_radius, v.stages[2].end.glued_radius);
  std::printf("rebinding, critical F %.12e (elastic %.12e)\n", v.critical->normal_force,
              e.critical->normal_force);
  EXPECT_NEAR(v.critical->normal_force, e.critical->normal_force, 1e-8 * press_force);
  expect_balances_close(v, "rebinding");
}

TEST(ViscoelasticFriction, AVanishingArmIsTheElasticCattaneoMindlin) {
  // Pressed and sheared into partial slip, then back and forth: every stage end and its
  // friction as the elastic friction program's, to 1e-8 (the arm's 1e-9 share).
  MindlinRun m;
  m.cycle = true;
  m.arm = 1.0e-3;
  const RunResult v = run_friction_text(mindlin_text(m));
  m.arm = 0.0;
  const RunResult e = run_friction_text(mindlin_text(m));
  ASSERT_EQ(v.stages.size(), e.stages.size());
  const double press_force = e.stages.front().end.normal_force;
  const double shear_work = std::abs(e.stages[1].work.tangential);
  for (std::size_t i = 0; i < v.stages.size(); ++i) {
    std::printf(
        "Mindlin, stage %s: F_x %.12e (elastic %.12e), sliding %lld (%lld), stick radius "
        "%.9e (%.9e), friction %.12e (%.12e)\n",
        v.stages[i].name.c_str(), v.stages[i].end.tangential_force,
        e.stages[i].end.tangential_force, static_cast<long long>(v.stages[i].end.springs_sliding),
        static_cast<long long>(e.stages[i].end.springs_sliding), v.stages[i].end.stick_radius,
        e.stages[i].end.stick_radius, v.stages[i].work.friction, e.stages[i].work.friction);
    EXPECT_NEAR(v.stages[i].end.normal_force, e.stages[i].end.normal_force, 1e-8 * press_force);
    EXPECT_NEAR(v.stages[i].end.tangential_force, e.stages[i].end.tangential_force,
                1e-8 * press_force);
    EXPECT_EQ(v.stages[i].end.springs_sliding, e.stages[i].end.springs_sliding);
    EXPECT_EQ(v.stages[i].end.stick_radius, e.stages[i].end.stick_radius);
    EXPECT_NEAR(v.stages[i].work.friction, e.stages[i].work.friction, 1e-8 * shear_work);
  }
  expect_balances_close(v, "Mindlin cycle");
}

/// Derivation (2) at the row's contact radius a (its outermost spring).
struct MindlinClosedForm {
  double stick_radius;
  double force;
};
MindlinClosedForm mindlin_closed_form(double modulus, double a, double u, double mu) {
  const double c = std::sqrt(std::max(a * a - u * kFrictionRadius / mu, 0.0));
  const double force =
      2.0 * (modulus * u * c +
             mu * modulus / kFrictionRadius * (a * a * (a - c) - (a * a * a - c * c * c) / 3.0));
  return {c, force};
}

TEST(ViscoelasticFriction, SlowAndFastMindlinMeetTheElasticLimits) {
  // E*_inf = 1 MPa, E*_1 = 9 MPa (E_0 = 10 E_inf), tau = 0.1 s, d = 1e-5 m (a = 0.316 mm),
  // u = 2e-6 m. Slow: pressed over 1e3 tau, held 40 tau, sheared over 1e8 tau (the arms' share
  // of F_x, 9 tau / T, ~1e-7); fast: both over 1e-7 tau. The row's stick radius lies within a
  // spring's dx of c; its F_x within 1/N of the closed form (a sum of N springs' loads, first
  // order in dx), at two spring counts.
  for (const std::int64_t n : {200, 400}) {
    for (const bool slow : {true, false}) {
      MindlinRun m;
      m.arm = 9.0e6;
      m.springs = n;
      m.press_time = slow ? 1.0e3 * kFrictionTau : 1.0e-7 * kFrictionTau;
      m.hold = slow ? 40.0 * kFrictionTau : 0.0;
      m.shear_time = slow ? 1.0e8 * kFrictionTau : 1.0e-7 * kFrictionTau;
      const RunResult r = run_friction_text(mindlin_text(m));
      const ContactSnapshot& end = r.stages.back().end;
      const double a = end.contact_radius;
      const MindlinClosedForm cf = mindlin_closed_form(slow ? 1.0e6 : 1.0e7, a, m.ux, 0.5);
      const double dx = a / static_cast<double>(n);
      std::printf(
          "Mindlin %s, N = %lld: stick radius %.9e (closed form %.9e, dx %.3e), F_x %.9e "
          "(%.9e, %.2e)\n",
          slow ? "slow" : "fast", static_cast<long long>(n), end.stick_radius, cf.stick_radius, dx,
          end.tangential_force, cf.force, end.tangential_force / cf.force - 1.0);
      EXPECT_NEAR(end.stick_radius, cf.stick_radius, dx);
      EXPECT_NEAR(end.tangential_force, cf.force, 1.0 / static_cast<double>(n) * cf.force);
      // A stage of 1e-7 tau sums each arm's dissipation as c h + a tau (1 - exp(-h / tau)),
      // two terms that cancel to h / tau: the press alone (no friction) closes to 5e-10 there.
      expect_balances_close(r, slow ? "slow" : "fast", slow ? 1e-12 : 2e-9);
    }
  }
}

TEST(ViscoelasticFriction, AClosedTangentialCycleLosesItsWorkToFrictionAndTheBulk) {
  // Shear to u, back to -u and to u again at a speed near 1 / tau: the work of the last two
  // stages (a closed loop of u_x) is what friction and the dashpots dissipated plus the change
  // of what the springs store, each term summed apart; over the loop both dissipations are
  // positive and the stored change small beside them.
  MindlinRun m;
  m.arm = 9.0e6;
  m.cycle = true;
  m.shear_time = kFrictionTau;
  const RunResult r = run_friction_text(mindlin_text(m));
  ASSERT_EQ(r.stages.size(), 4u);
  double work = 0.0, friction = 0.0, bulk = 0.0, stored = 0.0;
  for (std::size_t i = 2; i < 4; ++i) {
    work += r.stages[i].energy->machine_work;
    friction += r.stages[i].energy->dissipated_by_friction;
    bulk += r.stages[i].energy->dissipated_by_bulk;
    stored += r.stages[i].energy->stored_change;
  }
  std::printf("closed cycle: work %.12e = friction %.12e + bulk %.12e + stored %.3e (%.3e)\n", work,
              friction, bulk, stored, work - friction - bulk - stored);
  EXPECT_GT(friction, 0.0);
  EXPECT_GT(bulk, 0.0);
  EXPECT_NEAR(work, friction + bulk + stored, 1e-12 * work);
  expect_balances_close(r, "cycle");

  // Relaxed (pressed over 1e3 tau, held 40 tau, each sweep of u over 1e8 tau) the loop ends
  // where it began (Mindlin-Deresiewicz: the state at +u after -u is the one at +u), so its
  // work is what friction and the dashpots dissipated: the stored change is the arms' share
  // of the rates, ~9 tau / T.
  m.press_time = 1.0e3 * kFrictionTau;
  m.hold = 40.0 * kFrictionTau;
  m.shear_time = 1.0e8 * kFrictionTau;
  const RunResult slow = run_friction_text(mindlin_text(m));
  ASSERT_EQ(slow.stages.size(), 5u);
  work = friction = bulk = stored = 0.0;
  for (std::size_t i = 3; i < 5; ++i) {
    work += slow.stages[i].energy->machine_work;
    friction += slow.stages[i].energy->dissipated_by_friction;
    bulk += slow.stages[i].energy->dissipated_by_bulk;
    stored += slow.stages[i].energy->stored_change;
  }
  std::printf("slow closed cycle: work %.12e, friction %.12e + bulk %.3e (%.3e), stored %.3e\n",
              work, friction, bulk, (work - friction - bulk) / work, stored);
  EXPECT_NEAR(work, friction + bulk, 1e-6 * work);
  expect_balances_close(slow, "slow cycle");
}

}  // namespace
}  // namespace mdrsim
