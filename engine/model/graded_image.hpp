// The MDR image of a power-law indenter on a graded half-space and its integrals with the
// graded springs' weight (docs/graded.md).
#pragma once

#include <memory>
#include <optional>
#include <string>

namespace mdrsim {

class GradedShape;       // engine/model/graded_quadrature.hpp
class GradedQuadrature;  // kept out of the public headers: the image's API is this class

/// g_k(x) = |x|^(1-k) int_0^|x| f'(r) (x^2 - r^2)^((k-1)/2) dr: for f(r) = c r^n K |x|^n with
/// K = c (n/2) B(n/2, (1+k)/2) (k = 0: the homogeneous image); for other shapes by quadrature
/// (graded_quadrature.hpp: the sphere, tables, wavy). A flat punch's image is 0 on its face
/// (K = 0), as without grading. Its integrals carry the springs' weight c_k(x) / c_k-scale =
/// (1 + k) x^k / 2 on each half of the row.
class GradedImage {
 public:
  /// f(r) = coefficient r^exponent [m^(1-n)], n > 0, on the medium's exponent k.
  static GradedImage of_power_law(double coefficient, double exponent, double grading_exponent);
  /// The flat punch: g_k = 0 on its face.
  static GradedImage of_flat_punch(double grading_exponent);
  /// The shape named by profile.type with its keys' values (parabolic radius, cone
  /// slope_angle_deg, power_law coefficient and exponent, flat_punch); none for the shapes
  /// with no closed form here (sphere, tabulated, wavy).
  static std::optional<GradedImage> of_profile(const std::string& type, double first, double second,
                                               double grading_exponent);
  /// Any shape with a slope f'(r), by quadrature (GradedQuadrature).
  static GradedImage by_quadrature(std::shared_ptr<const GradedShape> shape,
                                   double grading_exponent);

  double image(double x) const;        ///< g_k(x) [m]
  double image_slope(double x) const;  ///< g_k'(x) [1]
  /// nf_k(a) = (1 + k) int_0^a x^k (g_k(a) - g_k(x)) dx = K n a^(n+1+k) / (n+1+k) [m^(2+k)]:
  /// the non-adhesive force over C_k.
  double nonadhesive_force_per_constant(double a) const;
  /// (1 + k) int_0^a x^k (d - g_k(x))^2 dx [m^(3+k)]: twice the energy the row stores over C_k.
  double squared_gap_integral(double a, double d) const;
  /// The contact radius [m] where g_k(a) = d (d > 0; not for the flat punch). By quadrature:
  /// the first root of g_k(a) = d that a doubling search brackets (before the sphere's pole),
  /// as Profile::contact_radius_at_depth; std::domain_error where none is in reach.
  double radius_at_depth(double d) const;
  /// The radius [m] where C_k nf_k(a) = F (F > 0; not for the flat punch).
  double radius_at_force(double force, double punch_constant) const;

  double coefficient() const { return coefficient_; }   ///< K [m^(1-n)]; 0 by quadrature
  double exponent() const { return exponent_; }         ///< n [1]
  double grading_exponent() const { return grading_; }  ///< k [1]
  /// The quadrature the image takes, none in closed form.
  const GradedQuadrature* quadrature() const { return quadrature_.get(); }

 private:
  double coefficient_ = 0.0;
  double exponent_ = 1.0;
  double grading_ = 0.0;
  std::shared_ptr<const GradedQuadrature> quadrature_;  ///< shared by copies (immutable)
};

}  // namespace mdrsim
