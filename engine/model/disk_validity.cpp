// The disk check: the MDR gap outside the contact and pressure inside it, by quadrature.
#include "engine/model/disk_validity.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "engine/base/bracketed_minimum.hpp"
#include "engine/base/zero_scale.hpp"

namespace mdrsim {
namespace {

constexpr double kNegativeShare = 1e-9;  ///< of the depth scale: below is a violation
constexpr double kFirstOffset = 2.5e-5;  ///< of the span r_max - a: the first sample past a
constexpr double kGrowth = 1.5;          ///< from one sample's distance to a to the next's
constexpr int kSpanSamples = 100;        ///< no two samples further apart than the span over this
constexpr int kFeatureSamples = 4;       ///< gap samples per shortest feature, where one may dip
constexpr int kShapeSamples = 16;        ///< shape samples per shortest feature, for the bound
constexpr int kMostSamples = 4000;       ///< of either, over the span: lambda = a / 100 is followed
constexpr int kMinimumBits = 26;         ///< a minimum's place to 2^-25 of its bracket: sqrt(eps)
constexpr int kPressureSamples = 200;
constexpr double kOuterFactor = 10.0;  ///< the gap is checked out to 10 a

/// int_lo^hi f by 20-point Gauss-Legendre on panels halved where they need it: a panel whose
/// halves sum to its own value within its share of 1e-12 of `scale` (by width) is done, down
/// to 1/1024 of the interval. That difference is the error of the panel itself: its halves,
/// the value kept, are more accurate by far (the tests hold Hertz's, JKR's and power laws'
/// displacement to 1e-12 of the depth, against a check whose threshold is 1e-9). Smooth
/// integrands take a panel and its two halves; a kink (a table's knot, a profile's corner) or
/// an oscillation (a wavy image) is refined where it is, not over the whole interval (halving
/// every panel took a kinked table's check a second).
template <class F>
double integral(F f, double lo, double hi, double scale) {
  constexpr int kDeepest = 10;
  const double tolerance = 1e-12 * scale / (hi - lo);  // per unit of width
  const auto gauss = [&](double a, double b) {
    return boost::math::quadrature::gauss<double, 20>::integrate(f, a, b);
  };
  const auto refine = [&](const auto& self, double a, double b, double whole, int depth) -> double {
    const double mid = 0.5 * (a + b);
    const double left = gauss(a, mid);
    const double right = gauss(mid, b);
    const double halves = left + right;
    if (depth >= kDeepest || std::abs(halves - whole) <= tolerance * (b - a)) return halves;
    return self(self, a, mid, left, depth + 1) + self(self, mid, b, right, depth + 1);
  };
  return refine(refine, lo, hi, gauss(lo, hi), 1);
}

/// The radii the gap is sampled at first, r_0 = a < r_1 < ... < r_n = r_max. From a, where the
/// gap opens from zero (like (r - a)^(3/2) at a pressed edge, sqrt(r - a) at a glued one) and
/// the surface displacement varies on the scale r - a, each sample is 1.5 times further from a
/// than the one before; from where that step would be wider than 1/100 of the span, they are
/// evenly spaced at that width: about 115 samples.
std::vector<double> coarse_radii(double a, double r_max) {
  const double span = r_max - a;
  const double widest = span / kSpanSamples;
  std::vector<double> radii{a};
  for (double offset = kFirstOffset * span; (kGrowth - 1.0) * offset < widest && offset < span;
       offset *= kGrowth) {
    radii.push_back(a + offset);
  }
  const double rest = span - (radii.back() - a);
  const double steps = std::max(1.0, std::ceil(rest / widest));
  const double from = radii.back();
  for (double k = 1.0; k < steps; k += 1.0) radii.push_back(from + rest * (k / steps));
  radii.push_back(r_max);
  return radii;
}

/// The gap at one radius, and the two terms it is made of.
struct GapSample {
  double r;  ///< [m]
  double w;  ///< the surface displacement there [m]
  double f;  ///< the shape there [m]
  double h;  ///< the gap w + f - d [m]
};

/// How far f falls below its chord between two samples at most [m], from f at `step` apart.
double shape_fall(const Profile& profile, const GapSample& lo, const GapSample& hi, double step) {
  double fall = 0.0;
  const double points = std::ceil((hi.r - lo.r) / step);
  for (double k = 1.0; k < points; k += 1.0) {
    const double t = k / points;
    fall = std::max(fall, lo.f + (hi.f - lo.f) * t - profile.shape(lo.r + (hi.r - lo.r) * t));
  }
  return fall;
}

/// The samples, with the intervals filled in where a trough of the shape, of length
/// `feature` and more, could take the gap below zero unseen: an interval wider than a quarter
/// of it is sampled at that width unless a bound keeps the gap positive across it. The bound:
/// the lower of its ends' gaps less how far f falls below its chord (f is cheap: taken at 16
/// points per feature) and how far w does, at most |w''| width^2 / 8 (w is smooth on the scale
/// r - a; taken twice, w'' from the samples' second differences at its ends).
template <class Sample>
std::vector<GapSample> fill_troughs(const Profile& profile, const std::vector<GapSample>& samples,
                                    double feature, const Sample& sample) {
  const double span = samples.back().r - samples.front().r;
  const double widest = std::max(feature / kFeatureSamples, span / kMostSamples);
  const double shape_step = std::max(feature / kShapeSamples, span / kMostSamples);
  const auto bend = [&](std::size_t j) {
    if (j == 0 || j + 1 >= samples.size()) return 0.0;
    const GapSample &l = samples[j - 1], &m = samples[j], &r = samples[j + 1];
    return std::abs(2.0 * ((r.w - m.w) / (r.r - m.r) - (m.w - l.w) / (m.r - l.r)) / (r.r - l.r));
  };
  std::vector<GapSample> filled{samples.front()};
  for (std::size_t j = 0; j + 1 < samples.size(); ++j) {
    const GapSample &lo = samples[j], &hi = samples[j + 1];
    const double width = hi.r - lo.r;
    if (width > widest) {
      const double w_fall = std::max(bend(j), bend(j + 1)) * width * width / 4.0;
      const double bound = std::min(lo.h, hi.h) - shape_fall(profile, lo, hi, shape_step) - w_fall;
      if (!(bound > 0.0)) {
        const double parts = std::ceil(width / widest);
        for (double k = 1.0; k < parts; k += 1.0)
          filled.push_back(sample(lo.r + width * (k / parts)));
      }
    }
    filled.push_back(hi);
  }
  return filled;
}

/// The lowest gap h(r) = w(r) + f(r) - d over (a, r_max], found without relying on samples that
/// land in a dip: the gap is sampled at coarse_radii, filled in where the profile's shortest
/// feature (a ripple's wavelength) could hide a trough (fill_troughs), and every local minimum
/// of the samples (a sample below its inner neighbour and not above its outer one, or the last
/// where the gap falls towards r_max) is refined by a bracketed minimum search over its two
/// intervals. The gap at a itself is 0 (w(a) = d - f(a): f is the Abel transform of g), not
/// sampled.
Minimum lowest_gap(const Profile& profile, double a, double indentation, double r_max) {
  const auto sample = [&](double r) {
    const double w = mdr_surface_displacement(profile, a, indentation, r);
    const double f = profile.shape(r);
    return GapSample{r, w, f, w + f - indentation};
  };
  const std::vector<double> coarse = coarse_radii(a, r_max);
  std::vector<GapSample> samples{{a, indentation - profile.shape(a), profile.shape(a), 0.0}};
  for (std::size_t j = 1; j < coarse.size(); ++j) samples.push_back(sample(coarse[j]));
  if (const auto feature = profile.shortest_feature(); feature && *feature > 0.0) {
    samples = fill_troughs(profile, samples, *feature, sample);
  }
  const auto gap = [&](double r) { return sample(r).h; };
  const std::size_t n = samples.size() - 1;
  Minimum lowest{samples[1].r, samples[1].h};
  for (std::size_t j = 1; j <= n; ++j) {
    const double h = samples[j].h;
    if (h < lowest.value) lowest = {samples[j].r, h};
    const bool falls_into = h < samples[j - 1].h;
    const bool rises_after = j == n || h <= samples[j + 1].h;
    if (!falls_into || !rises_after) continue;
    const Minimum m =
        bracketed_minimum(gap, samples[j - 1].r, samples[std::min(j + 1, n)].r, kMinimumBits);
    if (m.value < lowest.value) lowest = m;
  }
  return lowest;
}

}  // namespace

double mdr_surface_displacement(const Profile& profile, double contact_radius, double indentation,
                                double radius) {
  const double top = std::asin(std::min(1.0, contact_radius / radius));
  const double scale = std::abs(indentation) + std::abs(profile.mdr_image(contact_radius));
  // t = top q^2: an image that grows like x^n with n < 2 at the centre (a power law r^1.5, a
  // table of one) makes the integrand in t grow like t^n there, on which Gauss panels converge
  // slowly (a 201-point table of 0.8 r^1.5: 680 panels per integral on average, 45 % of them
  // stopping at the 1024 cap, 0.6 s for one continuum run); in q it grows like q^(2n+1).
  const auto in_q = [&](double q) {
    const double t = top * q * q;
    return 2.0 * top * q * (indentation - profile.mdr_image(radius * std::sin(t)));
  };
  return (2.0 / std::numbers::pi) * integral(in_q, 0.0, 1.0, scale);
}

double mdr_pressure(const Profile& profile, double effective_modulus, double contact_radius,
                    double indentation, double radius) {
  const double a = contact_radius;
  const double span = std::sqrt(std::max(0.0, a * a - radius * radius));
  const double edge = (indentation - profile.mdr_image(a)) / span;
  // x = r cosh u: dx / sqrt(x^2 - r^2) = du, smooth for r > 0.
  // At the centre itself, 1e-9 a next to it (a cone's pressure is log-singular there).
  const double r = std::max(radius, 1e-9 * a);
  const double top = std::acosh(a / r);
  const double inside =
      integral([&](double u) { return profile.mdr_image_slope(r * std::cosh(u)); }, 0.0, top,
               std::abs(profile.mdr_image_slope(a)) * top);
  return effective_modulus / std::numbers::pi * (edge + inside);
}

DiskValidity check_disk(const Profile& profile, double effective_modulus, double contact_radius,
                        double indentation, double unglued_from) {
  DiskValidity out;
  const double a = contact_radius;
  if (!(a > 0.0)) return out;
  // What is zero, decided once for the state: kNegativeShare of its depth D (a gap) and of
  // its flat punch's force E* a D (a pressure: that over a^2).
  const double depth = std::max(std::abs(indentation), std::abs(profile.mdr_image(a)));
  const ZeroScale zero{.force = kNegativeShare * effective_modulus * a * depth,
                       .displacement = kNegativeShare * depth};
  const auto penetrates = [&](double h) { return h < 0.0 && !zero.zero_displacement(h); };
  const double r_max = std::min(kOuterFactor * a, profile.outer_radius());
  if (r_max > a) {
    const Minimum lowest = lowest_gap(profile, a, indentation, r_max);
    if (penetrates(lowest.value)) {
      out.valid = false;
      out.violation = DiskValidity::Violation::gap;
      out.worst = lowest.value;
      out.worst_radius = lowest.at;
      out.zero = zero.displacement;
    }
  }
  const double c = std::max(0.0, unglued_from);
  if (out.valid && c < a && indentation >= profile.mdr_image(a)) {
    const double pressure_zero = zero.force / (a * a);
    for (int j = 0; j < kPressureSamples; ++j) {
      const double r = c + (a - c) * (j + 0.5) / kPressureSamples;
      const double p = mdr_pressure(profile, effective_modulus, a, indentation, r);
      if (p < std::min(out.worst, -pressure_zero)) {
        out.valid = false;
        out.violation = DiskValidity::Violation::pressure;
        out.worst = p;
        out.worst_radius = r;
        out.zero = pressure_zero;
      }
    }
  }
  return out;
}

}  // namespace mdrsim
