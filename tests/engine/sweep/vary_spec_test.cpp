// --vary KEY=FROM:TO:COUNT[:log] or KEY=V1,V2,...: the values it gives and the exact message for
// each malformed part.
#include "engine/sweep/vary_spec.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr const char* kForms = "KEY=FROM:TO:COUNT, KEY=FROM:TO:COUNT:log or KEY=V1,V2,...";

std::vector<double> numbers(const VarySpec& spec) {
  std::vector<double> out;
  for (const VaryValue& v : spec.values) out.push_back(v.number.value_or(NAN));
  return out;
}

std::vector<std::string> fields(const VarySpec& spec) {
  std::vector<std::string> out;
  for (const VaryValue& v : spec.values) out.push_back(v.text);
  return out;
}

std::string not_a_form(const std::string& text) {
  return fmt::format("--vary: '{}' is not {}", text, kForms);
}

TEST(VarySpec, EvenlySpacedFromFromToTo) {
  const VarySpec v = parse_vary("material.poisson_ratio=0:0.4:5");
  EXPECT_EQ(v.key, "material.poisson_ratio");
  EXPECT_EQ(v.form, VarySpec::Form::linear);
  const std::vector<double> x = numbers(v);
  ASSERT_EQ(x.size(), 5u);
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), 0.4);  // the end is exact, not 4 * 0.1
  EXPECT_DOUBLE_EQ(x[2], 0.2);
  // The CSV field is the shortest text that reads back as the same double.
  EXPECT_EQ(fields(v), (std::vector<std::string>{"0", "0.1", "0.2", "0.3", "0.4"}));
}

TEST(VarySpec, RangeValuesAreTheDecimalsAPersonWritesWithinTheFormulasRounding) {
  // (1 - t) FROM + t TO gives 0.30000000000000004 at t = 3/4 and 11000000.000000002 at t = 1/7:
  // within its rounding error of 0.3 and 11000000, which the range gives instead (the latter
  // a whole number, as discretization.springs needs).
  EXPECT_EQ(numbers(parse_vary("a.b=0:0.4:5"))[3], 0.3);
  EXPECT_EQ(fields(parse_vary("a.b=1e7:1.7e7:8")),
            (std::vector<std::string>{"10000000", "11000000", "12000000", "13000000", "14000000",
                                      "15000000", "16000000", "17000000"}));
  EXPECT_EQ(fields(parse_vary("a.b=0:2e-5:5")),
            (std::vector<std::string>{"0", "5e-06", "1e-05", "1.5e-05", "2e-05"}));
  // A range through zero: (1 - 2/3) (-2e-3) + (2/3) 1e-3 is -1e-19 in doubles; zero is within
  // the rounding error, and the row runs the value 0 (a held depth of 0, not -1e-19 m).
  EXPECT_EQ(fields(parse_vary("a.b=-2e-3:1e-3:4")),
            (std::vector<std::string>{"-0.002", "-0.001", "0", "0.001"}));
  // Values with no short decimal move by no more than the formula's rounding error (two
  // ulps of the larger end).
  const VarySpec sevenths = parse_vary("a.b=0:1:8");
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(numbers(sevenths)[static_cast<std::size_t>(i)], i / 7.0, 4.5e-16);
  }
  // Log: 1e-6 (1e3)^(1/3) is 9.999999999999999e-06 by pow, 1e-05 in the range.
  EXPECT_EQ(fields(parse_vary("a.b=1e-6:1e-3:4:log")),
            (std::vector<std::string>{"1e-06", "1e-05", "0.0001", "0.001"}));
  EXPECT_EQ(fields(parse_vary("a.b=100:1e6:9:log"))[3], "3162.27766016838");
  // A value 4.7e-16 from its nearest 15-digit decimal, more than the rounding error, stays
  // as computed: 1 + 2^-41, between 1 and 1 + 2^-40.
  const VarySpec fine = parse_vary("a.b=1:1.0000000000009095:3");
  EXPECT_EQ(numbers(fine)[1], 1.0 + std::ldexp(1.0, -41));
}

TEST(VarySpec, OneValueDescendingAndSpaces) {
  EXPECT_EQ(numbers(parse_vary("discretization.springs=100:100:1")), std::vector<double>{100.0});
  EXPECT_EQ(numbers(parse_vary("a.b=2:1:2")), (std::vector<double>{2.0, 1.0}));
  const VarySpec spaced = parse_vary(" a.b = +1e-3 : -1e-3 : 3 ");
  EXPECT_EQ(spaced.key, "a.b");
  EXPECT_EQ(numbers(spaced), (std::vector<double>{1e-3, 0.0, -1e-3}));
}

TEST(VarySpec, ExtremeEndsDoNotOverflow) {
  const double big = std::numeric_limits<double>::max();
  for (const double v : numbers(parse_vary("a.b=-1.7e308:1.7e308:7"))) {
    EXPECT_TRUE(std::isfinite(v)) << v;
    EXPECT_LE(std::abs(v), big);
  }
}

TEST(VarySpec, NotKeyEqualsValues) {
  EXPECT_THROW_MSG(parse_vary("material.poisson_ratio"), UsageError,
                   not_a_form("material.poisson_ratio"));
  EXPECT_THROW_MSG(parse_vary("=0:1:2"), UsageError, not_a_form("=0:1:2"));
  EXPECT_THROW_MSG(parse_vary(" =0:1:2"), UsageError, not_a_form(" =0:1:2"));
  EXPECT_THROW_MSG(parse_vary(""), UsageError, not_a_form(""));
  EXPECT_THROW_MSG(parse_vary("a.b="), UsageError, not_a_form("a.b="));
  EXPECT_THROW_MSG(parse_vary("a.b= "), UsageError, not_a_form("a.b= "));
}

TEST(VarySpec, MissingOrExtraParts) {
  EXPECT_THROW_MSG(parse_vary("a.b=0:1"), UsageError, not_a_form("a.b=0:1"));
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:2:log:3"), UsageError, not_a_form("a.b=0:1:2:log:3"));
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:2:3"), UsageError,
                   "--vary: a.b: '3' is not log (FROM:TO:COUNT:log)");
  EXPECT_THROW_MSG(parse_vary("a.b=1:2:3:Log"), UsageError,
                   "--vary: a.b: 'Log' is not log (FROM:TO:COUNT:log)");
}

TEST(VarySpec, BadFromAndTo) {
  EXPECT_THROW_MSG(parse_vary("a.b=x:1:2"), UsageError,
                   "--vary: a.b: FROM 'x' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=:1:2"), UsageError,
                   "--vary: a.b: FROM '' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=1e5x:1:2"), UsageError,
                   "--vary: a.b: FROM '1e5x' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=nan:1:2"), UsageError,
                   "--vary: a.b: FROM 'nan' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=0:inf:2"), UsageError,
                   "--vary: a.b: TO 'inf' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=0:1e999:2"), UsageError,
                   "--vary: a.b: TO '1e999' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=0:one:2"), UsageError,
                   "--vary: a.b: TO 'one' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=++1:1:2"), UsageError,
                   "--vary: a.b: FROM '++1' is not a finite number");
}

TEST(VarySpec, BadCount) {
  const char* expected = "a whole number from 1 to 1000000";
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:0"), UsageError,
                   std::string("--vary: a.b: COUNT '0' is not ") + expected);
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:-3"), UsageError,
                   std::string("--vary: a.b: COUNT '-3' is not ") + expected);
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:2.5"), UsageError,
                   std::string("--vary: a.b: COUNT '2.5' is not ") + expected);
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:1e3"), UsageError,
                   std::string("--vary: a.b: COUNT '1e3' is not ") + expected);
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:1000001"), UsageError,
                   std::string("--vary: a.b: COUNT '1000001' is not ") + expected);
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:99999999999999999999"), UsageError,
                   std::string("--vary: a.b: COUNT '99999999999999999999' is not ") + expected);
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:"), UsageError,
                   std::string("--vary: a.b: COUNT '' is not ") + expected);
}

TEST(VarySpec, ControlCharactersAreEscaped) {
  EXPECT_THROW_MSG(parse_vary("a\nb=0:1"), UsageError, not_a_form("a\\nb=0:1"));
  EXPECT_THROW_MSG(parse_vary("a.b=x\ty"), UsageError,
                   "--vary: a.b: 'x\\ty' is not a name (no quotes, backslashes or control "
                   "characters)");
}

TEST(VarySpec, OneValueWithFromAndToApartIsRefused) {
  // Else it would run FROM only, silently.
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:1"), UsageError,
                   "--vary: a.b: COUNT 1 gives one value, but FROM 0 and TO 1 differ (give a "
                   "COUNT of 2 or more, or one value)");
  EXPECT_EQ(numbers(parse_vary("a.b=0.5:0.5:1")), std::vector<double>{0.5});
  EXPECT_EQ(numbers(parse_vary("a.b=2:2:3")), (std::vector<double>{2.0, 2.0, 2.0}));
}

TEST(VarySpec, LogSpacing) {
  const VarySpec v = parse_vary("discretization.springs=100:10000:3:log");
  EXPECT_EQ(v.form, VarySpec::Form::log);
  EXPECT_EQ(numbers(v), (std::vector<double>{100.0, 1000.0, 10000.0}));
  EXPECT_EQ(fields(v), (std::vector<std::string>{"100", "1000", "10000"}));
  // FROM * (TO / FROM)^(i / (COUNT - 1)), the ends exact; negative ranges too.
  const std::vector<double> x = numbers(parse_vary("a.b=1e-6:1e-3:4:log"));
  ASSERT_EQ(x.size(), 4u);
  EXPECT_EQ(x[0], 1e-6);
  EXPECT_DOUBLE_EQ(x[1], 1e-6 * std::pow(1e-3 / 1e-6, 1.0 / 3.0));
  EXPECT_DOUBLE_EQ(x[2], 1e-4);
  EXPECT_EQ(x[3], 1e-3);
  EXPECT_EQ(numbers(parse_vary("a.b=-1:-100:3: log ")), (std::vector<double>{-1.0, -10.0, -100.0}));
  EXPECT_EQ(numbers(parse_vary("a.b=5:5:1:log")), std::vector<double>{5.0});
}

TEST(VarySpec, BadLogRange) {
  const std::string sign =
      "--vary: a.b: a log range needs FROM and TO of the same sign and not zero";
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:3:log"), UsageError, sign + ", not 0 and 1");
  EXPECT_THROW_MSG(parse_vary("a.b=-1:1:3:log"), UsageError, sign + ", not -1 and 1");
  EXPECT_THROW_MSG(parse_vary("a.b=1:0:3:log"), UsageError, sign + ", not 1 and 0");
  EXPECT_THROW_MSG(parse_vary("a.b=1e-300:1e300:3:log"), UsageError,
                   "--vary: a.b: TO/FROM = 1e+300/1e-300 is beyond a double");
  EXPECT_THROW_MSG(parse_vary("a.b=1:2:1:log"), UsageError,
                   "--vary: a.b: COUNT 1 gives one value, but FROM 1 and TO 2 differ (give a "
                   "COUNT of 2 or more, or one value)");
}

TEST(VarySpec, ListsOfNumbersAndNames) {
  const VarySpec names = parse_vary("detachment.criterion=mode-mixed, stress,deformation");
  EXPECT_EQ(names.form, VarySpec::Form::list);
  EXPECT_EQ(fields(names), (std::vector<std::string>{"mode-mixed", "stress", "deformation"}));
  for (const VaryValue& v : names.values) EXPECT_FALSE(v.number) << v.text;
  const VarySpec mixed = parse_vary("a.b=1e3,+2, -0.5,fixed-load,0.1");
  EXPECT_EQ(fields(mixed), (std::vector<std::string>{"1000", "2", "-0.5", "fixed-load", "0.1"}));
  EXPECT_EQ(mixed.values[0].number, 1000.0);
  EXPECT_EQ(mixed.values[4].number, 0.1);
  EXPECT_FALSE(mixed.values[3].number);
  // One value is a list of one: the key gets its own column, the rest of the scene stays.
  EXPECT_EQ(numbers(parse_vary("a.b=0")), std::vector<double>{0.0});
  // Repeats are kept: a list is the rows asked for.
  EXPECT_EQ(fields(parse_vary("a.b=x,x")), (std::vector<std::string>{"x", "x"}));
}

TEST(VarySpec, BadListItems) {
  EXPECT_THROW_MSG(parse_vary("a.b=1,,2"), UsageError, "--vary: a.b: value 2 of '1,,2' is empty");
  EXPECT_THROW_MSG(parse_vary("a.b=1,2,"), UsageError, "--vary: a.b: value 3 of '1,2,' is empty");
  EXPECT_THROW_MSG(parse_vary("a.b=1,nan"), UsageError,
                   "--vary: a.b: 'nan' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=inf"), UsageError, "--vary: a.b: 'inf' is not a finite number");
  EXPECT_THROW_MSG(parse_vary("a.b=1e999"), UsageError,
                   "--vary: a.b: '1e999' is not a finite number");
  EXPECT_THROW_MSG(parse_vary(R"(a.b="x")"), UsageError,
                   R"(--vary: a.b: '"x"' is not a name (no quotes, backslashes or control )"
                   "characters)");
}

TEST(VarySpec, ProbesAreEveryValueOfAListOrShortRangeElseTheEnds) {
  EXPECT_EQ(parse_vary("a.b=0:1:3").probes(), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(parse_vary("a.b=0:1:64").probes().size(), 64u);
  EXPECT_EQ(parse_vary("a.b=0:1:65").probes(), (std::vector<std::size_t>{0, 1, 64}));
  EXPECT_EQ(parse_vary("a.b=1:1e6:1000:log").probes(), (std::vector<std::size_t>{0, 1, 999}));
  std::string list = "a.b=0";
  for (int i = 1; i < 100; ++i) list += fmt::format(",{}", i);
  EXPECT_EQ(parse_vary(list).probes().size(), 100u);
}

}  // namespace
}  // namespace mdrsim::cli
