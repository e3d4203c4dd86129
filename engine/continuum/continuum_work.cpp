// Energy balance on the quasi-static branch: machine work = stored energy change + released.
#include "engine/continuum/continuum_work.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

namespace mdrsim {
namespace {

constexpr double kQuadratureTolerance = 1e-12;
constexpr unsigned kMaxDepth = 15;
constexpr double kRounding = 1e-15;  ///< of a sum of terms, relative to their magnitudes' sum

/// Over [lo, hi] mapped onto [0, 1]: Boost's adaptive rule compares the error of the unit
/// interval's sum with the tolerance times the scaled integral, so that on an interval of
/// 1e-4 m it never stops refining (1.5 million calls for a quartic); on [0, 1] the two agree.
template <class Fn>
Estimated integrate(Fn fn, double lo, double hi) {
  if (!(hi > lo)) return {};
  const double width = hi - lo;
  double error = 0.0;
  double l1 = 0.0;
  const double value = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      [&](double t) { return fn(lo + width * t); }, 0.0, 1.0, kMaxDepth, kQuadratureTolerance,
      &error, &l1);
  // Rounding of the sum of positive terms adds about 1e-15 of its size.
  return {width * value, width * (error + kRounding * l1)};
}

}  // namespace

Estimated glued_normal_energy(const ContinuumBranch& branch, const BranchState& s) {
  const Profile& profile = branch.profile();
  const double d = s.indentation;
  // x = a t^2: images like sqrt(x) (power laws with n < 1, the cone's tip) become smooth in t.
  const double a = s.contact_radius;
  Estimated e;
  if (const auto& graded = branch.graded()) {
    // int_0^a c_k (d - g_k)^2 dx = (C_k / 2) (1 + k) int_0^a x^k (d - g_k)^2 dx.
    const double ck = branch.material().grading.punch_constant;
    const double ga = std::abs(graded->image(a));
    const double size =
        std::pow(a, 1.0 + graded->grading_exponent()) * (std::abs(d) + ga) * (std::abs(d) + ga);
    return {0.5 * ck * graded->squared_gap_integral(a, d), kRounding * 0.5 * ck * size};
  }
  if (const auto exact = profile.squared_gap_integral(a, d)) {
    e = {exact->value, kRounding * exact->magnitude};
  } else {
    e = integrate(
        [&](double t) {
          const double gap = d - profile.mdr_image(a * t * t);
          return 2.0 * a * t * gap * gap;
        },
        0.0, 1.0);
  }
  const double modulus = branch.material().effective_modulus;
  e.value *= modulus;
  e.error *= modulus;
  return e;
}

Estimated stored_energy(const ContinuumBranch& branch, const BranchState& s,
                        const Estimated& normal) {
  const Material& m = branch.material();
  Estimated e = normal;
  const double ux = s.tangential_displacement;
  e.value += m.effective_shear_modulus * s.contact_radius * ux * ux;
  if (drives_through_spring(branch.normal())) {
    e.value += 0.5 * s.normal_force * s.normal_force * branch.normal().force_coefficient;
  }
  if (drives_through_spring(branch.tangential())) {
    e.value +=
        0.5 * s.tangential_force * s.tangential_force * branch.tangential().force_coefficient;
  }
  return e;
}

Estimated stored_energy(const ContinuumBranch& branch, const BranchState& s) {
  return stored_energy(branch, s, glued_normal_energy(branch, s));
}

StoredState stored_state(const ContinuumBranch& branch, const BranchState& s) {
  return {s, stored_energy(branch, s)};
}

Estimated released_energy(const ContinuumBranch& branch, double from, double to) {
  if (!(from > to)) return {};
  const Material& m = branch.material();
  const double width = from - to;
  if (branch.graded()) {
    // Hess's rule on the graded springs, c_k(x) e(x)^2 = 2 pi x dgamma: pi dgamma (from^2 - to^2).
    const double released = std::numbers::pi * m.work_of_adhesion * width * (from + to);
    return {released, kRounding * released};
  }
  // x = to + (from - to) t^2: where the path ends at the shear-off radius the let-go
  // elongation falls to 0 there like a root of the distance, smooth in t.
  Estimated e = integrate(
      [&](double t) {
        const double stretch = branch.stretch(to + width * t * t);
        return 2.0 * t * stretch * stretch;
      },
      0.0, 1.0);
  const double normal = m.effective_modulus * width;
  // u_x = H / (a_u + a_F 2 G* x), so int u_x^2 dx = u_x(to) u_x(from) (from - to) exactly.
  const double shear = m.effective_shear_modulus * branch.tangential_displacement(to) *
                       branch.tangential_displacement(from) * width;
  return {normal * e.value + shear, normal * e.error + kRounding * std::abs(shear)};
}

AxisWork stretch_work(const ContinuumBranch& branch, const StoredState& top,
                      const StoredState& bottom, double& error) {
  const Estimated& before = top.energy;
  const Estimated& after = bottom.energy;
  const Estimated released =
      released_energy(branch, top.state.contact_radius, bottom.state.contact_radius);
  const double total = after.value - before.value + released.value;
  error += before.error + after.error + released.error;
  AxisWork w;
  if (holds_force(branch.tangential())) {
    w.tangential = branch.tangential_held() *
                   (bottom.state.tangential_displacement - top.state.tangential_displacement);
  }
  w.normal = total - w.tangential;
  return w;
}

AxisWork stretch_work(const ContinuumBranch& branch, const BranchState& top,
                      const BranchState& bottom, double& error) {
  return stretch_work(branch, stored_state(branch, top), stored_state(branch, bottom), error);
}

AxisWork jump_work(const ContinuumBranch& branch, const BranchState& from, const BranchState& to) {
  AxisWork w;
  if (holds_force(branch.normal())) {
    w.normal = from.normal_force * (to.indentation - from.indentation);
  }
  if (holds_force(branch.tangential())) {
    w.tangential =
        branch.tangential_held() * (to.tangential_displacement - from.tangential_displacement);
  }
  return w;
}

}  // namespace mdrsim
