// The test-side continuum reference against JKR, the paper's eqs. 29-35, the held-force master
// curves, the cone's closed forms, its own laws and a profile with two folds.
#include "engine/reference/continuum_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <utility>

#include "engine/reference/parabolic_reference.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "tests/support/stepped_profile.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::test::ContinuumCritical;
using mdrsim::test::ContinuumMaterial;
using mdrsim::test::ContinuumReference;
using mdrsim::test::DetachmentLaw;
using mdrsim::test::NormalControl;
using mdrsim::test::TangentialLoad;
using Kind = mdrsim::test::ContinuumCritical::Kind;
using LawKind = mdrsim::test::DetachmentLaw::Kind;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.01;          // R [m]
constexpr double kWorkOfAdhesion = 0.05;  // dgamma [J/m^2]

ContinuumMaterial material(double nu) {
  return ContinuumMaterial::from_youngs_modulus(1e6, nu, kWorkOfAdhesion);
}

/// Paper eq. 17, written out here.
struct Scales {
  double force, radius, depth;
};
Scales scales(const ContinuumMaterial& m) {
  const double e = m.effective_modulus, w = m.work_of_adhesion;
  return {1.5 * kPi * kRadius * w, std::cbrt(9.0 * kPi * kRadius * kRadius * w / (8.0 * e)),
          std::cbrt(3.0 * kPi * kPi * kRadius * w * w / (64.0 * e * e))};
}
double gamma_of(const ContinuumMaterial& m) {
  return m.effective_shear_modulus / m.effective_modulus;
}

TangentialLoad held_u(double u) { return {TangentialLoad::Kind::displacement, u}; }
TangentialLoad held_force(double f) { return {TangentialLoad::Kind::force, f}; }

using mdrsim::test::SteppedProfile;

}  // namespace

// JKR: -F0 at a0 under fixed load; -5/9 F0 at a0/9^(1/3) under fixed grips, passing the peak
// -F0 at a0 on the way. The folds are refined to a few ulps of a; 1e-12 covers the rounding of
// the unit conversions and of the slope's cancellation (g' - e').
TEST(ContinuumReference, JkrFixedLoadAndFixedGrips) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  const ContinuumMaterial m = material(0.0);
  const Scales s = scales(m);
  const ContinuumCritical load =
      ContinuumReference(parabola, m, {}, {}, NormalControl::fixed_load()).pull_off(2.0 * s.radius);
  EXPECT_EQ(load.kind, Kind::fold);
  EXPECT_NEAR(load.point.normal_force / s.force, -1.0, 1e-12);
  EXPECT_NEAR(load.point.contact_radius / s.radius, 1.0, 1e-12);
  EXPECT_NEAR(load.point.indentation / s.depth, -1.0, 1e-12);
  EXPECT_NEAR(load.peak_adhesive_force / s.force, -1.0, 1e-12);
  EXPECT_TRUE(load.partial_jumps.empty());

  const ContinuumCritical grips =
      ContinuumReference(parabola, m, {}, {}, NormalControl::fixed_grips())
          .pull_off(2.0 * s.radius);
  EXPECT_EQ(grips.kind, Kind::fold);
  EXPECT_NEAR(grips.point.normal_force / s.force, -5.0 / 9.0, 1e-12);
  EXPECT_NEAR(grips.point.contact_radius / s.radius, std::cbrt(1.0 / 9.0), 1e-12);
  EXPECT_NEAR(grips.peak_adhesive_force / s.force, -1.0, 1e-12);
  EXPECT_NEAR(grips.peak.contact_radius / s.radius, 1.0, 1e-12);
  EXPECT_TRUE(grips.partial_jumps.empty());
}

// Eqs. 29 (fixed load), 31-33 (fixed grips), the compliant fold and the master curve eq. 34,
// for a held tangential displacement at nu = 0 and 0.3. Both sides are refined to full
// precision (they agree to 2e-15); 1e-12 leaves room for the conditioning of eq. 29 near shear-off
// (u = 4).
TEST(ContinuumReference, PapersFoldsWithTangentialDisplacement) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  for (const double nu : {0.0, 0.3}) {
    const ContinuumMaterial m = material(nu);
    const Scales s = scales(m);
    const double gamma = gamma_of(m);
    for (const double u : {0.0, 0.5, 1.0, 2.0, 3.0, 4.0}) {
      SCOPED_TRACE(testing::Message() << "nu = " << nu << ", u/d0 = " << u);
      const auto critical = [&](NormalControl control) {
        return ContinuumReference(parabola, m, {}, held_u(u * s.depth), control)
            .pull_off(3.0 * s.radius);
      };
      const ContinuumCritical grips = critical(NormalControl::fixed_grips());
      const ref::CriticalPoint grips_ref = ref::fixed_grips_critical(u, gamma);
      EXPECT_EQ(grips.kind, Kind::fold);
      EXPECT_NEAR(grips.point.contact_radius / s.radius, grips_ref.contact_radius, 1e-12);
      EXPECT_NEAR(grips.point.normal_force / s.force, grips_ref.normal_force, 1e-12);
      EXPECT_NEAR(grips.point.indentation / s.depth, grips_ref.indentation, 1e-12);
      EXPECT_NEAR(grips.point.normal_force / s.force,
                  ref::fixed_grips_master_curve(grips.point.tangential_force / s.force, gamma),
                  1e-12);

      const ContinuumCritical load = critical(NormalControl::fixed_load());
      const ref::CriticalPoint load_ref = ref::fixed_load_critical(u, gamma);
      EXPECT_EQ(load.kind, Kind::fold);
      EXPECT_NEAR(load.point.contact_radius / s.radius, load_ref.contact_radius, 1e-12);
      EXPECT_NEAR(load.point.normal_force / s.force, load_ref.normal_force, 1e-12);
      EXPECT_NEAR(load.point.tangential_force / s.force, load_ref.tangential_force, 1e-12);

      for (const double k : {0.1, 1.0, 10.0}) {  // k d0/F0
        const ContinuumCritical compliant =
            critical(NormalControl::compliant(k * s.force / s.depth));
        const ref::CriticalPoint compliant_ref = ref::compliant_critical(k, u, gamma);
        EXPECT_EQ(compliant.kind, Kind::fold);
        EXPECT_NEAR(compliant.point.normal_force / s.force, compliant_ref.normal_force, 1e-12);
        EXPECT_NEAR(compliant.point.contact_radius / s.radius, compliant_ref.contact_radius, 1e-12);
      }
    }
  }
}

// The held-force master curves: F/F0 = q/4 - 1 (fixed load) and the cubic of
// engine/reference/parabolic_reference (fixed grips), q = (F_x/F0)^2 E*/G*. 1e-12 as above.
TEST(ContinuumReference, HeldTangentialForceMasterCurves) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  for (const double nu : {0.0, 0.3}) {
    const ContinuumMaterial m = material(nu);
    const Scales s = scales(m);
    const double gamma = gamma_of(m);
    for (const double fx : {0.25, 1.0, 2.0, 4.0}) {
      SCOPED_TRACE(testing::Message() << "nu = " << nu << ", Fx/F0 = " << fx);
      const auto critical = [&](NormalControl control) {
        return ContinuumReference(parabola, m, {}, held_force(fx * s.force), control)
            .pull_off(3.0 * s.radius);
      };
      const double q = fx * fx / gamma;
      const ContinuumCritical load = critical(NormalControl::fixed_load());
      EXPECT_EQ(load.kind, Kind::fold);
      EXPECT_NEAR(load.point.normal_force / s.force, q / 4.0 - 1.0, 1e-12);
      EXPECT_NEAR(load.point.contact_radius / s.radius, std::cbrt(1.0 + q / 4.0), 1e-12);
      EXPECT_NEAR(load.point.tangential_force / s.force, fx, 1e-12);

      const ContinuumCritical grips = critical(NormalControl::fixed_grips());
      const ref::CriticalPoint grips_ref = ref::fixed_grips_critical_at_tangential_force(fx, gamma);
      EXPECT_EQ(grips.kind, Kind::fold);
      EXPECT_NEAR(grips.point.normal_force / s.force, grips_ref.normal_force, 1e-12);
      EXPECT_NEAR(grips.point.contact_radius / s.radius, grips_ref.contact_radius, 1e-12);
    }
  }
}

// The cone (scenes/cone_fixed_load.toml): with k = (pi/2) tan(theta), w = 2 pi dgamma/E*,
// fixed load folds at a = 9 w/(4 k^2), F = -54 dgamma^2/(pi E* tan^3), fixed grips at
// a = w/(4 k^2), F = -6 dgamma^2/(pi E* tan^3). At 60 degrees glued at 0.1 mm the fixed-grips
// fold sits at 1.06e-4 of the glued radius: the log scan must find it. 1e-12 relative: folds
// refined to a few ulps, closed forms evaluated directly.
TEST(ContinuumReference, ConeClosedForms) {
  const ContinuumMaterial m = material(0.0);
  const double e = m.effective_modulus, dg = m.work_of_adhesion;
  const double w = 2.0 * kPi * dg / e;
  for (const auto& [theta, glued] : {std::pair{10.0, 2e-5}, std::pair{60.0, 1e-4}}) {
    SCOPED_TRACE(testing::Message() << "theta = " << theta);
    const mdrsim::ConeProfile cone(theta);
    const double t = std::tan(theta * kPi / 180.0);
    const double k = 0.5 * kPi * t;
    const ContinuumCritical load =
        ContinuumReference(cone, m, {}, {}, NormalControl::fixed_load()).pull_off(glued);
    const ContinuumCritical grips =
        ContinuumReference(cone, m, {}, {}, NormalControl::fixed_grips()).pull_off(glued);
    const double load_force = -54.0 * dg * dg / (kPi * e * t * t * t);
    const double grips_force = -6.0 * dg * dg / (kPi * e * t * t * t);
    EXPECT_EQ(load.kind, Kind::fold);
    EXPECT_EQ(grips.kind, Kind::fold);
    EXPECT_NEAR(load.point.normal_force / load_force, 1.0, 1e-12);
    EXPECT_NEAR(load.point.contact_radius / (9.0 * w / (4.0 * k * k)), 1.0, 1e-12);
    EXPECT_NEAR(grips.point.normal_force / grips_force, 1.0, 1e-12);
    EXPECT_NEAR(grips.point.contact_radius / (w / (4.0 * k * k)), 1.0, 1e-12);
    if (theta == 60.0) {
      EXPECT_LT(grips.point.contact_radius, 1.1e-4 * glued);
    }
  }
}

// the docs' inequalities, written here once more (mode-dependent with tan, as in the table):
// the stretch is where each law's margin crosses zero, to 1e-12 of W (the stretch is solved
// in closed form or to a few ulps of the phase angle), holding just below and letting go
// just above. nu = 0.3, so that the mode-mixed, deformation and stress laws differ.
TEST(ContinuumReference, StretchIsWhereTheLawLetsGo) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  const ContinuumMaterial m = material(0.3);
  const Scales s = scales(m);
  const double es = m.effective_modulus, gs = m.effective_shear_modulus;
  const auto spec_holds_by = [&](const DetachmentLaw& law, double e, double ux, double a) {
    const double w = 2.0 * kPi * a * m.work_of_adhesion;
    switch (law.kind) {
      case LawKind::mode_mixed:
        return w - (es * e * e + gs * ux * ux);
      case LawKind::deformation: {
        const double dl = std::sqrt(w / es);
        return es * (dl * dl - (e * e + ux * ux));
      }
      case LawKind::stress: {
        const double limit = es * std::sqrt(w / es);
        return (limit * limit - (es * e * es * e + gs * ux * gs * ux)) / es;
      }
      case LawKind::normal_only:
        return w - es * e * e;
      case LawKind::mode_dependent: {
        const double tan_psi = std::sqrt(gs / es) * ux / e;
        const double x = std::tan((1.0 - law.lambda) * std::atan(tan_psi));
        return w * (1.0 + x * x) - (es * e * e + gs * ux * ux);
      }
    }
    return 0.0;
  };
  const std::initializer_list<DetachmentLaw> laws = {{LawKind::mode_mixed},
                                                     {LawKind::deformation},
                                                     {LawKind::stress},
                                                     {LawKind::normal_only},
                                                     {LawKind::mode_dependent, 0.0},
                                                     {LawKind::mode_dependent, 0.3},
                                                     {LawKind::mode_dependent, 0.8},
                                                     {LawKind::mode_dependent, 1.0}};
  for (const DetachmentLaw& law : laws) {
    for (const double u : {0.0, 0.5, 2.0}) {
      const ContinuumReference branch(parabola, m, law, held_u(u * s.depth),
                                      NormalControl::fixed_grips());
      for (const double a : {0.7, 1.0, 2.5}) {
        SCOPED_TRACE(testing::Message() << "law " << static_cast<int>(law.kind) << " lambda "
                                        << law.lambda << ", u/d0 = " << u << ", a/a0 = " << a);
        const double radius = a * s.radius;
        if (!(radius > branch.shear_off_radius())) continue;
        const double e = branch.stretch(radius), ux = u * s.depth;
        const double w = 2.0 * kPi * radius * m.work_of_adhesion;
        ASSERT_GT(e, 0.0);
        EXPECT_NEAR(spec_holds_by(law, e, ux, radius) / w, 0.0, 1e-12);
        EXPECT_NEAR(mdrsim::test::law_margin(law, m, e, ux, radius) / w, 0.0, 1e-12);
        EXPECT_GT(spec_holds_by(law, 0.999 * e, ux, radius), 0.0);
        EXPECT_LT(spec_holds_by(law, 1.001 * e, ux, radius), 0.0);
        // The analytic slope against a central difference (step 1e-5 a: truncation and
        // rounding both near 1e-9 of the slope).
        const double h = 1e-5 * radius;
        const double difference =
            (branch.stretch(radius + h) - branch.stretch(radius - h)) / (2 * h);
        EXPECT_NEAR(branch.stretch_slope(radius) / difference, 1.0, 1e-7);
      }
    }
  }
}

// lambda = 1 is the mode-mixed law and lambda = 0 the normal-only one (docs: the tan term
// vanishes, or takes psi whole): the mode-dependent root search must give their closed-form
// critical points, for every tangential hold and normal control, to 1e-12.
TEST(ContinuumReference, ModeDependentEndsAreModeMixedAndNormalOnly) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  const ContinuumMaterial m = material(0.3);
  const Scales s = scales(m);
  const TangentialLoad holds[] = {{}, held_u(2.0 * s.depth), held_force(1.0 * s.force)};
  const NormalControl controls[] = {NormalControl::fixed_grips(), NormalControl::fixed_load(),
                                    NormalControl::compliant(s.force / s.depth)};
  const std::pair<double, LawKind> ends[] = {{1.0, LawKind::mode_mixed},
                                             {0.0, LawKind::normal_only}};
  for (const auto& [lambda, closed] : ends) {
    for (const TangentialLoad& hold : holds) {
      for (const NormalControl& control : controls) {
        SCOPED_TRACE(testing::Message()
                     << "lambda " << lambda << ", hold " << static_cast<int>(hold.kind) << ", a_F "
                     << control.force_coefficient);
        const ContinuumReference dependent(parabola, m, {LawKind::mode_dependent, lambda}, hold,
                                           control);
        const ContinuumReference closed_form(parabola, m, {closed}, hold, control);
        EXPECT_NEAR(dependent.shear_off_radius(), closed_form.shear_off_radius(), 1e-14 * s.radius);
        for (const double a : {0.8, 1.5, 3.0}) {
          EXPECT_NEAR(dependent.stretch(a * s.radius) / closed_form.stretch(a * s.radius), 1.0,
                      1e-12);
        }
        const ContinuumCritical x = dependent.pull_off(3.0 * s.radius);
        const ContinuumCritical y = closed_form.pull_off(3.0 * s.radius);
        EXPECT_EQ(x.kind, y.kind);
        EXPECT_NEAR(x.point.normal_force / y.point.normal_force, 1.0, 1e-12);
        EXPECT_NEAR(x.point.contact_radius / y.point.contact_radius, 1.0, 1e-12);
      }
    }
  }
}

// The glue at a_g breaks as the load is applied when c u^2 >= 2 pi a_g dgamma; its strength
// is then 2 G* a_g u_max: sqrt(8 pi G* a_g^3 dgamma) for mode-mixed (docs/model.md), and
// 2 G* a_g dl(a_g) for the deformation law. Normal-only never shears off.
TEST(ContinuumReference, ShearOffAtApplication) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  const ContinuumMaterial m = material(0.3);
  const Scales s = scales(m);
  const double ag = s.radius, dg = m.work_of_adhesion, gs = m.effective_shear_modulus;
  const double u = 5.0 * s.depth;  // a_s = (G*/E*) u^2/16 a0 = 1.29 a0 for mode-mixed
  const ContinuumCritical mixed =
      ContinuumReference(parabola, m, {}, held_u(u), NormalControl::fixed_load()).pull_off(ag);
  EXPECT_EQ(mixed.kind, Kind::shear_off_at_application);
  EXPECT_NEAR(mixed.tangential_strength / std::sqrt(8.0 * kPi * gs * ag * ag * ag * dg), 1.0,
              1e-14);
  EXPECT_NEAR(mixed.point.indentation, parabola.mdr_image(ag), 1e-14 * s.depth);

  const ContinuumCritical deformation = ContinuumReference(parabola, m, {LawKind::deformation},
                                                           held_u(u), NormalControl::fixed_load())
                                            .pull_off(ag);
  EXPECT_EQ(deformation.kind, Kind::shear_off_at_application);
  const double dl = std::sqrt(2.0 * kPi * ag * dg / m.effective_modulus);
  EXPECT_NEAR(deformation.tangential_strength / (2.0 * gs * ag * dl), 1.0, 1e-14);

  const ContinuumCritical normal_only = ContinuumReference(parabola, m, {LawKind::normal_only},
                                                           held_u(u), NormalControl::fixed_load())
                                            .pull_off(2.0 * ag);
  EXPECT_EQ(normal_only.kind, Kind::fold);
  EXPECT_NEAR(normal_only.point.normal_force / s.force, -1.0, 1e-12);
}

// Mode-dependent with lambda < 1 has a finite stretch slope where e reaches 0: near a_s,
// sigma cos(mu (pi/2 - delta)) = omega cos(delta) gives delta = omega' (a - a_s) /
// (sigma mu sin(mu pi/2)), so e' -> sqrt(w/a_s) / (2 mu sin(mu pi/2)). With a_s = 2 a0 on
// the parabola that is below g'(a_s) = 2 a_s/R: under fixed grips the branch stays stable
// down to a_s and the contact shears off there, in the unstretched state d = a_s^2/R,
// F = 4 E* a_s^3/(3R).
TEST(ContinuumReference, ModeDependentShearsOffDuringThePullOff) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  const ContinuumMaterial m = material(0.0);
  const Scales s = scales(m);
  const double lambda = 0.5, mu = 1.0 - lambda;
  const double as = 2.0 * s.radius;
  const double c = m.effective_shear_modulus * std::pow(std::cos(mu * 0.5 * kPi), 2);
  const double u = std::sqrt(2.0 * kPi * as * m.work_of_adhesion / c);
  const ContinuumReference branch(parabola, m, {LawKind::mode_dependent, lambda}, held_u(u),
                                  NormalControl::fixed_grips());
  EXPECT_NEAR(branch.shear_off_radius() / as, 1.0, 1e-14);
  const double w = 2.0 * kPi * m.work_of_adhesion / m.effective_modulus;
  // 1e-6: the slope at a_s (1 + 1e-9) differs from its limit by O(1e-9) relative, and the
  // stretch there is solved from a residual that cancels to 1e-9 of sigma.
  EXPECT_NEAR(branch.stretch_slope(as * (1.0 + 1e-9)) /
                  (std::sqrt(w / as) / (2.0 * mu * std::sin(mu * 0.5 * kPi))),
              1.0, 1e-6);
  const ContinuumCritical critical = branch.pull_off(3.0 * s.radius);
  EXPECT_EQ(critical.kind, Kind::shear_off);
  EXPECT_NEAR(critical.point.contact_radius / as, 1.0, 1e-14);
  EXPECT_EQ(critical.point.stretch, 0.0);
  EXPECT_NEAR(critical.point.indentation / (as * as / kRadius), 1.0, 1e-14);
  EXPECT_NEAR(
      critical.point.normal_force / (4.0 * m.effective_modulus * as * as * as / (3.0 * kRadius)),
      1.0, 1e-13);
}

// Glued inside the fold (below a0/9^(1/3) under fixed grips, below a0 under fixed load), the
// first let-go at a_g already empties the contact.
TEST(ContinuumReference, GluedInsideTheFoldJumpsAtOnce) {
  const mdrsim::ParabolicProfile parabola(kRadius);
  const ContinuumMaterial m = material(0.0);
  const Scales s = scales(m);
  const ContinuumCritical grips =
      ContinuumReference(parabola, m, {}, {}, NormalControl::fixed_grips())
          .pull_off(0.3 * s.radius);
  EXPECT_EQ(grips.kind, Kind::first_detachment);
  EXPECT_EQ(grips.point.contact_radius, 0.3 * s.radius);
  const ContinuumCritical load =
      ContinuumReference(parabola, m, {}, {}, NormalControl::fixed_load()).pull_off(0.9 * s.radius);
  EXPECT_EQ(load.kind, Kind::first_detachment);
  EXPECT_NEAR(load.point.normal_force / s.force, 0.729 - 2.0 * std::pow(0.9, 1.5), 1e-12);
}

// f = 0.01 r^0.5 (c in m^0.5): g = kappa c sqrt(x) grows like the Hess stretch sqrt(w x) and
// 40 times faster, so d and F rise with a everywhere: no fold, the contact peels off smoothly.
TEST(ContinuumReference, SquareRootPowerLawPeelsSmoothly) {
  const mdrsim::PowerLawProfile root(0.01, 0.5);
  const ContinuumMaterial m = material(0.0);
  for (const NormalControl control : {NormalControl::fixed_grips(), NormalControl::fixed_load()}) {
    const ContinuumCritical c =
        ContinuumReference(root, m, {LawKind::normal_only}, {}, control).pull_off(1e-3);
    EXPECT_EQ(c.kind, Kind::none);
  }
}

// Two folds: the tip's A tanh(x/s) (a cone of slope A/s) and the parabola. With A = 3 um the
// parabola's fold is the lower one and ends the pull-off. With A = 6 um the parabola's fold
// sits above d = 0: its jump lands on the tip's branch where d falls back to the fold's value,
// and the pull-off ends at the tip's fold. Checked against a brute-force scan of d(a) (200000
// log-spaced radii: the minimum value to 1e-8 relative, its radius to 1e-4).
TEST(ContinuumReference, PartialJumpLandsOnTheTipsBranch) {
  const ContinuumMaterial m = material(0.0);
  const double glued = 3e-4;
  const auto brute_min = [](const ContinuumReference& branch, double lo, double hi) {
    std::pair<double, double> best{INFINITY, 0.0};
    for (int k = 0; k <= 200000; ++k) {
      const double a = hi * std::pow(lo / hi, k / 200000.0);
      const double d = branch.at(a).indentation;
      if (d < best.first) best = {d, a};
    }
    return best;
  };
  {
    const SteppedProfile profile(3e-6, 1e-5, kRadius);
    const ContinuumReference branch(profile, m, {}, {}, NormalControl::fixed_grips());
    const ContinuumCritical c = branch.pull_off(glued);
    EXPECT_EQ(c.kind, Kind::fold);
    EXPECT_TRUE(c.partial_jumps.empty());
    const auto [d, a] = brute_min(branch, 1e-5, glued);
    EXPECT_NEAR(c.point.indentation / d, 1.0, 1e-8);
    EXPECT_NEAR(c.point.contact_radius / a, 1.0, 1e-4);
  }
  {
    const SteppedProfile profile(6e-6, 1e-5, kRadius);
    const ContinuumReference branch(profile, m, {}, {}, NormalControl::fixed_grips());
    const ContinuumCritical c = branch.pull_off(glued);
    EXPECT_EQ(c.kind, Kind::fold);
    ASSERT_EQ(c.partial_jumps.size(), 1u);
    const auto& jump = c.partial_jumps.front();
    const auto [outer_d, outer_a] = brute_min(branch, 1e-5, glued);
    EXPECT_NEAR(jump.from.indentation / outer_d, 1.0, 1e-8);
    EXPECT_NEAR(jump.from.contact_radius / outer_a, 1.0, 1e-4);
    EXPECT_GT(jump.from.indentation, 0.0);
    EXPECT_NEAR(jump.to.control_value / jump.from.control_value, 1.0, 1e-12);
    EXPECT_LT(jump.to.contact_radius, 1e-5);
    EXPECT_GT(branch.control_slope(jump.to.contact_radius), 0.0);
    const auto [tip_d, tip_a] = brute_min(branch, 1e-9, 1e-5);
    EXPECT_NEAR(c.point.indentation / tip_d, 1.0, 1e-8);
    EXPECT_NEAR(c.point.contact_radius / tip_a, 1.0, 1e-4);
    // d' = g' - e' = 0 at the fold, to rounding against either term.
    EXPECT_NEAR(
        branch.control_slope(c.point.contact_radius) / branch.stretch_slope(c.point.contact_radius),
        0.0, 1e-12);
    // The peak is on the parabola's branch, before the jump.
    EXPECT_GT(c.peak.contact_radius, jump.from.contact_radius);
  }
}
