// The parabola's scales keep their paper form; other profiles name their own closed form.
#include "engine/model/dimensionless_scales.hpp"

#include "engine/model/jkr_scales.hpp"

namespace mdrsim {

std::optional<PullOffScales> dimensionless_scales(const Profile& profile,
                                                  const Material& material) {
  if (!(material.work_of_adhesion > 0.0)) return std::nullopt;
  // The scales are the homogeneous half-space's pull-off; a graded one has its own.
  if (material.grading.graded()) return std::nullopt;
  if (const auto tip = profile.jkr_scale_radius()) {
    const auto jkr = JkrScales::of(*tip, material.effective_modulus, material.work_of_adhesion);
    if (!jkr) return std::nullopt;
    return PullOffScales{jkr->force, jkr->radius, jkr->depth,
                         "parabolic tip of radius R (paper eq. 17): F0 = 1.5 pi R dgamma, a0 = (9 "
                         "pi R^2 dgamma/(8 E*))^(1/3), d0 = (3 pi^2 R dgamma^2/(64 E*^2))^(1/3)"};
  }
  return profile.pull_off_scales(material.effective_modulus, material.work_of_adhesion);
}

}  // namespace mdrsim
