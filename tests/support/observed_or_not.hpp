// A scene run twice, unobserved and with every event observed: the engine's shortcuts taken in
// bulk where nobody observes single springs must give the loop's numbers (bulk_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "engine/events/event_recorder.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim::test {

struct ObservedOrNot {
  RunResult bulk;        ///< no observer: the shortcuts in bulk
  RunResult one_by_one;  ///< an observer of every event: the loop takes each one
  EventRecorder recorder;
};

inline ObservedOrNot run_observed_or_not(const std::string& text) {
  const Scene scene = build_scene_text(text);
  ObservedOrNot p;
  p.bulk = run_scene(scene, {});
  ObserverList observers;
  observers.add(p.recorder);
  p.one_by_one = run_scene(scene, observers);
  return p;
}

/// Every number of two states to the bit.
inline void expect_same_state(const ContactSnapshot& a, const ContactSnapshot& b,
                              const std::string& what) {
  EXPECT_EQ(a.indentation, b.indentation) << what;
  EXPECT_EQ(a.normal_force, b.normal_force) << what;
  EXPECT_EQ(a.contact_radius, b.contact_radius) << what;
  EXPECT_EQ(a.tangential_displacement, b.tangential_displacement) << what;
  EXPECT_EQ(a.tangential_force, b.tangential_force) << what;
  EXPECT_EQ(a.springs_in_contact, b.springs_in_contact) << what;
  EXPECT_EQ(a.springs_sliding, b.springs_sliding) << what;
  EXPECT_EQ(a.stick_radius, b.stick_radius) << what;
}

}  // namespace mdrsim::test
