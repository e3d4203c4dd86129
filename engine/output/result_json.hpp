// The JSON result of `mdrsim run` (docs/outputs.md "The JSON result").
#pragma once

#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "engine/base/pull_off_scales.hpp"
#include "engine/model/dimensionless_scales.hpp"
#include "engine/model/jkr_scales.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The controllers on each axis (normal, tangential): the shorthand's, or those in force at
/// the end of a program's first `stages_run` stages (all of them by default; a program that
/// stops early reports the stage it stopped in).
std::pair<std::string, std::string> final_controls(
    const Scene& scene, std::size_t stages_run = std::numeric_limits<std::size_t>::max());

/// Scales of the dimensionless output: a parabolic tip's (eq. 17) or the profile's own closed
/// form (cone, power law n > 1/2, flat punch); none without adhesion or a closed form.
std::optional<PullOffScales> dimensionless_scales(const Scene& scene);

/// Maugis' lambda of a parabolic or spherical tip with finite-range adhesion (docs/maugis.md),
/// else none: the JSON's dimensionless.maugis_parameter.
std::optional<double> maugis_parameter(const Scene& scene);

/// The result, then what produced it: the material's effective values, the preload, the
/// scales, the resolution run, the program version and the resolved scene (docs).
nlohmann::ordered_json result_to_json(const Scene& scene, const RunResult& result);

}  // namespace mdrsim
