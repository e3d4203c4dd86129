// A held row's depth between events as an exponential sum, and the arms' response to it.
#include "engine/model/prony_load_drive.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

/// int_0^h exp(-rate s) ds.
double decay_integral(double rate, double h) {
  if (rate == 0.0) return h;
  return -std::expm1(-rate * h) / rate;
}

/// int_0^h s exp(-rate s) ds = (1 - exp(-x) (1 + x)) / rate^2, x = rate h; by its series where
/// the closed form cancels (x small).
double ramp_decay_integral(double rate, double h) {
  const double x = rate * h;
  if (std::abs(x) < 1e-2) {
    // h^2 sum_{n >= 2} (-1)^n (n - 1) x^(n-2) / n!
    double sum = 0.0;
    double power = 1.0;
    double factorial = 2.0;
    for (int n = 2; n < 12; ++n) {
      const double term = static_cast<double>(n - 1) / factorial;
      sum += ((n % 2 == 0) ? 1.0 : -1.0) * term * power;
      power *= x;
      factorial *= static_cast<double>(n + 1);
    }
    return h * h * sum;
  }
  return (-std::expm1(-x) - x * std::exp(-x)) / (rate * rate);
}

/// A Prony group: the terms of one relaxation time, moduli and arm sums added.
struct LoadDriveGroup {
  double modulus;  ///< E_g [Pa]
  double rate;     ///< r_g = 1 / tau_g [1/s]
  double arm_sum;  ///< S_g [N/m]
};

std::vector<LoadDriveGroup> grouped_terms(std::span<const PronyTerm> terms,
                                          std::span<const double> arm_sums) {
  std::vector<std::size_t> order(terms.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return terms[a].time > terms[b].time; });
  std::vector<LoadDriveGroup> groups;
  double last_time = 0.0;
  for (const std::size_t j : order) {
    if (groups.empty() || terms[j].time != last_time) {
      groups.push_back({0.0, 1.0 / terms[j].time, 0.0});
      last_time = terms[j].time;
    }
    groups.back().modulus += terms[j].modulus;
    groups.back().arm_sum += arm_sums[j];
  }
  return groups;
}

/// x with m x = y for a small dense m (row-major, size k x k), by Gaussian elimination with
/// partial pivoting.
std::vector<double> solved_dense(std::vector<double> m, std::vector<double> y) {
  const std::size_t k = y.size();
  for (std::size_t col = 0; col < k; ++col) {
    std::size_t pivot = col;
    for (std::size_t row = col + 1; row < k; ++row) {
      if (std::abs(m[row * k + col]) > std::abs(m[pivot * k + col])) pivot = row;
    }
    if (pivot != col) {
      for (std::size_t c = 0; c < k; ++c) std::swap(m[col * k + c], m[pivot * k + c]);
      std::swap(y[col], y[pivot]);
    }
    for (std::size_t row = col + 1; row < k; ++row) {
      const double factor = m[row * k + col] / m[col * k + col];
      for (std::size_t c = col; c < k; ++c) m[row * k + c] -= factor * m[col * k + c];
      y[row] -= factor * y[col];
    }
  }
  std::vector<double> x(k);
  for (std::size_t i = k; i-- > 0;) {
    double sum = y[i];
    for (std::size_t c = i + 1; c < k; ++c) sum -= m[i * k + c] * x[c];
    x[i] = sum / m[i * k + i];
  }
  return x;
}

}  // namespace

ExponentialSum shifted(const ExponentialSum& f, double s0) {
  ExponentialSum out{f.constant + f.slope * s0, f.slope, f.decays};
  for (ExponentialDecay& decay : out.decays) decay.amplitude *= std::exp(-s0 / decay.time);
  return out;
}

ExponentialSumBounds bounds_over(const ExponentialSum& f, double h) {
  ExponentialSumBounds b{f.constant, f.constant};
  const double line = f.slope * h;
  b.lo += std::min(0.0, line);
  b.hi += std::max(0.0, line);
  for (const ExponentialDecay& decay : f.decays) {
    const double end = decay.amplitude * std::exp(-h / decay.time);
    b.lo += std::min(decay.amplitude, end);
    b.hi += std::max(decay.amplitude, end);
  }
  return b;
}

double integral_of_product(const ExponentialSum& f, const ExponentialSum& g, double h) {
  double sum = f.constant * g.constant * h +
               (f.constant * g.slope + f.slope * g.constant) * 0.5 * h * h +
               f.slope * g.slope * h * h * h / 3.0;
  for (const ExponentialDecay& d : g.decays) {
    const double rate = 1.0 / d.time;
    sum += d.amplitude *
           (f.constant * decay_integral(rate, h) + f.slope * ramp_decay_integral(rate, h));
  }
  for (const ExponentialDecay& d : f.decays) {
    const double rate = 1.0 / d.time;
    sum += d.amplitude *
           (g.constant * decay_integral(rate, h) + g.slope * ramp_decay_integral(rate, h));
  }
  for (const ExponentialDecay& p : f.decays) {
    for (const ExponentialDecay& q : g.decays) {
      sum += p.amplitude * q.amplitude * decay_integral(1.0 / p.time + 1.0 / q.time, h);
    }
  }
  return sum;
}

ExponentialSum arm_stress_under(double stress, const PronyTerm& term,
                                const ExponentialSum& motion) {
  const double tau = term.time;
  ExponentialSum sigma{term.modulus * motion.slope * tau, 0.0, {}};
  double homogeneous = stress - sigma.constant;
  for (const ExponentialDecay& d : motion.decays) {
    const double a = term.modulus * d.amplitude * tau / (tau - d.time);
    sigma.decays.push_back({a, d.time});
    homogeneous -= a;
  }
  sigma.decays.push_back({homogeneous, tau});
  return sigma;
}

ExponentialSum depth_under_held_axis(double relaxed_modulus, std::span<const PronyTerm> terms,
                                     const PressedSprings& pressed, const RowHeldAxis& axis,
                                     double depth) {
  if (pressed.count == 0) {
    if (axis.stiffness > 0.0) return {axis.held / axis.stiffness, axis.rate / axis.stiffness, {}};
    return {depth, 0.0, {}};
  }
  const auto n = static_cast<double>(pressed.count);
  const std::vector<LoadDriveGroup> groups = grouped_terms(terms, pressed.arm_sums);
  double glassy = relaxed_modulus;
  for (const LoadDriveGroup& g : groups) glassy += g.modulus;
  const double relaxed_stiffness = relaxed_modulus * n + axis.stiffness;  // E* n + kappa
  const double glassy_stiffness = glassy * n + axis.stiffness;            // E_0 n + kappa
  const std::size_t k = groups.size();
  std::vector<double> w(k);
  double w_sum = 0.0;
  for (std::size_t g = 0; g < k; ++g) {
    w[g] = n * groups[g].modulus / glassy_stiffness;
    w_sum += w[g];
  }
  // The steady arms under phi' (S_p: E_j n d' tau_j at d' = phi' / (E* n + kappa)) and the rest,
  // which decays along the modes.
  std::vector<double> steady(k), rest(k);
  double arm_total = 0.0;
  for (std::size_t g = 0; g < k; ++g) {
    steady[g] = w[g] / groups[g].rate * axis.rate / (1.0 - w_sum);
    rest[g] = groups[g].arm_sum - steady[g];
    arm_total += groups[g].arm_sum;
  }
  const auto secular = [&](double mu) {
    double sum = -1.0;
    for (std::size_t g = 0; g < k; ++g) sum += w[g] * groups[g].rate / (groups[g].rate - mu);
    return sum;
  };
  std::vector<double> rates(k);
  for (std::size_t m = 0; m < k; ++m) {
    const double lo = m == 0 ? 0.0 : std::nextafter(groups[m - 1].rate, HUGE_VAL);
    const double hi = std::nextafter(groups[m].rate, 0.0);
    rates[m] = bracketed_root(secular, lo, hi);
  }
  // rest_g = sum_m alpha_m w_g / (r_g - mu_m): the modes' shares.
  std::vector<double> modes(k * k);
  for (std::size_t g = 0; g < k; ++g) {
    for (std::size_t m = 0; m < k; ++m) modes[g * k + m] = w[g] / (groups[g].rate - rates[m]);
  }
  const std::vector<double> alpha = solved_dense(modes, rest);
  // d = (phi + E* sum g - sum S) / (E* n + kappa), the constraint itself at s = 0.
  ExponentialSum d{0.0, axis.rate / relaxed_stiffness, {}};
  const double now = (axis.held + relaxed_modulus * pressed.images - arm_total) / relaxed_stiffness;
  double decaying_at_zero = 0.0;
  for (std::size_t m = 0; m < k; ++m) {
    double share = 0.0;
    for (std::size_t g = 0; g < k; ++g) share += modes[g * k + m];
    const double amplitude = -alpha[m] * share / relaxed_stiffness;
    d.decays.push_back({amplitude, 1.0 / rates[m]});
    decaying_at_zero += amplitude;
  }
  d.constant = now - decaying_at_zero;
  return d;
}

double held_axis_work(const RowHeldAxis& axis, const ExponentialSum& motion, double h) {
  ExponentialSum load{axis.held, axis.rate, {}};
  ExponentialSum driving{axis.rate / std::max(axis.stiffness, 1e-300), 0.0, {}};
  if (axis.stiffness > 0.0) {
    load.constant -= axis.stiffness * motion.constant;
    load.slope -= axis.stiffness * motion.slope;
    for (const ExponentialDecay& d : motion.decays) {
      load.decays.push_back({-axis.stiffness * d.amplitude, d.time});
    }
  } else {
    driving.constant = motion.slope;
    for (const ExponentialDecay& d : motion.decays) {
      driving.decays.push_back({-d.amplitude / d.time, d.time});
    }
  }
  return integral_of_product(load, driving, h);
}

}  // namespace mdrsim
