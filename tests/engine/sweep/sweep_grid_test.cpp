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
