// The crack-front codes' axisymmetric test case on the spring row against the independent front
// tracker (engine/reference/radial_front_reference): a parabola R = 1 on E* = 3/4 with
// w(r) = w0 (1 + A sin(2 pi r / 0.1)), w0 = 1/pi, reversible, pressed to d = 0.05 under fixed
// grips and retracted until it separates (scenes/programs/crack_front_sinusoid.toml).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/radial_front_reference.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

constexpr double kModulus = 0.75, kRadius = 1.0, kWavelength = 0.1, kDeepest = 0.05;
constexpr double kMean = 1.0 / std::numbers::pi;

radial_front_reference::RadialLoopReference tracked(double amplitude) {
  const double k = 2.0 * std::numbers::pi / kWavelength;
  radial_front_reference::RadialWorkOfAdhesion w{
      .value = [=](double r) { return kMean * (1.0 + amplitude * std::sin(k * r)); },
      .slope = [=](double r) { return kMean * amplitude * k * std::cos(k * r); },
      .finest_scale = kWavelength};
  return radial_front_reference::radial_fixed_grips_loop(kModulus, kRadius, w, kDeepest);
}

RunResult row(double amplitude, const std::string& discretization) {
  const std::string w = fmt::format("{{ mean = {:.17g}, amplitude = {}, wavelength = {} }}", kMean,
                                    amplitude, kWavelength);
  return run_scene(
      test::build_scene_text(fmt::format(R"(
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
normal = {{ control = "fixed-grips", by = -10.0 }}
until = "separation"
[discretization]
{}
[solver]
method = "event"
)",
                                         kModulus, w, w, kRadius, kDeepest, discretization)),
      {});
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

}  // namespace
}  // namespace mdrsim
