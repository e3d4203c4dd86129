// docs/programs.md "The shorthand as a program", over the whole grid: 3 profiles x 5 criteria x 3
// normal controls x 3 tangential displacements, each scene run as the shorthand and as its three
// stages on the same row, give the same status and the same critical point.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

constexpr double kModulus = 1.0e6;            ///< E [Pa], nu = 0: E* = G* (Fig. 3a)
constexpr double kWorkOfAdhesion = 0.05;      ///< [J/m^2]
constexpr double kGluedRadius = 5.0e-4;       ///< the preload's contact radius a_g [m]
constexpr double kComplianceStiffness = 5e2;  ///< k [N/m], about E* a_g: neither limit
constexpr std::int64_t kSprings = 3000;

struct Profile {
  const char* name;
  const char* table;
};

constexpr Profile kProfiles[] = {
    {"parabolic", "type = \"parabolic\"\nradius = 0.01\n"},
    {"cone", "type = \"cone\"\nslope_angle_deg = 2.0\n"},
    {"power_law", "type = \"power_law\"\ncoefficient = 0.8\nexponent = 1.5\n"},
};
constexpr const char* kCriteria[] = {"mode-mixed", "deformation", "stress", "normal-only",
                                     "mode-dependent"};
constexpr const char* kControls[] = {"fixed-grips", "fixed-load", "compliant"};
/// The tangential displacement over u_s = sqrt(2 pi a_g dgamma / G*), the stretch at which
/// the mode-mixed glue at a_g shears off at zero elongation. Under fixed grips on both axes
/// the parabola's critical force is compressive from about 0.6 u_s (Fig. 3a's positive
/// branch; the grid's first case checks it).
constexpr double kTangentialFractions[] = {0.0, 0.7, 0.85};

std::string common_tables(const Profile& profile, const char* criterion) {
  return fmt::format(
      "[material]\nyoungs_modulus = {}\npoisson_ratio = 0.0\nwork_of_adhesion = {}\n"
      "[profile]\n{}"
      "[detachment]\ncriterion = \"{}\"\n{}"
      "[discretization]\nsprings = {}\n",
      kModulus, kWorkOfAdhesion, profile.table, criterion,
      std::string(criterion) == "mode-dependent" ? "lambda = 0.5\n" : "", kSprings);
}

std::string normal_axis(const char* control) {
  return std::string(control) == "compliant"
             ? fmt::format("control = \"compliant\", stiffness = {}", kComplianceStiffness)
             : fmt::format("control = \"{}\"", control);
}

/// The pull-off stage's `by` per unit of its parameter: the held value's unit (m or N) at
/// a rate that crosses the whole path within a few units.
double pull_rate(const char* control) {
  return std::string(control) == "fixed-load" ? -1e-2 : -1e-5;
}

struct Pair {
  RunResult shorthand;
  RunResult program;
};

Pair run_both(const Profile& profile, const char* criterion, const char* control,
              double tangential) {
  const std::string tangential_key =
      tangential != 0.0
          ? fmt::format("tangential = {{ control = \"fixed-grips\", displacement = {:.17g} }}\n",
                        tangential)
          : std::string();
  const Scene shorthand = test::build_scene_text(
      common_tables(profile, criterion) +
      fmt::format("[loading]\npreload = {{ contact_radius = {} }}\n{}normal = {{ {} }}\n",
                  kGluedRadius, tangential_key, normal_axis(control)));
  const std::string tangential_stage =
      tangential != 0.0
          ? fmt::format("tangential = {{ control = \"fixed-grips\", to = {:.17g} }}\n", tangential)
          : std::string();
  const Scene program = test::build_scene_text(
      common_tables(profile, criterion) +
      fmt::format("[loading]\n"
                  "[[loading.stage]]\nname = \"preload\"\n"
                  "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\n"
                  "[[loading.stage]]\nname = \"tangential\"\nnormal = {{ {} }}\n{}"
                  "[[loading.stage]]\nname = \"pull-off\"\nnormal = {{ by = {} }}\n"
                  "until = \"separation\"\n",
                  shorthand.preload_depth, normal_axis(control), tangential_stage,
                  pull_rate(control)));
  return {run_scene(shorthand, {}), run_scene(program, {})};
}

double shear_stretch() { return std::sqrt(2.0 * M_PI * kGluedRadius * kWorkOfAdhesion / kModulus); }

// The first case of the grid is on Fig. 3a's positive branch: parabola, fixed grips on both
// axes, u = 0.85 u_s. The paper's closed form (eq. 35 and the fixed-grips line) puts the
// critical force there above zero, at a positive indentation: the grid exercises the branch.
TEST(ShorthandProgramGrid, ReachesThePositiveBranch) {
  const Pair p = run_both(kProfiles[0], "mode-mixed", "fixed-grips", 0.85 * shear_stretch());
  ASSERT_TRUE(p.shorthand.critical.has_value());
  EXPECT_EQ(p.shorthand.status, RunStatus::instability);
  EXPECT_GT(p.shorthand.critical->normal_force, 0.0);
  EXPECT_GT(p.shorthand.critical->indentation, 0.0);
}

// Same status and the same critical force. Both runs are one row of kSprings springs across
// a_g with the same events, so the forces are the same sums in another order: they agree to
// rounding, a few ulps times the springs (3000 * 1e-16 of the preload force); 1e-9 of the
// largest force on the path is far below the row's discretization error (about 1 / N).
TEST(ShorthandProgramGrid, SameStatusAndCriticalForce) {
  int cases = 0;
  int disagree = 0;
  for (const Profile& profile : kProfiles) {
    for (const char* criterion : kCriteria) {
      for (const char* control : kControls) {
        for (const double fraction : kTangentialFractions) {
          ++cases;
          const Pair p = run_both(profile, criterion, control, fraction * shear_stretch());
          const RunResult& a = p.shorthand;
          const RunResult& b = p.program;
          const std::string label =
              fmt::format("{} {} {} u = {} u_s", profile.name, criterion, control, fraction);
          bool same = a.status == b.status && a.critical.has_value() == b.critical.has_value();
          if (same && a.critical) {
            const double scale = a.stages.empty() ? std::abs(a.critical->normal_force)
                                                  : std::abs(a.stages[0].end.normal_force);
            same = a.critical->springs_in_contact == b.critical->springs_in_contact &&
                   std::abs(a.critical->normal_force - b.critical->normal_force) <= 1e-9 * scale;
          }
          if (!same) {
            ++disagree;
            ADD_FAILURE() << label << ": shorthand " << to_string(a.status) << " "
                          << (a.critical ? fmt::format("F = {:.10g} N, {} springs",
                                                       a.critical->normal_force,
                                                       a.critical->springs_in_contact)
                                         : std::string("no critical point"))
                          << "; program " << to_string(b.status) << " "
                          << (b.critical ? fmt::format("F = {:.10g} N, {} springs",
                                                       b.critical->normal_force,
                                                       b.critical->springs_in_contact)
                                         : std::string("no critical point"));
          }
        }
      }
    }
  }
  std::printf("%d of %d combinations disagree\n", disagree, cases);
  EXPECT_EQ(cases, 135);
}

}  // namespace
}  // namespace mdrsim
