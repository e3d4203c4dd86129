// The tabulated profile: exact on polynomial tables, converging on others, eq. 4 and eq. 5 round
// trip, monotone image, table checks and the CSV reader.
#include "profiles/tabulated_profile.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "profiles/mdr_transform.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "tests/support/expect_throw_msg.hpp"
#include "tests/support/run_command.hpp"

using mdrsim::ProfileTable;
using mdrsim::TabulatedProfile;

namespace {

/// points r_k = r_max (k/(n-1))^grading, k = 0..n-1, of f.
ProfileTable table_of(const std::function<double(double)>& f, int n, double r_max,
                      double grading = 1.0) {
  ProfileTable t;
  for (int k = 0; k < n; ++k) {
    const double r = r_max * std::pow(static_cast<double>(k) / (n - 1), grading);
    t.radii.push_back(r);
    t.gaps.push_back(f(r));
  }
  return t;
}

/// Largest |g_table/g - 1| over 500 points of [from, to].
double worst_relative_image_error(const TabulatedProfile& table, const mdrsim::Profile& exact,
                                  double from, double to) {
  double worst = 0.0;
  for (int i = 0; i <= 500; ++i) {
    const double x = from + (to - from) * i / 500.0;
    worst = std::max(worst, std::abs(table.mdr_image(x) / exact.mdr_image(x) - 1.0));
  }
  return worst;
}

}  // namespace

// The cubic through the points of a parabola or a cone is the shape itself, so the image is
// x^2/R or (pi/2) tan(theta) x to rounding: 1e-13 relative, everywhere from 1e-3 of the table.
TEST(TabulatedProfile, PolynomialTablesAreExact) {
  const double radius = 0.01;
  const TabulatedProfile parabola(
      table_of([&](double r) { return r * r / (2 * radius); }, 11, 1e-3));
  const TabulatedProfile cone(table_of([](double r) { return 0.25 * r; }, 7, 1e-3));
  for (int i = 1; i <= 1000; ++i) {
    const double x = 1e-3 * i / 1000.0;
    EXPECT_NEAR(parabola.mdr_image(x), x * x / radius, 1e-13 * x * x / radius) << x;
    EXPECT_NEAR(parabola.mdr_image_slope(x), 2 * x / radius, 1e-12 * 2 * x / radius) << x;
    EXPECT_NEAR(parabola.nonadhesive_force_per_modulus(x), 4 * x * x * x / (3 * radius),
                1e-12 * x * x * x / radius);
    EXPECT_NEAR(cone.mdr_image(x), M_PI / 2 * 0.25 * x, 1e-13 * x) << x;
  }
  EXPECT_NEAR(parabola.contact_radius_at_depth(1e-5), std::sqrt(radius * 1e-5), 1e-13);
  EXPECT_FALSE(parabola.jkr_scale_radius().has_value());
  EXPECT_EQ(parabola.outer_radius(), 1e-3);
}

// A sphere's table (uniform) and a power law's (graded to the tip, where f'' = c n (n-1)
// r^(n-2) is singular): the image converges to the closed form as the table is refined;
// measured errors over the outer 90 % of the table are 8e-7 and 4e-10 (sphere, 201 and
// 2001 points; at 2001 the image grid takes every second point) and 7e-9 (r^1.5, 201
// graded points). The bounds below are 3x those.
TEST(TabulatedProfile, SmoothTablesConvergeToTheirClosedForms) {
  const mdrsim::SphereProfile sphere(0.01);
  const auto cap = [&](double r) { return sphere.shape(r); };
  EXPECT_LT(
      worst_relative_image_error(TabulatedProfile(table_of(cap, 201, 9e-3)), sphere, 9e-4, 9e-3),
      2.5e-6);
  EXPECT_LT(
      worst_relative_image_error(TabulatedProfile(table_of(cap, 2001, 9e-3)), sphere, 9e-4, 9e-3),
      1.2e-9);
  const mdrsim::PowerLawProfile power(0.8, 1.5);
  const TabulatedProfile graded(table_of([&](double r) { return power.shape(r); }, 201, 1e-3, 2.0));
  EXPECT_LT(worst_relative_image_error(graded, power, 1e-4, 1e-3), 2e-8);
}

// Two independent quadratures of eq. 4 on the same interpolated shape: Gauss-Legendre after
// r = x sin t (the profile's) and tanh-sinh on the singular form (mdr_transform), split at
// the table's points where f'' has its kinks.
TEST(TabulatedProfile, ImageIsEquationFourOfTheInterpolatedShape) {
  const mdrsim::SphereProfile sphere(0.01);
  const TabulatedProfile table(table_of([&](double r) { return sphere.shape(r); }, 101, 9e-3));
  for (const double x : {1e-4, 2.34e-3, 9e-3}) {
    const double by_tanh_sinh =
        mdrsim::mdr_transform([&](double r) { return table.interpolated_shape().slope(r); }, x);
    EXPECT_NEAR(table.transform(x).image, by_tanh_sinh, 1e-12 * by_tanh_sinh) << x;
    // And the grid's Hermite interpolant agrees with the direct transform between nodes.
    EXPECT_NEAR(table.mdr_image(x), table.transform(x).image, 1e-12 * by_tanh_sinh) << x;
  }
  // The slope integral against a central difference of the transform (1e-9: the difference's
  // own error with step 1e-5 x).
  const double x = 4.321e-3, h = 1e-5 * x;
  EXPECT_NEAR(table.transform(x).slope,
              (table.transform(x + h).image - table.transform(x - h).image) / (2 * h),
              1e-9 * table.transform(x).slope);
}

// Eq. 5 on the tabulated image gives back the table: f -> g -> f, at the points and between
// them. g is not smooth at the table's points (f'' jumps there), so eq. 5 is split at them;
// measured 1e-12 (3e-8 without the split), bound 1e-11.
TEST(TabulatedProfile, RoundTripRecoversTheShape) {
  const mdrsim::SphereProfile sphere(1e-3);
  const ProfileTable t = table_of([&](double r) { return sphere.shape(r); }, 41, 8e-4);
  const TabulatedProfile table(t);
  for (std::size_t k = 1; k < t.radii.size(); k += 7) {
    for (const double r : {t.radii[k], t.radii[k] - 7e-6}) {
      const double f = table.shape(r);
      const double back =
          mdrsim::inverse_mdr_transform([&](double x) { return table.mdr_image(x); }, r, t.radii);
      EXPECT_NEAR(back, f, 1e-11 * f) << "r = " << r;
    }
  }
  EXPECT_EQ(table.shape(t.radii[5]), t.gaps[5]);
}

// A rounded punch: flat face (g = 0) up to 0.2 mm, then a rising rim. The image stays
// non-decreasing through the flat part and the rise.
TEST(TabulatedProfile, ImageNeverDecreases) {
  const auto rounded = [](double r) { return r < 2e-4 ? 0.0 : (r - 2e-4) * (r - 2e-4) / 2e-4; };
  const TabulatedProfile table(table_of(rounded, 31, 6e-4));
  double last = 0.0;
  for (int i = 0; i <= 6000; ++i) {
    const double g = table.mdr_image(6e-4 * i / 6000.0);
    EXPECT_GE(g, last);
    last = g;
  }
  EXPECT_EQ(table.mdr_image(1.9e-4), 0.0);
  EXPECT_GT(table.mdr_image(3e-4), 0.0);
}

// A cone capped by a plateau: for x beyond the cap g(x) = x tan(theta) arcsin(r_c/x) falls
// (r f' drops to 0), and the table is accepted (a front jumps over such a dip). Its image is
// eq. 4 of its own curve: against the tanh-sinh transform of the curve's slope (an
// independent quadrature) to 1e-9 of g's scale, and it falls beyond the cap.
TEST(TabulatedProfile, AcceptsAnImageThatDecreases) {
  ProfileTable t;
  t.radii = {0, 1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 6e-4, 8e-4, 1e-3};
  t.gaps = {0, 1e-4, 2e-4, 3e-4, 4e-4, 4e-4, 4e-4, 4e-4, 4e-4};
  const TabulatedProfile table{t};
  const auto slope = [&](double r) {
    const double h = 1e-7 * std::max(r, 1e-9);
    return (table.shape(r + h) - table.shape(std::max(r - h, 0.0))) /
           (r + h - std::max(r - h, 0.0));
  };
  for (const double x : {1.5e-4, 3.7e-4, 6e-4, 9.9e-4}) {
    SCOPED_TRACE(x);
    EXPECT_NEAR(table.mdr_image(x), mdrsim::mdr_transform(slope, x, t.radii), 1e-9 * 4e-4);
  }
  EXPECT_LT(table.mdr_image(9.9e-4), table.mdr_image(5e-4));
}

// A dimple: f rises, falls back and rises again; accepted, its curve through every point.
TEST(TabulatedProfile, AcceptsAGapThatDecreases) {
  ProfileTable t;
  t.radii = {0, 1e-4, 2e-4, 3e-4, 4e-4, 5e-4};
  t.gaps = {0, 2e-6, 1e-6, 3e-6, 8e-6, 1.5e-5};
  const TabulatedProfile table{t};
  // Through every point (the end of a piece rounds: 1e-12 of the largest gap).
  for (std::size_t i = 0; i < t.radii.size(); ++i) {
    EXPECT_NEAR(table.shape(t.radii[i]), t.gaps[i], 1e-12 * 1.5e-5);
  }
  EXPECT_LT(table.shape(1.5e-4), 2e-6);  // between the crest and the dip, no overshoot
}

// The disk check is skipped where the interpolated shape's r f'(r) never falls (then g' >= 0:
// Profile::proves_one_disk). Convex tables rising from the tip prove it, and so does a cone's
// table, whose second differences are rounding of either sign; a cone capped by a plateau does
// not (its image falls), nor a sphere's table with one point raised into a concave one, nor
// r^0.5's, whose spline rings near the singular tip.
TEST(TabulatedProfile, ProvesOneDiskWhereRSlopeNeverFalls) {
  const auto sphere = [](double r) { return 0.01 - std::sqrt(0.01 * 0.01 - r * r); };
  EXPECT_TRUE(TabulatedProfile(table_of(sphere, 200, 6e-3)).proves_one_disk());
  EXPECT_TRUE(TabulatedProfile(table_of([](double r) { return r * r / 0.02; }, 11, 1e-3))
                  .proves_one_disk());
  const double slope = std::tan(10.0 * std::numbers::pi / 180.0);
  EXPECT_TRUE(
      TabulatedProfile(table_of([&](double r) { return slope * r; }, 51, 5e-5)).proves_one_disk());
  EXPECT_TRUE(
      TabulatedProfile(table_of([](double r) { return 0.8 * std::pow(r, 1.5); }, 201, 1e-3, 2.0))
          .proves_one_disk());

  ProfileTable capped;
  capped.radii = {0, 1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 6e-4, 8e-4, 1e-3};
  capped.gaps = {0, 1e-4, 2e-4, 3e-4, 4e-4, 4e-4, 4e-4, 4e-4, 4e-4};
  EXPECT_FALSE(TabulatedProfile(capped).proves_one_disk());

  ProfileTable bumped = table_of(sphere, 200, 6e-3);
  const auto second_difference = [&](std::size_t i) {
    return bumped.gaps[i + 1] - 2.0 * bumped.gaps[i] + bumped.gaps[i - 1];
  };
  bumped.gaps[60] += 5.0 * second_difference(60);
  int concave = 0;
  for (std::size_t i = 1; i + 1 < bumped.gaps.size(); ++i) concave += second_difference(i) < 0.0;
  EXPECT_EQ(concave, 1);
  EXPECT_FALSE(TabulatedProfile(bumped).proves_one_disk());

  EXPECT_FALSE(TabulatedProfile(table_of([](double r) { return 1e-2 * std::sqrt(r); }, 101, 1e-3))
                   .proves_one_disk());
}

// The springs' stored energy per E*, int_0^a (d - g)^2 dx, exact on the image's pieces: on a
// parabola's table (g = x^2/R to 1e-13, PolynomialTablesAreExact) against
// d^2 a - 2 d a^3 / (3 R) + a^5 / (5 R^2), to 1e-12 (the image's error, and the closed form's
// own cancellation of a few ulps), pressed (d > g(a)) and stretched (d < g(a)), a at a knot
// and between knots.
TEST(TabulatedProfile, SquaredGapIntegralIsExactOnTheImage) {
  constexpr double kR = 0.01;
  const TabulatedProfile table(table_of([](double r) { return r * r / (2.0 * kR); }, 11, 1e-3));
  for (const double a : {1e-4, 3.3e-4, 7e-4, 1e-3}) {
    for (const double d : {2.0 * a * a / kR, a * a / kR, 0.2 * a * a / kR}) {
      SCOPED_TRACE(fmt::format("a {} d {}", a, d));
      const double exact =
          d * d * a - 2.0 * d * a * a * a / (3.0 * kR) + std::pow(a, 5) / (5.0 * kR * kR);
      const auto i = table.squared_gap_integral(a, d);
      ASSERT_TRUE(i.has_value());
      EXPECT_NEAR(i->value, exact, 1e-12 * i->magnitude);
      EXPECT_GE(i->magnitude, std::abs(i->value));
    }
  }
  EXPECT_EQ(table.squared_gap_integral(0.0, 1e-6)->value, 0.0);
}

// Each check of find_table_problem, with the point it names.
TEST(TabulatedProfile, TableProblemsNameTheirPoint) {
  const auto problem = [](std::vector<double> r, std::vector<double> f) {
    const auto p = mdrsim::find_table_problem({std::move(r), std::move(f), {}});
    if (!p) return std::string("none");
    return fmt::format("{}{} {}", p->column, p->point ? fmt::format("[{}]", *p->point) : "",
                       p->message);
  };
  EXPECT_EQ(problem({0, 1, 2, 3}, {0, 1, 2, 3}), "none");
  EXPECT_EQ(problem({0, 1, 2}, {0, 1, 2}), "count has 3 points, expected at least 4");
  EXPECT_EQ(problem({0, 1, 2, 3}, {0, 1, 2}), "f has 3 values for 4 radii r, expected one per r");
  EXPECT_EQ(problem({1, 2, 3, 4}, {0, 1, 2, 3}), "r[0] is not 0: the table starts at the tip");
  EXPECT_EQ(problem({0, 1, 2, 3}, {1, 1, 2, 3}), "f[0] is not 0: the gap is 0 at the tip");
  EXPECT_EQ(problem({0, 1, 1, 3}, {0, 1, 2, 3}),
            "r[2] is not above the previous r = 1; r must increase");
  EXPECT_EQ(problem({0, 1, 2, 3}, {0, 2, 1, 3}), "none");  // f may fall
  EXPECT_EQ(problem({0, 1, 2, 3}, {0, 1, -2, 3}), "f[2] is outside [0, inf)");
  EXPECT_EQ(problem({0, 1, 2, NAN}, {0, 1, 2, 3}), "r[3] is not a finite number");
}

TEST(TabulatedProfile, CsvReaderSkipsHeaderCommentsAndBlankLines) {
  const std::string dir = mdrsim::test::make_temp_dir();
  const std::string path = dir + "/t.csv";
  std::ofstream(path) << "# a comment\r\n r , f \r\n\r\n0,0\r\n1e-4, 2.5e-7\n+2e-4 ,1e-6\n";
  const ProfileTable t = mdrsim::read_profile_table(path);
  EXPECT_EQ(t.radii, (std::vector<double>{0.0, 1e-4, 2e-4}));
  EXPECT_EQ(t.gaps, (std::vector<double>{0.0, 2.5e-7, 1e-6}));
  EXPECT_EQ(t.lines, (std::vector<std::size_t>{4, 5, 6}));
  std::ofstream(path) << "0,0\n1e-4;2e-4\n";
  EXPECT_THROW_MSG(mdrsim::read_profile_table(path), std::invalid_argument,
                   "line 2 of '" + path + "': expected two numbers r,f, got \"1e-4;2e-4\"");
  std::ofstream(path) << "0,0\n1,nan\n";
  EXPECT_THROW_MSG(mdrsim::read_profile_table(path), std::invalid_argument,
                   "line 2 of '" + path + "': expected two numbers r,f, got \"1,nan\"");
  std::ofstream(path) << "0,0\nr,f\n";  // a header only as the first line
  EXPECT_THROW_MSG(mdrsim::read_profile_table(path), std::invalid_argument,
                   "line 2 of '" + path + "': expected two numbers r,f, got \"r,f\"");
  EXPECT_THROW_MSG(mdrsim::read_profile_table(dir + "/none.csv"), std::invalid_argument,
                   "cannot read '" + dir + "/none.csv': No such file or directory");
  EXPECT_THROW_MSG(mdrsim::read_profile_table(dir), std::invalid_argument,
                   "cannot read '" + dir + "': it is a directory");
  std::filesystem::remove_all(dir);
}

// A sweep builds a scene per value from one table: the profile is built once.
TEST(TabulatedProfile, SharedProfilesAreBuiltOncePerTable) {
  const ProfileTable t = table_of([](double r) { return r * r; }, 5, 1.0);
  const auto first = TabulatedProfile::shared(t);
  EXPECT_EQ(TabulatedProfile::shared(t), first);
  ProfileTable other = t;
  other.gaps.back() *= 1.5;
  EXPECT_NE(TabulatedProfile::shared(other), first);
}
