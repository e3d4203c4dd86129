// A run's reported numbers must be finite (docs): a NaN or infinity is a failure, not a result.
#pragma once

#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim::cli {

/// Throws std::runtime_error (exit code 1) naming the first non-finite critical or
/// dimensionless value: in-range but extreme scene values can overflow the run.
void require_finite(const Scene& scene, const RunResult& result);

}  // namespace mdrsim::cli
