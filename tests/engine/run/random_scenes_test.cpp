// The random scene set: fixed by its seed, loadable, and in line with a plain 200000-spring row.
#include "engine/reference/random_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

using mdrsim::test::ContinuumCritical;
using mdrsim::test::RandomScene;
using mdrsim::test::RandomSceneSet;

namespace {

constexpr std::uint64_t kSeed = 20240611;
constexpr int kCount = 120;

const RandomSceneSet& scene_set() {
  static const RandomSceneSet set = [] {
    const auto start = std::chrono::steady_clock::now();
    RandomSceneSet s = mdrsim::test::random_scene_set(kSeed, kCount);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto& d = s.discarded;
    std::printf(
        "random scenes: %zu kept of %d draws in %.3f s; discarded: none %d, shear-off at "
        "application %d, first detachment %d, critical within 5%% of a_g %d, near-zero force "
        "%d, setup %d\n",
        s.scenes.size(), s.draws, seconds, d.none, d.shear_off_at_application, d.first_detachment,
        d.near_glued_radius, d.near_zero_force, d.setup);
    return s;
  }();
  return set;
}

/// The critical normal force of a run, whether RunResult holds `critical` plainly or as an
/// optional (absent: no critical point).
template <class Critical>
std::optional<double> critical_force(const Critical& critical) {
  if constexpr (requires { critical.has_value(); }) {
    if (!critical.has_value()) return std::nullopt;
    return critical->normal_force;
  } else {
    return critical.normal_force;
  }
}

}  // namespace

// The seed fixes the set: the same text twice, >= 120 scenes with distinct names usable as
// GoogleTest parameter names, each ending at a fold or a shear-off below its glued radius.
TEST(RandomScenes, FixedSeedFixesTheSet) {
  const RandomSceneSet& set = scene_set();
  ASSERT_EQ(set.scenes.size(), static_cast<std::size_t>(kCount));
  EXPECT_EQ(set.draws, kCount + set.discarded.total());
  const std::vector<RandomScene> again = mdrsim::test::random_scenes(kSeed, kCount);
  ASSERT_EQ(again.size(), set.scenes.size());
  std::set<std::string> names;
  for (std::size_t i = 0; i < again.size(); ++i) {
    const RandomScene& s = set.scenes[i];
    EXPECT_EQ(again[i].name, s.name);
    EXPECT_EQ(again[i].toml_without_discretization, s.toml_without_discretization);
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_TRUE(std::all_of(s.name.begin(), s.name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    })) << s.name;
    EXPECT_TRUE(s.reference.kind == ContinuumCritical::Kind::fold ||
                s.reference.kind == ContinuumCritical::Kind::shear_off)
        << s.name;
    EXPECT_LT(s.reference.point.contact_radius * 1.05, s.glued_radius) << s.name;
    EXPECT_GE(std::abs(s.reference.point.normal_force),
              1e-3 * std::abs(s.reference.peak_adhesive_force))
        << s.name;
  }
}

// Every profile, criterion and control shows up, and some tangential loads come near the limit.
TEST(RandomScenes, CoverEveryPartAndControl) {
  const RandomSceneSet& set = scene_set();
  const auto count = [&](const std::string& part) {
    return std::count_if(set.scenes.begin(), set.scenes.end(), [&](const RandomScene& s) {
      return s.name.find(part) != std::string::npos;
    });
  };
  for (const char* part :
       {"_parabolic_", "_sphere_", "_cone_", "_power_law_", "_mode_mixed_", "_deformation_",
        "_stress_", "_normal_only_", "_mode_dependent_", "_fixed_grips_", "_fixed_load_",
        "_compliant_", "_no_shear", "_held_u", "_held_force"}) {
    EXPECT_GE(count(part), 5) << part;
  }
  EXPECT_GE(std::count_if(set.scenes.begin(), set.scenes.end(),
                          [](const RandomScene& s) { return s.tangential_fraction > 0.6; }),
            5);
}

// Every text is a scene the engine loads once a [discretization] is appended.
TEST(RandomScenes, EverySceneLoads) {
  for (const RandomScene& s : scene_set().scenes) {
    EXPECT_NO_THROW(mdrsim::test::build_scene_text(s.toml_without_discretization +
                                                   "[discretization]\nsprings = 1000\n"))
        << s.name << "\n"
        << s.toml_without_discretization;
  }
}

// A coarse cross-check that the engine and the reference model the same thing: a plain row of
// 200000 springs (first order, error ~ 1/N of the force scale) within 2e-2 of the continuum
// critical force, for the scenes whose critical radius holds >= 1000 of those springs.
TEST(RandomScenes, PlainRowAgreesWithTheReference) {
  constexpr std::int64_t kSprings = 200000;
  int compared = 0;
  std::vector<std::pair<double, std::string>> errors;
  for (const RandomScene& s : scene_set().scenes) {
    const double in_contact = kSprings * s.reference.point.contact_radius / s.glued_radius;
    if (in_contact < 1000.0) continue;
    const mdrsim::Scene scene = mdrsim::test::build_scene_text(
        s.toml_without_discretization + "[discretization]\nsprings = 200000\n");
    const mdrsim::RunResult result = mdrsim::run_scene(scene, {});
    const std::optional<double> force = critical_force(result.critical);
    ASSERT_TRUE(force.has_value()) << s.name;
    const double reference = s.reference.point.normal_force;
    const double error = std::abs(*force - reference) / std::abs(reference);
    errors.emplace_back(error, s.name);
    EXPECT_LE(error, 2e-2) << s.name << ": engine " << *force << " N, continuum " << reference
                           << " N (" << mdrsim::test::kind_name(s.reference.kind) << ")\n"
                           << s.toml_without_discretization;
    ++compared;
  }
  EXPECT_GE(compared, 100);
  std::sort(errors.rbegin(), errors.rend());
  for (std::size_t i = 0; i < std::min<std::size_t>(5, errors.size()); ++i) {
    std::printf("largest relative errors: %.3e %s\n", errors[i].first, errors[i].second.c_str());
  }
}
