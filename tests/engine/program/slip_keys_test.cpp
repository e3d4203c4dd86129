// The flat slip keys against a std::set of (key, spring) pairs, the structure they replace.
#include "engine/program/slip_keys.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <utility>

namespace {

using mdrsim::SlipKeys;
using Pair = std::pair<double, std::int64_t>;

/// The reference: the two ordered sets FrictionRow kept before (the first forward, the last
/// backward pair), and the keys each spring has in them.
struct Reference {
  std::set<Pair> forward;
  std::set<Pair> backward;
  std::map<std::int64_t, std::pair<double, double>> keys;
  void insert(std::int64_t i, double f, double b) {
    erase(i);
    forward.insert({f, i});
    backward.insert({b, i});
    keys[i] = {f, b};
  }
  void erase(std::int64_t i) {
    const auto at = keys.find(i);
    if (at == keys.end()) return;
    forward.erase({at->second.first, i});
    backward.erase({at->second.second, i});
    keys.erase(at);
  }
};

void expect_same(const SlipKeys& keys, const Reference& reference) {
  ASSERT_EQ(keys.size(), static_cast<std::int64_t>(reference.keys.size()));
  ASSERT_EQ(keys.empty(), reference.keys.empty());
  if (reference.keys.empty()) return;
  // Exact: the structure only picks among the keys it was given.
  EXPECT_EQ(keys.forward_first().value, reference.forward.begin()->first);
  EXPECT_EQ(keys.forward_first().spring, reference.forward.begin()->second);
  EXPECT_EQ(keys.backward_last().value, reference.backward.rbegin()->first);
  EXPECT_EQ(keys.backward_last().spring, reference.backward.rbegin()->second);
}

void random_changes(std::size_t max_runs);

TEST(SlipKeys, RandomChangesGiveTheFirstKeysOfOrderedSets) {
  // Runs only (no limit), runs then the tree (a few runs at most), the tree from the start.
  for (const std::size_t max_runs : {std::size_t{1} << 40U, std::size_t{6}, std::size_t{0}}) {
    random_changes(max_runs);
    if (HasFailure()) return;
  }
}

TEST(SlipKeys, RandomRunsOfNeighbours) {
  // Springs join and leave at the ends of runs with rising or falling keys, as a row's do, with
  // now and then one out of order: the runs must split, join and hold their least at an end.
  for (const std::size_t max_runs : {std::size_t{1} << 40U, std::size_t{3}}) {
    std::mt19937_64 random(7);
    SlipKeys keys(max_runs);
    Reference reference;
    std::int64_t next = 1;
    for (int step = 0; step < 20000; ++step) {
      const int op = static_cast<int>(random() % 10);
      while (reference.keys.count(next) == 1) ++next;
      if (op < 6 && next <= 500) {
        const double slope = (step / 100) % 2 == 0 ? 1.0 : -1.0;  // runs that rise, then fall
        const double f = op == 0 ? static_cast<double>(random() % 7) : slope * next;
        keys.insert(next, f, -f);
        reference.insert(next, f, -f);
        ++next;
      } else if (!reference.keys.empty()) {
        // The first forward spring, the last backward, or any spring.
        std::int64_t i = reference.forward.begin()->second;
        if (op == 7) i = reference.backward.rbegin()->second;
        if (op == 8) i = std::next(reference.keys.begin(), random() % reference.keys.size())->first;
        keys.erase(i);
        reference.erase(i);
        if (op == 9 && next > 1) next = 1 + static_cast<std::int64_t>(random() % (next - 1));
      }
      expect_same(keys, reference);
      if (HasFailure()) return;
    }
  }
}

void random_changes(std::size_t max_runs) {
  std::mt19937_64 random(21);
  // Few distinct values, so that ties (broken by the spring index) are common.
  std::uniform_int_distribution<int> value(-20, 20);
  std::uniform_int_distribution<int> op(0, 2);
  SlipKeys keys(max_runs);
  Reference reference;
  std::int64_t top = 1;  // the index range grows like a row's contact set, past a few regrowths
  for (int step = 0; step < 20000; ++step) {
    top = std::min<std::int64_t>(top + (step % 3 == 0 ? 1 : 0), 700);
    const std::int64_t i = std::uniform_int_distribution<std::int64_t>(1, top)(random);
    if (op(random) == 0 || reference.keys.count(i) == 1) {
      keys.erase(i);
      reference.erase(i);
    } else {
      const double f = 0.25 * value(random);
      const double b = 0.25 * value(random);
      keys.insert(i, f, b);
      reference.insert(i, f, b);
    }
    EXPECT_EQ(keys.contains(i), reference.keys.count(i) == 1);
    expect_same(keys, reference);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(SlipKeys, ARunInsertedInOrderAndTakenFromItsFront) {
  // A row pressed spring by spring (forward keys falling with i) then slipping from its edge:
  // one run, whatever the limit on runs.
  SlipKeys keys(1);
  const std::int64_t n = 1000;
  for (std::int64_t i = 1; i <= n; ++i) keys.insert(i, -static_cast<double>(i), 2.0 * i);
  for (std::int64_t i = n; i >= 1; --i) {
    ASSERT_EQ(keys.forward_first().spring, i);
    ASSERT_EQ(keys.backward_last().spring, i);
    keys.erase(i);
  }
  EXPECT_TRUE(keys.empty());
  EXPECT_EQ(keys.forward_first().spring, 0);
}

}  // namespace
