// JKR (eqs. 19, 33) and one tangential point of Fig. 3a (eqs. 29, 31-33) at u = 2 d0.
#include "bench/bench_cases.hpp"

#include <fmt/format.h>

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

std::string cycle_text(std::int64_t springs) {
  return fmt::format(
      "[material]\neffective_modulus = 1e6\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.05\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\n[[loading.stage]]\nnormal = {{ control = \"fixed-grips\", to = 2e-5 }}\n"
      "[[loading.stage]]\nnormal = {{ by = -2e-5 }}\nuntil = \"separation\"\n"
      "[discretization]\nsprings = {}\n",
      springs);
}

}  // namespace mdrsim::bench
