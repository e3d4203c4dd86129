// Coulomb friction in the MDR apart from the engine: Cattaneo-Mindlin, Mindlin-Deresiewicz.
#pragma once

#include <cstdint>
#include <vector>

#include "profiles/profile.hpp"

namespace mdrsim::friction_reference {

// SI units. A non-adhesive contact pressed to depth d has radius a, g(a) = d, and every spring
// at x < a is pressed with the line load l_z(x) = E* (d - g(x)) [N/m] (both halves: the force is
// 2 int_0^a). Under Coulomb friction each spring is independent (MDR): with the indenter moved
// by u from where it touched, a spring sticks, l_x = G* u, while G* u <= mu l_z, and slides at
// l_x = mu l_z beyond.
//
// Cattaneo-Mindlin (constant d, u rising from 0): the springs slide outside the stick radius
// c, G* u = mu E* (d - g(c)), so
//   F_x(u) = 2 mu E* [ c (d - g(c)) + int_c^a (d - g(x)) dx ],
// and full slip F_x = mu F_z at u* = mu E* d / G* (c = 0). Parabola g = x^2/R, d = a^2/R:
// c = a sqrt(1 - u/u*), F_x = (4 mu E*/(3R)) (a^3 - c^3) = mu F_z [1 - (1 - u/u*)^(3/2)], F_z =
// 4 E* a^3/(3R), so u* = 3 mu F_z/(4 a G*) (Mindlin's compliance with (2-nu)/G = 4/G*). Cone
// g = (pi/2) tan(theta) x, d = (pi/2) tan(theta) a: c = a (1 - u/u*) and F_x = mu F_z [1 - (1 -
// u/u*)^2], F_z = (pi/2) E* tan(theta) a^2.
//
// Mindlin-Deresiewicz (unloading from u_m, after loading to it): a spring that slid forward has
// offset u_m - mu l_z/G*; it slides back once G* (u_m - u) = 2 mu l_z, i.e. where the loading
// curve's spring at u_m - u over 2 would: F_unload(u) = L(u_m) - 2 L((u_m - u)/2), and from -u_m
// F_reload(u) = -L(u_m) + 2 L((u_m + u)/2), L the loading curve.
//
// Energy of the loop between -u_m and u_m (steady from the first cycle on), spring by spring:
// a spring of limit l = mu l_z and stiffness G* per length, driven over 2 u_m peak to peak,
// slides 2 (u_m - l/G*) each way when l < G* u_m, at force l: it dissipates 4 l (u_m - l/G*)
// per cycle, so
//   W = 2 int_0^a 4 mu l_z(x) (u_m - mu l_z(x)/G*)^+ dx.
// The same from the branches: W = int (F_reload - F_unload) du = 8 int_0^u_m L - 4 u_m L(u_m).
// For the parabola, with xi = u_m/u*:
//   W = mu F_z u* [4 xi - 16/5 + 4 xi (1 - xi)^(3/2) + (16/5) (1 - xi)^(5/2)]      (~ mu F_z u*
//   xi^3/2)
// and with the force amplitude F_x* = L(u_m), q = 1 - F_x*/(mu F_z) = (1 - xi)^(3/2):
//   W = (3 mu^2 F_z^2/(5 a G*)) [1 - 5 q^(2/3) + 5 q - q^(5/3)]
//     = (9 mu^2 F_z^2/(10 a)) (4/G*) [1 - q^(5/3) - (5/6)(1 - q)(1 + q^(2/3))].
// The last line is the literature's (Mindlin-Deresiewicz, as in Johnson's Contact Mechanics)
// with its compliance (2-nu)/G written as 4/G*: read with 1/G* in place of (2-nu)/G it would
// be 4 times too small. The tests check all three forms against each other and the row.

/// u* = mu E* d / G*: the displacement of full slip [m].
double full_slip_displacement(double coefficient, double effective_modulus,
                              double effective_shear_modulus, double indentation);

/// The parabola's loading curve mu F_z [1 - (1 - u/u*)^(3/2)] (mu F_z beyond u*) [N].
double parabola_loading_force(double friction_limit, double displacement, double full_slip);
/// Its stick radius a sqrt(1 - u/u*) (0 beyond u*) [m].
double parabola_stick_radius(double contact_radius, double displacement, double full_slip);
/// Its inverse: u = u* [1 - (1 - F_x/(mu F_z))^(2/3)] [m].
double parabola_displacement_at_force(double friction_limit, double tangential_force,
                                      double full_slip);
/// The cone's: mu F_z [1 - (1 - u/u*)^2] [N] and a (1 - u/u*) [m].
double cone_loading_force(double friction_limit, double displacement, double full_slip);
double cone_stick_radius(double contact_radius, double displacement, double full_slip);
/// The parabola's loop energy from the displacement amplitude u_m [J].
double parabola_loop_energy(double friction_limit, double full_slip, double amplitude);
/// The same from the force amplitude F_x* (the literature's form, see above) [J].
double parabola_loop_energy_at_force(double coefficient, double normal_force, double contact_radius,
                                     double effective_shear_modulus, double force_amplitude);

/// Cattaneo-Mindlin and Mindlin-Deresiewicz for any profile, through g by quadrature.
class CattaneoMindlin {
 public:
  CattaneoMindlin(const Profile& profile, double effective_modulus, double effective_shear_modulus,
                  double coefficient, double indentation);

  double contact_radius() const { return contact_radius_; }  ///< a, g(a) = d [m]
  double normal_force() const { return normal_force_; }      ///< 2 E* int_0^a (d - g) [N]
  double full_slip() const { return full_slip_; }            ///< u* [m]
  double stick_radius(double displacement) const;            ///< c [m]
  double loading_force(double displacement) const;           ///< L(u) [N]
  /// F on unloading from u_m to u >= -u_m, and on reloading from -u_m to u <= u_m [N].
  double unloading_force(double amplitude, double displacement) const;
  double reloading_force(double amplitude, double displacement) const;
  /// W spring by spring, 8 mu E* int_0^a (d - g) (u_m - mu E* (d - g)/G*)^+ dx [J].
  double loop_energy(double amplitude) const;
  /// W from the branches, 8 int_0^u_m L - 4 u_m L(u_m), the first integral taken over u first [J].
  double loop_energy_from_branches(double amplitude) const;

 private:
  const Profile* profile_;
  double effective_modulus_;
  double effective_shear_modulus_;
  double coefficient_;
  double indentation_;
  double contact_radius_;
  double normal_force_;
  double full_slip_;
};

/// The row moved in tiny fixed steps with no event location: after each step every spring in
/// contact is put back on its limit where the trial stick exceeds it (a return map). Springs
/// 1..glued are glued (always attached, limit mu max(f_z, 0) + 2 tau_0 sqrt(a_g^2 - x^2) dx); the
/// others are in contact while d > g_i, start unstretched on touch and forget their slip on
/// lifting.
class BruteForceRow {
 public:
  /// images: g(x_i) for i = 1..n [m]; spacing dx [m].
  BruteForceRow(std::vector<double> images, double spacing, double effective_modulus,
                double effective_shear_modulus, double coefficient, std::int64_t glued = 0,
                double shear_strength = 0.0);

  /// Springs not glued slide at coefficients[i] max(f_z, 0) + constants[i] [N] instead of the
  /// one coefficient: a law of their own (friction/friction_law.hpp).
  void set_limits(std::vector<double> coefficients, std::vector<double> constants);
  /// Moves the indenter to (d, u) in `steps` equal steps from where it is.
  void move_to(double indentation, double tangential, std::int64_t steps);
  double tangential_force() const;                   ///< 2 sum f_x [N]
  double dissipated() const { return dissipated_; }  ///< sum of limit x slip, both halves [J]
  /// Springs that slid in the last step.
  std::int64_t springs_sliding() const { return sliding_; }

 private:
  void step(double indentation, double tangential);

  std::vector<double> images_;
  std::vector<double> offsets_;
  std::vector<char> in_contact_;
  std::vector<double> limits_;
  double normal_stiffness_;
  double tangential_stiffness_;
  double spacing_;  ///< dx [m]
  double coefficient_;
  std::int64_t glued_;
  std::vector<double> coefficients_;  ///< set_limits: per spring not glued
  std::vector<double> constants_;
  double shear_strength_;  ///< tau_0 [Pa] of the glued springs (glued = "coulomb")
  double indentation_ = 0.0;
  double tangential_ = 0.0;
  double dissipated_ = 0.0;
  std::int64_t sliding_ = 0;
};

}  // namespace mdrsim::friction_reference
