// The viscoelastic row against Lee-Radok (loading) and Ting (unloading) from the independent
// reference (tests/support/lee_radok): a parabola pressed at constant speed into a standard
// linear solid and withdrawn at the same speed, the force at several times and the time the
// contact is lost, at two spring counts, the error shrinking as the row refines.
#include "engine/program/viscoelastic_row.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tests/support/lee_radok.hpp"

namespace mdrsim {
namespace {

const test::StandardLinearSolid kSolid{1.0e6, 9.0e6, 0.1};
const test::ParabolaRamp kRamp{0.01, 1.0e-4, 0.2};

// Springs across the largest contact radius sqrt(R V t_m), g(x) = x^2 / R (the parabola's MDR
// image).
ViscoelasticRowSprings parabola_row(std::int64_t n) {
  const double radius = std::sqrt(kRamp.radius * kRamp.speed * kRamp.turn_time);
  ViscoelasticRowSprings springs{
      kSolid.relaxed_modulus, {{kSolid.arm_modulus, kSolid.relaxation_time}}, radius / n, {}};
  for (std::int64_t i = 1; i <= n; ++i) {
    const double x = i == n ? radius : springs.spacing * static_cast<double>(i);
    springs.images.push_back(x * x / kRamp.radius);
  }
  return springs;
}

struct RowErrors {
  double force;       // largest |F - F_ref| / F(t_m) over the samples
  double separation;  // |t_s - t_s,ref| / t_m
};

RowErrors errors_at(std::int64_t n) {
  const double tm = kRamp.turn_time;
  const double separation = test::ting_separation_time(kSolid, kRamp);
  std::vector<double> times;
  for (const double f : {0.1, 0.25, 0.5, 0.75, 1.0}) times.push_back(f * tm);
  for (const double f : {0.1, 0.3, 0.5, 0.7, 0.9}) times.push_back(tm + f * (separation - tm));
  const DriveSegment segments[] = {{tm, kRamp.speed}, {tm, -kRamp.speed}};
  const ViscoelasticRowRun run = run_viscoelastic_row(parabola_row(n), segments, times);
  EXPECT_EQ(run.samples.size(), times.size());
  const double peak = test::lee_radok_force(kSolid, kRamp, tm);
  RowErrors errors{0.0, 0.0};
  for (std::size_t i = 0; i < run.samples.size(); ++i) {
    const ViscoelasticRowSample& s = run.samples[i];
    EXPECT_EQ(s.time, times[i]);
    EXPECT_NEAR(s.depth, kRamp.indentation(times[i]), 1e-15);
    errors.force = std::max(errors.force,
                            std::abs(s.force - test::ting_force(kSolid, kRamp, times[i])) / peak);
  }
  EXPECT_TRUE(run.separation_time.has_value());
  if (run.separation_time) {
    errors.separation = std::abs(*run.separation_time - separation) / tm;
  }
  std::printf(
      "N = %lld: force error %.3e of F(t_m), separation error %.3e of t_m, %lld touches, "
      "%lld releases\n",
      static_cast<long long>(n), errors.force, errors.separation,
      static_cast<long long>(run.touches), static_cast<long long>(run.releases));
  return errors;
}

// Each spring is exact in time (its arms' updates and its release), so what remains is the
// row's sampling of the contact: the force's error falls as 1/N (the edge's cell), the
// separation's faster (the innermost spring's touch at dx^2 / (R V) instead of 0). Tolerances:
// 2 / N of F(t_m) for the force and a fall of at least 3x from N = 100 to 400 (4x at order 1);
// the separation within 1e-3 of t_m and falling too.
TEST(ViscoelasticRow, LeeRadokAndTingAtTwoSpringCounts) {
  const RowErrors coarse = errors_at(100);
  const RowErrors fine = errors_at(400);
  EXPECT_LT(coarse.force, 2.0 / 100);
  EXPECT_LT(fine.force, 2.0 / 400);
  EXPECT_LT(fine.force, coarse.force / 3.0);
  EXPECT_LT(coarse.separation, 1e-3);
  EXPECT_LT(fine.separation, coarse.separation);
}

// An arm far faster than the ramp (tau = 1e-7 s against t_m = 0.2 s) relaxes at once: the row is
// the elastic one of E*_inf, F = 2 dx E*_inf sum over g_i < d of (d - g_i), on loading and on
// unloading alike, every spring touched once and released once, the contact lost at 2 t_m. The
// arm's steady part E_1 V tau adds 9e-6 of a spring's load at these numbers: tolerance 1e-4.
TEST(ViscoelasticRow, FastArmIsTheElasticRow) {
  const double tm = kRamp.turn_time;
  ViscoelasticRowSprings springs = parabola_row(200);
  springs.terms[0].time = 1e-7;
  const DriveSegment segments[] = {{tm, kRamp.speed}, {tm, -kRamp.speed}};
  const std::vector<double> times{0.3 * tm, 0.7 * tm, 1.2 * tm, 1.6 * tm, 1.9 * tm};
  const ViscoelasticRowRun run = run_viscoelastic_row(springs, segments, times);
  ASSERT_EQ(run.samples.size(), times.size());
  for (const ViscoelasticRowSample& s : run.samples) {
    double sum = 0.0;
    for (const double g : springs.images) sum += std::max(0.0, s.depth - g);
    const double elastic = 2.0 * springs.spacing * kSolid.relaxed_modulus * sum;
    EXPECT_NEAR(s.force, elastic, 1e-4 * elastic) << s.time;
  }
  EXPECT_EQ(run.touches, run.releases);
  EXPECT_EQ(run.touches, 199);  // the outermost spring is reached only at t_m, with no load
  ASSERT_TRUE(run.separation_time.has_value());
  EXPECT_NEAR(*run.separation_time, 2.0 * tm - springs.images[0] / kRamp.speed, 1e-5 * tm);
}

// Pressed, withdrawn fast (the outer springs let go, their arms in tension), then held: the free
// springs creep back (retardation time tau E_0 / E_inf = 1 s) and meet the held indenter again,
// and after 50 s everything has relaxed to the elastic row of E*_inf at that depth, every spring
// with g_i < d pressed. The exponentials left are below exp(-50): tolerance 1e-12.
TEST(ViscoelasticRow, FreeSpringsCreepBackUnderAHold) {
  const double tm = kRamp.turn_time;
  const ViscoelasticRowSprings springs = parabola_row(200);
  const DriveSegment segments[] = {
      {tm, kRamp.speed}, {0.05 * tm, -10.0 * kRamp.speed}, {50.0, 0.0}};
  const double end = 1.05 * tm + 50.0;
  const std::vector<double> times{1.05 * tm, end};
  const ViscoelasticRowRun run = run_viscoelastic_row(springs, segments, times);
  ASSERT_EQ(run.samples.size(), 2u);
  const ViscoelasticRowSample& released = run.samples[0];
  const ViscoelasticRowSample& held = run.samples[1];
  std::int64_t inside = 0;
  double sum = 0.0;
  for (const double g : springs.images) {
    if (g < held.depth) {
      ++inside;
      sum += held.depth - g;
    }
  }
  EXPECT_LT(released.pressed, inside);  // the withdrawal let springs go that the hold meets again
  EXPECT_GT(run.releases, 0);
  EXPECT_EQ(held.pressed, inside);
  EXPECT_EQ(run.touches - run.releases, inside);
  const double relaxed = 2.0 * springs.spacing * kSolid.relaxed_modulus * sum;
  EXPECT_NEAR(held.force, relaxed, 1e-12 * relaxed);
}

}  // namespace
}  // namespace mdrsim
