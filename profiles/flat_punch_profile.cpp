// The flat punch: a zero image on the face and a wall (+infinity) beyond its edge.
#include "profiles/flat_punch_profile.hpp"

#include <cmath>
#include <limits>
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

}  // namespace mdrsim
