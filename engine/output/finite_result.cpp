// Checks every number of the result before anything is written.
#include "engine/output/finite_result.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "engine/output/finite_check.hpp"

namespace mdrsim::cli {

void require_finite(const Scene& scene, const RunResult& result) {
  if (const auto bad = first_not_finite(scene, result)) {
    throw std::runtime_error(fmt::format(
        "the run gave {}, not a finite number; the scene's values may be too extreme for double "
        "precision",
        *bad));
  }
}

}  // namespace mdrsim::cli
