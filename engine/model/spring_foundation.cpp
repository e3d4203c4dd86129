// The spring row: spacing and the one O(N) pass that sums the profile's image (and its square).
#include "engine/model/spring_foundation.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "engine/base/interrupt_check.hpp"
#include "engine/model/compensated_sum.hpp"

namespace mdrsim {
namespace {

/// Rows of up to this many springs keep their images (8 MB at most) unless the profile's are
/// cheap: a row's loop asks for each spring's image again as it lets go, and a sphere's or a
/// table's costs more than the rest of the let-go; a parabola's costs less than the first touch
/// of the memory that would keep it.
constexpr std::int64_t kKeptImages = std::int64_t{1} << 20;

}  // namespace

SpringFoundation::SpringFoundation(const Profile& profile, double glued_radius,
                                   std::int64_t springs)
    : profile_(&profile),
      glued_radius_(glued_radius),
      springs_(springs),
      spacing_(glued_radius / static_cast<double>(springs)),
      total_image_(0.0) {
  if (springs < 1) throw std::invalid_argument("the foundation needs at least one spring");
  if (!(glued_radius > 0.0) || !std::isfinite(glued_radius)) {
    throw std::invalid_argument("the glued contact radius must be positive and finite");
  }
  CompensatedSum sum;
  CompensatedSum squares;
  std::shared_ptr<double[]> kept;
  if (springs <= kKeptImages && !profile.cheap_image()) {
    kept.reset(new double[static_cast<std::size_t>(springs)]);  // written below, spring by spring
  }
  for (std::int64_t i = 1; i <= springs; ++i) {
    // 1e8 springs take about 0.3 s here: a Ctrl-C from Python stops it too.
    if ((i & 0xFFFFF) == 0) poll_interrupt();
    const double g = profile_->mdr_image(position(i));
    sum.add(g);
    squares.add(g * g);
    if (kept) kept[static_cast<std::size_t>(i - 1)] = g;
  }
  images_ = std::move(kept);
  total_image_ = sum.value();
  total_image_squares_ = squares.value();
}

SpringFoundation::SpringFoundation(const Profile& profile, double glued_radius,
                                   std::int64_t springs, const GradedImage& graded,
                                   double punch_constant)
    : profile_(&profile),
      glued_radius_(glued_radius),
      springs_(springs),
      spacing_(glued_radius / static_cast<double>(springs)),
      total_image_(0.0),
      graded_(&graded),
      punch_constant_(punch_constant) {
  if (springs < 1) throw std::invalid_argument("the foundation needs at least one spring");
  if (!(glued_radius > 0.0) || !std::isfinite(glued_radius)) {
    throw std::invalid_argument("the glued contact radius must be positive and finite");
  }
  CompensatedSum sum;
  CompensatedSum squares;
  std::shared_ptr<double[]> kept;
  // A graded image costs a pow: kept wherever the row is short enough.
  if (springs <= kKeptImages) kept.reset(new double[static_cast<std::size_t>(springs)]);
  for (std::int64_t i = 1; i <= springs; ++i) {
    if ((i & 0xFFFFF) == 0) poll_interrupt();
    const double g = graded.image(position(i));
    const double w = graded_stiffness(i);
    sum.add(w * g);
    squares.add(w * g * g);
    if (kept) kept[static_cast<std::size_t>(i - 1)] = g;
  }
  images_ = std::move(kept);
  total_image_ = sum.value();
  total_image_squares_ = squares.value();
}

double SpringFoundation::graded_stiffness(std::int64_t i) const {
  // x_i^(1+k) (1 - (1 - 1/i)^(1+k)) by expm1 and log1p: the difference of two close powers
  // loses i digits' worth of rounding on long rows.
  const double p = 1.0 + graded_->grading_exponent();
  const double fraction = -std::expm1(p * std::log1p(-1.0 / static_cast<double>(i)));
  return punch_constant_ * std::pow(position(i), p) * fraction;
}

double SpringFoundation::graded_stiffness_to(std::int64_t n) const {
  if (n <= 0) return 0.0;
  return punch_constant_ * std::pow(position(n), 1.0 + graded_->grading_exponent());
}

}  // namespace mdrsim
