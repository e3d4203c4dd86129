// One half of the symmetric MDR foundation under the glued contact (paper eq. 7).
#pragma once

#include <cstdint>
#include <memory>

#include "profiles/profile.hpp"

namespace mdrsim {

/// Springs i = 1..N at x_i = i a_g / N: the boundary spring of i attached springs sits at the
/// contact radius x_i. Only the springs the glued contact can hold exist. Positions are computed
/// on demand; images are kept from the one pass that sums them on rows of up to 2^20 springs
/// (the pull-off asks for each again as its spring becomes the boundary), computed on demand
/// on longer ones and where the profile's are cheap (Profile::cheap_image).
class SpringFoundation {
 public:
  SpringFoundation(const Profile& profile, double glued_radius, std::int64_t springs);

  std::int64_t springs() const { return springs_; }
  double glued_radius() const { return glued_radius_; }  ///< a_g [m]
  double spacing() const { return spacing_; }            ///< dx [m]
  double position(std::int64_t i) const {                ///< x_i [m]
    // The outermost spring sits exactly at the glued radius, whatever the rounding of dx.
    return i == springs_ ? glued_radius_ : spacing_ * static_cast<double>(i);
  }
  double image(std::int64_t i) const {  ///< g(x_i) [m]
    return images_ ? images_[static_cast<std::size_t>(i - 1)] : profile_->mdr_image(position(i));
  }
  double total_image() const { return total_image_; }  ///< sum of g(x_i), i = 1..N [m]
  /// sum of g(x_i)^2, i = 1..N [m^2]: the work of pressing the row in (pull_off.cpp).
  double total_image_squares() const { return total_image_squares_; }
  const Profile& profile() const { return *profile_; }

 private:
  const Profile* profile_;
  double glued_radius_;
  std::int64_t springs_;
  double spacing_;
  double total_image_;
  double total_image_squares_ = 0.0;
  /// g(x_i) as the sum took them, on rows of up to kKeptImages springs; shared by copies.
  std::shared_ptr<const double[]> images_;
};

}  // namespace mdrsim
