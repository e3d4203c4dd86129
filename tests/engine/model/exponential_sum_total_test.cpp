// The running total of exponential sums against the sums of its members evaluated one by one,
// as members enter and leave at their own times.
#include "engine/model/exponential_sum_total.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace mdrsim {
namespace {

struct TotalMember {
  ExponentialSum f;
  double since;
  bool in = true;
};

TEST(ExponentialSumTotal, ReadsTheSumOfItsMembersAsTheyEnterAndLeave) {
  // 200 members with two decays (0.1 s and 0.03 s, as a two-term bulk's loads), entering every
  // 0.01 s, every third leaving 0.35 s after its entry, read at each step over 4 s (40 tau of
  // the slower term). The direct sum rounds at a few eps of sum |f_i|; the total, rebased at
  // each change, at some 10 eps of it: 1e-13 of sum |f_i| bounds both.
  ExponentialSumTotal total;
  total.clear(0.0);
  std::vector<TotalMember> members;
  double worst = 0.0;
  for (int step = 0; step < 400; ++step) {
    const double now = 0.01 * step;
    for (std::size_t i = 0; i < members.size(); ++i) {
      TotalMember& m = members[i];
      if (m.in && i % 3 == 0 && now - m.since >= 0.35) {
        total.add(m.f, m.since, now, -1.0);
        m.in = false;
      }
    }
    if (step < 200) {
      const double k = static_cast<double>(step);
      ExponentialSum f{3.0 + 0.5 * std::sin(k), -2.0 + std::cos(k), {}};
      f.decays.push_back({40.0 * std::sin(1.7 * k), 0.1});
      f.decays.push_back({-25.0 * std::cos(0.3 * k), 0.03});
      members.push_back({f, now});
      total.add(f, now, now, 1.0);
    }
    double direct = 0.0;
    double scale = 0.0;
    for (const TotalMember& m : members) {
      if (!m.in) continue;
      const double value = m.f.at(now + 0.005 - m.since);
      direct += value;
      scale += std::abs(value);
    }
    worst = std::max(worst, std::abs(total.at(now + 0.005) - direct) / scale);
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(ExponentialSumTotal, IsEmptyAfterClear) {
  ExponentialSumTotal total;
  total.clear(1.0);
  total.add({1.0, 2.0, {{3.0, 0.1}}}, 1.0, 1.5, 1.0);
  total.clear(2.0);
  EXPECT_EQ(total.at(3.0), 0.0);
}

}  // namespace
}  // namespace mdrsim
