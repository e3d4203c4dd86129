// The log observer asks for an event kind only where spdlog would print it: a program under
// rtol runs its finest row again only for an observer that wants that row's events
// (program_resolution.cpp), and at --log-level warn the log wants none of them.
#include "engine/events/log_observer.hpp"

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

namespace mdrsim {
namespace {

/// Sets spdlog's level for one test and puts the old one back.
class LogLevel {
 public:
  explicit LogLevel(spdlog::level::level_enum level) : saved_(spdlog::get_level()) {
    spdlog::set_level(level);
  }
  ~LogLevel() { spdlog::set_level(saved_); }
  LogLevel(const LogLevel&) = delete;
  LogLevel& operator=(const LogLevel&) = delete;

 private:
  spdlog::level::level_enum saved_;
};

TEST(LogObserver, WantsWhatTheLevelPrints) {
  const LogObserver log;
  {
    const LogLevel info(spdlog::level::info);
    EXPECT_TRUE(log.wants(EventKind::stage_end));
    EXPECT_TRUE(log.wants(EventKind::jump));
    EXPECT_TRUE(log.wants(EventKind::preload_reached));
    EXPECT_FALSE(log.wants(EventKind::spring_detached));
    EXPECT_FALSE(log.wants(EventKind::sample));
  }
  {
    const LogLevel warn(spdlog::level::warn);
    EXPECT_FALSE(log.wants(EventKind::stage_end));
    EXPECT_FALSE(log.wants(EventKind::jump));
    EXPECT_FALSE(log.wants(EventKind::preload_reached));
    EXPECT_FALSE(log.wants(EventKind::spring_detached));
  }
  {
    const LogLevel debug(spdlog::level::debug);
    EXPECT_TRUE(log.wants(EventKind::spring_detached));
    EXPECT_TRUE(log.wants(EventKind::spring_slipped));
    EXPECT_FALSE(log.wants(EventKind::step_accepted));
  }
}

}  // namespace
}  // namespace mdrsim
