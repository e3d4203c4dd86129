// JKR (eqs. 19, 33) and one tangential point of Fig. 3a (eqs. 29, 31-33) at u = 2 d0.
#include "bench/bench_cases.hpp"

#include "engine/reference/parabolic_reference.hpp"

namespace mdrsim::bench {

std::vector<BenchCase> paper_cases() {
  namespace ref = parabolic_reference;
  std::vector<BenchCase> cases;
  for (const char* normal : {"fixed-load", "fixed-grips"}) {
    const bool load = std::string(normal) == "fixed-load";
    test::JkrScenario jkr;
    jkr.normal = normal;
    cases.push_back({"jkr", jkr,
                     load ? ref::fixed_load_critical(0).normal_force
                          : ref::fixed_grips_critical(0).normal_force});
    test::JkrScenario tangential = jkr;
    tangential.tangential_displacement = 2.0;
    cases.push_back({"fig3a-u2", tangential,
                     load ? ref::fixed_load_critical(2.0).normal_force
                          : ref::fixed_grips_critical(2.0).normal_force});
  }
  return cases;
}

}  // namespace mdrsim::bench
