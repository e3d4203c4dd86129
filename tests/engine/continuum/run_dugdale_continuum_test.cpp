// The shorthand with finite-range adhesion, from scene text through run_scene, against Maugis'
// classical parabola (maugis_reference, written apart from the MDR), the cone's threshold and
// DMT limit, and the pinned phase's continuity with the branch.
#include "engine/continuum/run_dugdale_continuum.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "engine/continuum/dugdale_path.hpp"
#include "engine/model/dugdale_material.hpp"
#include "engine/output/result_json.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/maugis_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "tests/support/maugis_units.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
namespace maugis = maugis_reference;
using test::MaugisUnits;

/// Maugis' parabola (R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2) at lambda, glued at A = 3
/// (a = 3 of Maugis' length): every fold lies below it (checked below) and the pinned phase
/// ends at A = 3.
std::string parabola(double lambda, const std::string& normal) {
  const MaugisUnits u;
  return fmt::format(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\nmaugis_parameter = {}\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\npreload = {{ contact_radius = {} }}\nnormal = {{ {} }}\n",
      lambda, 3.0 * u.length(), normal);
}

RunResult run(const std::string& text) {
  return run_scene(test::build_scene_text(text), ObserverList{});
}

// P = F/(pi dgamma R) at the pull-off under fixed load and at the fixed-grips jump, lambda from
// DMT to JKR, within 1e-6 (the issue's; the reference's own Brent tolerance is 2e-8 of P).
TEST(RunDugdaleContinuum, TheParabolaIsMaugisFromDmtToJkr) {
  const MaugisUnits u;
  std::printf("%8s %14s %14s %10s | %14s %14s %10s\n", "lambda", "P load", "P Maugis", "rel",
              "P grips", "P Maugis", "rel");
  for (const double lambda : {0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0}) {
    SCOPED_TRACE(lambda);
    const RunResult load = run(parabola(lambda, "control = \"fixed-load\""));
    const RunResult grips = run(parabola(lambda, "control = \"fixed-grips\""));
    ASSERT_EQ(load.status, RunStatus::instability);
    ASSERT_EQ(grips.status, RunStatus::instability);
    const double p_load = load.critical->normal_force / u.force();
    const double p_grips = grips.critical->normal_force / u.force();
    const double ref_load = maugis::fixed_load_pull_off(lambda).force;
    const double ref_grips = maugis::fixed_grips_jump(lambda).force;
    EXPECT_NEAR(p_load, ref_load, 1e-6);
    EXPECT_NEAR(p_grips, ref_grips, 1e-6);
    // The estimates meet the default rtol 1e-10.
    EXPECT_TRUE(load.accuracy.rtol_met);
    EXPECT_TRUE(grips.accuracy.rtol_met);
    // The pull-off lies below the glued radius: the pinned phase ended before the fold.
    EXPECT_LT(load.critical->contact_radius, 3.0 * u.length());
    EXPECT_LT(grips.critical->contact_radius, 3.0 * u.length());
    // Under fixed load the pull-off is the most tensile state; under grips the peak is below it.
    EXPECT_EQ(load.peak->normal_force, load.critical->normal_force);
    EXPECT_LE(grips.peak->normal_force, grips.critical->normal_force);
    std::printf("%8.3f %14.9f %14.9f %10.2e | %14.9f %14.9f %10.2e\n", lambda, p_load, ref_load,
                std::abs(p_load / ref_load - 1.0), p_grips, ref_grips,
                std::abs(p_grips / ref_grips - 1.0));
  }
}

// The fixed-grips jump on the contact branch (lambda above 0.93885) to 1e-9: against the root
// of the slope of Maugis' own D(A) (maugis_reference, a fourth-order difference quotient at
// 1e-4 A, bisected), where fixed_grips_jump's Brent on values places the fold to only about
// sqrt(eps) in A (its P off by up to 2e-8).
TEST(RunDugdaleContinuum, TheGripsJumpIsTheRootOfTheSlopeOfMaugisDepth) {
  const MaugisUnits u;
  for (const double lambda : {1.0, 2.0, 10.0, 100.0}) {
    SCOPED_TRACE(lambda);
    const auto slope = [&](double a) {
      const double h = 1e-4 * a;
      const auto depth = [&](double x) { return maugis::contact_branch(lambda, x).indentation; };
      return (8.0 * (depth(a + h) - depth(a - h)) - (depth(a + 2.0 * h) - depth(a - 2.0 * h))) /
             (12.0 * h);
    };
    const double near = maugis::fixed_grips_jump(lambda).contact_radius;
    double lo = near * (1.0 - 1e-4);
    double hi = near * (1.0 + 1e-4);
    ASSERT_LT(slope(lo), 0.0);
    ASSERT_GT(slope(hi), 0.0);
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (slope(mid) < 0.0 ? lo : hi) = mid;
    }
    const double reference = maugis::contact_branch(lambda, 0.5 * (lo + hi)).force;
    const RunResult grips = run(parabola(lambda, "control = \"fixed-grips\""));
    EXPECT_NEAR(grips.critical->normal_force / u.force() / reference, 1.0, 1e-9);
  }
}

// Under fixed grips the parabola jumps from the contact branch above lambda = 0.93885 and from
// the no-contact branch (a = 0) below it.
TEST(RunDugdaleContinuum, TheGripsJumpLeavesFromEitherBranchAboutTheThreshold) {
  const RunResult below = run(parabola(0.9, "control = \"fixed-grips\""));
  const RunResult above = run(parabola(0.98, "control = \"fixed-grips\""));
  ASSERT_EQ(below.status, RunStatus::instability);
  ASSERT_EQ(above.status, RunStatus::instability);
  EXPECT_EQ(below.critical->contact_radius, 0.0);
  EXPECT_GT(below.critical->cohesive_radius, 0.0);
  EXPECT_GT(above.critical->contact_radius, 0.0);
  const MaugisUnits u;
  EXPECT_NEAR(below.critical->normal_force / u.force(), maugis::fixed_grips_jump(0.9).force, 1e-6);
  EXPECT_NEAR(above.critical->normal_force / u.force(), maugis::fixed_grips_jump(0.98).force, 1e-6);
}

/// A cone of 10 degrees on E* = 1 MPa, dgamma = 0.05 J/m^2, sigma_0 = ratio E* tan(theta).
std::string cone(double ratio, const std::string& normal, double glued) {
  return fmt::format(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\nadhesive_stress = {}\n"
      "[profile]\ntype = \"cone\"\nslope_angle_deg = 10.0\n"
      "[loading]\npreload = {{ contact_radius = {} }}\nnormal = {{ {} }}\n",
      ratio * 1e6 * std::tan(10.0 * kPi / 180.0), glued, normal);
}

// Fixed grips: d(c) = c (tan(theta) - 4 sigma_0/(pi E*)) - h0 once the contact has closed, so the
// cone peels to c -> 0 with no jump below sigma_0/(E* tan(theta)) = pi/4 and jumps above it.
TEST(RunDugdaleContinuum, TheConePeelsSmoothlyBelowPiOverFour) {
  const RunResult smooth = run(cone(0.7, "control = \"fixed-grips\"", 1e-4));
  const RunResult jump = run(cone(0.85, "control = \"fixed-grips\"", 1e-4));
  EXPECT_EQ(smooth.status, RunStatus::no_instability);
  EXPECT_FALSE(smooth.critical);
  ASSERT_TRUE(smooth.peak);
  EXPECT_LT(smooth.peak->normal_force, 0.0);
  EXPECT_EQ(jump.status, RunStatus::instability);
  ASSERT_TRUE(jump.critical);
  // It leaves next to the closing point (the branch's d(a) turns just above a = 0).
  EXPECT_LT(jump.critical->contact_radius, 1e-2 * 1e-4);
}

// Small sigma_0 is DMT: the fixed-load pull-off tends to -pi dgamma^2/(sigma_0 tan^2(theta)), the
// rigid cone's gap reaching h0 at the zone's edge; the relative difference shrinks with sigma_0
// (the zone's own stretch, O(sigma_0/(E* tan(theta)))): below 1e-3 at 1e-4 and 1e-4 at 1e-5.
TEST(RunDugdaleContinuum, TheConesFixedLoadPullOffTendsToDmt) {
  const double tan_theta = std::tan(10.0 * kPi / 180.0);
  double previous = 1.0;
  for (const double ratio : {1e-3, 1e-4, 1e-5}) {
    const double stress = ratio * 1e6 * tan_theta;
    const double limit = -kPi * 0.05 * 0.05 / (stress * tan_theta * tan_theta);
    // Glued well outside the zone's closing radius h0/tan(theta) = dgamma/(sigma_0 tan(theta)).
    const double glued = 10.0 * 0.05 / (stress * tan_theta);
    const RunResult r = run(cone(ratio, "control = \"fixed-load\"", glued));
    ASSERT_EQ(r.status, RunStatus::instability);
    const double difference = std::abs(r.critical->normal_force / limit - 1.0);
    EXPECT_LT(difference, 10.0 * ratio);
    EXPECT_LT(difference, previous);
    previous = difference;
  }
}

// The contact held at a_g while d falls (the pinned phase SPEC describes) meets the contact
// branch where both edge conditions hold: at the branch's depth d(a_g) its c and F are the
// branch's (1e-12: two root searches of the same opening). Above that depth its edge is
// compressive: at the preload depth the springs just outside a_g stretch less than nothing
// (g(a) - d - (2 sigma_0/E*) sqrt(c^2 - a^2) < 0, the surface passes through the indenter), so
// the path does not take it: it starts on the branch at a_p >= a_g, where d(a_p) = d_p.
TEST(RunDugdaleContinuum, TheHeldContactMeetsTheBranchButPassesThroughTheIndenterAbove) {
  const MaugisUnits u;
  const ParabolicProfile parabola(u.radius);
  for (const double lambda : {0.1, 1.0, 10.0}) {
    SCOPED_TRACE(lambda);
    const DugdaleLaw law = u.law(lambda);
    const double a = 3.0 * u.length();
    const DugdaleState branch = dugdale_contact_state(parabola, law, a);
    const DugdaleState held = dugdale_held_state(parabola, law, a, branch.indentation);
    EXPECT_NEAR(held.cohesive_radius / branch.cohesive_radius, 1.0, 1e-12);
    EXPECT_NEAR(held.normal_force / branch.normal_force, 1.0, 1e-12);
    const double preload_depth = parabola.mdr_image(a);
    const DugdaleState pressed = dugdale_held_state(parabola, law, a, preload_depth);
    const double c = pressed.cohesive_radius;
    EXPECT_LT(parabola.mdr_image(a) - preload_depth - law.zone_strain() * std::sqrt(c * c - a * a),
              0.0);
    // The path starts on the branch at the preload depth, with the contact pulled out.
    const DugdalePath path(parabola, law, a, preload_depth);
    EXPECT_NEAR(path.at(0.0).indentation / preload_depth, 1.0, 1e-12);
    EXPECT_GE(path.preload_radius(), a);
    EXPECT_EQ(path.at(1.0).normal_force, branch.normal_force);
  }
}

// The work of the pull-off is int F dd along the path: against the trapezoid sum over 2e5
// states (error ~ 1e-10 of the work's scale, well inside 1e-7).
TEST(RunDugdaleContinuum, ThePullOffWorkIsTheIntegralOfFdd) {
  const MaugisUnits u;
  const RunResult r = run(parabola(1.0, "control = \"fixed-load\""));
  const ParabolicProfile parabola(u.radius);
  const double a = 3.0 * u.length();
  const DugdalePath path(parabola, u.law(1.0), a, parabola.mdr_image(a));
  const auto fold = first_fold(path, {0.0, 1.0});
  ASSERT_TRUE(fold);
  double sum = 0.0;
  DugdaleState before = path.at(0.0);
  const int n = 200000;
  for (int k = 1; k <= n; ++k) {
    const DugdaleState here = path.at(fold->s * k / n);
    sum +=
        0.5 * (here.normal_force + before.normal_force) * (here.indentation - before.indentation);
    before = here;
  }
  ASSERT_EQ(r.stages.size(), 3U);
  EXPECT_NEAR(r.stages[2].work.normal / sum, 1.0, 1e-7);
}

// The JSON: every state carries cohesive_radius; lambda is in dimensionless.
TEST(RunDugdaleContinuum, TheJsonCarriesTheZoneAndLambda) {
  const Scene scene = test::build_scene_text(parabola(1.0, "control = \"fixed-grips\""));
  const RunResult r = run_scene(scene, ObserverList{});
  const auto j = result_to_json(scene, r);
  EXPECT_EQ(j.at("method"), "continuum");
  EXPECT_EQ(j.at("criterion"), "maugis-dugdale");  // the Dugdale law decides the edges
  EXPECT_GT(j.at("critical").at("cohesive_radius").get<double>(), 0.0);
  EXPECT_GT(j.at("peak_adhesion").at("cohesive_radius").get<double>(), 0.0);
  EXPECT_TRUE(j.at("stages").at(0).at("end").contains("cohesive_radius"));
  EXPECT_NEAR(j.at("dimensionless").at("maugis_parameter").get<double>(), 1.0, 1e-14);
  EXPECT_NE(scene.plan.describe(scene).find("material.adhesive_stress"), std::string::npos);
  // The resolved scene builds the same scene again (no criterion, no approach value).
  const Scene again = SceneDocument::from_scene_text(scene.resolved->dump(), "resolved.json")
                          .build(Registries::builtin());
  EXPECT_EQ(again.material.adhesive_stress, scene.material.adhesive_stress);
  EXPECT_EQ(again.plan.engine, RouteEngine::continuum);
}

// A compliant machine folds between the two: its pull-off force lies between the grips' jump
// and the fixed load's (lambda = 1, k = 2 E* a0).
TEST(RunDugdaleContinuum, ACompliantMachineFoldsBetweenGripsAndLoad) {
  const MaugisUnits u;
  const double k = 2.0 * u.modulus * u.length();
  const RunResult load = run(parabola(1.0, "control = \"fixed-load\""));
  const RunResult grips = run(parabola(1.0, "control = \"fixed-grips\""));
  const RunResult compliant =
      run(parabola(1.0, fmt::format("control = \"compliant\", stiffness = {}", k)));
  ASSERT_EQ(compliant.status, RunStatus::instability);
  EXPECT_LT(compliant.critical->normal_force, grips.critical->normal_force);
  EXPECT_GT(compliant.critical->normal_force, load.critical->normal_force);
  EXPECT_TRUE(compliant.accuracy.rtol_met);
}

// The --samples curve is solved as a walk (DugdalePath::states): the same states as path.at one
// at a time, over all four phases (a preload pressed past a_g, so that phase [0, 1] has its own
// radii), within 1e-13 of each quantity's scale on the curve (each solve ends at its root to
// rounding, from whichever start; a few ulps of d, which cancels as the contact lets go).
TEST(RunDugdaleContinuum, TheSampledCurveIsThePathsStatesOneByOne) {
  const MaugisUnits u;
  const ParabolicProfile parabola(u.radius);
  for (const double lambda : {0.3, 1.0, 5.0}) {
    SCOPED_TRACE(lambda);
    const double a = 3.0 * u.length();
    const DugdalePath path(parabola, u.law(lambda), a, 1.2 * parabola.mdr_image(a));
    ASSERT_GT(path.preload_radius(), a);
    std::vector<double> places;
    for (int k = 0; k <= 2000; ++k) places.push_back(DugdalePath::kEnd * k / 2000.0);
    const std::vector<DugdaleState> curve = path.states(places);
    ASSERT_EQ(curve.size(), places.size());
    double depth_scale = 0.0, force_scale = 0.0, radius_scale = 0.0;
    for (const DugdaleState& st : curve) {
      depth_scale = std::max(depth_scale, std::abs(st.indentation));
      force_scale = std::max(force_scale, std::abs(st.normal_force));
      radius_scale = std::max(radius_scale, st.cohesive_radius);
    }
    for (std::size_t k = 0; k < places.size(); ++k) {
      const DugdaleState one = path.at(places[k]);
      EXPECT_NEAR(curve[k].indentation, one.indentation, 1e-13 * depth_scale) << places[k];
      EXPECT_NEAR(curve[k].normal_force, one.normal_force, 1e-13 * force_scale) << places[k];
      EXPECT_NEAR(curve[k].contact_radius, one.contact_radius, 1e-13 * radius_scale) << places[k];
      EXPECT_NEAR(curve[k].cohesive_radius, one.cohesive_radius, 1e-13 * radius_scale) << places[k];
    }
  }
}

/// A parabola that counts its gap integrals J.
class GapCountingParabola final : public Profile {
 public:
  explicit GapCountingParabola(double radius) : parabola_(radius) {}
  double shape(double r) const override { return parabola_.shape(r); }
  double mdr_image(double x) const override { return parabola_.mdr_image(x); }
  double mdr_image_slope(double x) const override { return parabola_.mdr_image_slope(x); }
  double nonadhesive_force_per_modulus(double a) const override {
    return parabola_.nonadhesive_force_per_modulus(a);
  }
  DugdaleGap dugdale_gap(double a, double c, double t) const override {
    ++gaps;
    return parabola_.dugdale_gap(a, c, t);
  }
  mutable int gaps = 0;

 private:
  ParabolicProfile parabola_;
};

// A preload at the glued depth (a_p = a_g): every sample of [0, 1] is the glued state itself, bit
// for bit, and the walk takes no gap integral for them (it solved a_g again from its own root a
// sample, one J each).
TEST(RunDugdaleContinuum, APreloadAtTheGluedDepthSamplesTheGluedStateWithoutSolving) {
  const MaugisUnits u;
  const GapCountingParabola parabola(u.radius);
  const double a = 3.0 * u.length();
  const DugdaleLaw law = u.law(1.0);
  const DugdalePath path(parabola, law, a, dugdale_contact_state(parabola, law, a).indentation);
  ASSERT_EQ(path.preload_radius(), a);
  std::vector<double> places;
  for (int k = 0; k < 500; ++k) places.push_back(k / 500.0);
  parabola.gaps = 0;
  const std::vector<DugdaleState> curve = path.states(places);
  EXPECT_EQ(parabola.gaps, 0);
  const DugdaleState glued = path.at(1.0);
  for (const DugdaleState& st : curve) {
    EXPECT_EQ(st.contact_radius, glued.contact_radius);
    EXPECT_EQ(st.cohesive_radius, glued.cohesive_radius);
    EXPECT_EQ(st.indentation, glued.indentation);
    EXPECT_EQ(st.normal_force, glued.normal_force);
  }
}

}  // namespace
}  // namespace mdrsim
