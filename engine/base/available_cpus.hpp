// How many CPUs this process may run on: the default thread count of a sweep.
#pragma once

namespace mdrsim {

/// The CPUs in this process's affinity mask (sched_getaffinity), so that `taskset -c 0`, a
/// cgroup cpuset or a SLURM allocation is honoured; where the mask cannot be read, the
/// machine's hardware threads. At least 1.
int available_cpus();

}  // namespace mdrsim
