// --vary KEY=FROM:TO:COUNT: the values it gives and the exact message for each malformed part.
#include "apps/vary_spec.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "apps/usage_error.hpp"

namespace mdrsim::cli {
namespace {

TEST(VarySpec, EvenlySpacedFromFromToTo) {
  const VarySpec v = parse_vary("material.poisson_ratio=0:0.4:5");
  EXPECT_EQ(v.key, "material.poisson_ratio");
  ASSERT_EQ(v.values.size(), 5u);
  EXPECT_EQ(v.values.front(), 0.0);
  EXPECT_EQ(v.values.back(), 0.4);  // the end is exact, not 4 * 0.1
  EXPECT_DOUBLE_EQ(v.values[2], 0.2);
}

TEST(VarySpec, OneValueDescendingAndSpaces) {
  EXPECT_EQ(parse_vary("discretization.springs=100:200:1").values, std::vector<double>{100.0});
  EXPECT_EQ(parse_vary("a.b=2:1:2").values, (std::vector<double>{2.0, 1.0}));
  const VarySpec spaced = parse_vary(" a.b = +1e-3 : -1e-3 : 3 ");
  EXPECT_EQ(spaced.key, "a.b");
  EXPECT_EQ(spaced.values, (std::vector<double>{1e-3, 0.0, -1e-3}));
}

TEST(VarySpec, ExtremeEndsDoNotOverflow) {
  const double big = std::numeric_limits<double>::max();
  for (const double v : parse_vary("a.b=-1.7e308:1.7e308:7").values) {
    EXPECT_TRUE(std::isfinite(v)) << v;
    EXPECT_LE(std::abs(v), big);
  }
}

TEST(VarySpec, NotKeyEqualsRange) {
  EXPECT_THROW_MSG(parse_vary("material.poisson_ratio"), UsageError,
                   "--vary: 'material.poisson_ratio' is not KEY=FROM:TO:COUNT");
  EXPECT_THROW_MSG(parse_vary("=0:1:2"), UsageError, "--vary: '=0:1:2' is not KEY=FROM:TO:COUNT");
  EXPECT_THROW_MSG(parse_vary(" =0:1:2"), UsageError, "--vary: ' =0:1:2' is not KEY=FROM:TO:COUNT");
  EXPECT_THROW_MSG(parse_vary(""), UsageError, "--vary: '' is not KEY=FROM:TO:COUNT");
}

TEST(VarySpec, MissingOrExtraParts) {
  EXPECT_THROW_MSG(parse_vary("a.b=0:1"), UsageError, "--vary: 'a.b=0:1' is not KEY=FROM:TO:COUNT");
  EXPECT_THROW_MSG(parse_vary("a.b=0"), UsageError, "--vary: 'a.b=0' is not KEY=FROM:TO:COUNT");
  EXPECT_THROW_MSG(parse_vary("a.b="), UsageError, "--vary: 'a.b=' is not KEY=FROM:TO:COUNT");
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:2:3"), UsageError,
                   "--vary: 'a.b=0:1:2:3' is not KEY=FROM:TO:COUNT");
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
  EXPECT_THROW_MSG(parse_vary("a\nb=0:1"), UsageError,
                   "--vary: 'a\\nb=0:1' is not KEY=FROM:TO:COUNT");
}

}  // namespace
}  // namespace mdrsim::cli
