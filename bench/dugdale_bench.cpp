// Google Benchmark: the Maugis-Dugdale zone per profile: one contact state, the fixed-load
// pull-off search from a glued radius, and a 1000-point force curve down to the closing point
// (independent states, and each from its neighbour's zone).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "engine/continuum/dugdale_pull_off.hpp"
#include "engine/model/dugdale_zone.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"

namespace {

constexpr double kModulus = 1e6;       ///< E* [Pa]
constexpr double kWork = 0.05;         ///< dgamma [J/m^2]
constexpr double kGluedRadius = 5e-4;  ///< a_g [m]
constexpr double kRadius = 0.01;       ///< R of the parabola, the sphere and its table [m]
constexpr int kCurvePoints = 1000;

/// sigma_0 [Pa] of Maugis' lambda = sigma_0 (9 R / (2 pi dgamma E*^2))^(1/3) = 1 at R: the
/// transition, where neither limit holds and the zone is as wide as the contact.
double transition_stress() {
  return 1.0 / std::cbrt(9.0 * kRadius / (2.0 * std::numbers::pi * kWork * kModulus * kModulus));
}

/// A 200-point table of the sphere out to 0.6 R (the continuum bench's).
std::unique_ptr<mdrsim::Profile> tabulated_sphere() {
  mdrsim::ProfileTable table;
  for (int i = 0; i < 200; ++i) {
    const double r = 0.6 * kRadius * i / 199.0;
    table.radii.push_back(r);
    table.gaps.push_back(kRadius - std::sqrt(kRadius * kRadius - r * r));
  }
  return std::make_unique<mdrsim::TabulatedProfile>(table);
}

std::unique_ptr<mdrsim::Profile> profile_of(const std::string& name) {
  if (name == "parabolic") return std::make_unique<mdrsim::ParabolicProfile>(kRadius);
  if (name == "cone") return std::make_unique<mdrsim::ConeProfile>(5.0);
  if (name == "power_law") return std::make_unique<mdrsim::PowerLawProfile>(3e3, 2.5);
  if (name == "sphere") return std::make_unique<mdrsim::SphereProfile>(kRadius);
  return tabulated_sphere();
}

const mdrsim::DugdaleLaw kLaw{.adhesive_stress = transition_stress(),
                              .work_of_adhesion = kWork,
                              .effective_modulus = kModulus};

/// One contact state at half the glued radius.
void contact_state(benchmark::State& state, const std::string& name) {
  const auto profile = profile_of(name);
  mdrsim::DugdaleState s;
  for (auto _ : state) {
    s = mdrsim::dugdale_contact_state(*profile, kLaw, 0.5 * kGluedRadius);
    benchmark::DoNotOptimize(s);
  }
  state.counters["angle"] = s.angle;
}

/// The fixed-load pull-off search from the glued radius (dugdale_fixed_load_pull_off).
void fixed_load_pull_off(benchmark::State& state, const std::string& name) {
  const auto profile = profile_of(name);
  mdrsim::DugdalePullOff p;
  for (auto _ : state) {
    p = mdrsim::dugdale_fixed_load_pull_off(*profile, kLaw, kGluedRadius);
    benchmark::DoNotOptimize(p);
  }
  state.counters["normal_force"] = p.critical.normal_force;
  state.counters["contact_radius"] = p.critical.contact_radius;
}

/// 1000 contact states along a from the glued radius down towards the closing point (a -> 0).
void force_curve(benchmark::State& state, const std::string& name) {
  const auto profile = profile_of(name);
  std::vector<double> force(kCurvePoints);
  for (auto _ : state) {
    for (int k = 0; k < kCurvePoints; ++k) {
      const double a = kGluedRadius * (kCurvePoints - k) / kCurvePoints;
      force[k] = mdrsim::dugdale_contact_state(*profile, kLaw, a).normal_force;
    }
    benchmark::DoNotOptimize(force.data());
  }
  state.counters["points"] = kCurvePoints;
}

/// The same curve through dugdale_contact_states: each point starts from its neighbour's zone.
void continued_force_curve(benchmark::State& state, const std::string& name) {
  const auto profile = profile_of(name);
  std::vector<double> radii(kCurvePoints);
  for (int k = 0; k < kCurvePoints; ++k) {
    radii[k] = kGluedRadius * (kCurvePoints - k) / kCurvePoints;
  }
  for (auto _ : state) {
    const std::vector<mdrsim::DugdaleState> curve =
        mdrsim::dugdale_contact_states(*profile, kLaw, radii);
    benchmark::DoNotOptimize(curve.data());
  }
  state.counters["points"] = kCurvePoints;
}

}  // namespace

int main(int argc, char** argv) {
  for (const std::string name : {"parabolic", "cone", "power_law", "sphere", "tabulated"}) {
    benchmark::RegisterBenchmark(("dugdale_state/" + name).c_str(), contact_state, name)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("dugdale_fixed_load_pull_off/" + name).c_str(),
                                 fixed_load_pull_off, name)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("dugdale_force_curve_1000/" + name).c_str(), force_curve, name)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("dugdale_force_curve_1000_continued/" + name).c_str(),
                                 continued_force_curve, name)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
