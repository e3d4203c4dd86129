// The scales of the dimensionless output: a parabolic tip's JKR scales, or the profile's own.
#pragma once

#include <optional>

#include "engine/base/material.hpp"
#include "engine/base/pull_off_scales.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// Eq. 17 for a profile with a parabolic tip (Profile::jkr_scale_radius), else the profile's
/// closed-form fixed-load pull-off (Profile::pull_off_scales); none without adhesion.
std::optional<PullOffScales> dimensionless_scales(const Profile& profile, const Material& material);

}  // namespace mdrsim
