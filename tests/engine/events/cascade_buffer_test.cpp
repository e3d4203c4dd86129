// The cascade buffer: held events come out in order, past its memory too, and a flight drops
// all but the critical state's.
#include "engine/events/cascade_buffer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "engine/events/event_recorder.hpp"

namespace mdrsim {
namespace {

Event let_go(std::int64_t spring, bool in_cascade) {
  return {.kind = EventKind::spring_detached, .spring = spring, .in_cascade = in_cascade};
}

std::vector<std::int64_t> springs(const EventRecorder& r) {
  std::vector<std::int64_t> out;
  for (const Event& e : r.events()) out.push_back(e.spring);
  return out;
}

// Two events in memory, the rest in the temporary file: a partial flush passes on the first
// ones in order and holds the rest, which a later flush passes on after them.
TEST(CascadeBuffer, FlushesInOrderAcrossItsMemoryAndItsFile) {
  EventRecorder recorder;
  ObserverList inner;
  inner.add(recorder);
  CascadeBuffer buffer(inner, 2);
  for (std::int64_t i = 1; i <= 7; ++i) buffer.on_event(let_go(i, i > 1));
  EXPECT_EQ(buffer.held(), 7u);
  buffer.flush(3);
  EXPECT_EQ(springs(recorder), (std::vector<std::int64_t>{1, 2, 3}));
  EXPECT_EQ(buffer.held(), 4u);
  buffer.on_event(let_go(8, true));
  buffer.flush();
  EXPECT_EQ(springs(recorder), (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(buffer.held(), 0u);
}

TEST(CascadeBuffer, AFlightKeepsOnlyTheLetGoAtTheCriticalState) {
  EventRecorder recorder;
  ObserverList inner;
  inner.add(recorder);
  CascadeBuffer buffer(inner, 2);
  for (std::int64_t i = 1; i <= 5; ++i) buffer.on_event(let_go(i, i > 1));
  buffer.discard_flight(true);
  EXPECT_EQ(springs(recorder), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(buffer.held(), 0u);
}

}  // namespace
}  // namespace mdrsim
