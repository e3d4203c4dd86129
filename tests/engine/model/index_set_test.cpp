// The bitset of spring indices against a std::set of them.
#include "engine/model/index_set.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>

namespace {

using mdrsim::IndexSet;

TEST(IndexSet, RandomChangesKeepTheSmallestMemberOfAnOrderedSet) {
  std::mt19937_64 random(21);
  IndexSet set;
  std::set<std::int64_t> reference;
  // Up to 300000 indices: three summary levels, and regrowth on the way.
  for (const std::int64_t top : {std::int64_t{70}, std::int64_t{5000}, std::int64_t{300000}}) {
    std::uniform_int_distribution<std::int64_t> index(1, top);
    for (int step = 0; step < 20000; ++step) {
      const std::int64_t i = index(random);
      if (random() % 2 == 0) {
        set.insert(i);
        reference.insert(i);
      } else {
        set.erase(i);
        reference.erase(i);
      }
      ASSERT_EQ(set.size(), static_cast<std::int64_t>(reference.size()));
      ASSERT_EQ(set.contains(i), reference.count(i) == 1);
      ASSERT_EQ(set.first(), reference.empty() ? 0 : *reference.begin());
    }
  }
  for (const std::int64_t i : reference) set.erase(i);
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
