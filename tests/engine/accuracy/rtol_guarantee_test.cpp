// rtol is a guarantee: over a fixed random set of scenes, every run lands within it.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/random_scenes.hpp"
#include "engine/run/run_scene.hpp"

using mdrsim::RunStatus;
using mdrsim::test::ContinuumCritical;
using mdrsim::test::RandomScene;

namespace {

constexpr std::uint64_t kSeed = 20240611;
constexpr int kCount = 120;

const std::vector<RandomScene>& scenes() {
  static const std::vector<RandomScene> set = mdrsim::test::random_scenes(kSeed, kCount);
  return set;
}

/// rtol, extrapolation key ("" absent, "none", "richardson") and the part of the set: the
/// plain rows at 1e-6 (minutes in all) run as four cases of 30 scenes, so that ctest -j spreads
/// them over the cores.
struct Case {
  double rtol;
  std::string extrapolation;
  int part = 0;
  int parts = 1;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << "rtol " << c.rtol << ", extrapolation '" << c.extrapolation << "', part " << c.part + 1
      << " of " << c.parts;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const double rtol : {1e-4, 1e-6}) {
    for (const std::string extrapolation : {"", "none", "richardson"}) {
      const int parts = rtol == 1e-6 && extrapolation == "none" ? 4 : 1;
      for (int part = 0; part < parts; ++part) out.push_back({rtol, extrapolation, part, parts});
    }
  }
  return out;
}

class RtolGuarantee : public ::testing::TestWithParam<Case> {};

}  // namespace

// The reference is engine/reference/continuum_reference: the continuum branch solved for each
// criterion written from the criterion table of docs/scene.md, with no engine code. rtol is
// relative to the critical normal force, and the peak adhesive force is held to the same rtol. The
// error must also be within the run's own a posteriori estimate, and the estimate within rtol.
TEST_P(RtolGuarantee, WithinRtolOfTheContinuum) {
  const auto& [rtol, extrapolation, part, parts] = GetParam();
  const std::size_t first = scenes().size() * part / parts;
  const std::size_t last = scenes().size() * (part + 1) / parts;
  int unmet = 0;
  for (std::size_t k = first; k < last; ++k) {
    const RandomScene& s = scenes()[k];
    SCOPED_TRACE(s.name);
    // method = "event": the row's guarantee (rtol alone would take the continuum route).
    std::string text = s.toml_without_discretization + "[solver]\nmethod = \"event\"\n" +
                       "[discretization]\nrtol = " + std::to_string(rtol) + "\n";
    if (!extrapolation.empty()) text += "extrapolation = \"" + extrapolation + "\"\n";
    const mdrsim::RunResult r = mdrsim::run_scene(mdrsim::test::build_scene_text(text), {});

    const ContinuumCritical& ref = s.reference;
    const RunStatus expected = ref.kind == ContinuumCritical::Kind::shear_off
                                   ? RunStatus::shear_off
                                   : RunStatus::instability;
    EXPECT_EQ(r.status, expected);
    ASSERT_TRUE(r.critical.has_value());
    ASSERT_TRUE(r.accuracy.critical_error_estimate.has_value());
    const double exact = ref.point.normal_force;
    const double error = std::abs(r.critical->normal_force - exact) / std::abs(exact);
    const double estimate =
        *r.accuracy.critical_error_estimate / std::abs(r.critical->normal_force);
    // The estimate bounds the error, whatever happens.
    EXPECT_LE(error, estimate) << "the estimate does not bound the error";
    if (r.accuracy.rtol_met) {
      EXPECT_LE(error, rtol) << r.critical->normal_force << " against " << exact;
      EXPECT_LE(estimate, rtol);
      // The critical point and the peak met rtol: any warning may be only about the path's
      // stages, jumps and works, whose rows stop at 2^17 springs (shorthand_accuracy.cpp); a
      // path whose rtol was met is listed in `covers`, one that was not is not. (A glue that
      // lets go with the indenter pressed in runs the scene as its program, which follows the
      // pressed springs: no warning says it.)
      bool path_unmet = false;
      for (const std::string& w : r.warnings) {
        const bool unmet_path =
            w.find("not met for the stages, jumps and work") != std::string::npos;
        path_unmet = path_unmet || unmet_path;
        EXPECT_TRUE(unmet_path) << w;
      }
      const bool path_covered = std::find(r.accuracy.covers.begin(), r.accuracy.covers.end(),
                                          "work") != r.accuracy.covers.end();
      EXPECT_EQ(path_covered, !path_unmet);
    } else {
      // Only the plain route at 1e-6 may run out of springs (2^25 per row) on the hardest
      // scenes; it must then say so, never miss silently.
      EXPECT_EQ(extrapolation, "none") << (r.warnings.empty() ? "" : r.warnings.front());
      EXPECT_EQ(rtol, 1e-6);
      EXPECT_FALSE(r.warnings.empty());
      ++unmet;
    }

    const double peak = ref.peak_adhesive_force;
    if (peak >= 0.0) {
      // The path never pulls (a critical force on the compressive branch): no adhesive peak.
      EXPECT_FALSE(r.peak.has_value()) << r.peak->normal_force << " against " << peak;
      continue;
    }
    ASSERT_TRUE(r.peak.has_value()) << peak;
    const double peak_error = std::abs(r.peak->normal_force - peak) / std::abs(peak);
    ASSERT_TRUE(r.accuracy.peak_error_estimate.has_value());
    EXPECT_LE(peak_error, *r.accuracy.peak_error_estimate / std::abs(r.peak->normal_force))
        << "peak " << r.peak->normal_force << " against " << peak;
    if (r.accuracy.rtol_met) {
      EXPECT_LE(peak_error, rtol);
    }
  }
  std::printf("%zu scenes, %d reported rtol_met = false\n", last - first, unmet);
  // At most 6 of the 120 (5 %; 2 measured), in each part its share.
  EXPECT_LE(unmet, (6 + parts - 1) / parts);
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  std::string name = std::string(c.rtol == 1e-4 ? "rtol1e4" : "rtol1e6") + "_" +
                     (c.extrapolation.empty() ? "auto" : c.extrapolation);
  if (c.parts > 1) name += "_part" + std::to_string(c.part + 1) + "of" + std::to_string(c.parts);
  return name;
}

INSTANTIATE_TEST_SUITE_P(RandomSet, RtolGuarantee, ::testing::ValuesIn(cases()), case_name);
