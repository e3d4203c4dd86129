// Google Benchmark: the Maugis-Dugdale zone per profile: its gap integral, one contact state, the
// fixed-load pull-off search from a glued radius, and a 1000-point force curve down to the closing
// point (independent states, and each from its neighbour's zone); the shorthand's path: its first
// fold under each control, its most tensile state and its work up to the fold, and its --samples
// curve (a scene run's parts); a fold's line counts the gap integrals it takes.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/continuum/dugdale_path.hpp"
#include "engine/continuum/dugdale_pull_off.hpp"
#include "engine/model/dugdale_zone.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"
#include "profiles/wavy_profile.hpp"

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
  // A ripple of 10 nm at 100 um on the parabola (A k^2 R = 0.4: g still rises), whose gap
  // integral is a fixed Gauss rule over (0, a) (wavy_gap.hpp).
  if (name == "wavy") return std::make_unique<mdrsim::WavyProfile>(kRadius, 1e-8, 1e-4);
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

/// One gap integral J and its slope (Profile::dugdale_gap) at the zones of a thin state (at the
/// glued radius) and of a wide one (near the closing point): what each Newton step pays.
void gap_integral(benchmark::State& state, const std::string& name) {
  const auto profile = profile_of(name);
  const mdrsim::DugdaleState thin = mdrsim::dugdale_contact_state(*profile, kLaw, kGluedRadius);
  const mdrsim::DugdaleState wide =
      mdrsim::dugdale_contact_state(*profile, kLaw, 0.02 * kGluedRadius);
  for (auto _ : state) {
    for (const mdrsim::DugdaleState& z : {thin, wide}) {
      benchmark::DoNotOptimize(profile->dugdale_gap(z.contact_radius, z.cohesive_radius, z.angle));
    }
  }
  state.counters["thin_angle"] = thin.angle;
  state.counters["wide_angle"] = wide.angle;
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

/// A profile that counts its gap integrals J (what a Dugdale search pays for), read once after a
/// timed loop.
class CountingProfile final : public mdrsim::Profile {
 public:
  explicit CountingProfile(const mdrsim::Profile& p) : p_(p) {}
  double shape(double r) const override { return p_.shape(r); }
  double mdr_image(double x) const override { return p_.mdr_image(x); }
  double mdr_image_slope(double x) const override { return p_.mdr_image_slope(x); }
  double contact_radius_at_depth(double d) const override { return p_.contact_radius_at_depth(d); }
  double nonadhesive_force_per_modulus(double a) const override {
    return p_.nonadhesive_force_per_modulus(a);
  }
  mdrsim::DugdaleGap dugdale_gap(double a, double c, double t) const override {
    ++gaps;
    return p_.dugdale_gap(a, c, t);
  }
  double outer_radius() const override { return p_.outer_radius(); }
  mutable int gaps = 0;

 private:
  const mdrsim::Profile& p_;
};

/// The path from a preload pressed to the glued radius's own depth (a_p = a_g).
mdrsim::DugdalePath path_of(const mdrsim::Profile& profile) {
  return {profile, kLaw, kGluedRadius,
          mdrsim::dugdale_contact_state(profile, kLaw, kGluedRadius).indentation};
}

/// The machine's control: fixed load, fixed grips, or a 1 N/m cantilever.
mdrsim::AffineConstraint control_of(const std::string& control) {
  if (control == "fixed-load") return {0.0, 1.0};
  if (control == "fixed-grips") return {1.0, 0.0};
  return {1.0, 1.0};
}

/// The path's first fold (first_fold), as a scene run finds its critical point.
void path_first_fold(benchmark::State& state, const std::string& name, const std::string& control) {
  const auto profile = profile_of(name);
  const mdrsim::DugdalePath path = path_of(*profile);
  const mdrsim::AffineConstraint c = control_of(control);
  std::optional<mdrsim::DugdaleFold> fold;
  for (auto _ : state) {
    fold = mdrsim::first_fold(path, c);
    benchmark::DoNotOptimize(fold);
  }
  state.counters["normal_force"] = fold ? fold->state.normal_force : 0.0;
  state.counters["contact_radius"] = fold ? fold->state.contact_radius : 0.0;
  const CountingProfile counting(*profile);
  const mdrsim::DugdalePath counted = path_of(counting);
  counting.gaps = 0;
  benchmark::DoNotOptimize(mdrsim::first_fold(counted, c));
  state.counters["gap_integrals"] = counting.gaps;
}

/// The most tensile state and the work up to the fixed-load fold: the rest of a run's cost.
void path_peak_and_work(benchmark::State& state, const std::string& name) {
  const auto profile = profile_of(name);
  const mdrsim::DugdalePath path = path_of(*profile);
  const double s_end = mdrsim::first_fold(path, control_of("fixed-load"))->s;
  double work = 0.0;
  for (auto _ : state) {
    const mdrsim::DugdaleFold peak = mdrsim::most_tensile(path, s_end);
    double error = 0.0;
    work = mdrsim::path_work(path, 0.0, s_end, error);
    benchmark::DoNotOptimize(peak);
    benchmark::DoNotOptimize(work);
  }
  state.counters["work"] = work;
}

/// A scene run's --samples curve: 1000 states evenly in s from the preload to the fixed-load
/// fold, one path.at() each, or through path.states() (each from the last ones), as the run does.
void path_samples(benchmark::State& state, const std::string& name, bool continued) {
  const auto profile = profile_of(name);
  const mdrsim::DugdalePath path = path_of(*profile);
  const double s_end = mdrsim::first_fold(path, control_of("fixed-load"))->s;
  std::vector<double> places(kCurvePoints);
  for (int k = 0; k < kCurvePoints; ++k) places[k] = s_end * k / (kCurvePoints - 1);
  for (auto _ : state) {
    if (continued) {
      const std::vector<mdrsim::DugdaleState> curve = path.states(places);
      benchmark::DoNotOptimize(curve.data());
    } else {
      for (const double s : places) benchmark::DoNotOptimize(path.at(s));
    }
  }
  state.counters["points"] = kCurvePoints;
}

}  // namespace

int main(int argc, char** argv) {
  for (const std::string name : {"parabolic", "cone", "power_law", "sphere", "tabulated"}) {
    benchmark::RegisterBenchmark(("dugdale_gap_pair/" + name).c_str(), gap_integral, name)
        ->Unit(benchmark::kMicrosecond);
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
    for (const std::string control : {"fixed-load", "fixed-grips", "compliant"}) {
      benchmark::RegisterBenchmark(("dugdale_path_first_fold/" + name + "/" + control).c_str(),
                                   path_first_fold, name, control)
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("dugdale_path_peak_and_work/" + name).c_str(), path_peak_and_work,
                                 name)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("dugdale_path_samples_1000/" + name).c_str(), path_samples, name,
                                 false)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("dugdale_path_samples_1000_continued/" + name).c_str(),
                                 path_samples, name, true)
        ->Unit(benchmark::kMicrosecond);
  }
  // The wavy profile's zone, its fixed-load pull-off and its path's first fixed-grips fold (the
  // first of the folds at its crests); no curve.
  benchmark::RegisterBenchmark("dugdale_gap_pair/wavy", gap_integral, std::string("wavy"))
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("dugdale_state/wavy", contact_state, std::string("wavy"))
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("dugdale_fixed_load_pull_off/wavy", fixed_load_pull_off,
                               std::string("wavy"))
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("dugdale_path_first_fold/wavy/fixed-grips", path_first_fold,
                               std::string("wavy"), std::string("fixed-grips"))
      ->Unit(benchmark::kMicrosecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
