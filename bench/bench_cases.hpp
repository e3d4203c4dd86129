// The paper's scenes the bench measures, with their analytic critical forces.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"

namespace mdrsim::bench {

struct BenchCase {
  std::string name;            ///< e.g. "jkr" or "fig3a-u2"
  test::JkrScenario scenario;  ///< springs and method are set per measurement
  double exact_normal_force;   ///< F/F0 from the paper's closed forms
};

/// JKR under both normal controls, and the Fig. 3a point u = 2 d0 under each.
std::vector<BenchCase> paper_cases();

/// A reversible-JKR approach-retract cycle under fixed grips, to 2e-5 m and back until
/// separation, on `springs` springs (the driver's target 9 and the scene bench's cycle).
std::string cycle_text(std::int64_t springs);

}  // namespace mdrsim::bench
