// A free spring's creep against its closed form for one term and against a high-order ODE
// integration for several, and its touch with the indenter against the closed form.
#include "engine/model/prony_creep.hpp"

#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <vector>

namespace mdrsim {
namespace {

constexpr double kRelaxed = 1.0e6;

// One term: w(t) = w0 exp(-t E* / (tau E_0*)) with w0 = -sigma0 / E*. 1e-14 relative.
TEST(PronyCreep, OneTermRetardsAtTheRetardationTime) {
  const std::vector<PronyTerm> terms{{9.0e6, 0.1}};
  const double sigma0 = -25.0;  // w0 = 2.5e-5 m
  const FreeSpringCreep creep(kRelaxed, terms, std::vector<double>{sigma0});
  const double w0 = -sigma0 / kRelaxed;
  const double rate = kRelaxed / (0.1 * 1.0e7);
  ASSERT_EQ(creep.rates().size(), 1u);
  EXPECT_NEAR(creep.rates()[0], rate, 1e-14 * rate);
  for (const double t : {0.0, 0.1, 1.0, 5.0}) {
    EXPECT_NEAR(creep.stretch(t), w0 * std::exp(-rate * t), 1e-14 * w0) << t;
    EXPECT_NEAR(creep.stresses(t)[0], sigma0 * std::exp(-rate * t), 1e-14 * std::abs(sigma0));
  }
}

// Three terms, two of them with one relaxation time: with q = 0 the arms obey sigma_j' = E_j w' -
// sigma_j / tau_j and w' = sum_k (sigma_k / tau_k) / E_0*; Fehlberg 7(8) at 1e-14 gives the
// reference, agreeing to 1e-11 of the initial stresses (the integration's own error ~1e-13).
TEST(PronyCreep, SeveralTermsAgainstTheirEquations) {
  const std::vector<PronyTerm> terms{{9.0e6, 0.1}, {2.0e6, 3.0}, {1.0e6, 0.1}};
  const std::vector<double> sigma0{-25.0, 8.0, 3.0};
  const FreeSpringCreep creep(kRelaxed, terms, sigma0);
  EXPECT_EQ(creep.rates().size(), 2u);  // the two arms at 0.1 s act as one

  using State = std::array<double, 3>;
  const double glassy = kRelaxed + 12.0e6;
  const auto rhs = [&](const State& s, State& ds, double) {
    double wdot = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
      wdot += s[j] / terms[j].time;
    }
    wdot /= glassy;
    for (std::size_t j = 0; j < 3; ++j) {
      ds[j] = terms[j].modulus * wdot - s[j] / terms[j].time;
    }
  };
  namespace odeint = boost::numeric::odeint;
  State state{sigma0[0], sigma0[1], sigma0[2]};
  double t = 0.0;
  for (const double until : {0.05, 0.5, 2.0, 10.0}) {
    odeint::integrate_adaptive(
        odeint::make_controlled(1e-14, 1e-14, odeint::runge_kutta_fehlberg78<State>()), rhs, state,
        t, until, 1e-4);
    t = until;
    const auto stresses = creep.stresses(t);
    double load = kRelaxed * creep.stretch(t);
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_NEAR(stresses[j], state[j], 1e-11 * 25.0) << t << " " << j;
      load += stresses[j];
    }
    EXPECT_NEAR(load, 0.0, 1e-13 * 25.0) << t;  // free: no load
  }
}

// The indenter held at w0 - delta meets a one-term spring released at w0 when w0 exp(-mu s) =
// w0 - delta; withdrawing at a rate it meets it later, where the two stretches agree.
TEST(PronyCreep, TouchTime) {
  const std::vector<PronyTerm> terms{{9.0e6, 0.1}};
  const FreeSpringCreep creep(kRelaxed, terms, std::vector<double>{-25.0});
  const double w0 = 2.5e-5, delta = 0.4e-5, mu = creep.rates()[0];
  const auto held = touch_time(creep, 0.0, w0 - delta, 0.0, 100.0);
  ASSERT_TRUE(held.has_value());
  const double expected = -std::log(1.0 - delta / w0) / mu;
  EXPECT_NEAR(*held, expected, 1e-13 * expected);
  // Started later on the creep's clock, the same touch.
  const auto later = touch_time(creep, 0.5 * expected, w0 - delta, 0.0, 100.0);
  ASSERT_TRUE(later.has_value());
  EXPECT_NEAR(*later + 0.5 * expected, expected, 1e-13 * expected);
  // Withdrawing slowly: later, where the stretches meet.
  const double rate = -1e-6;
  const auto moving = touch_time(creep, 0.0, w0 - delta, rate, 100.0);
  ASSERT_TRUE(moving.has_value());
  EXPECT_GT(*moving, expected);
  EXPECT_NEAR(creep.stretch(*moving), w0 - delta + rate * *moving, 1e-14 * w0);
  // Withdrawing fast: never.
  EXPECT_FALSE(touch_time(creep, 0.0, w0 - delta, -1e-3, 100.0).has_value());
}

// What a free spring stores, E* w^2 / 2 + sum_j sigma_j^2 / (2 E_j) from its stretch and stresses
// (stresses_from_decays, built term by term), against stored(), which sums the modes' and the
// residuals' squares (their orthogonality in the pencil's inner product): three terms, two of
// them sharing a relaxation time (so with residuals), and one term alone. Both sum a few products
// of the same decays: 1e-14 of the energy at release.
TEST(PronyCreep, StoredEnergyAsASumOfSquares) {
  const std::vector<std::vector<PronyTerm>> materials{{{4.0e6, 0.1}, {3.0e6, 0.02}, {2.0e6, 0.1}},
                                                      {{9.0e6, 0.1}}};
  const std::vector<std::vector<double>> releases{{-30.0, 12.0, 5.0}, {-25.0}};
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const std::vector<PronyTerm>& terms = materials[m];
    const FreeSpringCreep creep(kRelaxed, terms, releases[m]);
    const auto direct = [&](double t) {
      double w = 0.0;
      const FewValues<double> sigma = creep.numbers().stresses(t, w);
      double e = 0.5 * kRelaxed * w * w;
      for (std::size_t j = 0; j < terms.size(); ++j) {
        e += 0.5 * sigma[j] * sigma[j] / terms[j].modulus;
      }
      return e;
    };
    const double at_release = direct(0.0);
    ASSERT_GT(at_release, 0.0);
    for (const double t : {0.0, 1e-4, 0.01, 0.05, 0.3, 2.0}) {
      EXPECT_NEAR(creep.numbers().stored(t), direct(t), 1e-14 * at_release) << m << " " << t;
    }
    // It only falls: the free spring dissipates.
    EXPECT_LT(creep.numbers().stored(0.3), creep.numbers().stored(0.05));
  }
}

}  // namespace
}  // namespace mdrsim
