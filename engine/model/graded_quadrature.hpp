// The graded image of any shape with a slope f'(r), by quadrature: sphere, tables, wavy.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace mdrsim {

class ShapePreservingCubic;  // profiles/shape_preserving_cubic.hpp

/// What the graded image's quadrature needs of a shape: f'(r) and (r f'(r))' on its smooth
/// pieces, the radii between them, and where f' diverges.
class GradedShape {
 public:
  virtual ~GradedShape() = default;
  /// f'(r) [1] at r on piece `piece` (the pieces lie between the breakpoints below: piece j is
  /// (b_(j-1), b_j), piece 0 starts at 0; r may lie a rounding outside it).
  virtual double slope(double r, std::size_t piece) const = 0;
  /// (r f'(r))' = f' + r f'' [1] on piece `piece`.
  virtual double radial_slope_derivative(double r, std::size_t piece) const = 0;
  /// How many breakpoints lie below x [m]: the radii, ascending and > 0, where f' is not
  /// analytic (a table's knots) or where the quadrature splits it (a ripple's quarter
  /// wavelengths).
  virtual std::size_t breakpoints_below(double x) const = 0;
  /// Breakpoint j (j = 0, 1, ...) [m].
  virtual double breakpoint(std::size_t j) const = 0;
  /// Where f' diverges (the sphere's radius R) [m]: g_k is +infinity from there on.
  virtual double pole_radius() const { return std::numeric_limits<double>::infinity(); }
  /// The largest radius the shape is given on [m] (a table's last point; the pole), as
  /// Profile::outer_radius: a preload is refused beyond it.
  virtual double outer_radius() const { return pole_radius(); }
};

/// R - sqrt(R^2 - r^2): f' = r / sqrt(R^2 - r^2), its pole at R.
std::shared_ptr<const GradedShape> graded_sphere(double radius);
/// r^2 / (2R) + A (1 - cos(2 pi r / lambda)), split every quarter wavelength (each piece's
/// ripple a quarter period: few nodes follow it).
std::shared_ptr<const GradedShape> graded_wavy(double radius, double amplitude, double wavelength);
/// The shape-preserving cubic of a table: its pieces are the cubic's, f'' jumps at the knots.
std::shared_ptr<const GradedShape> graded_table(const ShapePreservingCubic& shape);

/// g_k(x) = x int_0^(pi/2) f'(x cos s) sin^k s ds (r = x cos s in the defining integral
/// |x|^(1-k) int_0^x f'(r) (x^2 - r^2)^((k-1)/2) dr, whose (x^2 - r^2) singularity becomes
/// the bounded weight sin^k s). The s-range splits at the breakpoints' angles; the piece at
/// s = 0 takes a Gauss-Jacobi rule with the weight s^k (its non-smooth part) and the smooth
/// rest (sin s / s)^k f', every other piece Gauss-Legendre, each no longer than its distance
/// from s = 0 (and the first none longer than the distance acosh(R/x) to f''s pole): every
/// piece's integrand is analytic in an ellipse of ratio 3 + sqrt(8) about it, and 20 nodes
/// leave an error of about 5.8^-40 of its size, rounding (1e-15) what remains. So on g_k' and
/// nf_k (below), and on the squared gap's outer integral over x (see squared_gap_integral),
/// except at a table's knots, where g_k itself is not analytic.
class GradedQuadrature {
 public:
  GradedQuadrature(std::shared_ptr<const GradedShape> shape, double grading_exponent);

  double image(double x) const;        ///< g_k(x) [m], +infinity at and beyond the pole
  double image_slope(double x) const;  ///< g_k'(x) = int_0^(pi/2) (r f')'(x cos s) sin^k s ds
  /// nf_k(a) = (1 + k) int_0^a x^k (g_k(a) - g_k(x)) dx = int_0^a f'(r) r^2 (a^2 - r^2)^((k-1)/2)
  /// dr (the order of the double integral exchanged) = a^k int_0^(pi/2) r^2 f'(r) sin^k s ds.
  double nonadhesive_force_per_constant(double a) const;
  /// (1 + k) int_0^a x^k (d - g_k(x))^2 dx = d^2 a^(1+k) - 2 d (a^(1+k) g_k(a) - nf_k(a)) +
  /// (1 + k) int_0^a x^k g_k^2 dx, the last by Gauss-Jacobi on [0, min(b_0, a, P/2)] and
  /// Gauss-Legendre pieces between breakpoints beyond. A table's f'' jumps at a knot b, and g_k
  /// departs from a smooth function by (x - b)^((3+k)/2) beyond it: 20 nodes on the piece
  /// leave about 20^-(5+k) of that part (1e-7 of the jump's share of the energy), no
  /// quadrature being finer there. The energy alone takes it.
  double squared_gap_integral(double a, double d) const;
  double pole_radius() const { return shape_->pole_radius(); }
  bool has_pole() const { return std::isfinite(shape_->pole_radius()); }
  double outer_radius() const { return shape_->outer_radius(); }
  double grading_exponent() const { return grading_; }

 private:
  /// int_0^(pi/2) h(x cos s, piece) sin^k s ds [unit of h].
  template <class H>
  double angular_integral(double x, const H& h) const;

  std::shared_ptr<const GradedShape> shape_;
  double grading_;
  std::vector<double> jacobi_nodes_, jacobi_weights_;      ///< weight (1 + y)^k on [-1, 1]
  std::vector<double> legendre_nodes_, legendre_weights_;  ///< on [-1, 1]
};

/// Gauss-Jacobi nodes and weights for the weight (1 - y)^alpha (1 + y)^beta on [-1, 1]
/// (alpha, beta > -1), by Newton on the three-term recurrence: exact for polynomials of degree
/// up to 2 n - 1.
void gauss_jacobi_rule(int n, double alpha, double beta, std::vector<double>& nodes,
                       std::vector<double>& weights);

}  // namespace mdrsim
