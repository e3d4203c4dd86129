// docs: every number of a result is finite. One check for the command and the fuzz harness.
#pragma once

#include <optional>
#include <string>

#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The first number of the result (SI, and dimensionless where the JSON has it) that is not
/// finite, as "where.name = value (dimensionless scale s)"; empty when all are finite.
std::optional<std::string> first_not_finite(const Scene& scene, const RunResult& result);

}  // namespace mdrsim
