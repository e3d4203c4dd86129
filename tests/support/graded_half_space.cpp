// The graded half-space's point force by its Hankel-transformed equations, and the punch's
// deflection by a quadrature of the point-force kernel (graded_half_space.hpp says how).
#include "tests/support/graded_half_space.hpp"

#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

namespace mdrsim::test {

double graded_point_force_compliance_by_hankel(double exponent, double youngs_modulus, double depth,
                                               double poisson_ratio) {
  using State = std::array<double, 4>;  // U, V, S, T at xi = 1, m = 1
  const double k = exponent;
  const double nu = poisson_ratio;
  const double lame = nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double shear = 1.0 / (2.0 * (1.0 + nu));
  // z = t^p with p = N / (1 - k): z^-k dz/dt = p t^(N-1), and z^k = t^(N k / (1 - k)), a whole
  // power of t where N makes it one (k = 0.1, 0.25, 0.5, 0.75, 0.9: N = 9, 3, 1, 1, 1), so
  // that the equations are smooth up to the surface where the modulus vanishes.
  int whole = 1;
  while (whole < 20 &&
         std::abs(whole * k / (1.0 - k) - std::round(whole * k / (1.0 - k))) > 1e-12) {
    ++whole;
  }
  const double p = whole / (1.0 - k);
  const double zk_power = whole * k / (1.0 - k);
  const auto rhs = [&](const State& y, State& dy, double t) {
    const double zk = std::pow(t, zk_power);
    const double scale = p * std::pow(t, whole - 1);                     // z^-k dz/dt
    const double du = (y[2] - lame * zk * y[1]) / (lame + 2.0 * shear);  // z^k U'
    dy[0] = scale * du;
    dy[1] = scale * (y[3] / shear + zk * y[0]);
    dy[2] = -scale * zk * y[3];
    dy[3] = scale * zk * ((lame + 2.0 * shear) * zk * y[1] + lame * du);
  };
  constexpr double kDeepest = 60.0;
  const double t_deep = std::pow(kDeepest, 1.0 / p);
  std::array<State, 2> surface;
  for (int j = 0; j < 2; ++j) {
    State y{0.0, 0.0, 0.0, 0.0};
    y[j] = 1.0;
    namespace odeint = boost::numeric::odeint;
    odeint::integrate_adaptive(
        odeint::make_controlled(1e-15, 1e-14, odeint::runge_kutta_fehlberg78<State>()), rhs, y,
        t_deep, 0.0, -1e-3 * t_deep);
    surface[j] = y;
  }
  // alpha_0 y0 + alpha_1 y1 with S = -1, T = 0 at the surface.
  const double det = surface[0][2] * surface[1][3] - surface[1][2] * surface[0][3];
  const double alpha0 = -surface[1][3] / det;
  const double alpha1 = surface[0][3] / det;
  const double u1 = alpha0 * surface[0][0] + alpha1 * surface[1][0];
  const double m_times_modulus = u1 * std::pow(2.0, k) * std::tgamma(0.5 * (1.0 + k)) /
                                 (2.0 * std::numbers::pi * std::tgamma(0.5 * (1.0 - k)));
  return m_times_modulus * std::pow(depth, k) / youngs_modulus;
}

double graded_punch_deflection(double exponent, double compliance, double a, double r) {
  const double k = exponent;
  // The point at (r, 0); a ray at angle phi leaves the disk at rho_max(phi), where the pressure
  // has its edge singularity (a^2 - s^2)^((k-1)/2), and the kernel rho^-k sits at rho = 0.
  boost::math::quadrature::tanh_sinh<double> radial;
  const auto along_ray = [&](double phi) {
    const double c = std::cos(phi);
    const double reach = -r * c + std::sqrt(a * a - r * r * (1.0 - c * c));
    const auto integrand = [&](double rho, double to_end) {
      // a^2 - s^2 = (rho_max - rho)(rho_max + rho + 2 r cos(phi)), kept apart from rounding.
      const double gap = to_end > 0.0 ? to_end : reach - rho;
      const double inside = gap * (reach + rho + 2.0 * r * c);
      if (!(inside > 0.0) || !(rho > 0.0)) return 0.0;
      return std::pow(inside, 0.5 * (k - 1.0)) * std::pow(rho, -k);
    };
    // The area element is rho drho dphi; the kernel 1/rho^(1+k) leaves rho^-k.
    return radial.integrate(integrand, 0.0, reach, 1e-13);
  };
  // Symmetric about phi = 0: twice the half turn, by Gauss-Kronrod (smooth in phi for r < a).
  const double half_turn = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      along_ray, 0.0, std::numbers::pi, 12, 1e-13);
  return 2.0 * compliance * half_turn;
}

double graded_punch_deflection_outside(double exponent, double compliance, double a, double r) {
  const double k = exponent;
  // A ray at angle phi from the line to the centre crosses the disk on the chord rho in
  // [mid - half, mid + half], mid = r cos(phi), half = sqrt(a^2 - r^2 sin^2 phi), where
  // a^2 - s^2 = half^2 (1 - u^2). The area element rho drho dphi over the kernel's rho^(1+k)
  // leaves rho^-k: the chord gives half^k int (mid + half u)^-k (1 - u^2)^((k-1)/2) du.
  boost::math::quadrature::tanh_sinh<double> along_chord;
  const auto over_chord = [&](double psi) {
    const double sin_phi = (a / r) * std::sin(psi);
    const double cos_phi = std::sqrt(1.0 - sin_phi * sin_phi);
    const double half = a * std::cos(psi);
    const double mid = r * cos_phi;
    const auto integrand = [&](double u) {
      const double edge = (1.0 - u) * (1.0 + u);
      if (!(edge > 0.0)) return 0.0;
      return std::pow(mid + half * u, -k) * std::pow(edge, 0.5 * (k - 1.0));
    };
    const double chord = std::pow(half, k) * along_chord.integrate(integrand, -1.0, 1.0, 1e-14);
    // dphi = (a / r) cos(psi) dpsi / cos(phi)
    return chord * (a / r) * std::cos(psi) / cos_phi;
  };
  // Both sides of the line to the centre: twice psi in [0, pi/2].
  const double half_fan = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      over_chord, 0.0, 0.5 * std::numbers::pi, 12, 1e-14);
  return 2.0 * compliance * half_fan;
}

}  // namespace mdrsim::test
