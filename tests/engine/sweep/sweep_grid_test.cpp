// The row order of a sweep, its shards, and the identity line that resume and merge check.
#include "engine/sweep/sweep_grid.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <string>
#include <vector>

#include "engine/output/sweep_csv.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

SweepGrid grid_of(const std::vector<std::string>& varies) {
  std::vector<VarySpec> specs;
  for (const std::string& v : varies) specs.push_back(parse_vary(v));
  return SweepGrid(std::move(specs));
}

TEST(SweepGrid, RowsAreNestedLoopsTheLastKeyFastest) {
  const SweepGrid grid = grid_of({"a=1:3:3", "b=x,y", "c=0"});
  EXPECT_EQ(grid.rows(), 6u);
  const std::vector<std::vector<std::size_t>> expected{{0, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                                       {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  for (std::uint64_t row = 0; row < grid.rows(); ++row) {
    EXPECT_EQ(grid.indices(row), expected[row]) << row;
  }
}

TEST(SweepGrid, KeyTwiceOrTooManyRows) {
  EXPECT_THROW_MSG(grid_of({"a.b=0:1:2", "c=1", " a.b =3"}), UsageError,
                   "--vary: a.b is varied twice");
  EXPECT_THROW_MSG(grid_of({"a=0:1:40000", "b=0:1:25001"}), UsageError,
                   "--vary: the grid has more than 1000000000 rows");
  EXPECT_EQ(grid_of({"a=0:1:40000", "b=0:1:25000"}).rows(), 1'000'000'000u);
}

TEST(SweepGrid, HashOfTheValuesNotOfHowTheyWereWritten) {
  EXPECT_EQ(grid_of({"a=0:1:3"}).hash(), grid_of({"a=0,0.5,1"}).hash());
  EXPECT_EQ(grid_of({"a=1:100:3:log"}).hash(), grid_of({"a=1,10,1e2"}).hash());
  EXPECT_NE(grid_of({"a=0:1:3"}).hash(), grid_of({"a=0:1:4"}).hash());
  EXPECT_NE(grid_of({"a=0:1:3"}).hash(), grid_of({"b=0:1:3"}).hash());
  EXPECT_NE(grid_of({"a=1", "b=2"}).hash(), grid_of({"b=2", "a=1"}).hash());
  EXPECT_NE(grid_of({"a=1,2"}).hash(), grid_of({"a=1", "b=2"}).hash());
  // FNV-1a 64 of "a=0,0.5,1\n" (docs/sweeps.md: the identity line), as any language computes it.
  EXPECT_EQ(grid_of({"a=0:1:3"}).hash(), fnv1a("a=0,0.5,1\n"));
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cULL);
}

SweepGrid linked_grid(const std::vector<std::string>& varies,
                      const std::vector<std::string>& where = {}) {
  std::vector<VarySpec> specs;
  for (const std::string& v : varies) {
    const bool linked = v.rfind("&", 0) == 0;
    specs.push_back(parse_vary(linked ? v.substr(1) : v, false, linked ? "--link" : "--vary"));
    specs.back().linked = linked;
  }
  return SweepGrid(std::move(specs), where);
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

TEST(SweepGrid, LinkedKeysRideAlongWithTheirAxis) {
  // b and c are zipped with a (one axis of 3), d is the product's second axis.
  const SweepGrid grid = linked_grid({"a=1:3:3", "&b=10,20,30", "&c=x,y,z", "d=0:1:2"});
  EXPECT_EQ(grid.rows(), 6u);
  EXPECT_EQ(texts(grid), (std::vector<std::vector<std::string>>{{"1", "10", "x", "0"},
                                                                {"1", "10", "x", "1"},
                                                                {"2", "20", "y", "0"},
                                                                {"2", "20", "y", "1"},
                                                                {"3", "30", "z", "0"},
                                                                {"3", "30", "z", "1"}}));
  EXPECT_EQ(grid.indices(3), (std::vector<std::size_t>{1, 1, 1, 1}));
  // The first row with each value of each key, the keys in order (a's values, then d's 1).
  EXPECT_EQ(grid.probe_rows(), (std::vector<std::uint64_t>{0, 2, 4, 1}));
  // A linked key is another grid than the same key in the product.
  EXPECT_NE(grid.hash(), linked_grid({"a=1:3:3", "b=10,20,30", "c=x,y,z", "d=0:1:2"}).hash());
  EXPECT_EQ(grid.hash(), fnv1a("a=1,2,3\n&b=10,20,30\n&c=x,y,z\nd=0,1\n"));
}

TEST(SweepGrid, WhereKeepsTheProductRowsThatPassInOrder) {
  // b <= a over a, b in 1..4: the lower triangle, 10 of 16 rows, the product's order kept.
  const SweepGrid grid = linked_grid({"a=1:4:4", "b=1:4:4"}, {"b <= a"});
  EXPECT_EQ(grid.candidates(), 16u);
  ASSERT_EQ(grid.rows(), 10u);
  std::vector<std::vector<std::string>> expected;
  for (int a = 1; a <= 4; ++a) {
    for (int b = 1; b <= a; ++b) expected.push_back({std::to_string(a), std::to_string(b)});
  }
  EXPECT_EQ(texts(grid), expected);
  // Probes are rows the sweep runs: a's values with the smallest b, b's with the smallest a.
  EXPECT_EQ(grid.probe_rows(), (std::vector<std::uint64_t>{0, 1, 3, 6, 2, 5, 9}));
  // Two conditions: both hold. A factor on either side; 0.5*a is exact in binary.
  EXPECT_EQ(texts(linked_grid({"a=1:4:4", "b=1:4:4"}, {"b <= a", "b > 1"})).size(), 6u);
  EXPECT_EQ(
      texts(linked_grid({"a=1:4:4", "b=0.5:2:4"}, {"b == 0.5*a"})),
      (std::vector<std::vector<std::string>>{{"1", "0.5"}, {"2", "1"}, {"3", "1.5"}, {"4", "2"}}));
  EXPECT_EQ(texts(linked_grid({"a=1:4:4"}, {"2*a != 4", "a*1 < 4"})),
            (std::vector<std::vector<std::string>>{{"1"}, {"3"}}));
  // The identity: the keys' line as before, then each condition as written back.
  EXPECT_EQ(grid.hash(), fnv1a("a=1,2,3,4\nb=1,2,3,4\nwhere b <= a\n"));
  EXPECT_EQ(grid.hash(), linked_grid({"a=1:4:4", "b=1:4:4"}, {" b<=1*a "}).hash());
  // Shards and rows past a gap: row 9 is the product's last.
  EXPECT_EQ(grid.values(9)[0].text, "4");
  EXPECT_EQ(grid.values(9)[1].text, "4");
}

TEST(SweepGrid, BadLinksAndConditions) {
  EXPECT_THROW_MSG(linked_grid({"&a=1:3:3", "b=1"}), UsageError,
                   "--link: a follows no --vary (a linked key varies with the --vary before it)");
  EXPECT_THROW_MSG(linked_grid({"a=1:3:3", "&b=1,2"}), UsageError,
                   "--link: b has 2 values, a has 3 (a linked key needs as many as the key it "
                   "varies with)");
  EXPECT_THROW_MSG(linked_grid({"a=1:3:3", "&a=1,2,3"}), UsageError, "--link: a is varied twice");
  EXPECT_THROW_MSG(parse_vary("b=1:2", false, "--link"), UsageError,
                   "--link: 'b=1:2' is not KEY=FROM:TO:COUNT, KEY=FROM:TO:COUNT:log or "
                   "KEY=V1,V2,...");
  const std::string form =
      "is not A OP B (OP one of <=, <, >=, >, ==, !=; A and B a varied key, a number or "
      "NUMBER*KEY)";
  for (const char* where : {"a", "a = 1", "a <= ", "<= a", "a <= b <= 1", "x*a < 1", "a => 1"}) {
    EXPECT_THROW_MSG(linked_grid({"a=1:3:3", "b=1"}, {where}), UsageError,
                     std::string("--where: '") + where + "' " + form);
  }
  EXPECT_THROW_MSG(linked_grid({"a=1:3:3", "b=1"}, {"c <= a"}), UsageError,
                   "--where: c is not a varied key (known: a, b)");
  EXPECT_THROW_MSG(linked_grid({"a=1:3:3", "b=x,1"}, {"b <= a"}), UsageError,
                   "--where: b takes names ('x'), not numbers only");
  EXPECT_THROW_MSG(linked_grid({"a=1:3:3"}, {"1 < 2"}), UsageError,
                   "--where: '1 < 2' names no varied key");
  EXPECT_THROW_MSG(linked_grid({"a=1:3:3"}, {"a > 3"}), UsageError,
                   "--where: no row of the 3 candidates passes a > 3");
}

TEST(SweepGrid, ShardsTakeEveryNthRow) {
  EXPECT_EQ(parse_shard("0/1"), (Shard{0, 1}));
  EXPECT_EQ(parse_shard("3/4"), (Shard{3, 4}));
  const Shard s = parse_shard("2/4");
  EXPECT_EQ(s.rows_of(10), 2u);  // rows 2 and 6
  EXPECT_EQ(s.row(0), 2u);
  EXPECT_EQ(s.row(1), 6u);
  EXPECT_EQ(parse_shard("3/4").rows_of(3), 0u);
  EXPECT_EQ(parse_shard("0/4").rows_of(1), 1u);
  std::uint64_t total = 0;
  for (std::uint64_t i = 0; i < 7; ++i) total += Shard{i, 7}.rows_of(100);
  EXPECT_EQ(total, 100u);
}

TEST(SweepGrid, BadShards) {
  for (const char* text :
       {"", "1", "4/4", "5/4", "0/0", "-1/4", "+1/4", "1/4x", " 1/4", "1/2/3", "0/1000001"}) {
    EXPECT_THROW_MSG(parse_shard(text), UsageError,
                     std::string("--shard: '") + text + "' is not I/N with 0 <= I < N <= 1000000");
  }
}

TEST(SweepCsv, IdentityLineRoundTrip) {
  const SweepIdentity id{0x0123456789abcdefULL, 0xfedcba9876543210ULL, 41, {2, 5}};
  const std::string line = identity_line(id);
  EXPECT_EQ(line,
            "# mdrsim sweep: scene 0123456789abcdef, grid fedcba9876543210, rows 41, shard 2/5\n");
  EXPECT_EQ(parse_identity_line(line.substr(0, line.size() - 1)), id);
}

TEST(SweepCsv, OnlyTheExactIdentityLineIsOne) {
  for (const char* line : {
           "",
           "status,a",
           "# mdrsim sweep: scene 0123456789abcdef, grid fedcba9876543210, rows 41, shard 5/5",
           "# mdrsim sweep: scene 0123456789abcdef, grid fedcba9876543210, rows 41, shard 0/0",
           "# mdrsim sweep: scene 123456789abcdef, grid fedcba9876543210, rows 41, shard 0/1",
           "# mdrsim sweep: scene 0123456789ABCDEF, grid fedcba9876543210, rows 41, shard 0/1",
           "# mdrsim sweep: scene 0123456789abcdef, grid fedcba9876543210, rows +41, shard 0/1",
           "# mdrsim sweep: scene 0123456789abcdef, grid fedcba9876543210, rows 41, shard 0/1 ",
           "# mdrsim sweep: scene 0123456789abcdef, grid fedcba9876543210, rows 041, shard 0/1",
       }) {
    EXPECT_FALSE(parse_identity_line(line)) << line;
  }
}

TEST(SweepCsv, SceneHashCoversTheFileAndEverySet) {
  const std::uint64_t plain = scene_hash("[a]\nb = 1\n", {});
  EXPECT_EQ(plain, fnv1a("[a]\nb = 1\n"));
  EXPECT_NE(scene_hash("[a]\nb = 1\n", {"a.b=2"}), plain);
  EXPECT_EQ(scene_hash("[a]\nb = 1\n", {"a.b=2"}),
            fnv1a(std::string("[a]\nb = 1\n") + '\0' + "a.b=2"));
  EXPECT_NE(scene_hash("x", {"a=1", "b=2"}), scene_hash("x", {"b=2", "a=1"}));
}

TEST(SweepCsv, HeaderNamesEveryVariedKey) {
  const SweepGrid grid = grid_of({"material.poisson_ratio=0:0.3:2", "detachment.criterion=stress"});
  const std::string header = csv_header(grid, {});
  EXPECT_EQ(header.rfind(
                "status,stop_reason,material.poisson_ratio,detachment.criterion,normal_force,", 0),
            0u);
  EXPECT_EQ(header.find("dimensionless"), std::string::npos);
  EXPECT_EQ(header.find("sliding"), std::string::npos);
  EXPECT_NE(csv_header(grid, {.dimensionless = true}).find(",dimensionless_normal_force,"),
            std::string::npos);
  // Friction's columns come last, after disk_valid: the columns before keep their places.
  const std::string friction = csv_header(grid, {.friction = true});
  EXPECT_EQ(friction.substr(0, header.size() - 1), header.substr(0, header.size() - 1));
  EXPECT_EQ(friction.substr(header.size() - 1),
            ",springs_sliding,stick_radius,sliding,dissipated_by_friction\n");
  EXPECT_EQ(header.back(), '\n');
}

}  // namespace
}  // namespace mdrsim::cli
