// The spring row's O(N) set-up pass: its sums, and the caller's interrupt check polled during it.
#include "engine/model/spring_foundation.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/base/interrupt_check.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/sphere_profile.hpp"

namespace {

int polls = 0;

void stop_at_second_poll() {
  if (++polls >= 2) throw std::runtime_error("interrupted");
}

/// Restores the thread's check whatever the test does.
struct ScopedCheck {
  explicit ScopedCheck(mdrsim::InterruptCheck check) : previous(mdrsim::interrupt_check) {
    mdrsim::interrupt_check = check;
  }
  ~ScopedCheck() { mdrsim::interrupt_check = previous; }
  ScopedCheck(const ScopedCheck&) = delete;
  ScopedCheck& operator=(const ScopedCheck&) = delete;
  mdrsim::InterruptCheck previous;
};

TEST(SpringFoundation, SumsTheImageAndItsSquareOverTheRow) {
  // g(x) = x^2 / R for the parabola (MDR image of r^2 / (2R)): sum_i (i dx)^2 / R and its
  // square, in closed form: dx^2/R N(N+1)(2N+1)/6 and dx^4/R^2 N(N+1)(2N+1)(3N^2+3N-1)/30.
  const mdrsim::ParabolicProfile profile(0.01);
  const double a = 3e-4;
  const double n = 7.0;
  const mdrsim::SpringFoundation row(profile, a, 7);
  const double dx = a / n;
  const double r = 0.01;
  EXPECT_NEAR(row.total_image(), dx * dx / r * n * (n + 1) * (2 * n + 1) / 6.0, 1e-15 * a * a / r);
  EXPECT_NEAR(
      row.total_image_squares(),
      dx * dx * dx * dx / (r * r) * n * (n + 1) * (2 * n + 1) * (3 * n * n + 3 * n - 1) / 30.0,
      1e-15 * a * a * a * a / (r * r));
}

TEST(SpringFoundation, PollsTheInterruptCheckDuringItsSetUpPass) {
  // 2^22 springs: the pass polls every 2^20, so a check that throws on its second call stops
  // the set-up (before: 1e8 springs sat 0.3 s deaf to Python's Ctrl-C).
  polls = 0;
  const ScopedCheck scoped(&stop_at_second_poll);
  const mdrsim::ParabolicProfile profile(0.01);
  EXPECT_THROW(mdrsim::SpringFoundation(profile, 3e-4, std::int64_t{1} << 22), std::runtime_error);
  EXPECT_EQ(polls, 2);
}

TEST(SpringFoundation, GivesEachImageAsTheProfileDoesOnRowsThatKeepThemAndRowsThatDoNot) {
  // Rows of up to 2^20 springs keep the images of their set-up pass, unless the profile's are
  // cheap (the parabola's); longer ones compute them again. Either way a spring's image is the
  // profile's at its position, to the bit.
  const mdrsim::SphereProfile sphere(0.01);
  const mdrsim::ParabolicProfile parabola(0.01);
  for (const mdrsim::Profile* profile : {static_cast<const mdrsim::Profile*>(&sphere),
                                         static_cast<const mdrsim::Profile*>(&parabola)}) {
    for (const std::int64_t n :
         {std::int64_t{1}, std::int64_t{1000}, (std::int64_t{1} << 20) + 1}) {
      const mdrsim::SpringFoundation row(*profile, 5e-4, n);
      for (const std::int64_t i : {std::int64_t{1}, n / 2 + 1, n}) {
        EXPECT_EQ(row.image(i), profile->mdr_image(row.position(i)))
            << n << " springs, spring " << i;
      }
    }
  }
}

}  // namespace
