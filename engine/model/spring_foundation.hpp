// One half of the symmetric MDR foundation under the glued contact (paper eq. 7).
#pragma once

#include <cstdint>
#include <memory>

#include "engine/model/graded_image.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// Springs i = 1..N at x_i = i a_g / N: the boundary spring of i attached springs sits at the
/// contact radius x_i. Only the springs the glued contact can hold exist. Positions are computed
/// on demand; images are kept from the one pass that sums them on rows of up to 2^20 springs
/// (the pull-off asks for each again as its spring becomes the boundary), computed on demand
/// on longer ones and where the profile's are cheap (Profile::cheap_image).
///
/// On a graded half-space (docs/graded.md) the images are g_k(x_i) and spring i carries the
/// stiffness of its cell ((i - 1) dx, i dx], both halves: w_i = 2 int c_k = C_k (x_i^(1+k) -
/// x_(i-1)^(1+k)). The cell's integral, not c_k(x_i) dx: |x|^k has an unbounded slope at 0,
/// where a sample misses the first springs' stiffness by a factor (1 + k) i^k / (i^(1+k) -
/// (i-1)^(1+k)) (1 + k at the first); the integral makes the n inner springs carry
/// C_k x_n^(1+k) exactly, the continuum's punch stiffness, as 2 E* x_n does at k = 0.
class SpringFoundation {
 public:
  SpringFoundation(const Profile& profile, double glued_radius, std::int64_t springs);
  /// The row on a graded half-space: `graded` its image (kept by the caller, the scene's),
  /// `punch_constant` C_k [Pa / m^k].
  SpringFoundation(const Profile& profile, double glued_radius, std::int64_t springs,
                   const GradedImage& graded, double punch_constant);

  std::int64_t springs() const { return springs_; }
  double glued_radius() const { return glued_radius_; }  ///< a_g [m]
  double spacing() const { return spacing_; }            ///< dx [m]
  double position(std::int64_t i) const {                ///< x_i [m]
    // The outermost spring sits exactly at the glued radius, whatever the rounding of dx.
    return i == springs_ ? glued_radius_ : spacing_ * static_cast<double>(i);
  }
  double image(std::int64_t i) const {  ///< g(x_i) [m]
    if (images_) return images_[static_cast<std::size_t>(i - 1)];
    return graded_ ? graded_->image(position(i)) : profile_->mdr_image(position(i));
  }
  /// The graded image where the half-space is graded, else null.
  const GradedImage* graded() const { return graded_; }
  /// w_i = C_k (x_i^(1+k) - x_(i-1)^(1+k)) [N/m]: spring i's stiffness, both halves (graded).
  double graded_stiffness(std::int64_t i) const;
  /// C_k x_n^(1+k) [N/m]: the n inner springs' stiffness together, both halves (graded).
  double graded_stiffness_to(std::int64_t n) const;
  double punch_constant() const { return punch_constant_; }  ///< C_k [Pa / m^k] (graded)
  /// sum of g(x_i), i = 1..N [m]; graded: sum of w_i g(x_i) [N].
  double total_image() const { return total_image_; }
  /// sum of g(x_i)^2, i = 1..N [m^2]: the work of pressing the row in (pull_off.cpp); graded:
  /// sum of w_i g(x_i)^2 [N m].
  double total_image_squares() const { return total_image_squares_; }
  const Profile& profile() const { return *profile_; }

 private:
  const Profile* profile_;
  double glued_radius_;
  std::int64_t springs_;
  double spacing_;
  double total_image_;
  double total_image_squares_ = 0.0;
  const GradedImage* graded_ = nullptr;
  double punch_constant_ = 0.0;
  /// g(x_i) as the sum took them, on rows of up to kKeptImages springs; shared by copies.
  std::shared_ptr<const double[]> images_;
};

}  // namespace mdrsim
