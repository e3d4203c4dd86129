// Random and Latin hypercube designs: reproducible from the seed, inside their ranges, and
// the Latin hypercube with one sample in each stratum of every axis.
#include "engine/sweep/sweep_design.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "engine/sweep/sweep_grid.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

SweepGrid drawn_grid(const std::vector<std::string>& varies, const std::string& kind,
                     const std::string& samples, const std::string& seed,
                     const std::vector<std::string>& where = {}) {
  std::vector<VarySpec> specs;
  for (const std::string& v : varies) {
    const bool linked = v.rfind("&", 0) == 0;
    specs.push_back(parse_vary(linked ? v.substr(1) : v, true));
    specs.back().linked = linked;
  }
  return SweepGrid(std::move(specs), where, parse_design(kind, samples, seed));
}

std::vector<std::vector<std::string>> texts(const SweepGrid& grid) {
  std::vector<std::vector<std::string>> out;
  for (std::uint64_t row = 0; row < grid.rows(); ++row) {
    std::vector<std::string> fields;
    for (const VaryValue& v : grid.values(row)) fields.push_back(v.text);
    out.push_back(fields);
  }
  return out;
}

TEST(SweepDesign, SplitMix64IsTheReferenceGenerator) {
  // SplitMix64 (Steele, Lea, Flood 2014; Vigna's splitmix64.c) from state 0: its first output
  // is the mix of 0x9e3779b97f4a7c15, so any language reproduces the draws.
  EXPECT_EQ(splitmix64(0), 0xe220a8397b1dcdafULL);
}

TEST(SweepDesign, RandomIsReproducibleBySeedAndInsideItsBounds) {
  const std::vector<std::string> varies{"a=0.2:0.7", "b=1e-6:1e-2:log", "c=-3:-5", "d=x,y,z"};
  const SweepGrid one = drawn_grid(varies, "random", "2000", "7");
  ASSERT_EQ(one.rows(), 2000u);
  EXPECT_EQ(texts(one), texts(drawn_grid(varies, "random", "2000", "7")));
  EXPECT_NE(texts(one), texts(drawn_grid(varies, "random", "2000", "8")));
  EXPECT_EQ(one.hash(), drawn_grid(varies, "random", "2000", "7").hash());
  EXPECT_NE(one.hash(), drawn_grid(varies, "random", "2000", "8").hash());
  EXPECT_NE(one.hash(), drawn_grid(varies, "latin", "2000", "7").hash());
  EXPECT_NE(one.hash(), drawn_grid(varies, "random", "2001", "7").hash());
  // A row is drawn on its own: the first rows of a longer design are the same rows.
  const SweepGrid longer = drawn_grid(varies, "random", "3000", "7");
  for (std::uint64_t row = 0; row < one.rows(); row += 97) {
    EXPECT_EQ(one.values(row), longer.values(row)) << row;
  }
  std::set<std::string> names;
  double lowest = 1.0, highest = 0.0, log_sum = 0.0;
  for (std::uint64_t row = 0; row < one.rows(); ++row) {
    const std::vector<VaryValue> v = one.values(row);
    ASSERT_TRUE(v[0].number && v[1].number && v[2].number);
    EXPECT_GE(*v[0].number, 0.2);
    EXPECT_LE(*v[0].number, 0.7);
    EXPECT_GE(*v[1].number, 1e-6);
    EXPECT_LE(*v[1].number, 1e-2);
    EXPECT_GE(*v[2].number, -5.0);
    EXPECT_LE(*v[2].number, -3.0);
    // The CSV's text reads back as the value the scene is given.
    EXPECT_EQ(std::stod(v[0].text), *v[0].number);
    lowest = std::min(lowest, *v[0].number);
    highest = std::max(highest, *v[0].number);
    log_sum += std::log10(*v[1].number);
    names.insert(v[3].text);
  }
  // Uniform on [0.2, 0.7): 2000 draws leave gaps of about 0.5/2000 at the ends; 0.01 is 40 of
  // them (a miss has probability e^-40). log-uniform on [1e-6, 1e-2]: the mean of log10 is -4
  // with a standard error of (4/sqrt(3))/sqrt(2000) = 0.052; 0.3 is about 6 of them.
  EXPECT_LT(lowest, 0.21);
  EXPECT_GT(highest, 0.69);
  EXPECT_NEAR(log_sum / 2000.0, -4.0, 0.3);
  EXPECT_EQ(names, (std::set<std::string>{"x", "y", "z"}));
}

TEST(SweepDesign, LatinHypercubeHasOneSamplePerStratumOfEveryAxis) {
  constexpr std::uint64_t n = 500;
  const SweepGrid grid = drawn_grid({"a=0:1", "b=10:20", "c=1:1000:log"}, "latin", "500", "3");
  ASSERT_EQ(grid.rows(), n);
  std::vector<std::vector<int>> hits(3, std::vector<int>(n, 0));
  for (std::uint64_t row = 0; row < n; ++row) {
    const std::vector<VaryValue> v = grid.values(row);
    // The stratum of each value, from the value itself: t = (v - FROM) / (TO - FROM), or
    // log(v / FROM) / log(TO / FROM); the map rounds by a few ulps, far inside a stratum of
    // width 1/500 but for draws within 1e-12 of a stratum's edge (none with this seed).
    const double t[3] = {*v[0].number, (*v[1].number - 10.0) / 10.0,
                         std::log(*v[2].number) / std::log(1000.0)};
    for (int a = 0; a < 3; ++a) {
      const auto stratum = static_cast<std::uint64_t>(std::floor(t[a] * n));
      ASSERT_LT(stratum, n);
      ++hits[a][stratum];
    }
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(std::count(hits[a].begin(), hits[a].end(), 1), static_cast<long>(n)) << a;
  }
  EXPECT_EQ(texts(grid),
            texts(drawn_grid({"a=0:1", "b=10:20", "c=1:1000:log"}, "latin", "500", "3")));
}

TEST(SweepDesign, LinkedKeysShareTheirAxisDraw) {
  const SweepGrid grid = drawn_grid({"a=0:1", "&b=10:20", "&c=100:0", "d=0:1"}, "latin", "50", "1");
  for (std::uint64_t row = 0; row < grid.rows(); ++row) {
    const std::vector<VaryValue> v = grid.values(row);
    EXPECT_NEAR(*v[1].number, 10.0 + 10.0 * *v[0].number, 1e-13) << row;  // a few ulps of 20
    EXPECT_NEAR(*v[2].number, 100.0 - 100.0 * *v[0].number, 1e-13) << row;
    EXPECT_NE(*v[3].number, *v[0].number) << row;
  }
  // Lists on one axis take value floor(t k): as many values each, named against the first.
  EXPECT_THROW_MSG(drawn_grid({"a=0:1", "&b=x,y,z", "&c=0:1", "&d=1,2"}, "random", "5", "1"),
                   UsageError,
                   "--link: d has 2 values, b has 3 (a linked key needs as many as the key it "
                   "varies with)");
  const SweepGrid zipped = drawn_grid({"a=0:1", "&b=x,y,z", "&c=1,2,3"}, "random", "30", "1");
  for (std::uint64_t row = 0; row < zipped.rows(); ++row) {
    const std::vector<VaryValue> v = zipped.values(row);
    const auto third = static_cast<std::size_t>(*v[0].number * 3.0);
    EXPECT_EQ(v[1].text, std::string(1, static_cast<char>('x' + third))) << row;
    EXPECT_EQ(*v[2].number, static_cast<double>(third + 1)) << row;
  }
}

TEST(SweepDesign, WhereKeepsTheDrawsThatPassInSampleOrder) {
  const std::vector<std::string> varies{"a=0:1", "b=0:1"};
  const SweepGrid all = drawn_grid(varies, "random", "400", "5");
  const SweepGrid kept = drawn_grid(varies, "random", "400", "5", {"b <= a"});
  EXPECT_EQ(kept.candidates(), 400u);
  std::vector<std::vector<VaryValue>> expected;
  for (std::uint64_t row = 0; row < all.rows(); ++row) {
    const std::vector<VaryValue> v = all.values(row);
    if (*v[1].number <= *v[0].number) expected.push_back(v);
  }
  ASSERT_EQ(kept.rows(), expected.size());
  // About half of 400 (standard deviation 10).
  EXPECT_GT(kept.rows(), 150u);
  EXPECT_LT(kept.rows(), 250u);
  for (std::uint64_t row = 0; row < kept.rows(); ++row) EXPECT_EQ(kept.values(row), expected[row]);
  EXPECT_NE(kept.hash(), all.hash());
}

TEST(SweepDesign, BadDesignFlags) {
  EXPECT_THROW_MSG(parse_design("lhs", "", ""), UsageError,
                   "--design: unknown 'lhs' (known: grid, latin, random)");
  EXPECT_THROW_MSG(parse_design("random", "", "1"), UsageError,
                   "--samples: --design random needs --samples N");
  for (const char* samples : {"0", "-1", "1.5", "x", "100000001", " 3"}) {
    EXPECT_THROW_MSG(parse_design("random", samples, ""), UsageError,
                     std::string("--samples: '") + samples +
                         "' is not a whole number from 1 to 100000000 (--design random)");
  }
  EXPECT_THROW_MSG(parse_design("latin", "10000001", ""), UsageError,
                   "--samples: '10000001' is not a whole number from 1 to 10000000 (--design "
                   "latin)");
  EXPECT_THROW_MSG(parse_design("random", "3", "-2"), UsageError,
                   "--seed: '-2' is not a whole number from 0 to 18446744073709551615");
  EXPECT_THROW_MSG(parse_design("", "3", ""), UsageError,
                   "--samples: a grid has the rows of its --vary values (--samples belongs to "
                   "--design random or latin)");
  EXPECT_THROW_MSG(parse_design("grid", "", "3"), UsageError,
                   "--seed: a grid draws nothing (--seed belongs to --design random or latin)");
  EXPECT_EQ(parse_design("random", "3", "18446744073709551615").seed, UINT64_MAX);
  // A random design's ranges have no COUNT; a grid's need one.
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:5", true), UsageError,
                   "--vary: a.b: a random design draws from FROM:TO or FROM:TO:log, not a COUNT "
                   "('5')");
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:5:log", true), UsageError,
                   "--vary: 'a.b=0:1:5:log' is not KEY=FROM:TO, KEY=FROM:TO:log or KEY=V1,V2,...");
  EXPECT_THROW_MSG(parse_vary("a.b=0:1:log", true), UsageError,
                   "--vary: a.b: a log range needs FROM and TO of the same sign and not zero, "
                   "not 0 and 1");
  EXPECT_THROW_MSG(SweepGrid({parse_vary("a.b=0:1", true)}), UsageError,
                   "--vary: a.b: a grid needs FROM:TO:COUNT (FROM:TO draws from a range: "
                   "--design random or latin)");
}

}  // namespace
}  // namespace mdrsim::cli
