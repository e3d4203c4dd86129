// Reversible approach-retract loops under fixed grips with a work of adhesion that varies with
// the radius, on the spring row against the independent front tracker
// (engine/reference/radial_front_reference): the crack-front codes' sinusoidal case
// (scenes/programs/crack_front_sinusoid.toml) and a tougher core (a step of dgamma), whose
// receding front pins at the step.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/radial_front_reference.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

/// A parabola of radius R on E*, the same dgamma(r) (`work`, as the scene writes it) advancing
/// and receding, pressed to `deepest` under fixed grips and retracted by up to `retract_by`
/// until it separates.
RunResult loop_on_row(double e_star, double radius, const std::string& work,
                      const std::string& approach_work, double deepest, double retract_by,
                      const std::string& discretization) {
  return run_scene(test::build_scene_text(fmt::format(R"(
[material]
effective_modulus = {}
work_of_adhesion = {}
approach_work_of_adhesion = {}
[profile]
type = "parabolic"
radius = {}
[[loading.stage]]
name = "approach"
normal = {{ control = "fixed-grips", to = {} }}
[[loading.stage]]
name = "retract"
normal = {{ control = "fixed-grips", by = {} }}
until = "separation"
[discretization]
{}
[solver]
method = "event"
)",
                                                      e_star, work, approach_work, radius, deepest,
                                                      retract_by, discretization)),
                   {});
}

RunResult reversible_loop(double e_star, double radius, const std::string& work, double deepest,
                          double retract_by, const std::string& discretization) {
  return loop_on_row(e_star, radius, work, work, deepest, retract_by, discretization);
}

namespace crack_front {

constexpr double kModulus = 0.75, kRadius = 1.0, kWavelength = 0.1, kDeepest = 0.05;
constexpr double kMean = 1.0 / std::numbers::pi;

radial_front_reference::RadialWorkOfAdhesion sinusoid(double mean, double amplitude) {
  const double k = 2.0 * std::numbers::pi / kWavelength;
  return {.value = [=](double r) { return mean * (1.0 + amplitude * std::sin(k * r)); },
          .slope = [=](double r) { return mean * amplitude * k * std::cos(k * r); },
          .finest_scale = kWavelength};
}

radial_front_reference::RadialLoopReference tracked(double amplitude, double deepest = kDeepest) {
  return radial_front_reference::radial_fixed_grips_loop(kModulus, kRadius,
                                                         sinusoid(kMean, amplitude), deepest);
}

std::string sinusoid_text(double mean, double amplitude) {
  return fmt::format("{{ mean = {:.17g}, amplitude = {}, wavelength = {} }}", mean, amplitude,
                     kWavelength);
}

RunResult row(double amplitude, const std::string& discretization, double deepest = kDeepest) {
  const std::string w = fmt::format("{{ mean = {:.17g}, amplitude = {}, wavelength = {} }}", kMean,
                                    amplitude, kWavelength);
  return reversible_loop(kModulus, kRadius, w, deepest, -10.0, discretization);
}

struct Counts {
  std::size_t in = 0, out = 0;
};
Counts jumps_of(const RunResult& r) {
  Counts c;
  for (const JumpRecord& j : r.jumps) (j.inward ? c.in : c.out) += 1;
  return c;
}

// At N = 20000 springs the row's peak tension, loop energy and separation depth lie within
// 3/N of the tracker's (the row's O(1/N), measured below 1/N); with rtol = 1e-6 within 1e-6
// (measured 4e-11 to 3e-9), and the estimates the run reports cover the true error. The jumps
// are the same: the touch and, on the way out, one per wave the front passes (the last is the
// separation).
TEST(CrackFrontLoop, TheRowMatchesTheIndependentFrontTracker) {
  for (const double amplitude : {0.0, 0.1, 0.2}) {
    SCOPED_TRACE(fmt::format("A = {}", amplitude));
    const auto ref = tracked(amplitude);
    const double peak = ref.peak_tension.normal_force;
    const double energy = ref.loop_energy;
    const double separation = ref.separation.indentation;

    const RunResult coarse = row(amplitude, "springs = 20000");
    ASSERT_TRUE(coarse.peak.has_value());
    ASSERT_TRUE(coarse.critical.has_value());
    const double bound = 3.0 / 20000.0;
    EXPECT_NEAR(coarse.peak->normal_force / peak, 1.0, bound);
    EXPECT_NEAR(coarse.work->normal / energy, 1.0, bound);
    EXPECT_NEAR(coarse.critical->indentation / separation, 1.0, bound);
    const Counts counts = jumps_of(coarse);
    EXPECT_EQ(counts.in, ref.jumps_in());
    EXPECT_EQ(counts.out, ref.jumps_out());

    const RunResult fine = row(amplitude, "rtol = 1e-6");
    ASSERT_TRUE(fine.peak.has_value());
    EXPECT_TRUE(fine.accuracy.rtol_met);
    const double peak_error = std::abs(fine.peak->normal_force - peak);
    const double energy_error = std::abs(fine.work->normal - energy);
    EXPECT_LE(peak_error, 1e-6 * std::abs(peak));
    EXPECT_LE(energy_error, 1e-6 * energy);
    ASSERT_TRUE(fine.accuracy.peak_error_estimate.has_value());
    ASSERT_TRUE(fine.accuracy.work_error_estimate.has_value());
    ASSERT_TRUE(coarse.work.has_value() && fine.work.has_value());
    EXPECT_LE(peak_error, *fine.accuracy.peak_error_estimate);
    EXPECT_LE(energy_error, fine.accuracy.work_error_estimate->normal);
    std::printf(
        "A = %.1f: peak tension %.12g (tracker %.12g, error %.1e), loop energy %.12g "
        "(tracker %.12g, error %.1e); at N = 20000: %.1e and %.1e\n",
        amplitude, fine.peak->normal_force, peak, peak_error / std::abs(peak), fine.work->normal,
        energy, energy_error / energy, std::abs(coarse.peak->normal_force / peak - 1.0),
        std::abs(coarse.work->normal / energy - 1.0));
  }
}

// The front advances on half the work it recedes on (dgamma_a = dgamma/2, the same ripple):
// the approach stops at the first passage of its gluing depth through d = 0.05 (a = 1.0661;
// the gluing depth passes it twice more out to 1.146), and the retract holds the front pinned
// there until d(a) comes down to it. The row spans that first radius, so its N-th spring is
// reached; the loop energy at rtol = 1e-6 lies within 1e-6 of the tracker's (whose roots and
// quadrature are good to about 1e-13) and within the run's own estimate, which it missed by
// 5.3e-6 (estimate 7e-8) on a row spanning the third passage.
TEST(CrackFrontLoop, AnApproachOnHalfTheWorkMeetsRtolOnTheLoopEnergy) {
  constexpr double kAmplitude = 0.2;
  const auto ref = radial_front_reference::radial_fixed_grips_loop(
      kModulus, kRadius, sinusoid(kMean, kAmplitude), sinusoid(0.5 * kMean, kAmplitude), kDeepest);
  const auto run = [&](const std::string& discretization) {
    return loop_on_row(kModulus, kRadius, sinusoid_text(kMean, kAmplitude),
                       sinusoid_text(0.5 * kMean, kAmplitude), kDeepest, -10.0, discretization);
  };
  const RunResult coarse = run("springs = 2000");
  ASSERT_FALSE(coarse.stages.empty());
  EXPECT_EQ(coarse.stages[0].end.springs_in_contact, 2000);
  EXPECT_NEAR(coarse.stages[0].end.contact_radius, ref.approach.back().to.contact_radius,
              1e-12 * ref.approach.back().to.contact_radius);

  constexpr double kRtol = 1e-6;
  const RunResult fine = run(fmt::format("rtol = {}", kRtol));
  ASSERT_TRUE(fine.work.has_value());
  ASSERT_TRUE(fine.accuracy.work_error_estimate.has_value());
  EXPECT_TRUE(fine.accuracy.rtol_met);
  const double error = std::abs(fine.work->normal - ref.loop_energy);
  EXPECT_LE(error, kRtol * ref.loop_energy)
      << fine.work->normal << " against the tracker's " << ref.loop_energy;
  EXPECT_LE(error, fine.accuracy.work_error_estimate->normal);
  std::printf("loop energy %.12g (tracker %.12g, error %.1e, estimate %.1e)\n", fine.work->normal,
              ref.loop_energy, error / ref.loop_energy,
              fine.accuracy.work_error_estimate->normal / ref.loop_energy);
}

/// Pressed to d = 0.8 the front crosses three waves on the approach, each a jump in at a local
/// maximum of d(a): the fold of the advancing branch. (At d = 1 a fourth jump lands a few
/// springs inside a_max, where coarse rows' landing states are not yet O(1/N).)
constexpr double kDeepApproach = 0.8;

/// The row's jumps in, less the touch (from no contact), in order.
std::vector<const JumpRecord*> jumps_in_from_contact(const RunResult& r) {
  std::vector<const JumpRecord*> in;
  for (const JumpRecord& j : r.jumps) {
    if (j.inward && j.critical.springs_in_contact > 0) in.push_back(&j);
  }
  return in;
}

/// The tracker's jumps in, less the touch.
std::vector<radial_front_reference::RadialFrontJump> tracked_jumps_in(
    const radial_front_reference::RadialLoopReference& ref) {
  std::vector<radial_front_reference::RadialFrontJump> in;
  for (const auto& j : ref.jumps) {
    if (j.advancing && j.from_radius > 0.0) in.push_back(j);
  }
  return in;
}

/// F = E* (2 a d - 2 a^3 / (3R)) at the front a under d.
double front_force(double a, double d) {
  return kModulus * (2.0 * a * d - 2.0 * a * a * a / (3.0 * kRadius));
}

// Before each jump in the row reports its last equilibrium; located between springs at the fold
// of the advancing branch (the largest gluing depth of a run of single glues) it converges as
// O(1/N) and Richardson takes it to O(1/N^2): at rtol = 1e-6 every such state is within 1e-6 of
// the tracker's local maximum of d(a) (measured 2e-9 to 7e-8 relative in F, 1e-11 in d), and
// each estimate covers its error. The row's plain state sits on the spring before the fold
// (1e-5 to 1e-4 off, an error no extrapolation removes).
TEST(CrackFrontLoop, TheStatesBeforeEachJumpInAreTheTrackersFolds) {
  const auto want = tracked_jumps_in(tracked(0.2, kDeepApproach));
  ASSERT_EQ(want.size(), 3u);
  const RunResult r = row(0.2, "rtol = 1e-6", kDeepApproach);
  const auto got = jumps_in_from_contact(r);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    SCOPED_TRACE(fmt::format("jump in {} at d = {}", i + 1, want[i].indentation));
    const ContactSnapshot& c = got[i]->critical;
    const double force = front_force(want[i].from_radius, want[i].indentation);
    const double error = std::abs(c.normal_force - force);
    EXPECT_LE(error, 1e-6 * std::abs(force));
    ASSERT_TRUE(got[i]->critical_error_estimate.has_value());
    EXPECT_LE(error, *got[i]->critical_error_estimate);
    // d and a at the fold, where d'(a) = 0: d to the force's rtol, a (to which d is
    // insensitive there) to sqrt(rtol) of the wavelength.
    EXPECT_NEAR(c.indentation, want[i].indentation, 1e-6 * std::abs(want[i].indentation));
    EXPECT_NEAR(c.contact_radius, want[i].from_radius, 1e-3 * kWavelength);
  }
}

// The row lands after a jump at its own jump parameter, which misses the fold's by an O(dx^2)
// sawtooth (the fold falls anywhere between springs); located at the fold's parameter instead,
// each landing state converges as O(1/N), and rtol = 1e-6 is met on every jump with rows of up to
// 65536 springs, within 1e-6 of the tracker's landing (measured 5e-11 to 4.2e-8 relative). At
// the row's own parameter the landing states' estimates reached 2.2e-6 relative, and rtol was
// not met with rows of 131072 springs, with a warning.
TEST(CrackFrontLoop, TheStatesAfterEachJumpAreTheTrackersLandings) {
  const auto ref = tracked(0.2, kDeepApproach);
  const RunResult r = row(0.2, "rtol = 1e-6", kDeepApproach);
  EXPECT_TRUE(r.accuracy.rtol_met);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  ASSERT_EQ(r.jumps.size(), ref.jumps.size());
  for (std::size_t i = 0; i < r.jumps.size(); ++i) {
    const auto& want = ref.jumps[i];
    if (want.to_radius == 0.0) continue;  // the separation
    SCOPED_TRACE(fmt::format("jump {} at d = {}", i + 1, want.indentation));
    const JumpRecord& j = r.jumps[i];
    const double force = front_force(want.to_radius, want.indentation);
    const double error = std::abs(j.after.normal_force - force);
    EXPECT_LE(error, 1e-6 * std::abs(force));
    // The estimate (error_estimate.hpp) may fall short where rows agree by chance far below
    // rtol (3.3e-9 against 3.2e-9 N at jump 11): it must cover the error to 1 % of rtol.
    ASSERT_TRUE(j.after_error_estimate.has_value());
    EXPECT_LE(error, *j.after_error_estimate + 1e-8 * std::abs(force));
  }
}

// rtol = 1e-3 is met by rows below 10^4 springs (the jumps' states located between springs,
// every estimate within rtol of its force), and the jump-in states lie within it.
TEST(CrackFrontLoop, RtolOneInAThousandTakesRowsBelowTenThousandSprings) {
  const auto want = tracked_jumps_in(tracked(0.2, kDeepApproach));
  const RunResult r = row(0.2, "rtol = 1e-3", kDeepApproach);
  EXPECT_TRUE(r.accuracy.rtol_met);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  ASSERT_FALSE(r.accuracy.rows.empty());
  EXPECT_LT(r.accuracy.rows.back(), 10000);
  for (const JumpRecord& j : r.jumps) {
    ASSERT_TRUE(j.critical_error_estimate.has_value());
    EXPECT_LE(*j.critical_error_estimate, 1e-3 * std::abs(j.critical.normal_force));
    if (j.end != JumpEnd::state) continue;
    ASSERT_TRUE(j.after_error_estimate.has_value());
    EXPECT_LE(*j.after_error_estimate, 1e-3 * std::abs(j.after.normal_force));
  }
  ASSERT_TRUE(r.work && r.accuracy.work_error_estimate);
  EXPECT_LE(r.accuracy.work_error_estimate->normal, 1e-3 * std::abs(r.work->normal));
  const auto got = jumps_in_from_contact(r);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    const double force = front_force(want[i].from_radius, want[i].indentation);
    EXPECT_NEAR(got[i]->critical.normal_force, force, 1e-3 * std::abs(force));
  }
}

}  // namespace crack_front

namespace tougher_core {

constexpr double kModulus = 1e6, kRadius = 0.01, kStep = 2.5e-4, kInner = 0.2, kOuter = 0.05;
constexpr double kDeepest = 4.8e-6;

radial_front_reference::RadialLoopReference tracked() {
  radial_front_reference::RadialWorkOfAdhesion w{
      .value = [](double r) { return r < kStep ? kInner : kOuter; },
      .slope = [](double) { return 0.0; },
      .finest_scale = kStep,
      .steps = {kStep}};
  return radial_front_reference::radial_fixed_grips_loop(kModulus, kRadius, w, kDeepest);
}

RunResult row(const std::string& discretization) {
  const std::string w =
      fmt::format("{{ r = [0.0, {b}, {b}], value = [{i}, {i}, {o}] }}", fmt::arg("b", kStep),
                  fmt::arg("i", kInner), fmt::arg("o", kOuter));
  return reversible_loop(kModulus, kRadius, w, kDeepest, -1e-3, discretization);
}

// The row's error keeps to O(1/N) but changes sign with where the step falls between two
// springs (the pinned front sits at the last spring inside b): measured +6.9e-5, +1.5e-7 and
// -1.7e-5 at N = 4000, 16000, 64000, within 1.1/N; held to 2/N.
TEST(TougherCoreLoop, TheRowStaysWithinItsFirstOrderBound) {
  const auto ref = tracked();
  const double peak = ref.peak_tension.normal_force;
  const double energy = ref.loop_energy;
  for (const int n : {4000, 16000, 64000}) {
    SCOPED_TRACE(fmt::format("N = {}", n));
    const RunResult r = row(fmt::format("springs = {}", n));
    ASSERT_TRUE(r.peak.has_value() && r.work.has_value() && r.critical.has_value());
    const double bound = 2.0 / n;
    EXPECT_NEAR(r.peak->normal_force / peak, 1.0, bound);
    EXPECT_NEAR(r.work->normal / energy, 1.0, bound);
    EXPECT_NEAR(r.critical->indentation / ref.separation.indentation, 1.0, bound);
    EXPECT_EQ(r.jumps.size(), ref.jumps.size());
  }
}

// Because that error is not smooth in 1/N, the rows of rtol cannot extrapolate it: the run must
// either meet rtol (errors within it) or say it did not, with a warning, and then its own
// estimates must still cover the true errors (measured: not met at 1e-6 with rows up to
// 131072 springs; errors 1.6e-8 N and 1.2e-13 J within estimates 2.4e-7 N and 1.1e-12 J).
TEST(TougherCoreLoop, RtolMeetsItsPromiseOrSaysItCannot) {
  const auto ref = tracked();
  const RunResult r = row("rtol = 1e-6");
  ASSERT_TRUE(r.peak.has_value() && r.work.has_value());
  const double peak_error = std::abs(r.peak->normal_force - ref.peak_tension.normal_force);
  const double energy_error = std::abs(r.work->normal - ref.loop_energy);
  if (r.accuracy.rtol_met) {
    EXPECT_LE(peak_error, 1e-6 * std::abs(ref.peak_tension.normal_force));
    EXPECT_LE(energy_error, 1e-6 * ref.loop_energy);
  } else {
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings.front().find("rtol = 1e-06 not met"), std::string::npos)
        << r.warnings.front();
  }
  ASSERT_TRUE(r.accuracy.peak_error_estimate && r.accuracy.work_error_estimate);
  EXPECT_LE(peak_error, *r.accuracy.peak_error_estimate);
  EXPECT_LE(energy_error, r.accuracy.work_error_estimate->normal);
}

}  // namespace tougher_core

}  // namespace
}  // namespace mdrsim
