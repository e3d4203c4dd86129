// The progress lines of a long sweep: one per interval, rows written, the time to go at the
// rate so far (rows already in a resumed CSV do not count towards the rate).
#include "engine/sweep/sweep_progress.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace mdrsim::cli {
namespace {

using std::chrono::seconds;

TEST(SweepProgress, OneLinePerIntervalWithTheTimeToGo) {
  const SweepProgress::Clock::time_point start{};
  SweepProgress progress(0, 100, start);
  EXPECT_FALSE(progress.line(10, start + seconds(9)));
  const auto first = progress.line(20, start + seconds(10));
  ASSERT_TRUE(first);
  // 20 rows in 10 s: the other 80 take 40 s.
  EXPECT_EQ(*first, "sweep: 20 of 100 rows in 10 s, about 40 s to go");
  EXPECT_FALSE(progress.line(25, start + seconds(19)));
  const auto second = progress.line(40, start + seconds(20));
  ASSERT_TRUE(second);
  EXPECT_EQ(*second, "sweep: 40 of 100 rows in 20 s, about 30 s to go");
  EXPECT_FALSE(progress.line(100, start + seconds(60)));  // done: the closing line says so
}

TEST(SweepProgress, ResumedRowsDoNotCountTowardsTheRate) {
  const SweepProgress::Clock::time_point start{};
  SweepProgress progress(900, 1000, start);
  EXPECT_EQ(*progress.line(900, start + seconds(10)), "sweep: 900 of 1000 rows in 10 s");
  // 10 new rows in 20 s: 90 to go take 180 s.
  EXPECT_EQ(*progress.line(910, start + seconds(20)),
            "sweep: 910 of 1000 rows in 20 s, about 3 min to go");
}

TEST(SweepProgress, RoughDurations) {
  EXPECT_EQ(rough_duration(0.4), "0 s");
  EXPECT_EQ(rough_duration(99), "99 s");
  EXPECT_EQ(rough_duration(100), "2 min");
  EXPECT_EQ(rough_duration(5939), "99 min");
  EXPECT_EQ(rough_duration(9000), "2.5 h");
  EXPECT_EQ(rough_duration(3600 * 40), "40 h");
}

}  // namespace
}  // namespace mdrsim::cli
