// The flat punch: a zero image on the face and a wall (+infinity) beyond its edge.
#include "profiles/flat_punch_profile.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace mdrsim {
namespace {
constexpr double kWall = std::numeric_limits<double>::infinity();
}

FlatPunchProfile::FlatPunchProfile(double radius) : radius_(radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("the punch radius must be positive and finite");
  }
}

double FlatPunchProfile::shape(double r) const { return r <= radius_ ? 0.0 : kWall; }

double FlatPunchProfile::mdr_image(double x) const { return x <= radius_ ? 0.0 : kWall; }

// The slope at the edge is the face's (0): the spring row never reaches past it.
double FlatPunchProfile::mdr_image_slope(double x) const { return x <= radius_ ? 0.0 : kWall; }

double FlatPunchProfile::contact_radius_at_depth(double depth) const {
  return depth > 0.0 ? radius_ : 0.0;
}

double FlatPunchProfile::nonadhesive_force_per_modulus(double a) const {
  return a <= radius_ ? 0.0 : kWall;
}

// Every spring has g = 0 and the stretch -d, so the edge spring lets go at -d = dl(A) =
// sqrt(2 pi A dgamma/E*) and all follow: F = 2 E* A d there, under any normal control.
std::optional<PullOffScales> FlatPunchProfile::pull_off_scales(double effective_modulus,
                                                               double work_of_adhesion) const {
  if (!(work_of_adhesion > 0.0) || !(effective_modulus > 0.0)) return std::nullopt;
  const double depth = std::sqrt(2.0 * std::numbers::pi * radius_) * std::sqrt(work_of_adhesion) /
                       std::sqrt(effective_modulus);
  const double force = 2.0 * effective_modulus * radius_ * depth;
  for (const double s : {depth, force}) {
    if (!(s > 0.0) || !std::isfinite(s)) return std::nullopt;
  }
  return PullOffScales{force, radius_, depth,
                       "flat_punch: Kendall's pull-off, F0 = sqrt(8 pi A^3 E* dgamma), a0 = A, d0 "
                       "= sqrt(2 pi A dgamma/E*)"};
}

}  // namespace mdrsim
