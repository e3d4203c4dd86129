// The continuum branch under each law, its folds and the pull-off path with partial jumps.
#include "engine/reference/continuum_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace mdrsim::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Brent's method (zeroin) on [lo, hi] with f(lo) and f(hi) of opposite signs (or one zero),
/// to a relative width of a few ulps. Infinite values only steer it to bisection.
template <class Fn>
double root_between(const Fn& f, double lo, double hi, double f_lo, double f_hi) {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  double a = lo, fa = f_lo, b = hi, fb = f_hi;
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < 300; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = b - a;
      e = d;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * kEpsilon * std::abs(b) + 1e-300;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    bool bisect = true;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb) && std::isfinite(fa) &&
        std::isfinite(fb) && std::isfinite(fc)) {
      const double s = fb / fa;
      double p = 0.0, q = 0.0;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      if (std::isfinite(p) && std::isfinite(q) &&
          2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
        bisect = false;
      }
    }
    if (bisect) {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

template <class Fn>
double root_between(const Fn& f, double lo, double hi) {
  return root_between(f, lo, hi, f(lo), f(hi));
}

/// c such that the law lets go unstretched when c u_x^2 >= 2 pi a dgamma [Pa].
double shear_coefficient(const DetachmentLaw& law, const ContinuumMaterial& m) {
  switch (law.kind) {
    case DetachmentLaw::Kind::mode_mixed:
      return m.effective_shear_modulus;
    case DetachmentLaw::Kind::deformation:
      return m.effective_modulus;
    case DetachmentLaw::Kind::stress:
      return m.effective_shear_modulus * m.effective_shear_modulus / m.effective_modulus;
    case DetachmentLaw::Kind::normal_only:
      return 0.0;
    case DetachmentLaw::Kind::mode_dependent: {
      // At e = 0, psi = pi/2: G* u^2 cos^2((1 - lambda) pi/2) >= W.
      if (law.lambda == 0.0) return 0.0;
      const double c = std::cos((1.0 - law.lambda) * 0.5 * kPi);
      return m.effective_shear_modulus * c * c;
    }
  }
  return 0.0;
}

}  // namespace

std::string_view kind_name(ContinuumCritical::Kind kind) {
  switch (kind) {
    case ContinuumCritical::Kind::fold:
      return "fold";
    case ContinuumCritical::Kind::first_detachment:
      return "first-detachment";
    case ContinuumCritical::Kind::shear_off:
      return "shear-off";
    case ContinuumCritical::Kind::shear_off_at_application:
      return "shear-off-at-application";
    case ContinuumCritical::Kind::none:
      return "none";
  }
  return "?";
}

ContinuumMaterial ContinuumMaterial::from_youngs_modulus(double youngs_modulus,
                                                         double poisson_ratio,
                                                         double work_of_adhesion) {
  const double shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  return {youngs_modulus / (1.0 - poisson_ratio * poisson_ratio),
          4.0 * shear_modulus / (2.0 - poisson_ratio), work_of_adhesion};
}

double law_margin(const DetachmentLaw& law, const ContinuumMaterial& m, double e, double ux,
                  double a) {
  const double w = 2.0 * kPi * a * m.work_of_adhesion;
  const double es = m.effective_modulus, gs = m.effective_shear_modulus;
  switch (law.kind) {
    case DetachmentLaw::Kind::mode_mixed:
      return w - es * e * e - gs * ux * ux;
    case DetachmentLaw::Kind::deformation:
      return w - es * (e * e + ux * ux);
    case DetachmentLaw::Kind::stress:
      return w - (es * es * e * e + gs * gs * ux * ux) / es;
    case DetachmentLaw::Kind::normal_only:
      return w - es * e * e;
    case DetachmentLaw::Kind::mode_dependent: {
      // W (1 + tan^2 x) <= G is W <= G cos^2 x, finite also at x = pi/2.
      const double normal = es * e * e, shear = gs * ux * ux;
      const double psi = std::atan2(std::sqrt(shear), std::sqrt(normal));
      const double c = std::cos((1.0 - law.lambda) * psi);
      return w - (normal + shear) * c * c;
    }
  }
  return 0.0;
}

ContinuumReference::ContinuumReference(const Profile& profile, ContinuumMaterial material,
                                       DetachmentLaw law, TangentialLoad tangential,
                                       NormalControl normal)
    : profile_(&profile),
      material_(material),
      law_(law),
      tangential_(tangential),
      normal_(normal),
      adhesion_length_(2.0 * kPi * material.work_of_adhesion / material.effective_modulus),
      shear_coefficient_(shear_coefficient(law, material)),
      shear_off_radius_(0.0) {
  if (!(law.lambda >= 0.0 && law.lambda <= 1.0)) {
    throw std::invalid_argument("lambda must lie in [0, 1]");
  }
  const double v = tangential.value;
  if (tangential.kind == TangentialLoad::Kind::none || v == 0.0 || shear_coefficient_ == 0.0) {
    return;
  }
  const double two_pi_dgamma = 2.0 * kPi * material.work_of_adhesion;
  if (!(two_pi_dgamma > 0.0)) {
    shear_off_radius_ = kInfinity;
  } else if (tangential.kind == TangentialLoad::Kind::displacement) {
    // c u^2 = 2 pi a_s dgamma.
    shear_off_radius_ = shear_coefficient_ * v * v / two_pi_dgamma;
  } else {
    // c (F_x / (2 G* a_s))^2 = 2 pi a_s dgamma.
    const double gs = material.effective_shear_modulus;
    shear_off_radius_ = std::cbrt(shear_coefficient_ * v * v / (4.0 * gs * gs * two_pi_dgamma));
  }
}

double ContinuumReference::zero_stretch_limit(double a) const {
  if (shear_coefficient_ == 0.0) return kInfinity;
  return std::sqrt(2.0 * kPi * a * material_.work_of_adhesion / shear_coefficient_);
}

double ContinuumReference::tangential_displacement(double a) const {
  switch (tangential_.kind) {
    case TangentialLoad::Kind::none:
      return 0.0;
    case TangentialLoad::Kind::displacement:
      return tangential_.value;
    case TangentialLoad::Kind::force:
      return tangential_.value / (2.0 * material_.effective_shear_modulus * a);
  }
  return 0.0;
}

// The four closed-form laws share e^2 = (W - c u_x^2)/E* (the criterion table of docs/scene.md
// solved for e). Written against a_s, e^2 = w (a - a_s) for a held u and w (a - a_s)(1 + r + r^2),
// r = a_s/a, for a held force (c u_x^2 falls like 1/a^2), so that e keeps its digits next to a_s.
ContinuumReference::Edge ContinuumReference::edge(double a) const {
  if (!(a > shear_off_radius_)) return {0.0, kInfinity};
  const double ux = tangential_displacement(a);
  if (law_.kind == DetachmentLaw::Kind::mode_dependent && ux != 0.0) {
    return mode_dependent_edge(a, ux);
  }
  const double w = adhesion_length_, as = shear_off_radius_;
  double square = w * (a - as), square_slope = w;
  if (tangential_.kind == TangentialLoad::Kind::force && as > 0.0) {
    const double r = as / a;
    square *= 1.0 + r + r * r;
    square_slope *= 1.0 + 2.0 * r * r * r;
  }
  const double e = std::sqrt(square);
  return {e, square_slope / (2.0 * e)};
}

// With N = E* e^2, S = G* u_x^2 and tan psi = sqrt(S/N), N + S = S/sin^2 psi and
// 1 + tan^2 = 1/cos^2, so the law lets go where sigma cos(mu psi) = omega sin psi with
// sigma = sqrt(S), omega = sqrt(W), mu = 1 - lambda. The left side falls and the right rises
// on [0, pi/2], so the root is unique; then e = sigma cot(psi) / sqrt(E*). Its slope follows
// from the implicit function theorem on R(psi, a) = sigma cos(mu psi) - omega sin psi.
ContinuumReference::Edge ContinuumReference::mode_dependent_edge(double a, double ux) const {
  const double mu = 1.0 - law_.lambda;
  const double sigma = std::sqrt(material_.effective_shear_modulus) * std::abs(ux);
  const double omega = std::sqrt(2.0 * kPi * a * material_.work_of_adhesion);
  const auto residual = [&](double psi) {
    return sigma * std::cos(mu * psi) - omega * std::sin(psi);
  };
  const double top = residual(0.5 * kPi);
  const double psi = top >= 0.0 ? 0.5 * kPi : root_between(residual, 0.0, 0.5 * kPi, sigma, top);
  const double root_e = std::sqrt(material_.effective_modulus);
  const double sin_psi = std::sin(psi), cos_psi = std::cos(psi);
  const double e = top >= 0.0 ? 0.0 : sigma * cos_psi / (sin_psi * root_e);
  const double omega_slope = omega / (2.0 * a);
  const double sigma_slope = tangential_.kind == TangentialLoad::Kind::force ? -sigma / a : 0.0;
  const double residual_a = sigma_slope * std::cos(mu * psi) - omega_slope * sin_psi;
  const double residual_psi = -mu * sigma * std::sin(mu * psi) - omega * cos_psi;
  const double psi_slope = -residual_a / residual_psi;
  const double slope =
      (sigma_slope * cos_psi / sin_psi - sigma * psi_slope / (sin_psi * sin_psi)) / root_e;
  return {e, slope};
}

double ContinuumReference::stretch(double a) const { return edge(a).stretch; }

double ContinuumReference::stretch_slope(double a) const { return edge(a).slope; }

ContinuumState ContinuumReference::at(double a) const {
  const double e = stretch(a);
  const double es = material_.effective_modulus;
  const double ux = tangential_displacement(a);
  ContinuumState s;
  s.contact_radius = a;
  s.stretch = e;
  s.indentation = profile_->mdr_image(a) - e;
  s.normal_force = es * profile_->nonadhesive_force_per_modulus(a) - 2.0 * es * a * e;
  s.tangential_displacement = ux;
  s.tangential_force = 2.0 * material_.effective_shear_modulus * a * ux;
  s.control_value = normal_.displacement_coefficient * s.indentation;
  if (normal_.force_coefficient != 0.0)
    s.control_value += normal_.force_coefficient * s.normal_force;
  return s;
}

ContinuumState ContinuumReference::unstretched_state(double a) const {
  ContinuumState s = at(a);
  const double es = material_.effective_modulus;
  s.stretch = 0.0;
  s.indentation = profile_->mdr_image(a);
  s.normal_force = es * profile_->nonadhesive_force_per_modulus(a);
  s.control_value = normal_.displacement_coefficient * s.indentation;
  if (normal_.force_coefficient != 0.0)
    s.control_value += normal_.force_coefficient * s.normal_force;
  return s;
}

// d' = g' - e' and F' = 2 E* (a d' - e), since (E* nf)' = 2 E* a g'. A zero coefficient is
// left out so that an infinite slope next to a_s cannot make 0 * inf.
ContinuumReference::Sample ContinuumReference::sample(double a) const {
  const Edge ed = edge(a);
  const double es = material_.effective_modulus;
  const double d = profile_->mdr_image(a) - ed.stretch;
  const double force = es * profile_->nonadhesive_force_per_modulus(a) - 2.0 * es * a * ed.stretch;
  const double d_slope = profile_->mdr_image_slope(a) - ed.slope;
  const double force_slope = 2.0 * es * (a * d_slope - ed.stretch);
  Sample s{a, 0.0, 0.0, force, force_slope};
  if (normal_.displacement_coefficient != 0.0) {
    s.control += normal_.displacement_coefficient * d;
    s.control_slope += normal_.displacement_coefficient * d_slope;
  }
  if (normal_.force_coefficient != 0.0) {
    s.control += normal_.force_coefficient * force;
    s.control_slope += normal_.force_coefficient * force_slope;
  }
  return s;
}

double ContinuumReference::control_slope(double a) const { return sample(a).control_slope; }

double ContinuumReference::normal_force_slope(double a) const { return sample(a).force_slope; }

ContinuumCritical ContinuumReference::pull_off(double glued_radius, int samples_per_decade) const {
  ContinuumCritical out;
  out.shear_off_radius = shear_off_radius_;
  const double ag = glued_radius, as = shear_off_radius_;
  if (!(ag > as)) {
    out.kind = ContinuumCritical::Kind::shear_off_at_application;
    out.point = unstretched_state(ag);
    out.peak = out.point;
    out.peak_adhesive_force = out.point.normal_force;
    out.tangential_strength = 2.0 * material_.effective_shear_modulus * ag * zero_stretch_limit(ag);
    return out;
  }

  // Radii from a_g down: log-spaced over 12 decades, and log-spaced in a - a_s towards a_s.
  const int per_decade = std::max(samples_per_decade, 4);
  std::vector<double> radii;
  for (int j = 0; j <= 12 * per_decade; ++j) {
    const double a = ag * std::pow(10.0, -static_cast<double>(j) / per_decade);
    if (a > as) radii.push_back(a);
  }
  if (as > 0.0) {
    for (int j = 1; j <= 14 * per_decade; ++j) {
      const double a = as + (ag - as) * std::pow(10.0, -static_cast<double>(j) / per_decade);
      if (a > as && a < ag) radii.push_back(a);
    }
  }
  std::sort(radii.begin(), radii.end(), std::greater<>());
  radii.erase(std::unique(radii.begin(), radii.end(),
                          [](double x, double y) { return x - y <= 1e-13 * x; }),
              radii.end());

  // Samples, with each sign change of the control slope (a fold or a turn back) and of the
  // force slope (a force extremum, for the peak) refined between neighbours.
  std::vector<Sample> grid;
  grid.reserve(radii.size());
  for (const double a : radii) grid.push_back(sample(a));
  std::vector<Sample> path;
  path.reserve(grid.size() + 16);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    path.push_back(grid[k]);
    if (k + 1 == grid.size()) break;
    const Sample& hi = grid[k];
    const Sample& lo = grid[k + 1];
    std::vector<Sample> extra;
    if ((hi.control_slope > 0.0) != (lo.control_slope > 0.0)) {
      const double a = root_between([&](double x) { return sample(x).control_slope; }, lo.a, hi.a,
                                    lo.control_slope, hi.control_slope);
      Sample s = sample(a);
      s.fold = hi.control_slope > 0.0;  // falling towards a_g side, rising below: a minimum
      extra.push_back(s);
    }
    if ((hi.force_slope > 0.0) != (lo.force_slope > 0.0)) {
      const double a = root_between([&](double x) { return sample(x).force_slope; }, lo.a, hi.a,
                                    lo.force_slope, hi.force_slope);
      extra.push_back(sample(a));
    }
    std::sort(extra.begin(), extra.end(),
              [](const Sample& x, const Sample& y) { return x.a > y.a; });
    for (const Sample& s : extra) {
      if (s.a < hi.a && s.a > lo.a) path.push_back(s);
    }
  }

  double peak_force = kInfinity, peak_radius = ag;
  const auto visit = [&](double a, double force) {
    if (force < peak_force) {
      peak_force = force;
      peak_radius = a;
    }
  };
  visit(path[0].a, path[0].force);

  // i: the current equilibrium on the branch. Unstable there (control slope <= 0): it jumps.
  std::size_t i = 0;
  while (true) {
    std::size_t fold = i;
    if (path[i].control_slope > 0.0) {
      std::size_t j = i + 1;
      while (j < path.size() && !path[j].fold) {
        visit(path[j].a, path[j].force);
        ++j;
      }
      if (j == path.size()) {
        if (as > 0.0) {
          // e reaches 0 while the control still falls: below a_s the glue breaks at once.
          out.kind = ContinuumCritical::Kind::shear_off;
          out.point = unstretched_state(as);
        } else {
          out.kind = ContinuumCritical::Kind::none;
          out.point = at(path.back().a);
        }
        visit(out.point.contact_radius, out.point.normal_force);
        break;
      }
      visit(path[j].a, path[j].force);
      fold = j;
    }
    // Jump at the fold's control value: springs let go while the branch's control value
    // stays at or above it.
    const double level = path[fold].control;
    std::size_t k = fold + 1;
    while (k < path.size() && !(path[k].control < level)) ++k;
    if (k == path.size()) {
      out.kind =
          fold == 0 ? ContinuumCritical::Kind::first_detachment : ContinuumCritical::Kind::fold;
      out.point = at(path[fold].a);
      break;
    }
    const auto excess = [&](double x) { return sample(x).control - level; };
    double upper = path[k - 1].a;
    double upper_excess = path[k - 1].control - level;
    if (!(upper_excess > 0.0)) {
      // The next sample is below the level already: find a radius above it that is not.
      upper_excess = -1.0;
      for (int m = 1; m <= 60 && !(upper_excess > 0.0); ++m) {
        upper = path[fold].a - (path[fold].a - path[k].a) * std::ldexp(1.0, -m);
        upper_excess = excess(upper);
      }
    }
    const double landing = upper_excess > 0.0 ? root_between(excess, path[k].a, upper,
                                                             path[k].control - level, upper_excess)
                                              : path[k].a;
    const Sample land = sample(landing);
    visit(land.a, land.force);
    out.partial_jumps.push_back({at(path[fold].a), at(landing)});
    if (land.control_slope > 0.0) {
      path.insert(path.begin() + static_cast<std::ptrdiff_t>(k), land);
    }
    // Otherwise the landing only touches the level (a degenerate turn): go on from the next
    // sample, which keeps the walk moving down.
    i = k;
  }
  out.peak_adhesive_force = peak_force;
  out.peak = peak_radius == as && as > 0.0 ? unstretched_state(as) : at(peak_radius);
  return out;
}

}  // namespace mdrsim::test
