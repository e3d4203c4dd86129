// The event trajectory lies on the JKR curve of eqs. 18-19 (Fig. 2).
#include <gtest/gtest.h>

#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "engine/output/trajectory_csv.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/parabolic_reference.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::test::JkrScenario;

namespace {

struct Row {
  std::string event;
  bool in_cascade;
  double indentation, normal_force, contact_radius;
};

std::vector<Row> parse_csv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(
      line,
      "stage,event,in_cascade,indentation,normal_force,contact_radius,tangential_displacement,"
      "tangential_force,springs_in_contact");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cs(line);
    for (std::string cell; std::getline(cs, cell, ',');) cells.push_back(cell);
    EXPECT_EQ(cells.size(), 9u) << line;
    rows.push_back(
        {cells[1], cells[2] == "1", std::stod(cells[3]), std::stod(cells[4]), std::stod(cells[5])});
  }
  return rows;
}

/// Distance in the (d/d0, F/F0) plane from a point to the curve of eqs. 18-19, minimised
/// over a near the point's own contact radius.
double distance_to_jkr_curve(double d, double f, double a_guess) {
  const auto distance = [&](double a) {
    return std::hypot(ref::indentation(a) - d, ref::normal_force(a) - f);
  };
  const auto best = boost::math::tools::brent_find_minima(distance, std::max(1e-6, a_guess - 0.05),
                                                          a_guess + 0.05, 40);
  return best.second;
}

}  // namespace

class TrajectoryOnCurve : public ::testing::TestWithParam<std::string> {};

TEST_P(TrajectoryOnCurve, EveryEquilibriumEventLiesOnEquations18And19) {
  JkrScenario s;
  s.normal = GetParam();
  const auto k = s.scales();
  std::ostringstream csv;
  mdrsim::TrajectoryCsvWriter writer(csv);
  mdrsim::ObserverList observers;
  observers.add(writer);
  const auto result = mdrsim::run_pull_off(s.build(), observers);
  const auto rows = parse_csv(csv.str());

  int checked = 0;
  double worst = 0.0;
  for (const Row& row : rows) {
    if (row.event != "detached" && row.event != "instability") continue;
    if (row.in_cascade) continue;  // inside the final jump, not an equilibrium
    worst =
        std::max(worst, distance_to_jkr_curve(row.indentation / k.depth, row.normal_force / k.force,
                                              row.contact_radius / k.radius));
    ++checked;
  }
  // Every spring down to the fold is an equilibrium event, one row each.
  EXPECT_EQ(checked, s.springs - result.critical->springs_in_contact + 2);
  EXPECT_LE(worst, 1e-3);
  EXPECT_GT(worst, 0.0);  // the spring row is not the continuum: a zero would mean no check
}

INSTANTIATE_TEST_SUITE_P(Fig2, TrajectoryOnCurve, ::testing::Values("fixed-grips", "fixed-load"));
