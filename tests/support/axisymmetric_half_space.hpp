// A ring boundary-element solution of the elastic half-space under an axisymmetric pressure,
// with a Dugdale stress on (a, c): the check of the MDR's Maugis-Dugdale states that uses no
// Abel transform, only Boussinesq's ring kernel.
//
// Signs. z points into the half-space; p(r) > 0 presses (compression), and the surface moves
// into the body by
//   u(r) = (4 / (pi E*)) int_0^c p(s) s / (r + s) K(k) ds,   k = 2 sqrt(r s) / (r + s),
// (the Boussinesq ring load integrated over the angle; a uniform p0 on r < c gives
// u(0) = 2 p0 c / E*). The rigid indenter's tip sits at depth d, so its surface is at
// z = d - f(r). The gap, the indenter's surface above the body's, is
//   h(r) = u(r) - (d - f(r)) = f(r) - d + u(r),
// zero on the contact r < a (u = d - f there), h0 = dgamma / sigma_0 at the cohesive edge c,
// where the Dugdale zone a < r < c pulls with the tensile stress sigma_0, i.e. p = -sigma_0.
// The force F = int_0^c 2 pi r p(r) dr is positive when it presses, as the engine's.
//
// Near a the contact pressure of a given (d, a, c) is B / sqrt(a^2 - r^2) plus a bounded part;
// the body's tensile stress -p there is K_I / sqrt(2 pi (a - r)), so K_I = -B sqrt(pi / a).
// Maugis' condition is K_I = 0. The unknown is w = p cos(phi) on r = a sin(phi), which is
// smooth in phi up to phi = pi/2 for both a bounded and a square-root singular pressure
// (sqrt(a^2 - r^2) = a cos(phi)); then B = a w(pi/2) and p ds = a w dphi.
//
// Discretization: phi = (pi/2) tau^q / (tau^q + (1 - tau)^q) with tau cut into n equal elements
// (q > 1 grades the elements towards the axis, where the cone's pressure has its log
// singularity, and towards a, where K_I is read); on each element w is the polynomial through
// its values at the element's P Gauss-Legendre points, which are the collocation points of
// u = d - f. The log singularity of K at s = r is integrated by
// tanh-sinh rules from the singular point and by Gauss-Legendre on pieces whose length is their
// distance to it (so every rule converges geometrically), the dense system solved by LU.
#pragma once

#include <functional>
#include <vector>

namespace mdrsim::test {

/// K(k) [1] from the complementary modulus k' = sqrt(1 - k^2), by the arithmetic-geometric
/// mean: given k' directly, it keeps its precision at the log singularity k -> 1.
double elliptic_k_of_complement(double complementary_modulus);

/// The Boussinesq ring kernel s / (r + s) K(k) [1] with the signed offset s - r given apart, so
/// that k' = |s - r| / (r + s) is exact near the singular point.
double ring_kernel(double r, double s, double offset);

/// u(r) [m] under a uniform pressure [Pa] on the annulus inner < s < outer [m] of a half-space of
/// modulus E* [Pa], by quadrature of the ring kernel (no closed form used).
double annulus_displacement(double effective_modulus, double pressure, double inner, double outer,
                            double r);

/// One axisymmetric contact with a Dugdale zone, given (d, a, c): the contact pressure on r < a is
/// the unknown, the stress -sigma_0 is imposed on a < r < c.
struct DugdaleHalfSpaceProblem {
  std::function<double(double)> shape;  ///< f(r) [m]
  double effective_modulus = 0.0;       ///< E* [Pa]
  double adhesive_stress = 0.0;         ///< sigma_0 [Pa] (0: no zone)
  double contact_radius = 0.0;          ///< a [m]
  double cohesive_radius = 0.0;         ///< c [m] (a: no zone)
  double indentation = 0.0;             ///< d [m]
};

/// The ring mesh: n elements in tau, P points each, the grading q of phi(tau).
struct RingMesh {
  int elements = 16;
  int points = 5;
  int grading = 1;
};

class DugdaleHalfSpace {
 public:
  DugdaleHalfSpace(DugdaleHalfSpaceProblem problem, RingMesh mesh);

  double normal_force() const;  ///< int_0^c 2 pi r p dr [N], positive when pressing
  /// u(r) [m] of the solved pressure, at any r >= 0.
  double displacement(double r) const;
  double gap(double r) const;  ///< f(r) - d + u(r) [m]
  /// K_I [Pa m^(1/2)] at the contact edge, from w extrapolated to phi = pi/2 on the last element.
  double stress_intensity() const;
  double pressure(double r) const;  ///< p(r) [Pa] on 0 < r < c

 private:
  double phi_of_tau(double tau) const;
  double phi_slope(double tau) const;  ///< dphi/dtau
  /// phi(tau) - phi(sigma), with tau - sigma given apart: exact where they are close.
  double phi_difference(double tau, double sigma, double difference) const;
  double phi_complement(double tau) const;  ///< pi/2 - phi(tau)
  double tau_of_radius(double r) const;
  /// w on element e at its local coordinate xi in [-1, 1].
  double w_at(int e, double xi) const;
  /// The ring integrals a int L_m(xi) K-kernel(r, s) dphi over element f of its Lagrange
  /// polynomials, seen from r (tau_r: where r sits in tau, or the near end's stand-in beyond 1).
  std::vector<double> element_moments(int f, double r, double tau_r) const;
  /// The zone's part of u(r) times pi E* / 4.
  double zone_part(double r) const;

  DugdaleHalfSpaceProblem problem_;
  RingMesh mesh_;
  std::vector<double> nodes_;  ///< the P Gauss-Legendre points on [-1, 1]
  std::vector<double> w_;      ///< w at element e's point j: w_[e * P + j] [Pa]
};

/// A sequence of values at meshes refined by 2: Richardson's extrapolation from the last three
/// with the order they show, log2 of the ratio of successive changes.
struct Richardson {
  double value = 0.0;  ///< the extrapolated limit
  double order = 0.0;  ///< observed order of convergence (0 where the changes do not shrink)
};
Richardson richardson(const std::vector<double>& values);

}  // namespace mdrsim::test
