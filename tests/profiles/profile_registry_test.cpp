// Invariants over every registered profile: g(0) = 0, g non-decreasing, eq. 4 of the shape, and
// closed forms equal to the interface's numerical defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "profiles/mdr_transform.hpp"
#include "profiles/profile_registry.hpp"
#include "tests/support/run_command.hpp"

namespace {

mdrsim::ProfileRegistry registry() {
  mdrsim::ProfileRegistry r;
  mdrsim::register_builtin_profiles(r);
  return r;
}

/// Sample parameters per registered profile; a profile without one fails the test below,
/// so that every new profile is held to the invariants.
std::map<std::string, mdrsim::ParameterValues> samples() {
  std::map<std::string, mdrsim::ParameterValues> s;
  s["parabolic"].set("radius", 0.01);
  s["sphere"].set("radius", 2e-3);
  s["cone"].set("slope_angle_deg", 25.0);
  s["flat_punch"].set("radius", 1e-3);
  s["power_law"].set("coefficient", 0.5);
  s["power_law"].set("exponent", 1.5);
  // A ripple gentle enough (A k^2 R = 0.39) that f and g still rise: the invariants below.
  s["wavy"].set("radius", 0.01);
  s["wavy"].set("amplitude", 1e-8);
  s["wavy"].set("wavelength", 1e-4);
  s["tabulated"].set("r", std::vector<double>{0, 2e-4, 4e-4, 6e-4, 8e-4, 1e-3, 1.5e-3});
  s["tabulated"].set("f", std::vector<double>{0, 1e-6, 4.5e-6, 1.1e-5, 2e-5, 3.2e-5, 7.5e-5});
  return s;
}

}  // namespace

class EveryProfile : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryProfile, ImageAndClosedFormsAreConsistent) {
  const auto reg = registry();
  const auto all = samples();
  ASSERT_EQ(all.count(GetParam()), 1u) << "add sample parameters for " << GetParam();
  const auto profile = reg.find(GetParam())->create(all.at(GetParam()));
  const mdrsim::Profile& p = *profile;
  const double edge = std::min(p.outer_radius(), 1e-3);
  EXPECT_EQ(p.mdr_image(0.0), 0.0);
  double last = 0.0;
  for (int i = 1; i <= 1000; ++i) {
    const double g = p.mdr_image(edge * i / 1000.0);
    ASSERT_TRUE(std::isfinite(g));
    EXPECT_GE(g, last);
    last = g;
  }
  for (const double a : {0.13 * edge, 0.5 * edge, 0.9 * edge}) {
    // Eq. 4 from the shape alone: a central difference of f (step 1e-6 r, error ~1e-10
    // relative) in the tanh-sinh transform.
    const auto slope = [&](double r) {
      const double h = 1e-6 * std::max(r, 1e-9);
      return (p.shape(r + h) - p.shape(std::max(r - h, 0.0))) / (r + h - std::max(r - h, 0.0));
    };
    const double g = p.mdr_image(a);
    EXPECT_NEAR(mdrsim::mdr_transform(slope, a), g, 1e-8 * a) << "a = " << a;
    const double force = p.nonadhesive_force_per_modulus(a);
    EXPECT_NEAR(force, p.Profile::nonadhesive_force_per_modulus(a), 1e-10 * a * a);
    EXPECT_NEAR(p.mdr_image_slope(a), p.Profile::mdr_image_slope(a), 1e-8);
    if (!p.fixed_contact_radius()) {
      EXPECT_NEAR(p.contact_radius_at_depth(g), a, 1e-12 * a);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryProfile, ::testing::ValuesIn(registry().names()),
                         [](const auto& info) { return info.param; });

// What the engine asks of a profile instead of its name: whether its branch folds at every
// crest (the ripple only), and the file its points were read from (a table read from a CSV
// only; the result carries it).
TEST_P(EveryProfile, AnswersTheCapabilitiesTheEngineAsks) {
  const auto profile = registry().find(GetParam())->create(samples().at(GetParam()));
  EXPECT_EQ(profile->folds_at_every_crest(), GetParam() == "wavy");
  EXPECT_FALSE(profile->source_table_file());
}

TEST(TabulatedProfile, ReadFromAFileNamesItsFile) {
  const std::string dir = mdrsim::test::make_temp_dir();
  const std::string path = dir + "/table.csv";
  std::ofstream(path) << "r,f\n0,0\n1e-4,1e-6\n2e-4,4e-6\n3e-4,9e-6\n";
  mdrsim::ParameterValues values;
  values.set("file", path);
  EXPECT_EQ(registry().find("tabulated")->create(values)->source_table_file(), path);
  std::filesystem::remove_all(dir);
}
