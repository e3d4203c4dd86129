// The default thread count follows the affinity mask, not the machine (taskset, SLURM).
#include "engine/base/available_cpus.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <thread>

namespace mdrsim::test {
namespace {

/// Runs `body` in a fresh thread whose mask is the first CPU of this process's mask alone
/// (sched_getaffinity(0) reads the calling thread's mask, which a new thread inherits).
template <class Body>
void on_one_cpu(Body body) {
  std::thread worker([&] {
    cpu_set_t mask;
    CPU_ZERO(&mask);
    ASSERT_EQ(sched_getaffinity(0, sizeof mask, &mask), 0);
    int first = 0;
    while (first < CPU_SETSIZE && !CPU_ISSET(first, &mask)) ++first;
    ASSERT_LT(first, CPU_SETSIZE);
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    body();
  });
  worker.join();
}

TEST(AvailableCpus, CountsTheAffinityMask) {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  ASSERT_EQ(sched_getaffinity(0, sizeof mask, &mask), 0);
  EXPECT_EQ(available_cpus(), CPU_COUNT(&mask));
}

TEST(AvailableCpus, OneCpuUnderAMaskOfOne) {
  // What `taskset -c 0` or a one-CPU SLURM allocation gives, whatever the machine has.
  on_one_cpu([] { EXPECT_EQ(available_cpus(), 1); });
}

}  // namespace
}  // namespace mdrsim::test
