// Random scenes: draws mapped from raw 64-bit words, scaled on each scene's own critical radius.
#include "engine/reference/random_scenes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"

namespace mdrsim::test {
namespace {

constexpr double kPi = std::numbers::pi;

/// Uniform numbers from the raw words of mt19937_64: 53 bits -> [0, 1).
class Draws {
 public:
  explicit Draws(std::uint64_t seed) : engine_(seed) {}

  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  double log_uniform(double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * unit());
  }
  int index(int n) { return std::min(n - 1, static_cast<int>(unit() * n)); }

 private:
  std::mt19937_64 engine_;
};

/// One draw: every number is drawn whether used or not, so each draw takes the same words.
struct Parameters {
  int profile;       ///< 0 parabolic, 1 sphere, 2 cone, 3 power_law
  double size;       ///< parabola R, power-law length L [m]; sphere: a*/R [1]
  double angle_deg;  ///< cone
  double exponent;   ///< power law
  int criterion;     ///< 0 mode-mixed, 1 deformation, 2 stress, 3 normal-only, 4 mode-dependent
  double lambda;     ///< mode-dependent
  double youngs_modulus;  ///< [Pa]
  double poisson_ratio;
  double work_of_adhesion;  ///< [J/m^2]
  int normal;               ///< 0 fixed-grips, 1 fixed-load, 2 compliant
  double stiffness_ratio;   ///< k / (2 E* a_c)
  int tangential;           ///< 0 none, 1 fixed-grips u, 2 fixed-load F_x
  double tangential_fraction;
  double glued_ratio;  ///< a_g / a_c
};

Parameters draw(Draws& d) {
  Parameters p;
  p.profile = d.index(4);
  p.size = d.log_uniform(1e-3, 1e-1);
  p.angle_deg = d.uniform(5.0, 60.0);
  p.exponent = d.uniform(1.2, 4.0);
  p.criterion = d.index(5);
  p.lambda = d.unit();
  p.youngs_modulus = d.log_uniform(1e5, 1e8);
  p.poisson_ratio = d.uniform(0.0, 0.5);
  p.work_of_adhesion = d.log_uniform(1e-2, 1.0);
  p.normal = d.index(3);
  p.stiffness_ratio = d.log_uniform(1e-2, 1e2);
  p.tangential = d.index(3);
  p.tangential_fraction = d.uniform(0.0, 0.8);
  p.glued_ratio = d.log_uniform(1.2, 20.0);
  return p;
}

constexpr const char* kProfileNames[] = {"parabolic", "sphere", "cone", "power_law"};
constexpr const char* kCriterionKeys[] = {"mode-mixed", "deformation", "stress", "normal-only",
                                          "mode-dependent"};
constexpr const char* kCriterionNames[] = {"mode_mixed", "deformation", "stress", "normal_only",
                                           "mode_dependent"};
constexpr const char* kNormalKeys[] = {"fixed-grips", "fixed-load", "compliant"};
constexpr const char* kNormalNames[] = {"fixed_grips", "fixed_load", "compliant"};
constexpr const char* kTangentialNames[] = {"no_shear", "held_u", "held_force"};

/// The profile and the body of its [profile] table. The sphere's R is set from a*/R, a* the
/// radius where g(a*) = sqrt(w a*) (w = 2 pi dgamma/E*), so that its contact stays small.
struct DrawnProfile {
  std::unique_ptr<Profile> profile;
  std::string table;
  double outer = INFINITY;  ///< largest glued radius allowed [m]
};

DrawnProfile make_profile(const Parameters& p, double adhesion_length) {
  DrawnProfile out;
  switch (p.profile) {
    case 0:
      out.profile = std::make_unique<ParabolicProfile>(p.size);
      out.table = fmt::format("type = \"parabolic\"\nradius = {:.17g}\n", p.size);
      break;
    case 1: {
      // g ~ a^2/R at the tip: a* = (R^2 w)^(1/3), so a*/R = rho needs R = w / rho^3, with
      // rho = sqrt(1e-3 size) log-uniform in [1e-3, 1e-2].
      const double rho = std::sqrt(1e-3 * p.size);
      const double radius = adhesion_length / (rho * rho * rho);
      out.profile = std::make_unique<SphereProfile>(radius);
      out.table = fmt::format("type = \"sphere\"\nradius = {:.17g}\n", radius);
      out.outer = 0.3 * radius;
      break;
    }
    case 2:
      out.profile = std::make_unique<ConeProfile>(p.angle_deg);
      out.table = fmt::format("type = \"cone\"\nslope_angle_deg = {:.17g}\n", p.angle_deg);
      break;
    default: {
      // f = L (r/L)^n: c = L^(1 - n).
      const double coefficient = std::pow(p.size, 1.0 - p.exponent);
      out.profile = std::make_unique<PowerLawProfile>(coefficient, p.exponent);
      out.table = fmt::format("type = \"power_law\"\ncoefficient = {:.17g}\nexponent = {:.17g}\n",
                              coefficient, p.exponent);
      break;
    }
  }
  return out;
}

/// The radius a* where g(a) = sqrt(w a), by bisection in log a: the scale of the folds.
double adhesive_scale(const Profile& profile, double adhesion_length, double outer) {
  double lo = 1e-30, hi = std::isfinite(outer) ? outer : 1e6;
  const auto excess = [&](double a) {
    return profile.mdr_image(a) - std::sqrt(adhesion_length * a);
  };
  if (!(excess(lo) < 0.0) || !(excess(hi) > 0.0)) return NAN;
  for (int k = 0; k < 200; ++k) {
    const double mid = std::sqrt(lo * hi);
    (excess(mid) < 0.0 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

DetachmentLaw law_of(const Parameters& p) {
  constexpr DetachmentLaw::Kind kinds[] = {
      DetachmentLaw::Kind::mode_mixed, DetachmentLaw::Kind::deformation,
      DetachmentLaw::Kind::stress, DetachmentLaw::Kind::normal_only,
      DetachmentLaw::Kind::mode_dependent};
  return {kinds[p.criterion], p.criterion == 4 ? p.lambda : 1.0};
}

}  // namespace

RandomSceneSet random_scene_set(std::uint64_t seed, int count) {
  RandomSceneSet set;
  Draws draws(seed);
  while (static_cast<int>(set.scenes.size()) < count) {
    const Parameters p = draw(draws);
    ++set.draws;
    const ContinuumMaterial material = ContinuumMaterial::from_youngs_modulus(
        p.youngs_modulus, p.poisson_ratio, p.work_of_adhesion);
    const double es = material.effective_modulus, gs = material.effective_shear_modulus;
    const double adhesion_length = 2.0 * kPi * p.work_of_adhesion / es;
    const DrawnProfile drawn = make_profile(p, adhesion_length);
    const DetachmentLaw law = law_of(p);

    // The critical radius without tangential load: fixed grips (the stiffness's scale), then
    // the drawn control, from a contact glued well beyond a*.
    const double scale = adhesive_scale(*drawn.profile, adhesion_length, drawn.outer);
    if (!std::isfinite(scale)) {
      ++set.discarded.setup;
      continue;
    }
    const double wide = std::min(30.0 * scale, drawn.outer);
    const ContinuumCritical grips =
        ContinuumReference(*drawn.profile, material, law, {}, NormalControl::fixed_grips())
            .pull_off(wide);
    if (grips.kind != ContinuumCritical::Kind::fold) {
      ++set.discarded.setup;
      continue;
    }
    const double stiffness = p.stiffness_ratio * 2.0 * es * grips.point.contact_radius;
    const NormalControl normal = p.normal == 0   ? NormalControl::fixed_grips()
                                 : p.normal == 1 ? NormalControl::fixed_load()
                                                 : NormalControl::compliant(stiffness);
    const ContinuumCritical plain =
        ContinuumReference(*drawn.profile, material, law, {}, normal).pull_off(wide);
    if (plain.kind != ContinuumCritical::Kind::fold) {
      ++set.discarded.setup;
      continue;
    }
    const double glued = p.glued_ratio * plain.point.contact_radius;
    if (!(glued <= drawn.outer)) {
      ++set.discarded.setup;
      continue;
    }

    // The tangential load: a fraction of what the glue carries unstretched at a_g, capped at
    // ten times the mode-mixed limit for laws that carry more (or any).
    const double mixed_limit = std::sqrt(2.0 * kPi * glued * p.work_of_adhesion / gs);
    const double shear_free =
        ContinuumReference(*drawn.profile, material, law, {}, normal).zero_stretch_limit(glued);
    const double limit = std::min(shear_free, 10.0 * mixed_limit);
    TangentialLoad tangential;
    std::string tangential_line;
    if (p.tangential == 1) {
      tangential = {TangentialLoad::Kind::displacement, p.tangential_fraction * limit};
      tangential_line =
          fmt::format("tangential = {{ control = \"fixed-grips\", displacement = {:.17g} }}\n",
                      tangential.value);
    } else if (p.tangential == 2) {
      tangential = {TangentialLoad::Kind::force, p.tangential_fraction * 2.0 * gs * glued * limit};
      tangential_line = fmt::format(
          "tangential = {{ control = \"fixed-load\", force = {:.17g} }}\n", tangential.value);
    }

    const ContinuumCritical reference =
        ContinuumReference(*drawn.profile, material, law, tangential, normal).pull_off(glued);
    using Kind = ContinuumCritical::Kind;
    if (reference.kind == Kind::none) {
      ++set.discarded.none;
      continue;
    }
    if (reference.kind == Kind::shear_off_at_application) {
      ++set.discarded.shear_off_at_application;
      continue;
    }
    if (reference.kind == Kind::first_detachment) {
      ++set.discarded.first_detachment;
      continue;
    }
    if (!(reference.point.contact_radius * 1.05 < glued)) {
      ++set.discarded.near_glued_radius;
      continue;
    }
    if (!(std::abs(reference.point.normal_force) >=
          1e-3 * std::abs(reference.peak_adhesive_force))) {
      ++set.discarded.near_zero_force;
      continue;
    }

    const int index = static_cast<int>(set.scenes.size());
    RandomScene scene;
    scene.name = fmt::format("{:03d}_{}_{}_{}_{}", index, kProfileNames[p.profile],
                             kCriterionNames[p.criterion], kNormalNames[p.normal],
                             kTangentialNames[p.tangential]);
    scene.glued_radius = glued;
    scene.tangential_fraction = p.tangential == 0 ? 0.0 : p.tangential_fraction;
    std::string text = fmt::format(
        "title = \"random scene {}: continuum {} at F = {:.10g} N, a = {:.10g} m\"\n"
        "[material]\nyoungs_modulus = {:.17g}\npoisson_ratio = {:.17g}\n"
        "work_of_adhesion = {:.17g}\n[profile]\n{}"
        "[loading]\npreload = {{ contact_radius = {:.17g} }}\n{}",
        scene.name, kind_name(reference.kind), reference.point.normal_force,
        reference.point.contact_radius, p.youngs_modulus, p.poisson_ratio, p.work_of_adhesion,
        drawn.table, glued, tangential_line);
    text += p.normal == 2
                ? fmt::format("normal = {{ control = \"compliant\", stiffness = {:.17g} }}\n",
                              stiffness)
                : fmt::format("normal = {{ control = \"{}\" }}\n", kNormalKeys[p.normal]);
    text += fmt::format("[detachment]\ncriterion = \"{}\"\n", kCriterionKeys[p.criterion]);
    if (p.criterion == 4) text += fmt::format("lambda = {:.17g}\n", p.lambda);
    scene.toml_without_discretization = std::move(text);
    scene.reference = reference;
    set.scenes.push_back(std::move(scene));
  }
  return set;
}

std::vector<RandomScene> random_scenes(std::uint64_t seed, int count) {
  return random_scene_set(seed, count).scenes;
}

}  // namespace mdrsim::test
