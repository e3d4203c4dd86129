// Coulomb friction in the MDR apart from the engine: Cattaneo-Mindlin, Mindlin-Deresiewicz.
#include "engine/reference/friction_reference.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace mdrsim::friction_reference {

namespace {

template <class F>
double integrate(F f, double from, double to) {
  if (to <= from) return 0.0;
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, from, to, 8, 1e-13);
}

/// 1 - u/u*, clamped to [0, 1].
double stick_fraction(double displacement, double full_slip) {
  return std::clamp(1.0 - std::abs(displacement) / full_slip, 0.0, 1.0);
}

double sign_of(double value) { return value < 0.0 ? -1.0 : 1.0; }

}  // namespace

double full_slip_displacement(double coefficient, double effective_modulus,
                              double effective_shear_modulus, double indentation) {
  return coefficient * effective_modulus * indentation / effective_shear_modulus;
}

double parabola_loading_force(double friction_limit, double displacement, double full_slip) {
  return sign_of(displacement) * friction_limit *
         (1.0 - std::pow(stick_fraction(displacement, full_slip), 1.5));
}

double parabola_stick_radius(double contact_radius, double displacement, double full_slip) {
  return contact_radius * std::sqrt(stick_fraction(displacement, full_slip));
}

double parabola_displacement_at_force(double friction_limit, double tangential_force,
                                      double full_slip) {
  return full_slip * (1.0 - std::pow(1.0 - tangential_force / friction_limit, 2.0 / 3.0));
}

double cone_loading_force(double friction_limit, double displacement, double full_slip) {
  const double s = stick_fraction(displacement, full_slip);
  return sign_of(displacement) * friction_limit * (1.0 - s * s);
}

double cone_stick_radius(double contact_radius, double displacement, double full_slip) {
  return contact_radius * stick_fraction(displacement, full_slip);
}

double parabola_loop_energy(double friction_limit, double full_slip, double amplitude) {
  const double xi = std::min(amplitude / full_slip, 1.0);
  const double s = 1.0 - xi;
  // Full slip beyond u*: the part of the amplitude past u* slides at mu F_z both ways.
  const double beyond = 4.0 * friction_limit * std::max(amplitude - full_slip, 0.0);
  return friction_limit * full_slip *
             (4.0 * xi - 16.0 / 5.0 + 4.0 * xi * std::pow(s, 1.5) + 16.0 / 5.0 * std::pow(s, 2.5)) +
         beyond;
}

double parabola_loop_energy_at_force(double coefficient, double normal_force, double contact_radius,
                                     double effective_shear_modulus, double force_amplitude) {
  const double q = 1.0 - force_amplitude / (coefficient * normal_force);
  const double bracket =
      1.0 - std::pow(q, 5.0 / 3.0) - 5.0 / 6.0 * (1.0 - q) * (1.0 + std::pow(q, 2.0 / 3.0));
  return 9.0 * coefficient * coefficient * normal_force * normal_force / (10.0 * contact_radius) *
         (4.0 / effective_shear_modulus) * bracket;
}

CattaneoMindlin::CattaneoMindlin(const Profile& profile, double effective_modulus,
                                 double effective_shear_modulus, double coefficient,
                                 double indentation)
    : profile_(&profile),
      effective_modulus_(effective_modulus),
      effective_shear_modulus_(effective_shear_modulus),
      coefficient_(coefficient),
      indentation_(indentation),
      contact_radius_(profile.contact_radius_at_depth(indentation)),
      normal_force_(2.0 * effective_modulus *
                    integrate([&](double x) { return indentation - profile.mdr_image(x); }, 0.0,
                              contact_radius_)),
      full_slip_(full_slip_displacement(coefficient, effective_modulus, effective_shear_modulus,
                                        indentation)) {}

double CattaneoMindlin::stick_radius(double displacement) const {
  // G* u = mu E* (d - g(c)): c is the contact radius at the depth d - G* u/(mu E*).
  const double depth = indentation_ - effective_shear_modulus_ * std::abs(displacement) /
                                          (coefficient_ * effective_modulus_);
  if (depth <= profile_->mdr_image(0.0)) return 0.0;
  return profile_->contact_radius_at_depth(depth);
}

double CattaneoMindlin::loading_force(double displacement) const {
  const double c = stick_radius(displacement);
  const double d = indentation_;
  const double stuck = c * (d - profile_->mdr_image(c));
  const double sliding =
      integrate([&](double x) { return d - profile_->mdr_image(x); }, c, contact_radius_);
  return sign_of(displacement) * 2.0 * coefficient_ * effective_modulus_ * (stuck + sliding);
}

double CattaneoMindlin::unloading_force(double amplitude, double displacement) const {
  return loading_force(amplitude) - 2.0 * loading_force(0.5 * (amplitude - displacement));
}

double CattaneoMindlin::reloading_force(double amplitude, double displacement) const {
  return -loading_force(amplitude) + 2.0 * loading_force(0.5 * (amplitude + displacement));
}

double CattaneoMindlin::loop_energy(double amplitude) const {
  const double c = stick_radius(amplitude);
  const double mu_e = coefficient_ * effective_modulus_;
  return 8.0 * integrate(
                   [&](double x) {
                     const double limit = mu_e * (indentation_ - profile_->mdr_image(x));
                     return limit * std::max(amplitude - limit / effective_shear_modulus_, 0.0);
                   },
                   c, contact_radius_);
}

double CattaneoMindlin::loop_energy_from_branches(double amplitude) const {
  // int_0^u_m L(v) dv with L(v) = 2 int_0^a min(G* v, l(x)) dx, integrated over v first: a
  // spring of limit l contributes G* u_m^2/2 while it sticks (l >= G* u_m), else
  // l^2/(2 G*) + l (u_m - l/G*).
  const double c = stick_radius(amplitude);
  const double g = effective_shear_modulus_;
  const double mu_e = coefficient_ * effective_modulus_;
  const double sliding = integrate(
      [&](double x) {
        const double limit = mu_e * (indentation_ - profile_->mdr_image(x));
        return limit * limit / (2.0 * g) + limit * (amplitude - limit / g);
      },
      c, contact_radius_);
  const double area = 2.0 * (c * g * amplitude * amplitude / 2.0 + sliding);
  return 8.0 * area - 4.0 * amplitude * loading_force(amplitude);
}

BruteForceRow::BruteForceRow(std::vector<double> images, double spacing, double effective_modulus,
                             double effective_shear_modulus, double coefficient, std::int64_t glued,
                             double shear_strength)
    : images_(std::move(images)),
      offsets_(images_.size(), 0.0),
      in_contact_(images_.size(), 0),
      limits_(images_.size(), 0.0),
      normal_stiffness_(effective_modulus * spacing),
      tangential_stiffness_(effective_shear_modulus * spacing),
      spacing_(spacing),
      coefficient_(coefficient),
      glued_(glued),
      shear_strength_(shear_strength) {
  if (glued_ < 0 || glued_ > static_cast<std::int64_t>(images_.size()))
    throw std::invalid_argument("BruteForceRow: glued out of range");
  for (std::int64_t i = 0; i < glued_; ++i) in_contact_[static_cast<std::size_t>(i)] = 1;
}

void BruteForceRow::set_limits(std::vector<double> coefficients, std::vector<double> constants) {
  if (coefficients.size() != images_.size() || constants.size() != images_.size())
    throw std::invalid_argument("BruteForceRow::set_limits: one limit per spring");
  coefficients_ = std::move(coefficients);
  constants_ = std::move(constants);
}

void BruteForceRow::move_to(double indentation, double tangential, std::int64_t steps) {
  const double d0 = indentation_;
  const double u0 = tangential_;
  for (std::int64_t s = 1; s <= steps; ++s) {
    const double f = static_cast<double>(s) / static_cast<double>(steps);
    step(d0 + f * (indentation - d0), u0 + f * (tangential - u0));
  }
}

void BruteForceRow::step(double indentation, double tangential) {
  sliding_ = 0;
  for (std::size_t i = 0; i < images_.size(); ++i) {
    const bool glued = static_cast<std::int64_t>(i) < glued_;
    const double normal = normal_stiffness_ * (indentation - images_[i]);
    if (!glued && normal <= 0.0) {
      in_contact_[i] = 0;
      continue;
    }
    // The glued disk's uniform shear strength seen by the spring at x: 2 tau_0 sqrt(a_g^2 - x^2)
    // per unit length (the MDR transform of tau_0 over r < a_g).
    const double a_g = spacing_ * static_cast<double>(glued_);
    const double x = spacing_ * static_cast<double>(i + 1);
    const double adhesive =
        glued ? 2.0 * shear_strength_ * std::sqrt(std::max(a_g * a_g - x * x, 0.0)) * spacing_
              : 0.0;
    const bool own = !glued && !coefficients_.empty();
    const double limit = (own ? coefficients_[i] : coefficient_) * std::max(normal, 0.0) +
                         (own ? constants_[i] : adhesive);
    if (!in_contact_[i]) {
      in_contact_[i] = 1;
      offsets_[i] = tangential;
      limits_[i] = limit;
      continue;
    }
    const double trial = tangential_stiffness_ * (tangential - offsets_[i]);
    if (std::abs(trial) > limit) {
      const double offset = tangential - sign_of(trial) * limit / tangential_stiffness_;
      dissipated_ += 2.0 * 0.5 * (limits_[i] + limit) * std::abs(offset - offsets_[i]);
      offsets_[i] = offset;
      ++sliding_;
    }
    limits_[i] = limit;
  }
  indentation_ = indentation;
  tangential_ = tangential;
}

double BruteForceRow::tangential_force() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < images_.size(); ++i)
    if (in_contact_[i]) sum += tangential_stiffness_ * (tangential_ - offsets_[i]);
  return 2.0 * sum;
}

}  // namespace mdrsim::friction_reference
