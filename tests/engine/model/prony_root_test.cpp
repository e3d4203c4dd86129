// The first crossing of an exponential sum against closed forms: Lambert's W for one decay and a
// slope, polynomials in x = exp(-s) for sums of decays with several crossings.
#include "engine/model/prony_root.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/lambert_w.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

namespace mdrsim {
namespace {

// a + b s + c exp(-s / tau) = 0: with u = s + a / b, (u / tau) exp(u / tau) = -c exp(a / (b tau))
// / (b tau), so s = -a / b + tau W(z); two roots where -1/e < z < 0 (W_0 and W_-1), the first the
// smaller. Tolerance 1e-13 relative: the root is exact to a few ulps, W to about 1e-15.
TEST(PronyRoot, OneDecayAndASlopeByLambertW) {
  // A spring unloading: a load that falls linearly and recovers a relaxed part, q(0) > 0.
  const double a = 2.0, b = -3.0, c = 1.5, tau = 0.4;
  const ExponentialSum f{a, b, {{c, tau}}};
  const double z = -c * std::exp(a / (b * tau)) / (b * tau);
  const double expected = -a / b + tau * boost::math::lambert_w0(z);
  const auto s = first_crossing(f, 0.0, 10.0);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, expected, 1e-13 * expected);
  EXPECT_FALSE(first_crossing(f, 0.0, 0.99 * expected).has_value());

  // Two roots: f = -0.95 + 0.5 s + exp(-s) starts at 0.05, dips below zero (its minimum at
  // s = ln 2) and climbs back; z = -exp(-1.9) / 0.5 lies in (-1/e, 0).
  const double a2 = -0.95, b2 = 0.5;
  const ExponentialSum dip{a2, b2, {{1.0, 1.0}}};
  const double zd = -std::exp(a2 / b2) / b2;
  ASSERT_GT(zd, -1.0 / std::exp(1.0));
  const double first = -a2 / b2 + boost::math::lambert_wm1(zd);
  const double second = -a2 / b2 + boost::math::lambert_w0(zd);
  ASSERT_LT(first, second);
  const auto s_dip = first_crossing(dip, 0.0, 50.0);
  ASSERT_TRUE(s_dip.has_value());
  EXPECT_NEAR(*s_dip, first, 1e-13 * second);
  // From between the roots (below zero), the way back up is the second.
  const double mid = 0.5 * (first + second);
  const ExponentialSum from_mid{a2 + b2 * mid, b2, {{std::exp(-mid), 1.0}}};
  const auto s_back = first_crossing(from_mid, 0.0, 50.0);
  ASSERT_TRUE(s_back.has_value());
  EXPECT_NEAR(*s_back + mid, second, 1e-13 * second);
}

// The first crossing of f from 0 against its own root in long double, bisected next to it to
// 64 bits; whether it has one. Tolerance 4 eps of the root (the root finder's stopping rule: a
// step, or TOMS 748's bracket, within 4 eps of s) plus the rounding of f in double, 4 eps of
// its terms' sizes over its slope (a root near 0 sits where its terms cancel).
bool expect_root(const ExponentialSum& f, double span, std::optional<double> near = std::nullopt) {
  const std::optional<double> s = first_crossing(f, 0.0, span, near);
  if (!s) return false;
  const auto g = [&](long double x) {
    long double sum = static_cast<long double>(f.constant) + static_cast<long double>(f.slope) * x;
    for (const ExponentialDecay& d : f.decays) {
      sum +=
          static_cast<long double>(d.amplitude) * std::exp(-x / static_cast<long double>(d.time));
    }
    return sum;
  };
  long double lo = std::max(0.0L, static_cast<long double>(*s) * (1.0L - 1e-9L));
  long double hi = std::min(static_cast<long double>(span), *s * (1.0L + 1e-9L) + 1e-300L);
  EXPECT_NE(g(lo) < 0.0L, g(hi) < 0.0L);
  for (int i = 0; i < 200 && hi - lo > 0.0L; ++i) {
    const long double mid = 0.5L * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((g(mid) < 0.0L) == (g(lo) < 0.0L) ? lo : hi) = mid;
  }
  const double reference = static_cast<double>(0.5L * (lo + hi));
  const double eps = std::numeric_limits<double>::epsilon();
  double sizes = std::abs(f.constant) + std::abs(f.slope * reference);
  double slope = f.slope;
  for (const ExponentialDecay& d : f.decays) {
    const double decay = d.amplitude * std::exp(-reference / d.time);
    sizes += std::abs(decay);
    slope -= decay / d.time;
  }
  EXPECT_NEAR(*s, reference, 4.0 * eps * reference + 4.0 * eps * sizes / std::abs(slope))
      << "a " << f.constant << " b " << f.slope << " c " << f.decays.front().amplitude << " tau "
      << f.decays.front().time;
  return true;
}

bool expect_one_decay_root(double a, double b, double c, double tau, double span) {
  return expect_root(ExponentialSum{a, b, {{c, tau}}}, span);
}

// One decay and a slope over every sign of each (the loads of a spring pressed, withdrawn or
// held, a free surface met again).
TEST(PronyRoot, OneDecayRootsToTheirLastBits) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.05, 1.0);
  int found = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double b = (trial % 2 ? 1.0 : -1.0) * unit(random) * (trial % 8 < 4 ? 1.0 : 1e3);
    const double c = (trial % 4 < 2 ? 1.0 : -1.0) * unit(random) * 10.0;
    const double tau = 0.01 + unit(random);
    const double a = (unit(random) - 0.5) * 20.0;
    if (expect_one_decay_root(a, b, c, tau, 5.0)) ++found;
  }
  EXPECT_GT(found, 1000);
}

// A first root on the lower branch of Lambert's W whose argument -c exp(a / (b tau)) / (b tau)
// is denormal (a / (b tau) < -708: a slope far smaller than the decay's rate), where Boost's W
// raises: the root is still found, and exactly.
TEST(PronyRoot, OneDecayRootWhereLambertsArgumentIsDenormal) {
  EXPECT_TRUE(expect_one_decay_root(0.0020212469952489574, -0.00012404109684988903,
                                    -0.01948942312466341, 0.022200771402853006,
                                    5.2113221782724635));
  EXPECT_TRUE(expect_one_decay_root(5.4881945973060218e-05, -1.0908453491579908e-07,
                                    -0.00012968356403798053, 0.69668225962364971,
                                    2.792716863508002));
  EXPECT_TRUE(expect_one_decay_root(46.908810332294017 - 37.493556357571904, -0.13010657455781122,
                                    -67.124167327830975, 0.10001122274614205, 0.4938206141479739));
}

// Two and four decays of one sign (a spring withdrawn whose arms all push, or all pull) and of
// both, over every sign of the slope: roots to their last bits, as with one decay.
TEST(PronyRoot, SeveralDecaysRootsToTheirLastBits) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.05, 1.0);
  int found = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    ExponentialSum f{(unit(random) - 0.5) * 20.0,
                     (trial % 2 ? 1.0 : -1.0) * unit(random) * (trial % 8 < 4 ? 1.0 : 1e3),
                     {}};
    const int decays = trial % 3 == 0 ? 4 : 2;
    for (int j = 0; j < decays; ++j) {
      const double sign = trial % 4 < 2 ? 1.0 : (trial % 4 == 2 ? -1.0 : (j % 2 ? 1.0 : -1.0));
      f.decays.push_back({sign * unit(random) * 10.0, 0.01 + unit(random)});
    }
    if (expect_root(f, 5.0)) ++found;
  }
  EXPECT_GT(found, 1000);
}

// Newton started near the root (a neighbouring spring's crossing), on either side of it, or
// anywhere on the span: the same roots to their last bits, for one decay and for several of one
// sign; a start where there is no root finds none.
TEST(PronyRoot, RootsFromANearbyStartToTheirLastBits) {
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> unit(0.05, 1.0);
  int found = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    ExponentialSum f{(unit(random) - 0.5) * 20.0,
                     (trial % 2 ? 1.0 : -1.0) * unit(random) * (trial % 8 < 4 ? 1.0 : 1e3),
                     {}};
    const int decays = 1 + trial % 3;
    const double sign = trial % 16 < 8 ? 1.0 : -1.0;
    for (int j = 0; j < decays; ++j) {
      f.decays.push_back({sign * unit(random) * 10.0, 0.01 + unit(random)});
    }
    const std::optional<double> root = first_crossing(f, 0.0, 5.0);
    // Within 1e-5 of the root either side, or anywhere on the span.
    const double near = !root || trial % 3 == 0
                            ? 5.0 * unit(random)
                            : *root * (1.0 + (trial % 2 ? 1e-5 : -1e-5) * unit(random));
    EXPECT_EQ(first_crossing(f, 0.0, 5.0, near).has_value(), root.has_value());
    if (expect_root(f, 5.0, near)) ++found;
  }
  EXPECT_GT(found, 1000);
}

// (x - 0.9)(x - 0.5)(x - 0.2) with x = exp(-s): three decays (rates 1, 2, 3), roots at s =
// -ln 0.9, -ln 0.5, -ln 0.2, each the first crossing from a start before it; a level the sum
// reaches only inside its second monotone piece.
TEST(PronyRoot, SeveralDecaysAndCrossings) {
  const double p = 0.9, q = 0.5, r = 0.2;
  const ExponentialSum f{
      -p * q * r, 0.0, {{p * q + q * r + r * p, 1.0}, {-(p + q + r), 0.5}, {1.0, 1.0 / 3.0}}};
  for (const double root : {p, q, r}) {
    const double expected = -std::log(root);
    // Start halfway between the previous root and this one.
    const double start = root == p   ? 0.0
                         : root == q ? 0.5 * (-std::log(p) - std::log(q))
                                     : 0.5 * (-std::log(q) - std::log(r));
    ExponentialSum from{f.constant, 0.0, {}};
    for (const ExponentialDecay& decay : f.decays) {
      from.decays.push_back({decay.amplitude * std::exp(-start / decay.time), decay.time});
    }
    const auto s = first_crossing(from, 0.0, 20.0);
    ASSERT_TRUE(s.has_value()) << root;
    EXPECT_NEAR(start + *s, expected, 1e-13 * expected) << root;
  }
  EXPECT_FALSE(first_crossing(f, 0.0, 0.5 * -std::log(p)).has_value());
  // f's minimum between the roots at 0.9 and 0.5 lies at x = m, f(m) < 0; a level just above it
  // is first reached on the way down, past the first root, from above (f(0) = 0.04 > level).
  const double m =
      ((p + q + r) + std::sqrt((p + q + r) * (p + q + r) - 3.0 * (p * q + q * r + r * p))) / 3.0;
  const double lowest = (m - p) * (m - q) * (m - r);
  ASSERT_LT(lowest, 0.0);
  const double level = 0.5 * lowest;
  const auto s = first_crossing(f, level, 20.0);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(f.at(*s), level, 1e-15);
  EXPECT_GT(*s, -std::log(p));
  EXPECT_LT(*s, -std::log(m));
}

// A sum that starts at the level and moves away is not found at s = 0; one that only touches the
// level as s -> infinity is never found.
TEST(PronyRoot, StartingAtTheLevel) {
  const ExponentialSum rise{0.0, 0.0, {{1.0, 1.0}, {-1.0, 0.5}}};  // exp(-s) - exp(-2s) >= 0
  EXPECT_FALSE(first_crossing(rise, 0.0, 100.0).has_value());
  const ExponentialSum up_and_down{0.0, -0.05, {{1.0, 1.0}, {-1.0, 0.5}}};
  const auto s = first_crossing(up_and_down, 0.0, 100.0);
  ASSERT_TRUE(s.has_value());
  EXPECT_GT(*s, std::log(2.0));  // past the maximum
  EXPECT_NEAR(up_and_down.at(*s), 0.0, 1e-16);
}

}  // namespace
}  // namespace mdrsim
