// The bitset of spring indices against a std::set of them.
#include "engine/program/index_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace {

using mdrsim::IndexSet;

TEST(IndexSet, RandomChangesKeepTheSmallestMemberOfAnOrderedSet) {
  std::mt19937_64 random(21);
  IndexSet set;
  std::set<std::int64_t> reference;
  const auto check = [&](std::int64_t i) {
    ASSERT_EQ(set.size(), static_cast<std::int64_t>(reference.size()));
    ASSERT_EQ(set.contains(i), reference.count(i) == 1);
    ASSERT_EQ(set.first(), reference.empty() ? 0 : *reference.begin());
  };
  // Up to 300000 indices: three summary levels, and regrowth on the way. Each round fills the
  // set at random, mixes insertions and erasures, then empties it in random order: every
  // summary bit is set and cleared again.
  for (const std::int64_t top : {std::int64_t{70}, std::int64_t{5000}, std::int64_t{300000}}) {
    std::uniform_int_distribution<std::int64_t> index(1, top);
    for (int round = 0; round < 3; ++round) {
      for (int step = 0; step < 3000; ++step) {
        const std::int64_t i = index(random);
        if (step < 1000 || random() % 2 == 0) {
          set.insert(i);
          reference.insert(i);
        } else {
          set.erase(i);
          reference.erase(i);
        }
        check(i);
        if (HasFatalFailure()) return;
      }
      std::vector<std::int64_t> members(reference.begin(), reference.end());
      std::shuffle(members.begin(), members.end(), random);
      for (const std::int64_t i : members) {
        set.erase(i);
        reference.erase(i);
        check(i);
        if (HasFatalFailure()) return;
      }
    }
  }
  EXPECT_TRUE(set.empty());
  EXPECT_EQ(set.first(), 0);
}

TEST(IndexSet, TheSmallestOfMembersFarApart) {
  IndexSet set;
  set.insert(1'000'000);
  set.insert(64);
  set.insert(4096);
  EXPECT_EQ(set.first(), 64);
  set.erase(64);
  EXPECT_EQ(set.first(), 4096);
  set.erase(4096);
  EXPECT_EQ(set.first(), 1'000'000);
  set.insert(1);
  EXPECT_EQ(set.first(), 1);
}

}  // namespace
